//! A lift run's report directory: summary.json and summary.csv, each case's distribution (CSV
//! and figure), report.html and checks.xlsx, put in place whole or not at all.

use super::output::{LiftRun, LiftSummary};
use crate::design::lift::Lift;
use crate::report::{self, ReportError, csv_out, io, plot_distribution, target::ReportKind};
use std::fs::{self, File};
use std::io::BufWriter;
use std::path::Path;

/// What a lift run writes besides summary.json, summary.csv and the distributions.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct WriteOptions {
    /// Draw each case's distribution.png.
    pub plots: bool,
    /// Write report.html and checks.xlsx.
    pub document: bool,
}

/// Writes the report of a lift run to `dir`, whole or not at all.
pub fn write(dir: &Path, lift: &Lift, run: &LiftRun, options: WriteOptions) -> Result<(), ReportError> {
    let plots = options.plots;
    let summary = LiftSummary::of(lift, run);
    report::write_dir(dir, ReportKind::Run, |staged| {
        let json = staged.join("summary.json");
        fs::write(&json, summary.to_json() + "\n").map_err(io(&json))?;
        let csv_path = staged.join("summary.csv");
        let csv_err = |source| ReportError::Csv { path: csv_path.display().to_string(), source };
        let mut w = csv::Writer::from_path(&csv_path).map_err(csv_err)?;
        for s in &summary.scenes {
            w.serialize(s).map_err(|source| ReportError::Csv { path: csv_path.display().to_string(), source })?;
        }
        w.flush().map_err(io(&csv_path))?;
        for (t, wrap) in run.cases.iter().filter_map(|c| Some((&c.traction, c.wrap.as_ref()?))) {
            let case_dir = staged.join(t.case.name());
            fs::create_dir_all(&case_dir).map_err(io(&case_dir))?;
            let path = case_dir.join("distribution.csv");
            let f = File::create(&path).map_err(io(&path))?;
            csv_out::write_distribution(BufWriter::new(f), &[&wrap.distribution])
                .map_err(|source| ReportError::Csv { path: path.display().to_string(), source })?;
            if plots {
                let title = format!("{} — level 1 with the groove factor f = {:.4}", t.case.name(), t.f);
                plot_distribution::plot_distribution(&case_dir.join("distribution.png"), &title, &wrap.distribution)?;
            }
        }
        if !options.document {
            return Ok(());
        }
        let path = staged.join("report.html");
        fs::write(&path, super::html::render(lift, run, plots)).map_err(io(&path))?;
        let path = staged.join("checks.xlsx");
        super::workbook::write(&path, lift, run)
            .map_err(|source| ReportError::Xlsx { path: path.display().to_string(), source })?;
        Ok(())
    })
}
