//! The lift's checks as [`Check`] records, each limit resolved from the rule set `en81-50`
//! (codes/en81-50.toml): the three traction cases (`T1/T2 ≤ e^{fα}`, the stalled car `≥`), the
//! ropes' safety factor against max(Sf, the minimum for the rope count) and D/d of the sheave
//! and pulleys.

use super::cases::{Case, Loading, Tensions, rated_load_at_bottom, tensions};
use super::{Lift, RULE_SET, rope};
use crate::check::{Check, Quantity, Relation, q};
use crate::codes::{self, formula::Quantities};
use crate::design::Limit;

/// Name of the car-loading traction check.
pub const LOADING_CHECK: &str = "traction: car loading";
/// Name of the emergency-braking traction check.
pub const BRAKING_CHECK: &str = "traction: emergency braking";
/// Name of the car-stalled traction check.
pub const STALLED_CHECK: &str = "traction: car stalled";
/// Name of the suspension ropes' safety factor check.
pub const ROPE_SF_CHECK: &str = "suspension rope safety factor";
/// Name of the D/d check.
pub const D_RATIO_CHECK: &str = "D/d of the traction sheave and pulleys";

/// The rule set's values for one lift.
#[derive(Debug, Clone, PartialEq)]
pub struct Limits {
    /// Multiple of the rated load in the car-loading case.
    pub loading_factor: Limit,
    /// μ of the car-loading case.
    pub mu_loading: Limit,
    /// μ of the emergency-braking case (from the rope speed).
    pub mu_braking: Limit,
    /// μ of the car-stalled case.
    pub mu_stalled: Limit,
    /// Minimum safety factor of the ropes for their count.
    pub rope_sf_min: Limit,
    /// Minimum D/d.
    pub d_ratio_min: Limit,
}

impl Limits {
    /// The limits of the rule set `en81-50` for `lift`; `Err` names what could not be resolved.
    pub fn of(lift: &Lift) -> Result<Self, String> {
        let set = codes::find(RULE_SET).ok_or_else(|| format!("the rule set {RULE_SET} is not bundled"))?;
        let quantities = Quantities {
            rope_speed_m_s: Some(lift.rope_speed_m_s()),
            rope_count: Some(f64::from(lift.rope.count)),
            ..Quantities::default()
        };
        let get = |key: &str| {
            set.limit(key)
                .ok_or_else(|| format!("the rule set {RULE_SET} has no {key}"))
                .and_then(|l| l.resolve(&set, &quantities))
        };
        Ok(Self {
            loading_factor: get("lift_loading_factor")?,
            mu_loading: get("lift_traction_mu_loading")?,
            mu_braking: get("lift_traction_mu_braking")?,
            mu_stalled: get("lift_traction_mu_stalled")?,
            rope_sf_min: get("lift_rope_safety_factor_min")?,
            d_ratio_min: get("lift_d_ratio_min")?,
        })
    }

    /// The friction coefficient of `case`.
    pub fn mu(&self, case: Case) -> &Limit {
        match case {
            Case::CarLoading => &self.mu_loading,
            Case::BrakingLoadedBottom | Case::BrakingEmptyTop => &self.mu_braking,
            Case::CarStalled => &self.mu_stalled,
        }
    }
}

/// One traction case evaluated: its tensions, μ, f, the Euler limit and the ratio.
#[derive(Debug, Clone, PartialEq)]
pub struct Traction {
    /// The case.
    pub case: Case,
    /// What the car carries and how it moves.
    pub loading: Loading,
    /// The tensions at the sheave.
    pub tensions: Tensions,
    /// The case's μ.
    pub mu: f64,
    /// The groove factor f.
    pub f: f64,
    /// `e^{fα}`.
    pub euler_limit: f64,
    /// `T_hi/T_lo`; `None` when the lower tension is 0 (the ropes slip whatever the friction).
    pub ratio: Option<f64>,
}

impl Traction {
    /// Whether the case's requirement holds: the ropes hold (`ratio ≤ e^{fα}`), or for the
    /// stalled car slip (`ratio ≥ e^{fα}`).
    pub fn holds(&self) -> bool {
        match (self.case.must_slip(), self.ratio) {
            (true, None) => true,
            (false, None) => false,
            (true, Some(r)) => r >= self.euler_limit,
            (false, Some(r)) => r <= self.euler_limit,
        }
    }
}

/// Evaluates `case` of `lift` with the rule set's `limits`.
pub fn traction(lift: &Lift, limits: &Limits, case: Case) -> Traction {
    let loading = Loading::of(lift, case, limits.loading_factor.value);
    let tensions = tensions(lift, &loading);
    let mu = limits.mu(case).value;
    let f = lift.groove.factor(mu);
    Traction { case, loading, tensions, mu, f, euler_limit: (f * lift.wrap_angle_rad).exp(), ratio: tensions.ratio() }
}

