//! The scalar summary of a run, as written to summary.json and summary.csv (docs/interface.md).

use crate::check::Check;
use crate::design::damping::RopeDamping;
use crate::design::inputs::InputRecord;
use crate::design::{Design, Requirements};
use crate::load_cases::MatrixResult;
use crate::margins::Margins;
use crate::margins::fit::CreepFit;
use crate::model::Level;
use crate::model::history::SolverReport;
use crate::model::level3::Level3Stats;
use crate::model::stop::StopReport;
use crate::numerics::roots::RootStats;
use crate::plan::cost::Estimate;
use crate::run::{RunResult, SceneResult};
use serde::Serialize;

/// One scene's scalar fields, in the order docs/interface.md lists them; `None` is null / empty.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SceneSummary {
    /// The scene's name in the sheet.
    pub name: String,
    /// Its kind: `loads`, `history` or `duty-cycle`.
    pub kind: &'static str,
    /// The model level that ran (0–4).
    pub level: Level,
    /// Why the planner chose that level (or that it was forced).
    pub level_reason: String,
    /// Time of the reported state (s); `None` for a `loads` scene.
    pub t_s: Option<f64>,
    /// Side-1 end tension per rope of the reported state (N).
    pub t1_n: f64,
    /// Side-2 end tension per rope of the reported state (N).
    pub t2_n: f64,
    /// Rope speed of the reported state (m/s, > 0 side 1 → side 2).
    pub speed_m_s: f64,
    /// Acceleration of the reported state (m/s²).
    pub accel_m_s2: f64,
    /// Friction coefficient μ rope–lining.
    pub mu: f64,
    /// Wrap angle α (deg).
    pub wrap_angle_deg: f64,
    /// The Euler limit e^{μα}.
    pub euler_limit: f64,
    /// (T_hi − m'v²)/(T_lo − m'v²).
    pub tension_ratio: f64,
    /// (T_lo − m'v²)(e^{μα} − 1)/(T_hi − T_lo) of this state; `None` when T1 = T2.
    pub safety_factor: Option<f64>,
    /// The safety factor at rest (a = 0, v = 0); `None` when T1 = T2 at rest or when the scene
    /// never rests (then `rests` is false).
    pub static_safety_factor: Option<f64>,
    /// The dynamic safety factor (docs/interface.md §3.3); `None` without a state in motion.
    pub dynamic_safety_factor: Option<f64>,
    /// Dynamic angle β = ln(ratio)/μ (deg).
    pub dynamic_angle_deg: f64,
    /// Reserve angle α − β (deg).
    pub reserve_angle_deg: f64,
    /// Arc with |q| < 0.001μn (deg); `None` at level 0.
    pub idle_arc_deg: Option<f64>,
    /// Arc with q > 0.001μn (deg); `None` at level 0.
    pub positive_arc_deg: Option<f64>,
    /// Arc with q < −0.001μn (deg); `None` at level 0.
    pub reverse_arc_deg: Option<f64>,
    /// The demarcation point θ_JDP (deg); `None` where there is none.
    pub jdp_deg: Option<f64>,
    /// Largest |q|/(μn) over the wrap; `None` at level 0.
    pub max_utilization: Option<f64>,
    /// Whether the reported state slips grossly.
    pub gross_slip: bool,
    /// The friction coefficient at which the state would just slip, ln(ratio)/α.
    pub critical_mu: f64,
    /// Whether no check of the scene fails.
    pub checks_pass: bool,
    /// Wrap nodes, or level-3 segments; `None` at level 0.
    pub nodes: Option<usize>,
    /// The scene's run time (ms).
    pub runtime_ms: f64,
    /// Extension: centrifugal tension m'v² per rope (N).
    pub centrifugal_n: f64,
    /// Extension (time scenes): the reported row with the lowest safety factor, and its time.
    pub worst_t_s: Option<f64>,
    /// The lowest safety factor of the history rows (at `worst_t_s`).
    pub worst_safety_factor: Option<f64>,
    /// Extension (`margins`): extra side-1 payload (kg, all ropes) before gross slip, and before
    /// the safety factor falls to its minimum; braking deceleration (m/s²) before gross slip and
    /// before the dynamic safety factor falls to its minimum. Null when the search found no such
    /// value (its verdict in summary.json says why).
    pub payload_margin_kg: Option<f64>,
    /// Extra side-1 payload (kg, all ropes) before the safety factor falls to its minimum.
    pub payload_margin_sf_kg: Option<f64>,
    /// Braking deceleration (m/s²) before gross slip.
    pub braking_margin_m_s2: Option<f64>,
    /// Braking deceleration (m/s²) before the dynamic safety factor falls to its minimum.
    pub braking_margin_sf_m_s2: Option<f64>,
    /// Extension (`fit`): the creep-theory active arc fitted to the distribution, and the RMS
    /// residual relative to the range of T over the wrap (0: exactly the classical picture).
    pub fit_active_arc_deg: Option<f64>,
    /// RMS residual of the fit relative to the range of T over the wrap.
    pub fit_rms_residual_rel: Option<f64>,
    /// Extension (duty cycles with the ropes' dynamics): the lowest dynamic safety factor in
    /// motion with them; `dynamic_safety_factor` is then the code value, on rigid ropes.
    pub rope_dynamics_safety_factor: Option<f64>,
    /// Extension (duty cycles): the onset of gross slip, where the trip ends (time, ratio).
    pub slip_onset_t_s: Option<f64>,
    /// The tension ratio at the onset of gross slip.
    pub slip_onset_ratio: Option<f64>,
    /// Extension (duty cycles with an emergency stop): the deceleration reached (mean from full
    /// brake force to standstill), its peak, the slip-limited deceleration on rigid ropes, the
    /// stopping time from the trip and the stopping distance.
    pub emergency_decel_m_s2: Option<f64>,
    /// Peak deceleration of the emergency stop (m/s²).
    pub emergency_peak_decel_m_s2: Option<f64>,
    /// The rigid-rope deceleration at which the stop would slip grossly (m/s²).
    pub slip_limited_decel_m_s2: Option<f64>,
    /// Time from the trip to standstill (s).
    pub stopping_time_s: Option<f64>,
    /// Distance from the trip to standstill (m).
    pub stopping_distance_m: Option<f64>,
    /// Whether the scene has a state at rest (a history that never rests has no static state).
    pub rests: bool,
}

