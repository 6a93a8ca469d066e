//! CSV reports: summary.csv (one row per scene), `<scene>/distribution.csv` and `<scene>/history.csv`.

use super::number::{display, display_opt};
use super::summary::Summary;
use crate::design::HISTORY_COLUMNS;
use crate::model::history::HistoryRow;
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

/// distribution.csv header (the columns of docs/interface.md §3, then the extension column `sliding`:
/// `true` where the rope moves relative to the lining, [`crate::wrap::Sample::sliding`]).
pub const DISTRIBUTION_HEADER: [&str; 9] = [
    "t_s",
    "theta_deg",
    "tension_n",
    "normal_n_per_rad",
    "friction_n_per_rad",
    "utilization",
    "state",
    "slip_velocity_m_s",
    "sliding",
];

/// distribution.csv: one block of rows per reported time.
pub fn write_distribution<W: Write>(out: W, blocks: &[&Distribution]) -> csv::Result<()> {
    let mut w = csv::Writer::from_writer(out);
    w.write_record(DISTRIBUTION_HEADER)?;
    for d in blocks {
        for s in &d.samples {
            w.write_record([
                display(d.t_s),
                display(s.theta_deg),
                display(s.tension_n),
                display(s.normal_n_per_rad),
                display(s.friction_n_per_rad),
                display(s.utilization),
                s.state.as_str().to_string(),
                display_opt(s.slip_velocity_m_s),
                s.sliding().to_string(),
            ])?;
        }
    }
    w.flush()?;
    Ok(())
}

/// history.csv: one row per reported time (docs/interface.md's columns), then the extension columns
/// `anchor1_n,anchor2_n,mid1_n,mid2_n` (tension per rope at the conveyance anchors and halfway down
/// each hanging rope; empty but for duty cycles with the ropes' dynamics).
pub fn write_history<W: Write>(
    out: W,
    rows: &[HistoryRow],
    anchors_n: &[[f64; 2]],
    midpoints_n: &[[f64; 2]],
) -> csv::Result<()> {
    let mut w = csv::Writer::from_writer(out);
    w.write_record(HISTORY_COLUMNS.map(|(name, _)| name))?;
    for (i, r) in rows.iter().enumerate() {
        let anchors = anchors_n.get(i);
        let mids = midpoints_n.get(i);
        w.write_record([
            display(r.t_s),
            display(r.t1_n),
            display(r.t2_n),
            display(r.speed_m_s),
            display(r.accel_m_s2),
            display_opt(r.jdp_deg),
            display(r.positive_arc_deg),
            display(r.reverse_arc_deg),
            display(r.max_utilization),
            display_opt(r.safety_factor),
            r.gross_slip.to_string(),
            display_opt(anchors.map(|a| a[0])),
            display_opt(anchors.map(|a| a[1])),
            display_opt(mids.map(|a| a[0])),
            display_opt(mids.map(|a| a[1])),
        ])?;
    }
    w.flush()?;
    Ok(())
}

/// track.csv: one row per element and reported time while the element is on the pulley.
pub fn write_tracks<W: Write>(out: W, tracks: &[crate::model::track::Track]) -> csv::Result<()> {
    let mut w = csv::Writer::from_writer(out);
    w.write_record([
        "element",
        "t_s",
        "theta_deg",
        "tension_n",
        "normal_n_per_rad",
        "friction_n_per_rad",
        "utilization",
        "state",
        "contact_force_n",
        "friction_force_n",
        "impulse_n_s",
    ])?;
    for track in tracks {
        for r in &track.rows {
            w.write_record([
                track.label.clone(),
                display(r.t_s),
                display(r.theta_deg),
                display(r.tension_n),
                display(r.normal_n_per_rad),
                display(r.friction_n_per_rad),
                display(r.utilization),
                r.state.as_str().to_string(),
                display(r.contact_force_n),
                display(r.friction_force_n),
                display(r.impulse_n_s),
            ])?;
        }
    }
    w.flush()?;
    Ok(())
}