/// The inputs and intermediates of a traction case, for its record.
fn traction_quantities(lift: &Lift, t: &Traction) -> (Vec<Quantity>, Vec<Quantity>) {
    let l = &t.loading;
    let mut inputs = vec![
        q("P (empty car)", lift.car_mass_kg, "kg"),
        q("load in the car", l.load_kg, "kg"),
        q("counterweight", lift.counterweight_kg, "kg"),
        q("r (roping)", f64::from(lift.roping), ""),
        q("n (ropes)", f64::from(lift.rope.count), ""),
        q("H (travel)", lift.travel_m, "m"),
        q("a_car (up positive)", l.car_accel_m_s2, "m/s²"),
        q("g", lift.g_m_s2, "m/s²"),
        q("μ", t.mu, ""),
        q("α", lift.wrap_angle_rad.to_degrees(), "deg"),
    ];
    inputs.extend(lift.groove.angles_deg().into_iter().map(|(s, v)| q(s, v, "deg")));
    let tn = &t.tensions;
    let mut intermediates = vec![
        q("M_car (car side, before /r)", tn.car_mass_kg, "kg"),
        q("M_cwt (counterweight side, before /r)", tn.counterweight_mass_kg, "kg"),
        q("car-side rope", tn.car_rope_kg, "kg"),
        q("counterweight-side rope", tn.counterweight_rope_kg, "kg"),
        q("T_car (all ropes)", tn.car_n, "N"),
        q("T_cwt (all ropes)", tn.counterweight_n, "N"),
        q("f", t.f, ""),
        q("e^{fα}", t.euler_limit, ""),
    ];
    if let Some(r) = t.ratio {
        intermediates.push(q("T1/T2 (larger over smaller)", r, ""));
    }
    (inputs, intermediates)
}

/// The limit `e^{fα}` of a traction case, with the rule its μ comes from.
fn euler_limit(t: &Traction, mu: &Limit, lift: &Lift) -> Limit {
    Limit {
        value: t.euler_limit,
        source: format!("e^{{fα}}, f by the {} groove formula with μ = {:.6}: {}", lift.groove.word(), t.mu, mu.source),
        rule: mu.rule.clone(),
    }
}

/// A traction check of one case (or the worse of the two braking cases).
pub fn traction_check(lift: &Lift, limits: &Limits, t: &Traction, name: &'static str) -> Check {
    let (formula, relation) = if t.case.must_slip() {
        ("T1/T2 ≥ e^{fα} (the ropes must slip); T from the masses, f from μ and the groove", Relation::AtLeast)
    } else {
        ("T1/T2 ≤ e^{fα} (the ropes must hold); T from the masses, f from μ and the groove", Relation::AtMost)
    };
    let (inputs, intermediates) = traction_quantities(lift, t);
    let limit = euler_limit(t, limits.mu(t.case), lift);
    let check = Check::new(name, formula, t.ratio, "").inputs(inputs).intermediates(intermediates);
    let mut check = match t.ratio {
        Some(_) => check.against(relation, Some(&limit), true),
        // No tension on the low side: nothing holds the ropes, they slip whatever f is.
        None => {
            let mut c = check.against(relation, Some(&limit), true);
            c.value = None;
            if !t.case.must_slip() {
                c.fail();
            }
            c.with_note("the lower tension is 0: the ropes slip whatever the friction")
        }
    };
    check.governing_case = Some(t.case.name().to_string());
    if t.case.must_slip() && !t.holds() {
        check.note =
            Some("the ropes hold: the machine could haul the car up with its counterweight on the buffer".into());
    }
    check
}

/// The emergency braking check: the worse of its two cases (the larger ratio).
pub fn braking_check(lift: &Lift, limits: &Limits, loaded: &Traction, empty: &Traction) -> Check {
    let worse = if loaded.ratio.unwrap_or(f64::MAX) >= empty.ratio.unwrap_or(f64::MAX) { loaded } else { empty };
    let mut check = traction_check(lift, limits, worse, BRAKING_CHECK);
    for t in [loaded, empty] {
        if let Some(r) = t.ratio {
            check.intermediates.push(q(&format!("T1/T2 {}", t.case.name()), r, ""));
        }
    }
    check
}

