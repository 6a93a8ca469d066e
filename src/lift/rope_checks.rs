//! The suspension ropes' checks: the actual safety factor `n F_min / T_car` (rated load at rest
//! at the lowest landing) against Sf of EN 81-50 5.12 (not judged outside Figure 10's range or
//! without N_equiv(t)) and against EN 81-20 5.5.2.2's minimum for the rope count; their nominal
//! diameter (EN 81-20 5.5.1.2 a)); and D/d of the traction sheave, a double wrap's secondary
//! sheave and every pulley.

use super::cases::rated_load_at_bottom;
use super::checks::Limits;
use super::rope::{self, Equivalent, SheaveSource, TABLE_SOURCE};
use crate::check::{Check, Quantity, Relation, q};
use crate::design::Limit;
use crate::design::lift::{Lift, RULE_SET};
use crate::design::requirements::Rule;

/// Name of the check of the ropes' safety factor against Sf (EN 81-50 5.12).
pub const ROPE_SF_CHECK: &str = "suspension rope safety factor";
/// Name of the check of the ropes' safety factor against the minimum for the rope count.
pub const ROPE_MIN_CHECK: &str = "suspension rope safety factor: minimum for the rope count";
/// Name of the check of the ropes' nominal diameter.
pub const ROPE_DIAMETER_CHECK: &str = "suspension rope nominal diameter";
/// Name of the D/d check.
pub const D_RATIO_CHECK: &str = "D/d of the traction sheave and pulleys";

/// The clause Sf is judged by.
pub const SF_CLAUSE: &str =
    "5.12 (Sf from the equivalent number of pulleys N_equiv and D_t/d_r; Figure 10 shows it for 34 ≤ D_t/d_r ≤ 80)";

/// The actual safety factor and what it rests on.
fn actual(lift: &Lift) -> (f64, Vec<Quantity>, Quantity) {
    let t = rated_load_at_bottom(lift);
    let n = f64::from(lift.rope.count);
    let inputs = vec![q("n", n, ""), q("F_min (one rope)", lift.rope.min_breaking_force_n, "N")];
    let t_car = q("T_car (rated load at rest, lowest landing, all ropes)", t.car_n, "N");
    (n * lift.rope.min_breaking_force_n / t.car_n, inputs, t_car)
}

/// Where N_equiv(t) came from, in words.
fn sheave_note(lift: &Lift, eq: &Equivalent) -> String {
    let passes = if eq.passes > 1 {
        format!(
            "; double wrap: the ropes pass the sheave twice, N_equiv(t) = {} × {}, and the secondary sheave counts as two \
             simple bends (Annex E.3)",
            eq.passes, eq.sheave_per_pass
        )
    } else {
        String::new()
    };
    let table = match rope::table_value(&lift.groove) {
        Ok((v, _)) => format!("Table 2 gives {v:.4} for this groove"),
        Err(_) => "Table 2 has no value for this groove".to_string(),
    };
    match &eq.sheave_source {
        SheaveSource::Sheet => format!(
            "N_equiv(t) = {} given by the sheet (lift.n_equiv_t), overriding Table 2 ({table}){passes}",
            eq.sheave_per_pass
        ),
        SheaveSource::Table { angle: "", .. } => {
            format!("N_equiv(t) = {} from {TABLE_SOURCE}, U groove without undercut{passes}", eq.sheave_per_pass)
        }
        SheaveSource::Table { angle, deg } => format!(
            "N_equiv(t) = {:.4} from {TABLE_SOURCE}, at {angle} = {deg}°, linear between the table's rows{passes}",
            eq.sheave_per_pass
        ),
    }
}

