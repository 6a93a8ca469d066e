//! `wrapcalc bench`: run time against error for every model level on fixed cases with exact
//! (or finest-resolution) references, peak memory, and the measured scaling of each level.
//!
//! Stages: [`cases`] (the cases, their closed forms, one run of a point) → [`measure`] (median
//! time, peak memory) → this module (the case × level table, the sweep, scaling slopes) →
//! [`output`] (bench.csv, scaling.csv, bench.png, written whole or not at all).
//!
//! Everything runs on one rayon thread, so times mean "one core".

pub mod accuracy;
pub mod bound;
pub mod cases;
pub mod measure;
pub mod model_time;
pub mod output;
pub mod plot;
pub mod scaling;
pub mod table;
pub mod walk;

use crate::model::Level;
use crate::model::level2::{Level2Error, Solver};
use crate::run::RunError;
use crate::sheet::SheetError;
use cases::{Case, Outcome};
pub use scaling::{Scaling, log_log_slope, scaling};
use serde::Serialize;
use std::path::PathBuf;
pub use table::{DUTY_DEFAULT_STEP_S, DUTY_REFERENCE_NODES, DUTY_REFERENCE_STEP_S, Entry, Sweep, TABLE};

/// What `wrapcalc bench` runs, from its command line.
#[derive(Debug, Clone, PartialEq)]
pub struct BenchOptions {
    /// Also the largest cases (N = 100 000, a history of 1e6 samples).
    pub long: bool,
    /// The reference sheet holding the duty cycle.
    pub sheet: PathBuf,
    /// The `wrapcalc` executable: each point's peak memory is measured by running it alone in a
    /// child process (`wrapcalc bench --probe SPEC`); `None` reports no memory.
    pub probe_exe: Option<PathBuf>,
    /// Only these cases (by [`Case::name`]); all when empty.
    pub cases: Vec<String>,
}

/// One row of bench.csv.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BenchRow {
    /// Case name ([`Case::name`]).
    pub case: &'static str,
    /// Model level (0–4).
    pub level: Level,
    /// Solver of the wrap model.
    pub solver: Solver,
    /// Sweep name ([`Sweep::name`]).
    pub sweep: &'static str,
    /// Node count of the wrap (none at level 0).
    pub nodes: Option<usize>,
    /// Integration step of the suspended ropes (s; duty cycle only).
    pub time_step_s: Option<f64>,
    /// History samples (the rolling walk only).
    pub samples: Option<usize>,
    /// Increments of the wrap model (levels 2–4; level 3 with its run-in from the first loads).
    pub steps: Option<u64>,
    /// Median run time of the repeats (ms).
    pub runtime_ms: f64,
    /// How many runs the median is taken over.
    pub repeats: usize,
    /// Error against the case's reference, as `error_metric` says (none without a reference).
    pub error: Option<f64>,
    /// What `error` measures.
    pub error_metric: &'static str,
    /// Duty cycle: RMS difference of the history's positive and reverse arcs from the finest
    /// run (deg), reported beside the error (see [`cases`]).
    pub arc_rms_deg: Option<f64>,
    /// Peak resident memory of the point run alone in a child process (kB; none without a probe).
    pub peak_rss_kb: Option<u64>,
    /// Median run time of the wrap model alone, without sampling its output grid (ms; the
    /// level-2 closed-form cases, [`model_time`]).
    pub model_ms: Option<f64>,
}