/// The suspension ropes' safety factor `n F_min / T_car` (rated load at rest at the lowest
/// landing) against max(Sf(N_equiv, D_t/d_r), the minimum for the rope count).
pub fn rope_safety_factor(lift: &Lift, limits: &Limits) -> Check {
    let t = rated_load_at_bottom(lift);
    let n = f64::from(lift.rope.count);
    let actual = n * lift.rope.min_breaking_force_n / t.car_n;
    let eq = rope::equivalent(lift);
    let ratio = lift.sheave_diameter_m / lift.rope.diameter_m;
    let sf = rope::required_safety_factor(eq.total, ratio);
    let mut inputs = vec![
        q("n", n, ""),
        q("F_min (one rope)", lift.rope.min_breaking_force_n, "N"),
        q("N_equiv(t)", eq.sheave, ""),
        q("N_ps", eq.simple as f64, ""),
        q("N_pr", eq.reverse as f64, ""),
        q("D_t", lift.sheave_diameter_m, "m"),
        q("d_r", lift.rope.diameter_m, "m"),
    ];
    if let Some(d) = eq.pulley_diameter_m {
        inputs.push(q("D_p (mean of the pulleys)", d, "m"));
    }
    let mut intermediates = vec![
        q("T_car (rated load at rest, lowest landing, all ropes)", t.car_n, "N"),
        q("K_p = (D_t/D_p)^4", eq.k_p, ""),
        q("N_equiv(p) = K_p(N_ps + 4N_pr)", eq.pulleys, ""),
        q("N_equiv", eq.total, ""),
        q("D_t/d_r", ratio, ""),
        q("minimum for the rope count", limits.rope_sf_min.value, ""),
    ];
    let formula = "n·F_min/T_car ≥ max(Sf, 12 with ≥ 3 ropes or 16 with 2); Sf = 10^(2.6834 − log(695.85e6·N_equiv/(D_t/d_r)^8.567)/log(77.09·(D_t/d_r)^−2.894))";
    let check = Check::new(ROPE_SF_CHECK, formula, Some(actual), "");
    let Some(sf) = sf else {
        return check
            .inputs(inputs)
            .intermediates(intermediates)
            .against(Relation::AtLeast, Some(&limits.rope_sf_min), true)
            .with_note(format!("Sf not evaluated: the formula needs D_t/d_r > {:.2}", rope::smallest_ratio()));
    };
    intermediates.push(q("Sf", sf, ""));
    let (value, source) = if sf > limits.rope_sf_min.value {
        (sf, format!("Sf from N_equiv = {:.4} and D_t/d_r = {ratio:.2} (EN 81-50's formula)", eq.total))
    } else {
        (limits.rope_sf_min.value, limits.rope_sf_min.source.clone())
    };
    let limit = Limit { value, source, rule: limits.rope_sf_min.rule.clone() };
    check.inputs(inputs).intermediates(intermediates).against(Relation::AtLeast, Some(&limit), true)
}

/// D/d of the sheave and every pulley: the smallest against the minimum.
pub fn d_ratio(lift: &Lift, limits: &Limits) -> Check {
    let d = lift.rope.diameter_m;
    let mut ratios = vec![("traction sheave".to_string(), lift.sheave_diameter_m / d)];
    ratios.extend(lift.pulleys.iter().enumerate().map(|(i, p)| (format!("pulley {}", i + 1), p.diameter_m / d)));
    let (case, smallest) = ratios.iter().min_by(|a, b| a.1.total_cmp(&b.1)).cloned().unwrap_or_default();
    let mut inputs = vec![q("d_r", d, "m"), q("D_t", lift.sheave_diameter_m, "m")];
    inputs.extend(lift.pulleys.iter().enumerate().map(|(i, p)| q(&format!("D_p{}", i + 1), p.diameter_m, "m")));
    let intermediates = ratios.iter().map(|(name, r)| q(&format!("D/d {name}"), *r, "")).collect();
    Check::new(D_RATIO_CHECK, "min(D/d) over the sheave and pulleys ≥ 40", Some(smallest), "")
        .inputs(inputs)
        .intermediates(intermediates)
        .against(Relation::AtLeast, Some(&limits.d_ratio_min), true)
        .governed_by(case)
}

/// Every check of the lift, in report order, with the traction cases they rest on.
pub fn all(lift: &Lift, limits: &Limits) -> (Vec<Check>, Vec<Traction>) {
    let cases: Vec<Traction> = Case::ALL.iter().map(|&c| traction(lift, limits, c)).collect();
    let checks = vec![
        traction_check(lift, limits, &cases[0], LOADING_CHECK),
        braking_check(lift, limits, &cases[1], &cases[2]),
        traction_check(lift, limits, &cases[3], STALLED_CHECK),
        rope_safety_factor(lift, limits),
        d_ratio(lift, limits),
    ];
    (checks, cases)
}
