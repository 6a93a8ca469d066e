//! The bench report: `bench.csv` (one row per point), `scaling.csv` (fitted slopes) and
//! `bench.png` (error against run time), put in place whole or not at all.

use super::plot;
use super::{BenchRow, Scaling};
use crate::report::{self, ReportError};
use std::fs::File;
use std::io::BufWriter;
use std::path::Path;

/// Writes the report for `rows` to `dir` (replacing an older one only once the new one is complete).
pub fn write(dir: &Path, rows: &[BenchRow], scaling: &[Scaling]) -> Result<(), ReportError> {
    report::write_dir(dir, report::ReportKind::Bench, |staged| {
        write_csv(&staged.join("bench.csv"), rows)?;
        write_csv(&staged.join("scaling.csv"), scaling)?;
        plot::plot_bench(&staged.join("bench.png"), rows)?;
        Ok(())
    })
}

fn write_csv<T: serde::Serialize>(path: &Path, rows: &[T]) -> Result<(), ReportError> {
    let csv_err = |source| ReportError::Csv { path: path.display().to_string(), source };
    let file = File::create(path).map_err(report::io(path))?;
    let mut w = csv::Writer::from_writer(BufWriter::new(file));
    for r in rows {
        w.serialize(r).map_err(csv_err)?;
    }
    w.flush().map_err(report::io(path))
}

/// One plain line per measured point (for progress on stderr).
pub fn progress_line(r: &BenchRow) -> String {
    let opt = |v: Option<String>| v.unwrap_or_else(|| "-".into());
    format!(
        "{:<17} level {} {:<8} {:<9} N {:>7} dt {:>7} samples {:>8} steps {:>9}  {:>10.3} ms (model {:>9} ms)  error {:>9}  peak {} kB",
        r.case,
        r.level,
        format!("{:?}", r.solver).to_lowercase(),
        r.sweep,
        opt(r.nodes.map(|n| n.to_string())),
        opt(r.time_step_s.map(|d| format!("{d:e}"))),
        opt(r.samples.map(|n| n.to_string())),
        opt(r.steps.map(|n| n.to_string())),
        r.runtime_ms,
        opt(r.model_ms.map(|m| format!("{m:.4}"))),
        opt(r.error.map(|e| format!("{e:.2e}"))),
        opt(r.peak_rss_kb.map(|k| k.to_string())),
    )
}

/// The fitted slopes as a plain table.
pub fn scaling_table(scaling: &[Scaling]) -> String {
    let mut s = String::from(
        "case              level solver   variable        range               time slope  memory slope  model time slope\n",
    );
    let opt = |v: Option<f64>| v.map_or_else(|| "-".into(), |v| format!("{v:.2}"));
    for x in scaling {
        s += &format!(
            "{:<17} {:>5} {:<8} {:<15} {:>8.0} – {:<8.0} {:>11} {:>13} {:>17}\n",
            x.case,
            x.level,
            format!("{:?}", x.solver).to_lowercase(),
            x.variable,
            x.from,
            x.to,
            opt(x.time_slope),
            opt(x.memory_slope),
            opt(x.model_time_slope)
        );
    }
    s
}
