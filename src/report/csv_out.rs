//! CSV reports: summary.csv (one row per scene) and `<scene>/distribution.csv`.

use super::summary::Summary;
use crate::wrap::Distribution;
use std::io::Write;

/// summary.csv: the scalar fields of every scene (empty where null).
pub fn write_summary<W: Write>(out: W, summary: &Summary) -> csv::Result<()> {
    let mut w = csv::Writer::from_writer(out);
    for scene in &summary.scenes {
        w.serialize(&scene.summary)?;
    }
    w.flush()?;
    Ok(())
}

/// distribution.csv header (INTERFACE.md).
pub const DISTRIBUTION_HEADER: [&str; 8] = [
    "t_s",
    "theta_deg",
    "tension_n",
    "normal_n_per_rad",
    "friction_n_per_rad",
    "utilization",
    "state",
    "slip_velocity_m_s",
];

/// distribution.csv: one block of rows per reported time.
pub fn write_distribution<W: Write>(out: W, blocks: &[&Distribution]) -> csv::Result<()> {
    let mut w = csv::Writer::from_writer(out);
    w.write_record(DISTRIBUTION_HEADER)?;
    for d in blocks {
        for s in &d.samples {
            w.write_record([
                d.t_s.to_string(),
                s.theta_deg.to_string(),
                s.tension_n.to_string(),
                s.normal_n_per_rad.to_string(),
                s.friction_n_per_rad.to_string(),
                s.utilization.to_string(),
                s.state.as_str().to_string(),
                s.slip_velocity_m_s.map_or_else(String::new, |v| v.to_string()),
            ])?;
        }
    }
    w.flush()?;
    Ok(())
}

/// history.csv: one row per reported time (INTERFACE.md).
pub fn write_history<W: Write>(out: W, rows: &[crate::model::level2::HistoryRow]) -> csv::Result<()> {
    let mut w = csv::Writer::from_writer(out);
    for row in rows {
        w.serialize(row)?;
    }
    w.flush()?;
    Ok(())
}