impl SceneSummary {
    /// The scalar fields of one scene's result.
    pub fn of(r: &SceneResult) -> Self {
        let c = &r.classical;
        let w = r.wrap.as_ref().map(|w| &w.summary);
        let m = r.margins.as_ref();
        let worst = r.history.as_ref().and_then(|h| {
            h.rows.iter().filter_map(|row| row.safety_factor.map(|sf| (row.t_s, sf))).min_by(|a, b| a.1.total_cmp(&b.1))
        });
        Self {
            name: r.name.clone(),
            kind: r.kind,
            level: r.plan.level,
            level_reason: r.plan.reason.clone(),
            t_s: r.t_s,
            t1_n: c.state.t1_n,
            t2_n: c.state.t2_n,
            speed_m_s: c.state.speed_m_s,
            accel_m_s2: c.state.accel_m_s2,
            mu: c.mu,
            wrap_angle_deg: c.wrap_angle_rad.to_degrees(),
            euler_limit: c.euler_limit,
            tension_ratio: c.tension_ratio,
            safety_factor: c.safety_factor,
            static_safety_factor: c.static_safety_factor,
            rests: c.static_state.is_some(),
            dynamic_safety_factor: c.dynamic_safety_factor,
            dynamic_angle_deg: c.dynamic_angle_rad.to_degrees(),
            reserve_angle_deg: c.reserve_angle_rad.to_degrees(),
            idle_arc_deg: w.map(|w| w.idle_arc_rad.to_degrees()),
            positive_arc_deg: w.map(|w| w.positive_arc_rad.to_degrees()),
            reverse_arc_deg: w.map(|w| w.reverse_arc_rad.to_degrees()),
            jdp_deg: w.and_then(|w| w.jdp_rad.map(f64::to_degrees)),
            max_utilization: w.map(|w| w.max_utilization),
            gross_slip: c.gross_slip,
            critical_mu: c.critical_mu,
            checks_pass: r.checks_pass(),
            nodes: r.nodes,
            runtime_ms: r.runtime_ms,
            centrifugal_n: c.state.centrifugal_n,
            worst_t_s: worst.map(|w| w.0),
            worst_safety_factor: worst.map(|w| w.1),
            payload_margin_kg: m.and_then(|m| m.payload_to_slip_kg.value),
            payload_margin_sf_kg: m.and_then(|m| m.payload_to_min_safety_factor_kg.value),
            braking_margin_m_s2: m.and_then(|m| m.braking_to_slip_m_s2.value),
            braking_margin_sf_m_s2: m.and_then(|m| m.braking_to_min_safety_factor_m_s2.value),
            fit_active_arc_deg: r.fit.as_ref().map(|f| f.active_arc_deg),
            fit_rms_residual_rel: r.fit.as_ref().map(|f| f.rms_residual_rel),
            rope_dynamics_safety_factor: r.rope_dynamics_safety_factor,
            slip_onset_t_s: r.slip_onset.map(|o| o.t_s),
            slip_onset_ratio: r.slip_onset.map(|o| o.ratio),
            emergency_decel_m_s2: r.stop.map(|s| s.decel_m_s2),
            emergency_peak_decel_m_s2: r.stop.map(|s| s.peak_decel_m_s2),
            slip_limited_decel_m_s2: r.stop.map(|s| s.slip_limited_decel_m_s2),
            stopping_time_s: r.stop.map(|s| s.stop_s - s.trip_s),
            stopping_distance_m: r.stop.map(|s| s.distance_m),
        }
    }
}

