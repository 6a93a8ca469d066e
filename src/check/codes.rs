//! The checks that rule sets of friction-hoist codes need beside the classical ones (docs/codes.md):
//! the lining's friction coefficient against a minimum, dry and with water or rope dressing; the
//! tail (balance) ropes' safety factor; the friction wheel's design load case (the full rope
//! breaking force on one side, a third of it on the other). Each is made only where the sheet gives
//! its limit or its input, so that a sheet without them reports what it did before.

use super::{Check, Relation, q};
use crate::design::{Design, Hoist};

/// Name of the check of the design μ against the lining's minimum.
pub const LINING_MU_CHECK: &str = "friction coefficient of the lining";
/// Name of the check of the lining's μ with water or rope dressing against its minimum.
pub const LINING_MU_WET_CHECK: &str = "friction coefficient of the lining, wet";
/// Name of the tail ropes' safety factor check.
pub const TAIL_SF_CHECK: &str = "tail rope safety factor";
/// Name of the friction wheel's design load case check.
pub const WHEEL_DESIGN_CHECK: &str = "friction wheel design load case";

/// Name of the static anti-slip check at the wet μ (the load-case matrix at μ_wet).
pub const WET_STATIC_CHECK: &str = "static safety factor at the wet μ";
/// Name of the dynamic anti-slip check at the wet μ.
pub const WET_DYNAMIC_CHECK: &str = "dynamic safety factor at the wet μ";
/// Name of the gross-slip check at the wet μ.
pub const WET_SLIP_CHECK: &str = "gross slip at the wet μ";

/// The checks of this module the design calls for.
pub fn code_checks(design: &Design) -> Vec<Check> {
    let req = &design.requirements;
    let mut out = Vec::new();
    if let Some(limit) = &req.lining_mu_min {
        out.push(
            Check::new(LINING_MU_CHECK, "μ ≥ μ_min: the design μ (pulley.mu) against the lining's minimum", None, "")
                .inputs(vec![q("μ", design.pulley.mu, "")])
                .with_value(design.pulley.mu)
                .against(Relation::AtLeast, Some(limit), true),
        );
    }
    if req.lining_mu_wet_min.is_some() || req.code_inputs.lining_mu_wet.is_some() {
        out.push(lining_mu_wet(design));
    }
    if req.tail_rope_safety_factor_min.is_some()
        || design.hoist.as_ref().is_some_and(|h| h.tail_min_breaking_force_n.is_some())
    {
        out.push(tail_rope_safety_factor(design));
    }
    if req.pulley_design_load_min_n.is_some() || req.code_inputs.pulley_design_load_n.is_some() {
        out.push(wheel_design_load(design));
    }
    out
}

/// The lining's μ with water or rope dressing (`requirements.lining_mu_wet`) against its minimum.
fn lining_mu_wet(design: &Design) -> Check {
    let req = &design.requirements;
    let c = Check::new(
        LINING_MU_WET_CHECK,
        "μ_wet ≥ μ_wet,min: the lining's μ with water or rope dressing (its test report)",
        None,
        "",
    );
    match req.code_inputs.lining_mu_wet {
        None => c.not_evaluated("requirements.lining_mu_wet is not given"),
        Some(mu) => c.inputs(vec![q("μ_wet", mu, "")]).with_value(mu).against(
            Relation::AtLeast,
            req.lining_mu_wet_min.as_ref(),
            true,
        ),
    }
}

/// The longest tail rope hanging below a conveyance over the `[hoist]` trip (m): side 1 is lifted
/// by the travel s, so its tail lengthens to tail1 + s while side 2's shortens from tail2.
pub fn longest_tail_m(hoist: &Hoist) -> (f64, f64) {
    let travel = crate::dynamics::lift_travel_m(hoist);
    ((hoist.tail1_length_m + travel).max(hoist.tail2_length_m), travel)
}

/// n_t·F_t over the largest static load of the tail rope set, its own hanging weight.
fn tail_rope_safety_factor(design: &Design) -> Check {
    let c = Check::new(
        TAIL_SF_CHECK,
        "n_t·F_t / (n_t·m'_t·g·L_t,max): minimum breaking force of the tail rope set over its largest hanging weight",
        None,
        "",
    );
    let Some(h) = design.hoist.as_ref().filter(|h| h.tail_count > 0 && h.tail_mass_per_m_kg > 0.0) else {
        return c.not_evaluated("the [hoist] has no tail ropes (hoist.tail_count, hoist.tail_mass_per_m_kg)");
    };
    let Some(f) = h.tail_min_breaking_force_n else {
        return c.not_evaluated("hoist.tail_min_breaking_force_n is not given");
    };
    let (l_max, travel) = longest_tail_m(h);
    let n_t = f64::from(h.tail_count);
    let load = h.tail_mass_per_m_kg * design.g_m_s2 * l_max;
    c.inputs(vec![
        q("n_t", n_t, ""),
        q("F_t (one rope)", f, "N"),
        q("m'_t", h.tail_mass_per_m_kg, "kg/m"),
        q("g", design.g_m_s2, "m/s²"),
        q("tail1 at the start", h.tail1_length_m, "m"),
        q("tail2 at the start", h.tail2_length_m, "m"),
        q("travel s", travel, "m"),
    ])
    .intermediates(vec![q("L_t,max = max(tail1 + s, tail2)", l_max, "m"), q("n_t·m'_t·g·L_t,max", n_t * load, "N")])
    .with_value(f / load)
    .governed_by(format!("tail rope {l_max:.2} m long below a conveyance"))
    .against(Relation::AtLeast, design.requirements.tail_rope_safety_factor_min.as_ref(), true)
}

/// The friction wheel's design load (sheet) against the design case's load: the full breaking
/// force of the rope set on one side, a third of it on the other, in the ropes' direction.
fn wheel_design_load(design: &Design) -> Check {
    let req = &design.requirements;
    let c = Check::new(
        WHEEL_DESIGN_CHECK,
        "P_design ≥ n·F_min + n·F_min/3: the wheel with shaft and bearings at yield against the full rope breaking force on one side and a third on the other (parallel ropes)",
        None,
        "N",
    );
    let Some(p) = req.code_inputs.pulley_design_load_n else {
        return c.not_evaluated("requirements.pulley_design_load_n is not given");
    };
    let mut inputs = vec![q("P_design", p, "N")];
    let mut intermediates = Vec::new();
    if let Some(f) = design.rope.min_breaking_force_n {
        let n = f64::from(design.rope.count);
        inputs.extend([q("n", n, ""), q("F_min (one rope)", f, "N")]);
        intermediates.extend([q("n·F_min (one side)", n * f, "N"), q("n·F_min/3 (other side)", n * f / 3.0, "N")]);
    }
    c.inputs(inputs).intermediates(intermediates).with_value(p).against(
        Relation::AtLeast,
        req.pulley_design_load_min_n.as_ref(),
        true,
    )
}