/// The ropes' safety factor against Sf of EN 81-50 5.12; not judged (with the reason) where
/// N_equiv(t) is neither given nor in Table 2, or D_t/d_r is outside Figure 10's range.
pub fn rope_safety_factor(lift: &Lift) -> Check {
    let (value, mut inputs, t_car) = actual(lift);
    let ratio = lift.sheave_diameter_m / lift.rope.diameter_m;
    inputs.extend([q("D_t", lift.sheave_diameter_m, "m"), q("d_r", lift.rope.diameter_m, "m")]);
    let formula = "n·F_min/T_car ≥ Sf; Sf = 10^(2.6834 − log(695.85e6·N_equiv/(D_t/d_r)^8.567)/log(77.09·(D_t/d_r)^−2.894)), \
                   N_equiv = N_equiv(t) + K_p(N_ps + 4N_pr), K_p = (D_t/D_p)^4";
    let check = Check::new(ROPE_SF_CHECK, formula, Some(value), "");
    let rule = Rule { code: RULE_SET.to_string(), clause: SF_CLAUSE.to_string() };
    let mut intermediates = vec![t_car, q("D_t/d_r", ratio, "")];
    let not_judged = |check: Check, inputs: Vec<Quantity>, intermediates: Vec<Quantity>, why: String| {
        let mut c = check.inputs(inputs).intermediates(intermediates).not_evaluated(why);
        (c.value, c.code, c.clause) = (Some(value), rule.code.clone(), rule.clause.clone());
        c
    };
    let eq = match rope::equivalent(lift) {
        Ok(eq) => eq,
        Err(why) => return not_judged(check, inputs, intermediates, format!("Sf not judged: {why}")),
    };
    inputs.extend([
        q("N_equiv(t), one pass", eq.sheave_per_pass, ""),
        q("passes over the sheave", f64::from(eq.passes), ""),
        q("N_ps", eq.simple as f64, ""),
        q("N_pr", eq.reverse as f64, ""),
    ]);
    if let Some(d) = eq.pulley_diameter_m {
        inputs.push(q("D_p (mean of the pulleys)", d, "m"));
    }
    intermediates.extend([
        q("N_equiv(t)", eq.sheave, ""),
        q("K_p = (D_t/D_p)^4", eq.k_p, ""),
        q("N_equiv(p) = K_p(N_ps + 4N_pr)", eq.pulleys, ""),
        q("N_equiv", eq.total, ""),
    ]);
    let source = sheave_note(lift, &eq);
    let sf = match (rope::outside_figure(ratio), rope::required_safety_factor(eq.total, ratio)) {
        (Some(why), _) => return not_judged(check, inputs, intermediates, format!("Sf not judged: {why}; {source}")),
        (None, None) => {
            let why = format!("Sf not judged: the formula gives no number at N_equiv = {}", eq.total);
            return not_judged(check, inputs, intermediates, why);
        }
        (None, Some(sf)) => sf,
    };
    intermediates.push(q("Sf", sf, ""));
    let limit = Limit {
        value: sf,
        source: format!(
            "Sf by EN 81-50's formula from N_equiv = {:.4} and D_t/d_r = {ratio:.2} ({}, 5.12, as transcribed from TS EN \
             81-50:2021 in a public note; to be confirmed against the standard in force)",
            eq.total, RULE_SET
        ),
        rule,
    };
    check.inputs(inputs).intermediates(intermediates).against(Relation::AtLeast, Some(&limit), true).with_note(source)
}

/// The ropes' safety factor against the minimum for the rope count (EN 81-20 5.5.2.2: 12 with
/// three or more ropes, 16 with two).
pub fn rope_minimum(lift: &Lift, limits: &Limits) -> Check {
    let (value, inputs, t_car) = actual(lift);
    Check::new(ROPE_MIN_CHECK, "n·F_min/T_car ≥ 12 with three or more ropes, 16 with two", Some(value), "")
        .inputs(inputs)
        .intermediates(vec![t_car])
        .against(Relation::AtLeast, Some(&limits.rope_sf_min), true)
}

/// The suspension ropes' nominal diameter against the minimum (EN 81-20 5.5.1.2 a): 8 mm).
pub fn rope_diameter(lift: &Lift, limits: &Limits) -> Check {
    // Back to the sheet's millimetres, rounded to 1e-9 mm (6.5 mm comes back from metres as
    // 6.500000000000001), so that a diameter at the bound is judged as written.
    let d_mm = (lift.rope.diameter_m * 1e12).round() / 1e9;
    Check::new(ROPE_DIAMETER_CHECK, "d_r ≥ 8 mm", Some(d_mm), "mm").inputs(vec![q("d_r", d_mm, "mm")]).against(
        Relation::AtLeast,
        Some(&limits.rope_diameter_min_mm),
        true,
    )
}

/// D/d of the sheave, a double wrap's secondary sheave and every pulley: the smallest against
/// the minimum.
pub fn d_ratio(lift: &Lift, limits: &Limits) -> Check {
    let d = lift.rope.diameter_m;
    let mut ratios = vec![("traction sheave".to_string(), lift.sheave_diameter_m / d)];
    let mut inputs = vec![q("d_r", d, "m"), q("D_t", lift.sheave_diameter_m, "m")];
    if let Some(s) = lift.secondary_sheave_diameter_m {
        ratios.push(("secondary sheave".to_string(), s / d));
        inputs.push(q("D_s (secondary sheave)", s, "m"));
    }
    ratios.extend(lift.pulleys.iter().enumerate().map(|(i, p)| (format!("pulley {}", i + 1), p.diameter_m / d)));
    let (case, smallest) = ratios.iter().min_by(|a, b| a.1.total_cmp(&b.1)).cloned().unwrap_or_default();
    inputs.extend(lift.pulleys.iter().enumerate().map(|(i, p)| q(&format!("D_p{}", i + 1), p.diameter_m, "m")));
    let intermediates = ratios.iter().map(|(name, r)| q(&format!("D/d {name}"), *r, "")).collect();
    Check::new(D_RATIO_CHECK, "min(D/d) over the sheave and pulleys ≥ 40", Some(smallest), "")
        .inputs(inputs)
        .intermediates(intermediates)
        .against(Relation::AtLeast, Some(&limits.d_ratio_min), true)
        .governed_by(case)
}