/// A scene in summary.json: the scalar fields plus its checks and solver verdicts.
#[derive(Debug, Clone, Serialize)]
pub struct SceneJson {
    #[serde(flatten)]
    /// The scalar fields of §3.3 of docs/interface.md, flattened into the scene.
    pub summary: SceneSummary,
    /// The scene's design checks.
    pub checks: Vec<Check>,
    /// Extension: a what-if scene (sheet key `informational`): its checks stand outside
    /// `all_checks_pass`, the verdict and the governing cases.
    pub informational: bool,
    /// Calls and iterations of argmin's Brent method on the distribution (level 1 and up).
    pub root_finding: Option<RootStats>,
    /// Increments, node events and clarabel verdicts of the discrete level.
    pub solver: Option<SolverReport>,
    /// Level 3: the active-set solver's terminations, Newton steps, increments handed to
    /// clarabel and clarabel's verdicts, over the scene and its run-in.
    pub level3_solver: Option<Level3Stats>,
    /// Design margins with their verdicts and root-finding tallies (when asked for).
    pub margins: Option<Margins>,
    /// The creep-theory picture fitted to the reported distribution (when asked for).
    pub fit: Option<CreepFit>,
    /// The cost estimated before the scene ran: work per stage and seconds on one core.
    pub cost: Option<Estimate>,
    /// Duty cycles with an emergency stop: what it reached, with its masses.
    pub stop: Option<StopReport>,
    /// Rope elements followed through the wrap (scenes with `track_*` keys only).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tracks: Option<Vec<TrackJson>>,
    /// Every demarcation point of the reported state's wrap, in θ order (deg); the scalar
    /// `jdp_deg` is the principal one (docs/physics.md, JDP).
    pub demarcations_deg: Vec<f64>,
    /// Where q is zero at the JDP, `[start, end]` (deg): the stick gap whose middle `jdp_deg` is
    /// (both ends `jdp_deg` where q changes sign at a point); null without a JDP.
    pub jdp_gap_deg: Option<[f64; 2]>,
    /// Multi-rope load sharing (duty cycles of a sheet with `[ropes]` only): the largest
    /// deviation of a rope's tension from the mean over every round trip run (%).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub max_rope_deviation_pct: Option<f64>,
    /// Multi-rope load sharing: the worst rope, each rope's totals, the cylinders' stroke.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub ropes: Option<super::ropes_out::RopesJson>,
    /// Duty cycles: the drive's peak and RMS torque and power, energy per trip and per tonne.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub drive: Option<super::drive_out::DriveJson>,
    /// Duty cycles with the ropes' dynamics: the overlay's governing instant and the dominant
    /// longitudinal frequency, measured and the first mode's closed form.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rigid_dynamic: Option<super::rigid_dynamic_out::RigidDynamicJson>,
}

