//! What a scene will cost, known from the sheet before it runs, in each model's own measure of
//! work (docs/physics.md §7 picks the level; this says what that level will do):
//!
//! | level | measure |
//! |---|---|
//! | 4, suspended ropes | rope elements × integration steps: 2 sides × 12 elements × ⌈T / `time_step_s`⌉ (and the emergency margins' trials of the braking stretch) |
//! | 3, elastic lining | segments × increments: `--nodes` × Σ max(travel / pitch, load change / 1 %) over the sample and report intervals, plus a segment pass per report row |
//! | 2, rigid lining | breakpoint updates: [`level2_work`] from the samples, the load reversals and the report rows |
//! | 1, creep theory | `--nodes` |
//! | 0, checks | one state per sample |
//!
//! Each measure is turned into seconds on one core with a cost per unit measured on the
//! reference machine (2 cores, one used; see the constants), so that scenes of every level are
//! held to one limit (and the history rows a run keeps to [`MEMORY_LIMIT_BYTES`]): a scene
//! above it is refused before its first increment
//! ([`crate::run::RunError::Costly`]), with the estimate and the sheet keys and options that drive it.

use crate::design::{Design, HistorySample, Output, Scene, SceneKind};
use crate::dynamics::{self, Side};
use crate::model::Level;
use crate::model::level2::Solver;
use crate::model::level4;
use crate::model::numerics::Numerics;
use crate::plan::{self, Plan};
use serde::Serialize;

/// Largest estimated run time of one scene accepted by default (s): ten minutes. Every sheet in
/// `tables/` and every test is estimated below 5 s.
pub const DEFAULT_LIMIT_S: u64 = 600;

/// Cost per rope element-step of the suspended ropes (trapezoidal rule, tridiagonal solve), ns.
pub const ROPE_NS: f64 = 25.0;
/// The part of a duty cycle's estimate its suspended ropes take.
pub const SUSPENDED_ROPES: &str = "suspended ropes (level 4)";
/// The part of the wrap on the rigid lining.
pub const WRAP_LEVEL2: &str = "wrap (level 2)";
/// The part of the wrap on the elastic lining.
pub const WRAP_LEVEL3: &str = "wrap (level 3)";
/// Cost per segment-increment at level 3 with the fast path (a tridiagonal solve), ns.
pub const LEVEL3_FAST_NS: f64 = 100.0;
/// Cost per segment-increment at level 3 with clarabel on every increment, ns.
pub const LEVEL3_CLARABEL_NS: f64 = 3500.0;
/// Cost per breakpoint update at level 2, ns.
pub const LEVEL2_NS: f64 = 5000.0;
/// Cost per node of a creep-theory field (level 1), and per sample of the level-0 checks, ns.
pub const NODE_NS: f64 = 50.0;

/// Breakpoints a level-2 sample updates (one at each end of the wrap).
pub const BREAKPOINTS_PER_SAMPLE: f64 = 2.0;
/// Breakpoints a load reversal creates (and later wipes out) at level 2.
pub const BREAKPOINTS_PER_REVERSAL: f64 = 2.0;
/// Breakpoints a level-2 report row reads (its arcs, JDP, peak utilization and map).
pub const BREAKPOINTS_PER_ROW: f64 = 2.0;

/// Breakpoints a step of m'v² on its lattice updates (the zones at the two ends, and the stuck
/// rope it repairs).
pub const BREAKPOINTS_PER_CENTRIFUGAL_STEP: f64 = 2.0;

/// Level 2's work, in breakpoint updates, for a history of `samples` samples with `reversals`
/// load reversals and `centrifugal_steps` steps of m'v² on its lattice
/// ([`crate::model::level2::lattice::centrifugal_steps`]), reported in `rows` rows: linear in
/// each, independent of the node count (`--nodes` only sets the output grid of the
/// distributions).
pub fn level2_work(samples: u64, reversals: u64, centrifugal_steps: u64, rows: u64) -> f64 {
    BREAKPOINTS_PER_SAMPLE * samples as f64
        + BREAKPOINTS_PER_REVERSAL * reversals as f64
        + BREAKPOINTS_PER_CENTRIFUGAL_STEP * centrifugal_steps as f64
        + BREAKPOINTS_PER_ROW * rows as f64
}

