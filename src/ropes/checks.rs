//! The load sharing's checks, as check records like the others: the largest deviation of a
//! rope's tension from the mean against `[ropes] max_deviation_pct`, each equalising
//! conveyance's piston travel against its stroke, the worst rope's anti-slip safety factor at
//! rest and in motion, the worst rope's safety factor against breaking, and the groove turning
//! tolerance found by root finding against the sheet's groove deviation.

use super::scene::{SceneRopes, WorstRope};
use crate::check::{Check, Relation, q};
use crate::design::requirements::Rule;
use crate::design::{Attachment, DEFAULT_DEVIATION_SOURCE};
use crate::design::{Design, Limit};
use crate::numerics::roots::Holding;

/// Name of the check of the largest deviation from the mean tension.
pub const DEVIATION_CHECK: &str = "rope tension deviation from the mean";
/// Name of the check of conveyance 1's cylinders' stroke.
pub const STROKE1_CHECK: &str = "equalising cylinders' stroke, conveyance 1";
/// Name of the check of conveyance 2's cylinders' stroke.
pub const STROKE2_CHECK: &str = "equalising cylinders' stroke, conveyance 2";
/// Name of the worst rope's anti-slip check at rest.
pub const WORST_STATIC_CHECK: &str = "anti-slip safety factor of the most loaded rope, at rest";
/// Name of the worst rope's anti-slip check in motion.
pub const WORST_DYNAMIC_CHECK: &str = "anti-slip safety factor of the most loaded rope, in motion";
/// Name of the worst rope's safety factor against breaking.
pub const WORST_ROPE_SF_CHECK: &str = "rope safety factor of the most loaded rope";
/// Name of the groove tolerance check.
pub const GROOVE_TOLERANCE_CHECK: &str = "groove pitch-diameter deviation against the tolerance";

/// Every check of one scene's sharing. `rope_dynamics`: the mean rope's tensions come from the
/// suspended ropes' dynamics (level 4), so the in-motion check binds only where the sheet's
/// `dynamic_safety_factor_basis` is "rope-dynamics", as the mean rope's own check.
pub fn checks(design: &Design, ropes: &SceneRopes, rope_dynamics: bool, scene: &str) -> Vec<Check> {
    let req = &design.requirements;
    let mut out = vec![deviation(ropes, scene)];
    for (side, name) in [(0, STROKE1_CHECK), (1, STROKE2_CHECK)] {
        if let Attachment::Equalising { stroke_m, .. } = ropes.set.attachment[side] {
            out.push(stroke(ropes, side, stroke_m, name, scene));
        }
    }
    let formula_rest = "σ_s,i = T_lo,i(e^{μα} − 1)/(T_hi,i − T_lo,i), lowest over the ropes i and the instants at rest";
    out.push(worst(ropes, ropes.worst_rest, (WORST_STATIC_CHECK, formula_rest), &req.static_limit(), true));
    let basis_binding =
        !rope_dynamics || req.dynamic_safety_factor_basis == crate::design::SafetyFactorBasis::RopeDynamics;
    let formula_motion =
        "σ_d,i = (T_lo,i − m'v²)(e^{μα} − 1)/(T_hi,i − T_lo,i), lowest over the ropes i and the instants in motion";
    let mut motion =
        worst(ropes, ropes.worst_motion, (WORST_DYNAMIC_CHECK, formula_motion), &req.dynamic_limit(), basis_binding);
    if rope_dynamics {
        motion = motion.with_note(if basis_binding {
            "each rope's share of the mean rope's tensions with the suspended ropes' dynamics: binding"
        } else {
            "each rope's share of the mean rope's tensions with the suspended ropes' dynamics; not binding \
             (requirements.dynamic_safety_factor_basis = \"code\")"
        });
    }
    out.push(motion);
    out.push(rope_safety_factor(design, ropes));
    out.push(groove_tolerance(ropes));
    out.into_iter().map(|c| if c.governing_case.is_none() { c.governed_by(scene) } else { c }).collect()
}

/// The deviation limit with its rule: the program's default or the sheet's own.
fn deviation_limit(ropes: &SceneRopes) -> Limit {
    let rule = if ropes.set.deviation_limit_source == DEFAULT_DEVIATION_SOURCE {
        Rule::default_value()
    } else {
        Rule::sheet()
    };
    Limit { value: ropes.set.deviation_limit_pct, source: ropes.set.deviation_limit_source.clone(), rule }
}

fn deviation(ropes: &SceneRopes, scene: &str) -> Check {
    let trips = &ropes.sharing.trips;
    let all = ropes.sharing.max_deviation_pct();
    let mut c = Check::new(
        DEVIATION_CHECK,
        "δ = max |T_i − T̄|/T̄ over the ropes i, both ends and every instant of every round trip run",
        Some(all),
        "%",
    );
    c.inputs.push(q("n", ropes.set.count() as f64, ""));
    c.inputs.push(q("round trips run", trips.len() as f64, ""));
    if let Some(d) = ropes.deviation_at {
        c.inputs.extend([q("t (first trip)", d.t_s, "s"), q("rope", d.rope as f64, ""), q("end", d.side as f64, "")]);
        c.intermediates.extend([q("T_i", d.tension_n, "N"), q("T̄", d.mean_n, "N"), q("δ first trip", d.pct(), "%")]);
    }
    if let Some(last) = trips.last().filter(|_| trips.len() > 1) {
        c.intermediates.push(q("δ last round trip", last.max_deviation_pct, "%"));
    }
    c.governed_by(scene).against(Relation::AtMost, Some(&deviation_limit(ropes)), true)
}