/// One followed element in summary.json: when it was on the pulley, its largest forces, its
/// impulse and where the impulse turned down (null when it did not).
#[derive(Debug, Clone, Serialize)]
pub struct TrackJson {
    /// The element's label, as in track.csv.
    pub element: String,
    /// Length of the element along the rope (m).
    pub length_m: f64,
    /// First time any of the element is on the pulley (s); null when it never is.
    pub first_t_s: Option<f64>,
    /// Last time any of it is on the pulley (s); null when it never is.
    pub last_t_s: Option<f64>,
    /// Largest contact force on the whole element (N; 0 when it never touches the pulley).
    pub max_contact_force_n: f64,
    /// Largest friction force on the element, positive in +θ (N; at least 0).
    pub max_friction_force_n: f64,
    /// Smallest friction force on the element, positive in +θ (N; at most 0).
    pub min_friction_force_n: f64,
    /// Friction impulse `∫ F dt` at the element's last row (N·s, positive in +θ).
    pub impulse_n_s: f64,
    /// When the impulse turns down (s); null when it does not.
    pub turn_down_t_s: Option<f64>,
    /// Angle of the element's centre then (deg from the side-1 tangent point).
    pub turn_down_theta_deg: Option<f64>,
    /// The impulse reached then (N·s).
    pub turn_down_impulse_n_s: Option<f64>,
}

impl TrackJson {
    fn of(t: &crate::model::track::Track, length_m: f64) -> Self {
        let fold = |f: &dyn Fn(&crate::model::track::TrackRow) -> f64, max: bool| {
            let it = t.rows.iter().map(f);
            if max { it.fold(0.0, f64::max) } else { it.fold(0.0, f64::min) }
        };
        Self {
            element: t.label.clone(),
            length_m,
            first_t_s: t.rows.first().map(|r| r.t_s),
            last_t_s: t.rows.last().map(|r| r.t_s),
            max_contact_force_n: fold(&|r| r.contact_force_n, true),
            max_friction_force_n: fold(&|r| r.friction_force_n, true),
            min_friction_force_n: fold(&|r| r.friction_force_n, false),
            impulse_n_s: t.impulse_n_s(),
            turn_down_t_s: t.turn_down.map(|d| d.t_s),
            turn_down_theta_deg: t.turn_down.map(|d| d.theta_deg),
            turn_down_impulse_n_s: t.turn_down.map(|d| d.impulse_n_s),
        }
    }
}