/// One stage of a scene's work.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Part {
    /// What runs, e.g. "suspended ropes (level 4)".
    pub what: &'static str,
    /// The amount of work, in `unit`.
    pub work: f64,
    /// Unit of `work` (e.g. "nodes").
    pub unit: &'static str,
    /// How `work` follows from the sheet.
    pub formula: String,
    /// Estimated run time on one core (s).
    pub seconds: f64,
    /// The run time it usually takes (s): `seconds` but for the emergency margins, whose bound
    /// counts [`MARGIN_TRIALS`] trials per margin where a few are usual ([`TYPICAL_TRIAL_STRETCHES`]).
    /// The scenes of a run are ordered by it.
    pub typical_seconds: f64,
}

/// A scene's estimated cost.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Estimate {
    /// The model level the scene runs at.
    pub level: Level,
    /// The stages of the work.
    pub parts: Vec<Part>,
    /// The sheet keys and options the cost grows with, with their values.
    pub drivers: Vec<String>,
    /// Estimated run time on one core (s).
    pub seconds: f64,
    /// The run time it usually takes on one core (s; [`Part::typical_seconds`]).
    pub typical_seconds: f64,
    /// History rows kept in memory until the report is written.
    pub rows: f64,
    /// Estimated memory of those rows (bytes), [`ROW_BYTES`] each.
    pub memory_bytes: f64,
}

/// Memory of one history row while a run keeps it: its scalars and its line of the θ–t map
/// (181 angles of 8 bytes), bytes.
pub const ROW_BYTES: f64 = 1600.0;
/// Largest estimated memory of a scene's history rows accepted (bytes): 4 GiB.
pub const MEMORY_LIMIT_BYTES: f64 = 4.0 * 1024.0 * 1024.0 * 1024.0;

impl Estimate {
    fn new(level: Level, parts: Vec<Part>, drivers: Vec<String>) -> Self {
        Self::with_rows(level, parts, drivers, 0.0)
    }

    fn with_rows(level: Level, parts: Vec<Part>, drivers: Vec<String>, rows: f64) -> Self {
        let seconds = parts.iter().map(|p| p.seconds).sum();
        let typical_seconds = parts.iter().map(|p| p.typical_seconds).sum();
        Self { level, parts, drivers, seconds, typical_seconds, rows, memory_bytes: rows * ROW_BYTES }
    }

    /// What usually remains of the run ([`Self::typical_seconds`]) when it continues from a
    /// start shared with other scenes: `ropes_shared` of its suspended ropes' work and
    /// `wrap_shared` of its wrap's (fractions, each clamped to [0, 1]) are done once for all.
    pub fn typical_after_shared(&self, ropes_shared: f64, wrap_shared: f64) -> f64 {
        let of = |what: &str| self.parts.iter().filter(|p| p.what == what).map(|p| p.typical_seconds).sum::<f64>();
        self.typical_seconds
            - ropes_shared.clamp(0.0, 1.0) * of(SUSPENDED_ROPES)
            - wrap_shared.clamp(0.0, 1.0) * (of(WRAP_LEVEL2) + of(WRAP_LEVEL3))
    }

    /// The parts as one line: "suspended ropes (level 4): 3.1e6 rope element-steps (…); …".
    pub fn describe(&self) -> String {
        let parts: Vec<String> =
            self.parts.iter().map(|p| format!("{}: {:.3e} {} ({})", p.what, p.work, p.unit, p.formula)).collect();
        parts.join("; ")
    }
}

/// A duration for a person: seconds, minutes, hours.
pub fn human_duration(seconds: f64) -> String {
    match seconds {
        s if s < 120.0 => format!("{s:.1} s"),
        s if s < 7200.0 => format!("{:.0} min", s / 60.0),
        s if s < 1e7 => format!("{:.1} h", s / 3600.0),
        s => format!("{:.1e} h", s / 3600.0),
    }
}