/// Why `wrapcalc bench` failed.
#[derive(Debug, thiserror::Error)]
pub enum BenchError {
    /// A case's run of the design failed.
    #[error("bench case {case}: {source}")]
    Run {
        /// The case's name.
        case: &'static str,
        /// Why the run failed.
        source: RunError,
    },
    /// A case's level-2 model failed.
    #[error("bench case {case}: {source}")]
    Level2 {
        /// The case's name.
        case: &'static str,
        /// Why the model failed.
        source: Level2Error,
    },
    /// The reference sheet could not be read.
    #[error(transparent)]
    Sheet(#[from] SheetError),
    /// The reference sheet has no duty-cycle scene.
    #[error("{sheet}: the bench runs the duty-cycle scene \"{}\", which this sheet does not have", cases::DUTY_SCENE)]
    NoDutyScene {
        /// The sheet's path.
        sheet: String,
    },
    /// The single-threaded rayon pool could not start.
    #[error("cannot start the single-threaded pool: {0}")]
    Pool(String),
    /// A `--probe` spec that does not parse.
    #[error("--probe {0:?}: expected case:level:solver:nodes:time_step_s:samples")]
    Probe(String),
    /// The bench's report files could not be written.
    #[error(transparent)]
    Report(#[from] crate::report::ReportError),
    /// A `--case` that names no bench case.
    #[error("--case {name:?}: no such bench case; the cases are {}", Case::ALL.map(|c| c.name()).join(", "))]
    UnknownCase {
        /// The name given.
        name: String,
    },
}

/// One point of a sweep.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Point {
    nodes: Option<usize>,
    time_step_s: Option<f64>,
    samples: Option<usize>,
}

/// A point with its case, level and solver, as passed to a memory probe:
/// `case:level:solver:nodes:time_step_s:samples` (`-` for none).
#[derive(Debug, Clone, Copy, PartialEq)]
struct Spec {
    case: Case,
    level: Level,
    solver: Solver,
    point: Point,
}

impl Spec {
    fn to_arg(self) -> String {
        let opt = |v: Option<String>| v.unwrap_or_else(|| "-".into());
        let solver = match self.solver {
            Solver::Fast => "fast",
            Solver::Clarabel => "clarabel",
        };
        format!(
            "{}:{}:{solver}:{}:{}:{}",
            self.case.name(),
            self.level,
            opt(self.point.nodes.map(|n| n.to_string())),
            opt(self.point.time_step_s.map(|d| format!("{d:e}"))),
            opt(self.point.samples.map(|n| n.to_string())),
        )
    }

    fn parse(arg: &str) -> Option<Self> {
        let parts: Vec<&str> = arg.split(':').collect();
        let [case, level, solver, nodes, dt, samples] = parts[..] else { return None };
        fn opt<T: std::str::FromStr>(s: &str) -> Option<Option<T>> {
            if s == "-" { Some(None) } else { s.parse().ok().map(Some) }
        }
        Some(Spec {
            case: Case::ALL.iter().copied().find(|c| c.name() == case)?,
            level: Level::from_number(level.parse().ok()?)?,
            solver: match solver {
                "fast" => Solver::Fast,
                "clarabel" => Solver::Clarabel,
                _ => return None,
            },
            point: Point { nodes: opt(nodes)?, time_step_s: opt(dt)?, samples: opt(samples)? },
        })
    }
}

fn points(sweep: &Sweep, long: bool) -> Vec<Point> {
    let none = Point { nodes: None, time_step_s: None, samples: None };
    let extra = |l: &'static [usize]| if long { l } else { &[] };
    match *sweep {
        Sweep::Single => vec![none],
        Sweep::Nodes { nodes, long: l } => {
            nodes.iter().chain(extra(l)).map(|&n| Point { nodes: Some(n), ..none }).collect()
        }
        Sweep::TimeStep { nodes, steps_s } => {
            steps_s.iter().map(|&dt| Point { nodes: Some(nodes), time_step_s: Some(dt), ..none }).collect()
        }
        Sweep::Samples { nodes, samples, long: l } => {
            samples.iter().chain(extra(l)).map(|&s| Point { nodes: Some(nodes), samples: Some(s), ..none }).collect()
        }
    }
}

/// Runs the whole table on one thread; `progress` sees every row as it is measured.
pub fn run(options: &BenchOptions, progress: &mut (dyn FnMut(&BenchRow) + Send)) -> Result<Vec<BenchRow>, BenchError> {
    let pool = rayon::ThreadPoolBuilder::new().num_threads(1).build().map_err(|e| BenchError::Pool(e.to_string()))?;
    pool.install(|| run_table(options, progress))
}

/// The lines of the table the options select (an unknown case name is an error).
fn selected(options: &BenchOptions) -> Result<Vec<&'static Entry>, BenchError> {
    if let Some(bad) = options.cases.iter().find(|n| !Case::ALL.iter().any(|c| c.name() == n.as_str())) {
        return Err(BenchError::UnknownCase { name: bad.clone() });
    }
    Ok(TABLE.iter().filter(|e| options.cases.is_empty() || options.cases.iter().any(|n| n == e.case.name())).collect())
}

