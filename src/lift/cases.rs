//! The rope tensions at the traction sheave in EN 81-50's traction cases, from the masses.
//!
//! Model (docs/lifts.md §Tensions): with roping r:1 and n ropes, the car side carries at the
//! sheave, over all ropes,
//!
//! ```text
//! T_car = M_car (g + a_car)/r + n m_r L_car (g + r a_car)
//! T_cwt = M_cwt (g − a_car)/r + n m_r L_cwt (g − r a_car)
//! ```
//!
//! `M_car` = car + load in it + compensation hanging under it + travelling cable it carries (0
//! when the car rests on its buffer), `M_cwt` = counterweight + compensation under it (0 when the
//! counterweight rests on its buffer), `a_car` the car's acceleration (upward positive; the counterweight's is −a_car),
//! `L` the hanging rope length from the sheave on each side (only the fall that reaches the
//! sheave loads it: with r:1 the other falls end at the hitch), and the rope moving r times as
//! fast as the car. Compensation: its whole length m_c·H hangs under the car at the top landing
//! and under the counterweight at the bottom one; travelling cable: its loop hangs from mid-travel,
//! so the car carries m_t·H/2 at the top and nothing at the bottom. The centrifugal term m'v² of
//! the wrap is left out, as EN 81-50's ratio leaves it out.

use crate::design::Side;
use crate::design::groove::Duty;
use crate::design::lift::Lift;

/// EN 81-50's traction cases, the emergency braking and the stalled one each in two positions.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Case {
    /// Car loading: 125 % of the rated load in the car at the lowest landing, at rest.
    CarLoading,
    /// Emergency braking of the car with rated load near the lowest landing, travelling down.
    BrakingLoadedBottom,
    /// Emergency braking of the empty car near the highest landing, travelling up.
    BrakingEmptyTop,
    /// Car stalled at the highest position: the counterweight on its buffer, the empty car at the
    /// top, the machine turning in the up direction.
    CarStalled,
    /// Car stalled at the lowest position: the empty car on its buffer, the machine turning in
    /// the down direction (hauling the counterweight up).
    CarStalledBottom,
}

impl Case {
    /// Every case, in report order.
    pub const ALL: [Case; 5] =
        [Case::CarLoading, Case::BrakingLoadedBottom, Case::BrakingEmptyTop, Case::CarStalled, Case::CarStalledBottom];

    /// The case's name in the outputs (a folder name in the report).
    pub fn name(self) -> &'static str {
        match self {
            Case::CarLoading => "car-loading",
            Case::BrakingLoadedBottom => "braking-loaded-bottom",
            Case::BrakingEmptyTop => "braking-empty-top",
            Case::CarStalled => "car-stalled",
            Case::CarStalledBottom => "car-stalled-bottom",
        }
    }

    /// The rule-set key of the case's friction coefficient μ.
    pub fn mu_key(self) -> &'static str {
        match self {
            Case::CarLoading => "lift_traction_mu_loading",
            Case::BrakingLoadedBottom | Case::BrakingEmptyTop => "lift_traction_mu_braking",
            Case::CarStalled | Case::CarStalledBottom => "lift_traction_mu_stalled",
        }
    }

    /// Whether the ropes must slip (the stalled car) rather than hold.
    pub fn must_slip(self) -> bool {
        matches!(self, Case::CarStalled | Case::CarStalledBottom)
    }

    /// Which groove formula the case takes (an unhardened V groove has one for the stalled car).
    pub fn duty(self) -> Duty {
        if self.must_slip() { Duty::Stalled } else { Duty::Hold }
    }
}

/// The state of a traction case: where the car is, what it carries and how it moves.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Loading {
    /// Load in the car (kg).
    pub load_kg: f64,
    /// Car at the lowest landing (else at the highest).
    pub car_at_bottom: bool,
    /// The car's velocity, upward positive (m/s).
    pub car_velocity_m_s: f64,
    /// The car's acceleration, upward positive (m/s²).
    pub car_accel_m_s2: f64,
    /// The counterweight rests on its buffer.
    pub counterweight_on_buffer: bool,
    /// The car rests on its buffer (its mass and what hangs under it are not on the ropes).
    pub car_on_buffer: bool,
}