fn part(what: &'static str, work: f64, unit: &'static str, formula: String, ns_per_unit: f64) -> Part {
    let seconds = work * ns_per_unit * 1e-9;
    Part { what, work, unit, formula, seconds, typical_seconds: seconds }
}

/// The cost of running `scene` as `plan` says, with `nodes` wrap nodes and `solver`.
pub fn estimate(design: &Design, scene: &Scene, plan: &Plan, nodes: usize, solver: Solver) -> Estimate {
    let wrap = plan::wrap_level(plan, design.lining.is_some());
    let n = nodes as f64;
    match &scene.kind {
        SceneKind::Loads(_) => match plan.level {
            Level::Closed0 => Estimate::new(Level::Closed0, Vec::new(), Vec::new()),
            Level::Capstan1 => Estimate::new(
                Level::Capstan1,
                vec![part("creep theory (level 1)", n, "nodes", format!("--nodes {nodes}"), NODE_NS)],
                vec![format!("--nodes {nodes}")],
            ),
            _ if wrap == Level::Elastic3 => {
                let increments = 1.5 * n + 1.0;
                let formula = format!("{nodes} segments × {increments:.0} increments (1.5 wrap lengths of run-in)");
                Estimate::new(
                    Level::Elastic3,
                    vec![level3_part(n * increments, formula, solver)],
                    vec![format!("--nodes {nodes}")],
                )
            }
            level => Estimate::new(level, vec![level2_part(3, 0, 0, 1)], Vec::new()),
        },
        SceneKind::History(h) => history(design, h, plan.level, wrap, nodes, solver),
        SceneKind::DutyCycle(cycle) => duty_cycle(design, scene, cycle, plan.level, wrap, nodes, solver),
    }
}

fn level2_part(samples: u64, reversals: u64, centrifugal_steps: u64, rows: u64) -> Part {
    part(
        WRAP_LEVEL2,
        level2_work(samples, reversals, centrifugal_steps, rows),
        "breakpoint updates",
        format!("{samples} samples, {reversals} load reversals, {centrifugal_steps} steps of m'v², {rows} report rows"),
        LEVEL2_NS,
    )
}

fn level3_part(work: f64, formula: String, solver: Solver) -> Part {
    let ns = if solver == Solver::Clarabel { LEVEL3_CLARABEL_NS } else { LEVEL3_FAST_NS };
    part(WRAP_LEVEL3, work, "segment-increments", formula, ns)
}

fn history(
    design: &Design,
    h: &crate::design::HistoryScene,
    level: Level,
    wrap: Level,
    nodes: usize,
    solver: Solver,
) -> Estimate {
    let samples = &h.samples;
    let output = crate::model::history::Output {
        snapshots_s: &h.snapshots_s,
        step_s: h.output_step_s,
        sample_rows: true,
        utilization_map: true,
    };
    let times = output.times(samples);
    let mut drivers = vec![format!("{} samples (t_s or csv)", samples.len())];
    if let Some(step) = h.output_step_s {
        drivers.push(format!("output_step_s = {step} s ({} report rows)", times.len()));
    }
    let checks = part("checks (level 0)", samples.len() as f64, "states", "one per sample".into(), NODE_NS);
    if level < Level::Rigid2 {
        return Estimate::new(level, vec![checks], drivers);
    }
    let rows = times.len() as u64;
    if wrap == Level::Elastic3 {
        let first = samples[0];
        let run_in = if first.t1_n != first.t2_n { 1.5 * nodes as f64 } else { 0.0 };
        let increments = run_in + level3_increments(design, samples, &times, nodes);
        let n = nodes as f64;
        let work = n * (increments + rows as f64);
        let formula = format!("{nodes} segments × ({increments:.0} increments + {rows} report rows)");
        drivers.push(format!("--nodes {nodes}"));
        return Estimate::with_rows(level, vec![checks, level3_part(work, formula, solver)], drivers, rows as f64);
    }
    let reversals = load_reversals(samples);
    drivers.push(format!("{reversals} load reversals"));
    let steps =
        crate::model::level2::lattice::centrifugal_steps(samples, design.rope.mass_per_m_kg, &Numerics::default())
            as u64;
    let parts = vec![checks, level2_part(samples.len() as u64, reversals, steps, rows)];
    Estimate::with_rows(level, parts, drivers, rows as f64)
}

