//! `wrapcalc bench`: run time against error for every model level on fixed cases with exact
//! (or finest-resolution) references, peak memory, and the measured scaling of each level.
//!
//! Stages: [`cases`] (the cases, their closed forms, one run of a point) → [`measure`] (median
//! time, peak memory) → this module (the case × level table, the sweep, scaling slopes) →
//! [`output`] (bench.csv, scaling.csv, bench.png, written whole or not at all).
//!
//! Everything runs on one rayon thread, so times mean "one core".

pub mod cases;
pub mod measure;
pub mod output;

use crate::model::level2::{Level2Error, Solver};
use crate::run::RunError;
use crate::sheet::SheetError;
use cases::{Case, Outcome};
use serde::Serialize;
use std::path::PathBuf;

/// What a point varies along its sweep.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Sweep {
    /// One point (level 0: no node count).
    Single,
    /// Node counts; the `long` ones only with `--long`.
    Nodes { nodes: &'static [usize], long: &'static [usize] },
    /// Integration steps of the suspended ropes at a fixed node count.
    TimeStep { nodes: usize, steps_s: &'static [f64] },
    /// History samples at a fixed node count; the `long` ones only with `--long`.
    Samples { nodes: usize, samples: &'static [usize], long: &'static [usize] },
}

impl Sweep {
    pub fn name(&self) -> &'static str {
        match self {
            Sweep::Single => "single",
            Sweep::Nodes { .. } => "nodes",
            Sweep::TimeStep { .. } => "time_step",
            Sweep::Samples { .. } => "samples",
        }
    }
}

/// One line of the case × level table.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Entry {
    pub case: Case,
    pub level: u8,
    pub solver: Solver,
    pub sweep: Sweep,
}

/// Node counts: ×4 from 16, and the default (180).
const NODES: &[usize] = &[16, 64, 180, 256, 1024, 4096, 16384];
const LONG_NODES: &[usize] = &[65536, 100_000];
const CLARABEL_NODES: &[usize] = &[16, 64, 180, 256, 1024];
/// Node counts of the duty cycle at its default time step, and the time steps at N = 360.
const DUTY_NODES: &[usize] = &[90, 180, 360, 720, 1440];
const DUTY_STEPS_S: &[f64] = &[4e-3, 2e-3, 1e-3, 5e-4];
/// Δt below the wrap's sample interval (5 ms) changes only the dynamics; the sweep's finest
/// run ([`DUTY_REFERENCE_STEP_S`]) is its reference.
/// The duty cycle's reference: the finest run.
pub const DUTY_REFERENCE_NODES: usize = 2880;
pub const DUTY_REFERENCE_STEP_S: f64 = 2.5e-4;
/// Time step of the duty cycle's node sweep (the sheet default).
pub const DUTY_DEFAULT_STEP_S: f64 = 1e-3;