impl Loading {
    /// The loading of `case`; `loading_factor` is the car-loading case's multiple of the rated
    /// load (1.25).
    pub fn of(lift: &Lift, case: Case, loading_factor: f64) -> Self {
        let (v, a) = (lift.rated_speed_m_s, lift.emergency_decel_m_s2);
        let state = |load_kg, car_at_bottom, car_velocity_m_s, car_accel_m_s2, counterweight_on_buffer| Loading {
            load_kg,
            car_at_bottom,
            car_velocity_m_s,
            car_accel_m_s2,
            counterweight_on_buffer,
            car_on_buffer: false,
        };
        match case {
            Case::CarLoading => state(loading_factor * lift.rated_load_kg, true, 0.0, 0.0, false),
            // Travelling down and stopping: the car's acceleration points up.
            Case::BrakingLoadedBottom => state(lift.rated_load_kg, true, -v, a, false),
            Case::BrakingEmptyTop => state(0.0, false, v, -a, false),
            Case::CarStalled => state(0.0, false, v, 0.0, true),
            // The machine turns down: the rope runs as if the car travelled down.
            Case::CarStalledBottom => Loading { car_on_buffer: true, ..state(0.0, true, -v, 0.0, false) },
        }
    }
}

/// Rope tensions at the sheave for one loading, all ropes and per rope, with the masses behind.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Tensions {
    /// Suspended mass on the car side, before the roping divides it (kg).
    pub car_mass_kg: f64,
    /// Suspended mass on the counterweight side (kg).
    pub counterweight_mass_kg: f64,
    /// Rope hanging from the sheave on the car side, all ropes (kg).
    pub car_rope_kg: f64,
    /// Rope hanging from the sheave on the counterweight side, all ropes (kg).
    pub counterweight_rope_kg: f64,
    /// Car-side tension, all ropes (N).
    pub car_n: f64,
    /// Counterweight-side tension, all ropes (N).
    pub counterweight_n: f64,
    /// Side-1 tension per rope (N).
    pub t1_n: f64,
    /// Side-2 tension per rope (N).
    pub t2_n: f64,
    /// Rope speed at the sheave, positive side 1 → side 2 (m/s).
    pub speed_m_s: f64,
    /// Rope acceleration at the sheave, positive when side 1 accelerates up (m/s²).
    pub accel_m_s2: f64,
}

impl Tensions {
    /// The tension ratio `T_hi/T_lo` (≥ 1); `None` when the lower tension is not positive.
    pub fn ratio(&self) -> Option<f64> {
        let (hi, lo) = (self.t1_n.max(self.t2_n), self.t1_n.min(self.t2_n));
        (lo > 0.0).then(|| hi / lo).filter(|r| r.is_finite())
    }
}

/// The tensions of `loading` (module docs for the model).
pub fn tensions(lift: &Lift, loading: &Loading) -> Tensions {
    let g = lift.g_m_s2;
    let r = f64::from(lift.roping);
    let n = f64::from(lift.rope.count);
    let h = lift.travel_m;
    let (at_bottom, a) = (loading.car_at_bottom, loading.car_accel_m_s2);
    let (l_car, l_cwt) = if at_bottom {
        (lift.top_rope_length_m + h, lift.top_rope_length_m)
    } else {
        (lift.top_rope_length_m, lift.top_rope_length_m + h)
    };
    let comp = lift.compensation_mass_per_m_kg * h;
    let (comp_car, comp_cwt) = if at_bottom { (0.0, comp) } else { (comp, 0.0) };
    let cable = if at_bottom { 0.0 } else { 0.5 * lift.travelling_cable_mass_per_m_kg * h };
    let car_mass_kg = if loading.car_on_buffer { 0.0 } else { lift.car_mass_kg + loading.load_kg + comp_car + cable };
    let counterweight_mass_kg = if loading.counterweight_on_buffer { 0.0 } else { lift.counterweight_kg + comp_cwt };
    let car_rope_kg = n * lift.rope.mass_per_m_kg * l_car;
    let counterweight_rope_kg = n * lift.rope.mass_per_m_kg * l_cwt;
    let car_n = car_mass_kg * (g + a) / r + car_rope_kg * (g + r * a);
    let counterweight_n = counterweight_mass_kg * (g - a) / r + counterweight_rope_kg * (g - r * a);
    // Side 1 is lifted when the rope speed is positive.
    let sign = match lift.car_side {
        Side::One => 1.0,
        Side::Two => -1.0,
    };
    let (t1_n, t2_n) = match lift.car_side {
        Side::One => (car_n / n, counterweight_n / n),
        Side::Two => (counterweight_n / n, car_n / n),
    };
    Tensions {
        car_mass_kg,
        counterweight_mass_kg,
        car_rope_kg,
        counterweight_rope_kg,
        car_n,
        counterweight_n,
        t1_n,
        t2_n,
        speed_m_s: sign * r * loading.car_velocity_m_s,
        accel_m_s2: sign * r * a,
    }
}

/// The rope-safety-factor state: rated load in the car at rest at the lowest landing.
pub fn rated_load_at_bottom(lift: &Lift) -> Tensions {
    let loading = Loading {
        load_kg: lift.rated_load_kg,
        car_at_bottom: true,
        car_velocity_m_s: 0.0,
        car_accel_m_s2: 0.0,
        counterweight_on_buffer: false,
        car_on_buffer: false,
    };
    tensions(lift, &loading)
}
