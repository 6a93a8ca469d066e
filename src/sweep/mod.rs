//! Parameter sweeps: a sheet run over a grid of one or two varied keys (`wrapcalc sweep`),
//! optionally one slice of it (`--shard K/N`), and the join of such slices (`wrapcalc merge`).
//!
//! Stages, one module each: [`grid`] (the `--vary` and `--shard` specs, the points) →
//! [`apply`] (a point's values set in the sheet, validated by the sheet parser) → [`run`]
//! (the points in parallel, rows in point order) → [`csv`] (sweep.csv, read and written) →
//! [`merge`] (shards joined). The plot is [`plot`].

pub mod apply;
pub mod csv;
pub mod grid;
mod labels;
pub mod merge;
pub mod plot;
mod plot_map;
pub mod run;

use crate::report::ReportError;
use crate::report::plot::PlotError;
use crate::report::target::{self, Existing, ReportKind};
use crate::run::{MAX_NODES, Options, RunError};
use crate::sheet::SheetError;
use apply::Template;
use csv::SweepFile;
use grid::{Grid, Shard};
use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};

/// The CSV of a whole sweep (single run or merged shards).
pub const SWEEP_CSV: &str = "sweep.csv";
/// Its plot.
pub const SWEEP_PNG: &str = "sweep.png";

/// Why a point failed.
#[derive(Debug, thiserror::Error)]
pub enum PointError {
    /// The sheet with the point's values does not validate.
    #[error(transparent)]
    Sheet(#[from] SheetError),
    /// The point's run failed.
    #[error(transparent)]
    Run(#[from] RunError),
}

/// Why a sweep failed.
#[derive(Debug, thiserror::Error)]
pub enum SweepError {
    /// A `--vary` spec that does not parse or names no sweepable key.
    #[error("--vary {spec}: {message}")]
    Vary {
        /// The spec given.
        spec: String,
        /// What is wrong with it.
        message: String,
    },
    /// A `--shard` spec that does not parse.
    #[error("--shard {spec}: {message}")]
    Shard {
        /// The spec given.
        spec: String,
        /// What is wrong with it.
        message: String,
    },
    /// The sheet could not be read or does not validate.
    #[error(transparent)]
    Sheet(#[from] SheetError),
    /// The sweep's options do not fit the sheet (no such scene, a key it has no place for).
    #[error("{sheet}: {message}")]
    Input {
        /// The sheet's path.
        sheet: String,
        /// What does not fit.
        message: String,
    },
    /// A run of the sheet failed.
    #[error(transparent)]
    Run(#[from] RunError),
    /// A point of the grid failed.
    /// (The point's error is part of this message, not a separate cause.)
    #[error("point {point} ({assignment}): {error}")]
    Point {
        /// Global index of the point.
        point: u64,
        /// The point's key values, `KEY = VALUE` each, comma-separated.
        assignment: String,
        /// Why it failed.
        error: PointError,
    },
    /// Shard CSVs that cannot be merged.
    #[error("merge: {message}")]
    Merge {
        /// What is wrong with them.
        message: String,
    },
    /// An output file could not be written.
    #[error("cannot write {path}: {message}")]
    Write {
        /// The file's path.
        path: String,
        /// The system's reason.
        message: String,
    },
    /// The sweep's plot could not be drawn.
    #[error(transparent)]
    Plot(#[from] PlotError),
    /// A report file could not be written.
    #[error(transparent)]
    Report(#[from] ReportError),
}

/// What to sweep.
#[derive(Debug, Clone, PartialEq)]
pub struct Spec {
    /// `KEY=START:STOP:COUNT`, one or two.
    pub vary: Vec<String>,
    /// Scenes to run (empty: all).
    pub scenes: Vec<String>,
    /// Run options of every point.
    pub options: Options,
    /// Only this slice of the points (all without).
    pub shard: Option<Shard>,
}

/// Reads the sheet at `path` and runs the sweep (or its shard); rows in point order.
pub fn sweep(path: &Path, spec: &Spec, progress: &(dyn Fn(u64) + Sync)) -> Result<SweepFile, SweepError> {
    let grid = Grid::parse(&spec.vary)?;
    if spec.options.nodes == 0 || spec.options.nodes > MAX_NODES {
        return Err(RunError::Nodes(spec.options.nodes).into());
    }
    let design = crate::sheet::load(path)?;
    let file = design.sheet;
    // The sheet was just read as UTF-8 text.
    let text = std::fs::read_to_string(path).map_err(|e| SweepError::Input {
        sheet: file.clone(),
        message: format!("cannot read the design sheet: {e}"),
    })?;
    let template = Template::new(&file, &text, &spec.scenes, &grid.varies)?;
    let range = spec.shard.map_or(0..grid.points(), |s| s.range(grid.points()));
    let rows = run::run(&template, &grid, spec.options, range, progress)?;
    Ok(SweepFile { keys: grid.keys().into_iter().map(str::to_string).collect(), rows })
}

/// The CSV's file name: `sweep.csv`, or `sweep-shard-K-of-N.csv` for a shard.
pub fn csv_name(shard: Option<Shard>) -> String {
    shard.map_or_else(|| SWEEP_CSV.to_string(), |s| format!("sweep-shard-{}-of-{}.csv", s.k, s.n))
}

/// Writes `csv_name` (and `sweep.png` when `plot`) into `dir`, next to the other files of the
/// sweep there. `dir` must be missing, empty or a wrapcalc report ([`crate::report::target`]; it is
/// marked as a sweep report when new). The files are drawn in a staging directory inside `dir`
/// and renamed into place only once all are complete, while holding the directory's lock, so a
/// failure leaves `dir` as it was and two writers never mix their files.
pub fn write(dir: &Path, csv_name: &str, file: &SweepFile, plot: bool) -> Result<Vec<PathBuf>, SweepError> {
    let fail = |path: &Path| {
        let path = path.display().to_string();
        move |e: &dyn std::fmt::Display| SweepError::Write { path: path.clone(), message: e.to_string() }
    };
    let dir = target::resolve(dir);
    target::check(&dir)?;
    let _lock = target::lock(&dir)?;
    if target::check(&dir)? != Existing::Report {
        std::fs::create_dir_all(&dir).map_err(|e| fail(&dir)(&e))?;
        target::mark(&dir, ReportKind::Sweep)?;
    }
    // Removed with whatever is left in it when dropped.
    let staging = tempfile::Builder::new().prefix(".wrapcalc-sweep-").tempdir_in(&dir).map_err(|e| fail(&dir)(&e))?;
    let staged_csv = staging.path().join(csv_name);
    let csv_file = File::create(&staged_csv).map_err(|e| fail(&staged_csv)(&e))?;
    let mut out = BufWriter::new(csv_file);
    csv::write(&mut out, &file.keys, &file.rows).map_err(|e| fail(&staged_csv)(&e))?;
    out.flush().map_err(|e| fail(&staged_csv)(&e))?;
    let mut names = vec![csv_name];
    if plot {
        plot::plot_sweep(&staging.path().join(SWEEP_PNG), &file.keys, &file.rows)?;
        names.push(SWEEP_PNG);
    }
    let mut written = Vec::new();
    for name in names {
        let path = dir.join(name);
        std::fs::rename(staging.path().join(name), &path).map_err(|e| fail(&path)(&e))?;
        written.push(path);
    }
    Ok(written)
}
