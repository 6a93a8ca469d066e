//! The lift's checks as [`Check`] records, each limit resolved from the rule set `en81-50`
//! (codes/en81-50.toml): the traction cases (`T1/T2 ≤ e^{fα}`; the stalled car at the highest
//! and the lowest position `≥`, or not judged where an electric safety device stops the machine),
//! the ropes' safety factor against Sf of EN 81-50 5.12 and against the minimum for the rope
//! count ([`super::rope_checks`]), and D/d of the sheave and pulleys.

use super::cases::{Case, Loading, Tensions, tensions};
use super::rope_checks::{d_ratio, rope_diameter, rope_minimum, rope_safety_factor};
use crate::check::{Check, Quantity, Relation, Verdict, q};
use crate::codes::{self, formula::Quantities};
use crate::design::Limit;
use crate::design::lift::{Lift, RULE_SET, StalledProtection};

/// Name of the car-loading traction check.
pub const LOADING_CHECK: &str = "traction: car loading";
/// Name of the emergency-braking traction check.
pub const BRAKING_CHECK: &str = "traction: emergency braking";
/// Name of the car-stalled traction check at the highest position (counterweight on its buffer).
pub const STALLED_CHECK: &str = "traction: car stalled";
/// Name of the car-stalled traction check at the lowest position (car on its buffer).
pub const STALLED_BOTTOM_CHECK: &str = "traction: car stalled at the lowest position";
pub use super::rope_checks::{D_RATIO_CHECK, ROPE_DIAMETER_CHECK, ROPE_MIN_CHECK, ROPE_SF_CHECK};

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
    /// Minimum nominal diameter of a suspension rope (mm).
    pub rope_diameter_min_mm: Limit,
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
            rope_diameter_min_mm: get("lift_rope_diameter_min_mm")?,
        })
    }

    /// The friction coefficient of `case`.
    pub fn mu(&self, case: Case) -> &Limit {
        match case {
            Case::CarLoading => &self.mu_loading,
            Case::BrakingLoadedBottom | Case::BrakingEmptyTop => &self.mu_braking,
            Case::CarStalled | Case::CarStalledBottom => &self.mu_stalled,
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
    let f = lift.groove.factor(mu, case.duty());
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
        source: format!(
            "e^{{fα}}, f by the {} groove formula {} with μ = {:.6}: {}",
            lift.groove.word(),
            lift.groove.formula(t.case.duty()),
            t.mu,
            mu.source
        ),
        rule: mu.rule.clone(),
    }
}

/// A traction check of one case (or the worse of the two braking cases).
pub fn traction_check(lift: &Lift, limits: &Limits, t: &Traction, name: &'static str) -> Check {
    let (formula, relation) = if t.case == Case::CarStalledBottom {
        (
            "T1/T2 ≥ e^{fα} (the ropes must slip); the lowest position read as the empty car on its buffer, the machine \
             turning down; T from the masses, f from μ and the groove",
            Relation::AtLeast,
        )
    } else if t.case.must_slip() {
        (
            "T1/T2 ≥ e^{fα} (the ropes must slip); the empty car at the highest position, the counterweight on its \
             buffer; T from the masses, f from μ and the groove",
            Relation::AtLeast,
        )
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
    if t.case.must_slip() && lift.stalled_protection == StalledProtection::ElectricSafetyDevice {
        return declared_device(check, t);
    }
    if t.case.must_slip() && !t.holds() {
        check.note = Some(match t.case {
            Case::CarStalledBottom => {
                "the ropes hold: the machine could haul the counterweight up with the car on its buffer".into()
            }
            _ => "the ropes hold: the machine could haul the car up with its counterweight on the buffer".into(),
        });
    }
    check
}

/// A stalled case where the sheet declares that an electric safety device stops the machine
/// (EN 81-20 5.5.3 c): the ratio and e^{fα} are reported, the slip is not judged.
fn declared_device(mut check: Check, t: &Traction) -> Check {
    let holds = if t.holds() { "the ropes would slip" } else { "the ropes would hold" };
    check.verdict = Verdict::NotEvaluated;
    check.pass = true;
    check.note = Some(format!(
        "not judged: the sheet declares (lift.stalled_protection = \"electric-safety-device\") that an electric safety \
         device stops the machine when the car or the counterweight is stalled, the alternative EN 81-20 5.5.3 c) gives \
         to the ropes slipping; {holds} ({})",
        t.case.name()
    ));
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

/// Every check of the lift, in report order, with the traction cases they rest on.
pub fn all(lift: &Lift, limits: &Limits) -> (Vec<Check>, Vec<Traction>) {
    let cases: Vec<Traction> = Case::ALL.iter().map(|&c| traction(lift, limits, c)).collect();
    let checks = vec![
        traction_check(lift, limits, &cases[0], LOADING_CHECK),
        braking_check(lift, limits, &cases[1], &cases[2]),
        traction_check(lift, limits, &cases[3], STALLED_CHECK),
        traction_check(lift, limits, &cases[4], STALLED_BOTTOM_CHECK),
        rope_safety_factor(lift),
        rope_minimum(lift, limits),
        rope_diameter(lift, limits),
        d_ratio(lift, limits),
    ];
    (checks, cases)
}