/// The case × level table: add a line here to bench a new level or case.
pub const TABLE: &[Entry] = &[
    Entry { case: Case::StandstillStep, level: 0, solver: Solver::Fast, sweep: Sweep::Single },
    Entry {
        case: Case::StandstillStep,
        level: 2,
        solver: Solver::Fast,
        sweep: Sweep::Nodes { nodes: NODES, long: LONG_NODES },
    },
    Entry {
        case: Case::StandstillStep,
        level: 2,
        solver: Solver::Clarabel,
        sweep: Sweep::Nodes { nodes: CLARABEL_NODES, long: &[] },
    },
    Entry {
        case: Case::NestedUnloading,
        level: 2,
        solver: Solver::Fast,
        sweep: Sweep::Nodes { nodes: NODES, long: LONG_NODES },
    },
    Entry {
        case: Case::NestedUnloading,
        level: 2,
        solver: Solver::Clarabel,
        sweep: Sweep::Nodes { nodes: CLARABEL_NODES, long: &[] },
    },
    Entry {
        case: Case::SteadyRolling,
        level: 1,
        solver: Solver::Fast,
        sweep: Sweep::Nodes { nodes: NODES, long: LONG_NODES },
    },
    // Rolling at level 2 costs O(N) per node event (the exit's creep arc is a slip run of β/h
    // nodes) and 1.5 N events: O(N²), so no long points.
    Entry {
        case: Case::SteadyRolling,
        level: 2,
        solver: Solver::Fast,
        sweep: Sweep::Nodes { nodes: NODES, long: &[] },
    },
    Entry {
        case: Case::SteadyRolling,
        level: 2,
        solver: Solver::Clarabel,
        sweep: Sweep::Nodes { nodes: &[16, 64], long: &[] },
    },
    Entry { case: Case::DutyMid, level: 4, solver: Solver::Fast, sweep: Sweep::Nodes { nodes: DUTY_NODES, long: &[] } },
    Entry {
        case: Case::DutyMid,
        level: 4,
        solver: Solver::Fast,
        sweep: Sweep::TimeStep { nodes: 360, steps_s: DUTY_STEPS_S },
    },
    Entry {
        case: Case::ShearLag,
        level: 3,
        solver: Solver::Fast,
        sweep: Sweep::Nodes { nodes: &[16, 64, 180, 256, 1024, 4096], long: &[16384] },
    },
    Entry {
        case: Case::ShearLag,
        level: 3,
        solver: Solver::Clarabel,
        sweep: Sweep::Nodes { nodes: &[16, 64, 180, 256], long: &[] },
    },
    Entry {
        case: Case::RollingWalk,
        level: 2,
        solver: Solver::Fast,
        sweep: Sweep::Samples { nodes: 720, samples: &[1_000, 10_000, 100_000], long: &[1_000_000] },
    },
];

#[derive(Debug, Clone, PartialEq)]
pub struct BenchOptions {
    /// Also the largest cases (N = 100 000, a history of 1e6 samples).
    pub long: bool,
    /// The reference sheet holding the duty cycle.
    pub sheet: PathBuf,
    /// The `wrapcalc` executable: each point's peak memory is measured by running it alone in a
    /// child process (`wrapcalc bench --probe SPEC`); `None` reports no memory.
    pub probe_exe: Option<PathBuf>,
}

/// One row of bench.csv.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct BenchRow {
    pub case: &'static str,
    pub level: u8,
    pub solver: Solver,
    pub sweep: &'static str,
    pub nodes: Option<usize>,
    pub time_step_s: Option<f64>,
    pub samples: Option<usize>,
    /// Increments of the wrap model (levels 2 and 4).
    pub steps: Option<u64>,
    pub runtime_ms: f64,
    pub repeats: usize,
    pub error: Option<f64>,
    pub error_metric: &'static str,
    /// Duty cycle: RMS difference of the history's positive and reverse arcs from the finest
    /// run (deg), reported beside the error (see [`cases`]).
    pub arc_rms_deg: Option<f64>,
    pub peak_rss_kb: Option<u64>,
}