/// How often the difference of the end tensions turns between rising and falling.
fn load_reversals(samples: &[HistorySample]) -> u64 {
    let mut last = 0.0;
    let mut count = 0;
    for w in samples.windows(2) {
        let d = (w[1].t1_n - w[1].t2_n) - (w[0].t1_n - w[0].t2_n);
        if d != 0.0 {
            if last * d < 0.0 {
                count += 1;
            }
            last = d;
        }
    }
    count
}

/// Level 3's increments through `samples`, reported at `times`: each interval between a sample
/// and a report time is split so that an increment moves the pulley at most one pitch and
/// changes an end's contact force by at most 1 % (as the level-3 time stepping does).
fn level3_increments(design: &Design, samples: &[HistorySample], times: &[f64], nodes: usize) -> f64 {
    let radius_m = 0.5 * design.pulley.diameter_m;
    let pitch_rad = design.pulley.wrap_angle_rad / nodes as f64;
    let m = design.rope.mass_per_m_kg;
    let mut cuts: Vec<f64> = samples.iter().map(|s| s.t_s).chain(times.iter().copied()).collect();
    cuts.sort_by(f64::total_cmp);
    cuts.dedup();
    let at = |t: f64| {
        let k = samples.partition_point(|s| s.t_s <= t).clamp(1, samples.len().max(2) - 1);
        let (a, b) = (samples[k - 1], samples[k.min(samples.len() - 1)]);
        let w = if b.t_s > a.t_s { ((t - a.t_s) / (b.t_s - a.t_s)).clamp(0.0, 1.0) } else { 0.0 };
        let lerp = |x: f64, y: f64| x + w * (y - x);
        (lerp(a.t1_n, b.t1_n), lerp(a.t2_n, b.t2_n), lerp(a.speed_m_s, b.speed_m_s))
    };
    cuts.windows(2)
        .map(|w| {
            let ((t1a, t2a, va), (t1b, t2b, vb)) = (at(w[0]), at(w[1]));
            let travel = 0.5 * (va + vb) * (w[1] - w[0]) / radius_m;
            let n_lo = (t1a.min(t2a) - m * va * va).max(f64::MIN_POSITIVE);
            let load = (t1b - t1a).abs().max((t2b - t2a).abs()) / (0.01 * n_lo);
            (travel.abs() / pitch_rad).max(load).ceil().clamp(1.0, 1e6)
        })
        .sum()
}

/// Emergency margins: Brent's method evaluates at most about this many trial decelerations per
/// margin (the bound the estimate takes).
pub const MARGIN_TRIALS: f64 = 20.0;

/// Emergency margins: the trial runs both margins usually take together, in braking stretches:
/// the two ends of the range (the gentlest deceleration runs about twice the stretch), then a
/// few evaluations near each root (on the reference sheet 8 runs in all, about 7.5 stretches).
pub const TYPICAL_TRIAL_STRETCHES: f64 = 8.0;