fn stroke(ropes: &SceneRopes, side: usize, stroke_m: f64, name: &'static str, scene: &str) -> Check {
    let used = ropes.sharing.stroke_used_m()[side];
    let half = 0.5 * stroke_m;
    let limit = Limit::computed(
        half,
        "half the cylinders' stroke: the pistons start at mid-stroke ([ropes.conveyanceN] stroke_m)",
    );
    let mut c = Check::new(
        name,
        "max |c_i|: largest piston travel from mid-stroke over the ropes and every round trip",
        Some(used),
        "m",
    )
    .inputs(vec![q("stroke_m", stroke_m, "m")])
    .intermediates(vec![q("stroke available each way", half, "m")])
    .governed_by(scene)
    .against(Relation::AtMost, Some(&limit), true);
    // A piston at its stop no longer equalises: the ropes on it are rigid from there.
    if used >= half * (1.0 - 1e-9) {
        c.fail();
        c.note = Some("a piston reached its stop: the equalisation is lost, the ropes on it act as rigid".into());
    }
    c
}

fn worst(
    ropes: &SceneRopes,
    w: Option<WorstRope>,
    (name, formula): (&'static str, &'static str),
    limit: &Limit,
    binding: bool,
) -> Check {
    let c = Check::new(name, formula, None, "");
    let Some(w) = w else {
        return c.not_evaluated("no instant of this kind in the scene, or every rope's end tensions are equal");
    };
    let h = &ropes.hoisting;
    let (hi, lo) = (w.t1_n.max(w.t2_n), w.t1_n.min(w.t2_n));
    let mut c = Check { value: Some(w.safety_factor), ..c }
        .inputs(vec![
            q("t", w.t_s, "s"),
            q("rope", w.rope as f64, ""),
            q("T1,i", w.t1_n, "N"),
            q("T2,i", w.t2_n, "N"),
            q("v", w.speed_m_s, "m/s"),
            q("μ", h.mu, ""),
            q("α", h.wrap_angle_rad.to_degrees(), "deg"),
            q("m'", h.mass_per_m_kg, "kg/m"),
        ])
        .intermediates(vec![
            q("e^{μα}", (h.mu * h.wrap_angle_rad).exp(), ""),
            q("m'v²", h.mass_per_m_kg * w.speed_m_s * w.speed_m_s, "N"),
            q("T_hi − T_lo", hi - lo, "N"),
        ]);
    if let Some(m) = w.mean_safety_factor {
        c.intermediates.push(q("σ of the mean rope then", m, ""));
    }
    c.against(Relation::AtLeast, Some(limit), binding)
}

fn rope_safety_factor(design: &Design, ropes: &SceneRopes) -> Check {
    let c = Check::new(
        WORST_ROPE_SF_CHECK,
        "F_min / max T_i: the rope's minimum breaking force over the largest tension of any rope at a tangent point, every instant of every round trip",
        None,
        "",
    );
    let Some(f) = design.rope.min_breaking_force_n else {
        return c.not_evaluated("rope.min_breaking_force_n is not given");
    };
    let (rope, t_max) = ropes.sharing.max_tension_n();
    Check { value: Some(f / t_max), ..c }
        .inputs(vec![q("F_min (one rope)", f, "N"), q("rope", rope as f64, ""), q("T_max,i", t_max, "N")])
        .against(Relation::AtLeast, design.requirements.rope_safety_factor_min.as_ref(), true)
}

fn groove_tolerance(ropes: &SceneRopes) -> Check {
    let k = ropes.tolerance_rope;
    let actual = ropes.set.groove_diameter_dev_m[k].abs();
    let c = Check::new(
        GROOVE_TOLERANCE_CHECK,
        "|ΔD_k| ≤ ΔD_tol: ΔD_tol the largest deviation of rope k's groove (the others as given) for which δ ≤ δ_max and every rope's σ ≥ σ_d,min over the trip (root finding on the whole sharing run)",
        Some(1e3 * actual),
        "mm",
    )
    .inputs(vec![
        q("rope k", (k + 1) as f64, ""),
        q("ΔD_k (sheet)", 1e3 * ropes.set.groove_diameter_dev_m[k], "mm"),
        q("δ_max", ropes.set.deviation_limit_pct, "%"),
    ]);
    let source = |what: &str| format!("root finding on the sharing run ({what}); 20 nm tolerance");
    match ropes.groove_tolerance {
        Holding::Until(x) => c.against(
            Relation::AtMost,
            Some(&Limit::computed(1e3 * x, source("the deviation limit or the anti-slip minimum reached"))),
            true,
        ),
        Holding::Throughout => c.against(
            Relation::AtMost,
            Some(&Limit::computed(1e3 * super::margin::SEARCH_MAX_M, source("holds up to the search's end, 20 mm"))),
            true,
        ),
        Holding::NotAtStart => c.against(
            Relation::AtMost,
            Some(&Limit::computed(
                0.0,
                source("the other ropes' deviations already reach a limit with this groove true"),
            )),
            true,
        ),
        Holding::NotFinite | Holding::Failed(_) => c.not_evaluated("the tolerance search did not converge"),
    }
}