/// The whole summary.json document.
#[derive(Debug, Clone, Serialize)]
pub struct Summary {
    /// The sheet's path as given.
    pub sheet: String,
    /// The sheet's title.
    pub title: String,
    /// wrapcalc's version.
    pub version: &'static str,
    /// Whether no check of the run fails (every binding check passes; warnings and unjudged
    /// checks may stand: see `warnings` and `unjudged`).
    pub all_checks_pass: bool,
    /// Extension: the headline, as the terminal and the report print it.
    pub headline: String,
    /// Extension: how many checks are warnings (beyond a limit that does not decide the design).
    pub warnings: usize,
    /// Extension: how many checks are not judged (no requirement given, or not evaluated).
    pub unjudged: usize,
    /// Extension: what the verdict rests on — the governing check, and each failure, warning
    /// and unjudged check with its sentence in engineering terms.
    pub verdict: super::verdict::Overview,
    /// The run's wall time (ms).
    pub runtime_ms: f64,
    /// Extension: the limits the checks used, each with its source.
    pub requirements: Requirements,
    /// Every scene that ran, in sheet order.
    pub scenes: Vec<SceneJson>,
    /// Extension (a whole sheet run): the checks of the design as a whole — beside anti-slip,
    /// then the load-case matrix's — each with its governing case.
    pub design_checks: Option<Vec<Check>>,
    /// Extension (a sheet with `[load_cases]`): the load-case matrix, every case.
    pub load_cases: Option<MatrixResult>,
    /// Extension: inputs far outside their ranges of practice, each with the key, the value,
    /// the usual range and the likely slip (empty when every input is usual). They change no
    /// result and no verdict.
    pub input_warnings: Vec<crate::design::plausible::InputWarning>,
    /// Extension (a sheet with duty cycles): the rope damping ζ they ran with, whether the
    /// sheet gave it or the default was used, the default's basis, its plausible range, and
    /// the warning of an undamped run.
    pub rope_damping: Option<RopeDamping>,
    /// Extension: every input of the sheet with its `source` (`sheet`, `default` or `rule set`)
    /// and, for a default or a rule set's value, its `basis`.
    pub inputs: Vec<InputRecord>,
}

impl Summary {
    /// The summary of a run of a design.
    pub fn of(design: &Design, run: &RunResult) -> Self {
        let tally = super::checklist::tally(run);
        Self {
            sheet: design.sheet.clone(),
            title: design.title.clone(),
            version: env!("CARGO_PKG_VERSION"),
            all_checks_pass: run.all_checks_pass(),
            headline: super::checklist::headline(run.all_checks_pass(), &tally),
            warnings: tally.warnings,
            unjudged: tally.unjudged,
            verdict: super::verdict::Overview::of(run),
            runtime_ms: run.runtime_ms,
            requirements: design.requirements.clone(),
            scenes: run
                .scenes
                .iter()
                .map(|s| SceneJson {
                    summary: SceneSummary::of(s),
                    checks: s.classical.checks.clone(),
                    informational: s.informational,
                    demarcations_deg: s
                        .wrap
                        .as_ref()
                        .map(|w| w.summary.demarcations_rad.iter().map(|r| r.to_degrees()).collect())
                        .unwrap_or_default(),
                    jdp_gap_deg: s
                        .wrap
                        .as_ref()
                        .and_then(|w| w.summary.jdp_gap_rad)
                        .map(|(a, b)| [a.to_degrees(), b.to_degrees()]),
                    root_finding: s.wrap.as_ref().map(|w| w.summary.roots),
                    solver: s.history.as_ref().map(|h| h.stats),
                    level3_solver: s.level3,
                    margins: s.margins.clone(),
                    fit: s.fit.clone(),
                    cost: s.cost.clone(),
                    stop: s.stop,
                    tracks: s
                        .tracks
                        .as_ref()
                        .map(|o| o.tracks.iter().map(|t| TrackJson::of(t, o.element_length_m)).collect()),
                    max_rope_deviation_pct: s.ropes.as_ref().map(|r| r.sharing.max_deviation_pct()),
                    ropes: s
                        .ropes
                        .as_ref()
                        .map(|r| super::ropes_out::RopesJson::of(r, design.rope.min_breaking_force_n)),
                    drive: s.drive.as_deref().map(super::drive_out::DriveJson::of),
                    rigid_dynamic: s.rigid_dynamic.as_deref().map(super::rigid_dynamic_out::RigidDynamicJson::of),
                })
                .collect(),
            design_checks: run.design.as_ref().map(|d| d.checks.clone()),
            load_cases: run.design.as_ref().and_then(|d| d.matrix.clone()),
            input_warnings: crate::design::plausible::warnings(design),
            rope_damping: design.duty_cycle_damping(),
            inputs: design.inputs.clone(),
        }
    }

    /// The document as pretty-printed JSON.
    pub fn to_json(&self) -> String {
        // Serializing plain structs of finite numbers and strings cannot fail.
        serde_json::to_string_pretty(self).unwrap_or_else(|e| format!("{{\"error\": \"{e}\"}}"))
    }
}