fn run_table(
    options: &BenchOptions,
    progress: &mut (dyn FnMut(&BenchRow) + Send),
) -> Result<Vec<BenchRow>, BenchError> {
    let mut rows = Vec::new();
    let table = selected(options)?;
    // A sheet that cannot be read fails the bench before anything runs.
    if table.iter().any(|e| e.case == Case::DutyMid) {
        cases::duty_design(&options.sheet, DUTY_DEFAULT_STEP_S)?;
    }
    // Finest runs of the duty cycle, by (N, Δt): each is run once, as a "reference" row.
    let mut references: Vec<((usize, f64), cases::DutyRun)> = Vec::new();
    for entry in table {
        let reference_key = duty_reference(entry);
        if let Some(key) = reference_key.filter(|k| !references.iter().any(|r| r.0 == *k)) {
            let spec = Spec {
                case: Case::DutyMid,
                level: entry.level,
                solver: entry.solver,
                point: Point { nodes: Some(key.0), time_step_s: Some(key.1), samples: None },
            };
            let m = run_point(options, spec)?;
            let row = BenchRow { sweep: "reference", ..row_of(options, spec, entry.sweep.name(), &m, (None, None))? };
            progress(&row);
            rows.push(row);
            references.push((key, m.value.duty.unwrap_or_default()));
        }
        let reference = reference_key.and_then(|key| references.iter().find(|r| r.0 == key)).map(|r| &r.1);
        for point in points(&entry.sweep, options.long) {
            let spec = Spec { case: entry.case, level: entry.level, solver: entry.solver, point };
            let m = run_point(options, spec)?;
            let error = match (reference, &m.value.duty) {
                (Some(r), Some(run)) => cases::duty_error(run, r),
                _ => (m.value.error, None),
            };
            let row = row_of(options, spec, entry.sweep.name(), &m, error)?;
            progress(&row);
            rows.push(row);
        }
    }
    Ok(rows)
}

/// The (N, Δt) of the run a duty-cycle point is compared with: the finest of both for the
/// node sweep, the finest Δt at the sweep's N for the time-step sweep (so it measures the
/// time discretization alone).
fn duty_reference(entry: &Entry) -> Option<(usize, f64)> {
    match (entry.case, entry.sweep) {
        (Case::DutyMid, Sweep::TimeStep { nodes, .. }) => Some((nodes, DUTY_REFERENCE_STEP_S)),
        (Case::DutyMid, _) => Some((DUTY_REFERENCE_NODES, DUTY_REFERENCE_STEP_S)),
        _ => None,
    }
}

/// Runs one point alone and returns the peak resident set of the process (kB): what
/// `wrapcalc bench --probe SPEC` prints.
pub fn probe(options: &BenchOptions, arg: &str) -> Result<Option<u64>, BenchError> {
    let spec = Spec::parse(arg).ok_or_else(|| BenchError::Probe(arg.to_string()))?;
    run_once(options, spec)?;
    Ok(measure::peak_rss_kb())
}

/// Peak memory of a point run alone in a child process (kB), when a probe executable is set
/// and the platform reports it.
fn child_peak_rss_kb(options: &BenchOptions, spec: Spec) -> Option<u64> {
    let exe = options.probe_exe.as_ref()?;
    let out = std::process::Command::new(exe)
        .args(["bench", "--probe", &spec.to_arg(), "--sheet"])
        .arg(&options.sheet)
        .stderr(std::process::Stdio::null())
        .output()
        .ok()?;
    if !out.status.success() {
        return None;
    }
    String::from_utf8(out.stdout).ok()?.trim().parse().ok()
}

fn run_point(options: &BenchOptions, spec: Spec) -> Result<measure::Measured<Outcome>, BenchError> {
    measure::measure(|| run_once(options, spec))
}

/// One run of a point, as timed: it includes reading the sheet of the duty cycle (milliseconds
/// against 0.1–5 s) and drawing the random walk's samples (under 1 % of its run),
/// so that a memory probe measures the same work.
fn run_once(options: &BenchOptions, spec: Spec) -> Result<Outcome, BenchError> {
    let case = spec.case.name();
    let run_err = |source| BenchError::Run { case, source };
    let nodes = spec.point.nodes.unwrap_or(crate::run::DEFAULT_NODES);
    match spec.case {
        Case::DutyMid => {
            let design = cases::duty_design(&options.sheet, spec.point.time_step_s.unwrap_or(DUTY_DEFAULT_STEP_S))?;
            cases::run_duty(&design, nodes).map_err(run_err)
        }
        Case::RollingWalk => {
            let samples = walk::rolling_walk(spec.point.samples.unwrap_or(1000));
            walk::run_walk(&samples, nodes).map_err(|source| BenchError::Level2 { case, source })
        }
        _ if spec.level == Level::Closed0 => cases::run_checks(spec.case).map_err(run_err),
        _ => cases::run_closed_form(spec.case, spec.level, spec.solver, nodes).map_err(run_err),
    }
}

