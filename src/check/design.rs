//! The checks beside anti-slip (docs/physics.md §10), each over the static states of a design (the
//! load-case matrix's payloads × positions and every scene's state at rest): the rope safety
//! factor, D/d of the friction pulley and of the guide sheave, the specific pressure on the
//! lining (the classical mean and the local peak of n(θ), which the wrap models give), the
//! design cap on μ and the machine ratings. A limit the sheet does not give is reported as "no
//! requirement given"; an input it does not give leaves the check "not evaluated".

use super::{Check, Relation, q};
use crate::design::{Design, Limit};

/// A static state (per rope, at rest) and the case it belongs to.
#[derive(Debug, Clone, PartialEq)]
pub struct StaticState {
    /// The case's label.
    pub case: String,
    /// Tension at the side-1 tangent point, per rope (N).
    pub t1_n: f64,
    /// Tension at the side-2 tangent point, per rope (N).
    pub t2_n: f64,
}

/// The largest contact force per radian n(θ) over the wrap, and where it occurs.
#[derive(Debug, Clone, PartialEq)]
pub struct PeakContact {
    /// The case where the largest contact force occurs.
    pub case: String,
    /// The largest contact force per radian, n = T − m'v² (N/rad).
    pub normal_n_per_rad: f64,
}

/// Name of the rope safety factor check.
pub const ROPE_SF_CHECK: &str = "rope safety factor";
/// Name of the friction pulley's D/d check.
pub const PULLEY_D_CHECK: &str = "D/d of the friction pulley";
/// Name of the guide sheave's D/d check.
pub const GUIDE_D_CHECK: &str = "D/d of the guide sheave";
/// Name of the check of the specific pressure (T1 + T2)/(D·d) on the lining.
pub const PRESSURE_CHECK: &str = "specific pressure on the lining";
/// Name of the check of the local peak pressure n(θ)/(R·d) on the lining.
pub const PEAK_PRESSURE_CHECK: &str = "peak pressure on the lining";
/// Name of the check of μ against the design cap.
pub const MU_CAP_CHECK: &str = "friction coefficient against the design cap";
/// Name of the machine rating's largest static tension check.
pub const TENSION_RATING_CHECK: &str = "largest static tension (machine rating)";
/// The input of [`PROFILE_END_CHECK`]: the profile's signed speed at its end.
pub const PROFILE_END_SPEED: &str = "v at t_end";
/// Name of the check that the `[hoist]` motion profile brings the hoist to rest.
pub const PROFILE_END_CHECK: &str = "motion profile ends at rest";
/// Name of the machine rating's largest static tension difference check.
pub const DIFFERENCE_RATING_CHECK: &str = "largest static tension difference (machine rating)";

/// The static state with the largest `key`.
fn largest(statics: &[StaticState], key: impl Fn(&StaticState) -> f64) -> Option<&StaticState> {
    statics.iter().max_by(|a, b| key(a).total_cmp(&key(b)))
}

/// Why a check that needs the rope's diameter is not evaluated.
const NO_DIAMETER: &str = "rope.diameter_m is not given";
/// Why a check over the static states is not evaluated.
const NO_STATES: &str = "no static state: the sheet has neither [load_cases] nor scenes at rest";

/// The larger end tension of a static state, per rope.
fn t_hi(s: &StaticState) -> f64 {
    s.t1_n.max(s.t2_n)
}

/// Every check beside anti-slip over `statics`; `peak`: the largest n(θ) of the wrap models (a
/// run's distributions), else taken as the larger end tension at rest (exact for the string on a
/// rigid lining, where n = T − m'v² ≤ T_hi).
pub fn design_checks(design: &Design, statics: &[StaticState], peak: Option<PeakContact>) -> Vec<Check> {
    let req = &design.requirements;
    let mut checks = vec![rope_safety_factor(design, statics)];
    checks.push(ratio_check(design, PULLEY_D_CHECK, design.pulley.diameter_m, req.pulley_d_ratio_min.as_ref()));
    if let Some(g) = design.machine.guide {
        checks.push(ratio_check(design, GUIDE_D_CHECK, g.diameter_m, req.guide_d_ratio_min.as_ref()));
    }
    checks.push(specific_pressure(design, statics));
    checks.push(peak_pressure(design, statics, peak));
    // The design cap on μ: a warning above it, not a failure.
    checks.push(
        Check::new(MU_CAP_CHECK, "μ ≤ μ_cap (a warning above it)", Some(design.pulley.mu), "")
            .inputs(vec![q("μ", design.pulley.mu, "")])
            .against(Relation::AtMost, req.mu_design_max.as_ref(), false),
    );
    let allowed = req.dynamic_allowance_min.is_some();
    checks.push(rating(
        design,
        statics,
        (
            TENSION_RATING_CHECK,
            if allowed {
                "n·max(T1, T2)·(1 + z), static plus the dynamic allowance z"
            } else {
                "n·max(T1, T2), static"
            },
        ),
        &|s| s.t1_n.max(s.t2_n),
        req.static_tension_max_n.as_ref(),
    ));
    checks.push(rating(
        design,
        statics,
        (
            DIFFERENCE_RATING_CHECK,
            if allowed {
                "n·|T1 − T2|·(1 + z), static plus the dynamic allowance z"
            } else {
                "n·|T1 − T2|, static"
            },
        ),
        &|s| (s.t1_n - s.t2_n).abs(),
        req.static_tension_difference_max_n.as_ref(),
    ));
    checks.extend(super::codes::code_checks(design));
    checks
}