#[derive(Debug, thiserror::Error)]
pub enum BenchError {
    #[error("bench case {case}: {source}")]
    Run { case: &'static str, source: RunError },
    #[error("bench case {case}: {source}")]
    Level2 { case: &'static str, source: Level2Error },
    #[error(transparent)]
    Sheet(#[from] SheetError),
    #[error("{sheet}: the bench runs the duty-cycle scene \"{}\", which this sheet does not have", cases::DUTY_SCENE)]
    NoDutyScene { sheet: String },
    #[error("cannot start the single-threaded pool: {0}")]
    Pool(String),
    #[error("--probe {0:?}: expected case:level:solver:nodes:time_step_s:samples")]
    Probe(String),
    #[error(transparent)]
    Report(#[from] crate::report::ReportError),
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
    level: u8,
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
            level: level.parse().ok()?,
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

fn run_table(
    options: &BenchOptions,
    progress: &mut (dyn FnMut(&BenchRow) + Send),
) -> Result<Vec<BenchRow>, BenchError> {
    let mut rows = Vec::new();
    // A sheet that cannot be read fails the bench before anything runs.
    if TABLE.iter().any(|e| e.case == Case::DutyMid) {
        cases::duty_design(&options.sheet, DUTY_DEFAULT_STEP_S)?;
    }
    // Finest runs of the duty cycle, by (N, Δt): each is run once, as a "reference" row.
    let mut references: Vec<((usize, f64), cases::DutyRun)> = Vec::new();
    for entry in TABLE {
        let reference_key = duty_reference(entry);
        if let Some(key) = reference_key.filter(|k| !references.iter().any(|r| r.0 == *k)) {
            let spec = Spec {
                case: Case::DutyMid,
                level: entry.level,
                solver: entry.solver,
                point: Point { nodes: Some(key.0), time_step_s: Some(key.1), samples: None },
            };
            let m = run_point(options, spec)?;
            let row = BenchRow { sweep: "reference", ..row_of(options, spec, entry.sweep.name(), &m, (None, None)) };
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
            let row = row_of(options, spec, entry.sweep.name(), &m, error);
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
            let samples = cases::rolling_walk(spec.point.samples.unwrap_or(1000));
            cases::run_walk(&samples, nodes).map_err(|source| BenchError::Level2 { case, source })
        }
        _ if spec.level == 0 => cases::run_checks(spec.case).map_err(run_err),
        _ => cases::run_closed_form(spec.case, spec.level, spec.solver, nodes).map_err(run_err),
    }
}

fn row_of(
    options: &BenchOptions,
    spec: Spec,
    sweep: &'static str,
    m: &measure::Measured<Outcome>,
    (error, arc_rms_deg): (Option<f64>, Option<f64>),
) -> BenchRow {
    let point = spec.point;
    let error_metric = match (spec.case, spec.level) {
        (Case::RollingWalk, _) => "none (scaling only)",
        (Case::DutyMid, _) => cases::DUTY_METRIC,
        (_, 0) => cases::CHECKS_METRIC,
        _ => cases::TENSION_METRIC,
    };
    let time_step_s = match spec.case {
        Case::DutyMid => Some(point.time_step_s.unwrap_or(DUTY_DEFAULT_STEP_S)),
        _ => None,
    };
    BenchRow {
        case: spec.case.name(),
        level: spec.level,
        solver: spec.solver,
        sweep,
        nodes: point.nodes.filter(|_| spec.level > 0),
        time_step_s,
        samples: point.samples,
        steps: m.value.steps,
        runtime_ms: m.runtime_ms,
        repeats: m.repeats,
        error,
        error_metric,
        arc_rms_deg,
        peak_rss_kb: child_peak_rss_kb(options, spec),
    }
}

/// The measured scaling of one sweep: log–log slopes of run time and of peak memory (above the
/// smallest point's process) against the swept size (N, samples, or 1/Δt), fitted over its
/// larger half (at least three points) where fixed costs have faded.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Scaling {
    pub case: &'static str,
    pub level: u8,
    pub solver: Solver,
    pub variable: &'static str,
    pub points: usize,
    pub from: f64,
    pub to: f64,
    pub time_slope: Option<f64>,
    pub memory_slope: Option<f64>,
}

/// Slopes of every sweep with at least two points in its larger half.
pub fn scaling(rows: &[BenchRow]) -> Vec<Scaling> {
    let mut out = Vec::new();
    let baseline_kb = rows.iter().filter_map(|r| r.peak_rss_kb).min();
    for entry in TABLE {
        let (variable, size): (&str, fn(&BenchRow) -> Option<f64>) = match entry.sweep {
            Sweep::Single => continue,
            Sweep::Nodes { .. } => ("nodes", |r| r.nodes.map(|n| n as f64)),
            Sweep::TimeStep { .. } => ("1/time_step_s", |r| r.time_step_s.map(|d| 1.0 / d)),
            Sweep::Samples { .. } => ("samples", |r| r.samples.map(|n| n as f64)),
        };
        let mut pts: Vec<(f64, &BenchRow)> = rows
            .iter()
            .filter(|r| {
                r.case == entry.case.name()
                    && r.level == entry.level
                    && r.solver == entry.solver
                    && r.sweep == entry.sweep.name()
            })
            .filter_map(|r| size(r).map(|x| (x, r)))
            .collect();
        pts.sort_by(|a, b| a.0.total_cmp(&b.0));
        // The larger half, but at least three points where the sweep has them.
        let upper = &pts[(pts.len() / 2).min(pts.len().saturating_sub(3))..];
        if upper.len() < 2 {
            continue;
        }
        let time: Vec<(f64, f64)> = upper.iter().map(|(x, r)| (*x, r.runtime_ms)).collect();
        // Memory above the smallest process's (program, allocator, thread pool); growth below
        // 1 MB is the allocator's granularity, not the case's footprint.
        let memory: Vec<(f64, f64)> = upper
            .iter()
            .filter_map(|(x, r)| {
                let grown = r.peak_rss_kb?.checked_sub(baseline_kb?)?;
                (grown >= 1024).then_some((*x, grown as f64))
            })
            .collect();
        out.push(Scaling {
            case: entry.case.name(),
            level: entry.level,
            solver: entry.solver,
            variable,
            points: upper.len(),
            from: upper[0].0,
            to: upper[upper.len() - 1].0,
            time_slope: log_log_slope(&time),
            memory_slope: log_log_slope(&memory),
        });
    }
    out
}

/// Least-squares slope of ln y against ln x (positive values only; `None` with fewer than two).
pub fn log_log_slope(points: &[(f64, f64)]) -> Option<f64> {
    let logs: Vec<(f64, f64)> =
        points.iter().filter(|(x, y)| *x > 0.0 && *y > 0.0).map(|(x, y)| (x.ln(), y.ln())).collect();
    let n = logs.len() as f64;
    if logs.len() < 2 {
        return None;
    }
    let (mx, my) = (logs.iter().map(|p| p.0).sum::<f64>() / n, logs.iter().map(|p| p.1).sum::<f64>() / n);
    let sxx: f64 = logs.iter().map(|p| (p.0 - mx).powi(2)).sum();
    let sxy: f64 = logs.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
    (sxx > 0.0).then(|| sxy / sxx)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn slope_of_a_power_law_is_its_exponent() {
        // y = 3 x^1.5 exactly: the fit returns 1.5 to rounding (1e-12).
        let pts: Vec<(f64, f64)> = [10.0, 100.0, 1000.0].iter().map(|&x: &f64| (x, 3.0 * x.powf(1.5))).collect();
        assert!((log_log_slope(&pts).unwrap() - 1.5).abs() < 1e-12);
        assert_eq!(log_log_slope(&pts[..1]), None);
        assert_eq!(log_log_slope(&[(1.0, 1.0), (1.0, 2.0)]), None);
    }

    #[test]
    fn probe_specs_round_trip() {
        let spec = Spec {
            case: Case::DutyMid,
            level: 4,
            solver: Solver::Fast,
            point: Point { nodes: Some(360), time_step_s: Some(2.5e-4), samples: None },
        };
        assert_eq!(Spec::parse(&spec.to_arg()), Some(spec));
        assert_eq!(Spec::parse("duty-MID:4:fast:360"), None);
        assert_eq!(Spec::parse("nope:4:fast:-:-:-"), None);
    }

    #[test]
    fn long_points_only_with_long() {
        let sweep = Sweep::Nodes { nodes: &[16, 64], long: &[100_000] };
        assert_eq!(points(&sweep, false).len(), 2);
        assert_eq!(points(&sweep, true).last().and_then(|p| p.nodes), Some(100_000));
    }
}