/// The median time of the point's wrap model alone ([`model_time`]; level 2 only).
fn model_ms(spec: Spec) -> Result<Option<f64>, BenchError> {
    let Some(model) = model_time::ModelRun::of(spec.case, spec.solver).filter(|_| spec.level == Level::Rigid2) else {
        return Ok(None);
    };
    let case = spec.case.name();
    let m = measure::measure(|| model.run().map(|(increments, _)| increments))
        .map_err(|source| BenchError::Level2 { case, source })?;
    Ok(Some(m.runtime_ms))
}

fn row_of(
    options: &BenchOptions,
    spec: Spec,
    sweep: &'static str,
    m: &measure::Measured<Outcome>,
    (error, arc_rms_deg): (Option<f64>, Option<f64>),
) -> Result<BenchRow, BenchError> {
    let point = spec.point;
    let error_metric = match (spec.case, spec.level) {
        (Case::RollingWalk, _) => "none (scaling only)",
        (Case::DutyMid, _) => cases::DUTY_METRIC,
        (_, Level::Closed0) => cases::CHECKS_METRIC,
        (Case::BoundStep | Case::BoundRolling, _) => cases::WINDOW_METRIC,
        _ => cases::TENSION_METRIC,
    };
    let time_step_s = match spec.case {
        Case::DutyMid => Some(point.time_step_s.unwrap_or(DUTY_DEFAULT_STEP_S)),
        _ => None,
    };
    Ok(BenchRow {
        case: spec.case.name(),
        level: spec.level,
        solver: spec.solver,
        sweep,
        nodes: point.nodes.filter(|_| spec.level > Level::Closed0),
        time_step_s,
        samples: point.samples,
        steps: m.value.steps,
        runtime_ms: m.runtime_ms,
        repeats: m.repeats,
        error,
        error_metric,
        arc_rms_deg,
        peak_rss_kb: child_peak_rss_kb(options, spec),
        model_ms: model_ms(spec)?,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn probe_specs_round_trip() {
        let spec = Spec {
            case: Case::DutyMid,
            level: Level::Dynamic4,
            solver: Solver::Fast,
            point: Point { nodes: Some(360), time_step_s: Some(2.5e-4), samples: None },
        };
        assert_eq!(Spec::parse(&spec.to_arg()), Some(spec));
        assert_eq!(Spec::parse("duty-MID:4:fast:360"), None);
        assert_eq!(Spec::parse("nope:4:fast:-:-:-"), None);
    }

    #[test]
    fn a_case_filter_selects_its_lines_and_refuses_unknown_names() {
        let options = |cases: &[&str]| BenchOptions {
            long: false,
            sheet: PathBuf::from("tables/guo2020.toml"),
            probe_exe: None,
            cases: cases.iter().map(|c| c.to_string()).collect(),
        };
        assert_eq!(selected(&options(&[])).unwrap().len(), TABLE.len());
        let bound = selected(&options(&["bound-rolling"])).unwrap();
        assert_eq!(bound.len(), 2, "fast and clarabel");
        assert!(bound.iter().all(|e| e.case == Case::BoundRolling && e.level == Level::Elastic3));
        let err = selected(&options(&["bound-rolling", "nope"])).unwrap_err();
        assert!(matches!(&err, BenchError::UnknownCase { name } if name == "nope"), "{err}");
        assert!(err.to_string().contains("bound-step"), "{err}");
    }

    #[test]
    fn long_points_only_with_long() {
        let sweep = Sweep::Nodes { nodes: &[16, 64], long: &[100_000] };
        assert_eq!(points(&sweep, false).len(), 2);
        assert_eq!(points(&sweep, true).last().and_then(|p| p.nodes), Some(100_000));
    }
}