fn duty_cycle(
    design: &Design,
    scene: &Scene,
    cycle: &crate::design::DutyCycleScene,
    level: Level,
    wrap: Level,
    nodes: usize,
    solver: Solver,
) -> Estimate {
    let profile = design.hoist.as_ref().and_then(|h| level4::motion_profile(h, cycle).ok());
    let Some(profile) = profile else {
        // Nothing to run: the scene fails on its hoist or profile at once.
        return Estimate::new(level, Vec::new(), Vec::new());
    };
    let duration_s = profile.duration_s();
    let rows = (duration_s / cycle.output_step_s).floor() + cycle.snapshots_s.len() as f64 + 2.0;
    let mut drivers = vec![
        format!("the motion profile's {duration_s:.3} s ([hoist] stages, emergency_stop_s)"),
        format!("output_step_s = {} s ({rows:.0} report rows)", cycle.output_step_s),
    ];
    if level < Level::Dynamic4 {
        let checks = part("checks (level 0, rigid ropes)", rows, "states", "one per report row".into(), NODE_NS);
        return Estimate::new(level, vec![checks], drivers);
    }
    let element_steps = |t_s: f64| 2.0 * level4::ELEMENTS_PER_SIDE as f64 * (t_s / cycle.time_step_s).ceil();
    let steps = (duration_s / cycle.time_step_s).ceil();
    let mut parts = vec![part(
        SUSPENDED_ROPES,
        element_steps(duration_s),
        "rope element-steps",
        format!("2 sides × {} elements × {steps:.0} steps of time_step_s", level4::ELEMENTS_PER_SIDE),
        ROPE_NS,
    )];
    drivers.insert(0, format!("time_step_s = {} s", cycle.time_step_s));
    if let Some(stop) = cycle.emergency.filter(|_| scene.outputs.contains(Output::Margins)) {
        // Two margins; a trial runs the braking stretch, longer at a gentler deceleration.
        let (trials, stretch_s) = (2.0 * MARGIN_TRIALS, 1.5 * (duration_s - stop.at_s));
        let work = trials * element_steps(stretch_s);
        let formula = format!("{trials:.0} trial stops of about {stretch_s:.2} s");
        let mut margins = part("emergency margins (level 4)", work, "rope element-steps", formula, ROPE_NS);
        margins.typical_seconds = TYPICAL_TRIAL_STRETCHES * element_steps(duration_s - stop.at_s) * ROPE_NS * 1e-9;
        parts.push(margins);
    }
    let samples = (duration_s / level4::WRAP_SAMPLE_S).ceil() + 1.0;
    if wrap == Level::Elastic3 {
        let travel_m: f64 =
            profile.x_extreme_times().windows(2).map(|w| (profile.at(w[1]).x_m - profile.at(w[0]).x_m).abs()).sum();
        let pitch_m = 0.5 * design.pulley.diameter_m * design.pulley.wrap_angle_rad / nodes as f64;
        let increments = samples + travel_m / pitch_m;
        let n = nodes as f64;
        let formula = format!("{nodes} segments × ({increments:.0} increments + {rows:.0} report rows)");
        parts.push(level3_part(n * (increments + rows), formula, solver));
        drivers.push(format!("--nodes {nodes}"));
    } else {
        let reversals = rope_reversals(design, cycle, duration_s);
        // m'v² rises to its top and falls back once a trip: at most 2/CENTRIFUGAL_STEP_OF_RANGE
        // steps of its lattice.
        let trips = if cycle.return_after_s.is_some() { 2.0 } else { 1.0 };
        let steps = trips * 2.0 / crate::model::numerics::CENTRIFUGAL_STEP_OF_RANGE;
        parts.push(level2_part(samples as u64, reversals, steps as u64, rows as u64));
    }
    Estimate::with_rows(level, parts, drivers, rows)
}

/// Load reversals the suspended ropes give the wrap: each side's tension swings at its first
/// longitudinal mode, two reversals a period (the spring–mass estimate at the start).
fn rope_reversals(design: &Design, cycle: &crate::design::DutyCycleScene, duration_s: f64) -> u64 {
    let Some(hoist) = &design.hoist else { return 0 };
    let params = level4::hoist_params(design, hoist, cycle);
    let f_hz: f64 = Side::BOTH.iter().filter_map(|&s| dynamics::spring_mass_frequency_hz(&params, s, 0.0).ok()).sum();
    (2.0 * f_hz * duration_s).ceil() as u64
}