/// Rope safety factor n·F_min / (n·T_max).
fn rope_safety_factor(design: &Design, statics: &[StaticState]) -> Check {
    let n = f64::from(design.rope.count);
    let c = Check::new(
        ROPE_SF_CHECK,
        "n·F_min / max(n·T_s): minimum breaking force of the rope set over its largest static load, hanging ropes included",
        None,
        "",
    );
    match (design.rope.min_breaking_force_n, largest(statics, t_hi)) {
        (None, _) => c.not_evaluated("rope.min_breaking_force_n is not given"),
        (_, None) => c.not_evaluated(NO_STATES),
        (Some(f), Some(s)) => Check { value: Some(f / t_hi(s)), ..c }
            .inputs(vec![q("n", n, ""), q("F_min (one rope)", f, "N"), q("T_s,max (per rope)", t_hi(s), "N")])
            .intermediates(vec![q("n·F_min", n * f, "N"), q("n·T_s,max", n * t_hi(s), "N")])
            .governed_by(s.case.clone())
            .against(Relation::AtLeast, design.requirements.rope_safety_factor_min.as_ref(), true),
    }
}

/// D/d of a sheave of diameter `d_sheave`.
fn ratio_check(design: &Design, name: &'static str, d_sheave: f64, limit: Option<&Limit>) -> Check {
    let c = Check::new(name, "D/d: sheave diameter over rope diameter", None, "");
    match design.rope.diameter_m {
        None => c.not_evaluated(NO_DIAMETER),
        Some(d) => Check { value: Some(d_sheave / d), ..c }
            .inputs(vec![q("D", d_sheave, "m"), q("d", d, "m")])
            .against(Relation::AtLeast, limit, true),
    }
}

/// Specific pressure (T1 + T2)/(D·d), the classical mean, at the largest static T1 + T2.
fn specific_pressure(design: &Design, statics: &[StaticState]) -> Check {
    let d_pulley = design.pulley.diameter_m;
    let c = Check::new(PRESSURE_CHECK, "p = (T1 + T2)/(D·d) per rope, static tensions", None, "Pa");
    match (design.rope.diameter_m, largest(statics, |s| s.t1_n + s.t2_n)) {
        (None, _) => c.not_evaluated(NO_DIAMETER),
        (_, None) => c.not_evaluated(NO_STATES),
        (Some(d), Some(s)) => Check { value: Some((s.t1_n + s.t2_n) / (d_pulley * d)), ..c }
            .inputs(vec![q("T1", s.t1_n, "N"), q("T2", s.t2_n, "N"), q("D", d_pulley, "m"), q("d", d, "m")])
            .governed_by(s.case.clone())
            .against(Relation::AtMost, design.requirements.lining_pressure_max_pa.as_ref(), true),
    }
}

/// Local peak n(θ)/(R·d); without the wrap models' peak, n ≤ T_hi at rest.
fn peak_pressure(design: &Design, statics: &[StaticState], peak: Option<PeakContact>) -> Check {
    let c = Check::new(
        PEAK_PRESSURE_CHECK,
        "p_peak = max n(θ)/(R·d): largest contact force per radian over the wrap",
        None,
        "Pa",
    );
    let peak = peak.or_else(|| {
        largest(statics, t_hi)
            .map(|s| PeakContact { case: format!("{} (n ≤ T_hi at rest)", s.case), normal_n_per_rad: t_hi(s) })
    });
    match (design.rope.diameter_m, peak) {
        (None, _) => c.not_evaluated(NO_DIAMETER),
        (_, None) => c.not_evaluated(NO_STATES),
        (Some(d), Some(p)) => {
            let r = 0.5 * design.pulley.diameter_m;
            Check { value: Some(p.normal_n_per_rad / (r * d)), ..c }
                .inputs(vec![q("n_max", p.normal_n_per_rad, "N/rad"), q("R", r, "m"), q("d", d, "m")])
                .governed_by(p.case)
                .against(Relation::AtMost, design.requirements.lining_peak_pressure_max_pa.as_ref(), true)
        }
    }
}

/// A machine rating: all ropes together, n·key at the static state with the largest `key`.
fn rating(
    design: &Design,
    statics: &[StaticState],
    (name, formula): (&'static str, &'static str),
    key: &dyn Fn(&StaticState) -> f64,
    limit: Option<&Limit>,
) -> Check {
    let n = f64::from(design.rope.count);
    let c = Check::new(name, formula, None, "N");
    let allowance = design.requirements.dynamic_allowance_min.as_ref();
    let z = allowance.map_or(0.0, |a| a.value);
    match statics.iter().max_by(|a, b| key(a).total_cmp(&key(b))) {
        None => c.not_evaluated(NO_STATES),
        Some(s) => {
            let mut inputs = vec![q("n", n, ""), q("T1", s.t1_n, "N"), q("T2", s.t2_n, "N")];
            let mut c = Check { value: Some(n * key(s) * (1.0 + z)), ..c };
            if let Some(a) = allowance {
                inputs.push(q("z", z, ""));
                c = c.intermediates(vec![q("static, all ropes", n * key(s), "N")]).with_note(format!(
                    "dynamic allowance z = {z} on the static load: {} ({}: {})",
                    a.source, a.rule.code, a.rule.clause
                ));
            }
            c.inputs(inputs).governed_by(s.case.clone()).against(Relation::AtMost, limit, true)
        }
    }
}
