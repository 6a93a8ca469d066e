//! The emergency stop of a trip, at level 0 (rigid ropes) and level 4 (the suspended ropes'
//! dynamics), with the brake of the sheet's `[brake]` stopping the pulley as a body (docs/physics.md §11)
//! or an imposed deceleration; the tensions at the friction pulley with the guide sheave's
//! inertia; the onset of gross slip, after which a trip's results are not valid; and what the
//! stop reached (deceleration, stopping distance, the slip-limited deceleration).

use super::shared::RopePrefix;
use super::{ELEMENTS_PER_SIDE, Level4Error, WRAP_SAMPLE_S, profile_until};
use crate::design::{Brake, Design, Direction, HistorySample, Hoist};
use crate::dynamics::{
    self, DynSample, DynamicsError, HoistParams, Kinematics, MotionProfile, PulleyBody, SimOptions, Stage,
};
use crate::model::braking::{self, StopMasses};
use crate::model::level0::{EndState, euler_limit};

/// The suspended ropes' parameters of `design` with `payload_kg` on conveyance 1, the travel
/// measured from `x0_m` (lowering from the top: `x0_m` = the travel's end). The lengths at the
/// new origin are `L1 = L1₀ − x0`, `L2 = L2₀ + x0`, tails `Lt1₀ + x0`, `Lt2₀ − x0`.
pub fn params_at(design: &Design, hoist: &Hoist, payload_kg: f64, x0_m: f64) -> HoistParams {
    HoistParams {
        ropes: design.rope.count as usize,
        rope_mass_per_m_kg: design.rope.mass_per_m_kg,
        rope_ea_n: design.rope.ea_n,
        damping_ratio: hoist.rope_damping_ratio,
        tail_ropes: hoist.tail_count as usize,
        tail_mass_per_m_kg: hoist.tail_mass_per_m_kg,
        side1_mass_kg: hoist.conveyance1_kg + payload_kg,
        side2_mass_kg: hoist.conveyance2_kg,
        side1_length0_m: hoist.side1_length_m - x0_m,
        side2_length0_m: hoist.side2_length_m + x0_m,
        tail1_length0_m: hoist.tail1_length_m + x0_m,
        tail2_length0_m: hoist.tail2_length_m - x0_m,
        g_m_s2: design.g_m_s2,
    }
}

/// The tensions at the friction pulley from those at the top of the suspended ropes: the guide
/// sheave's rim moves with the rope, so its inertia adds `m_g·a` against the acceleration of its
/// side: `T1 += m_g1·a/n`, `T2 −= m_g2·a/n` (a: side 1 upward).
pub fn with_guide(design: &Design, samples: &mut [DynSample]) {
    let [g1, g2] = design.guide_mass_kg();
    if g1 == 0.0 && g2 == 0.0 {
        return;
    }
    let n = f64::from(design.rope.count);
    for s in samples {
        s.t1_n += g1 * s.accel_m_s2 / n;
        s.t2_n -= g2 * s.accel_m_s2 / n;
    }
}

/// Rigid-rope tensions per rope at travel x and acceleration a: `T1 = T1s(x)(g + a)/g + m_g1·a/n`,
/// `T2 = T2s(x)(g − a)/g − m_g2·a/n`, `T1s, T2s` the static tensions ([`dynamics::static_tensions_n`]).
pub fn rigid_tensions_n(design: &Design, params: &HoistParams, k: &Kinematics) -> Result<(f64, f64), DynamicsError> {
    let (t1s, t2s) = dynamics::static_tensions_n(params, k.x_m)?;
    let g = params.g_m_s2;
    let [g1, g2] = design.guide_mass_kg();
    let n = params.ropes as f64;
    let a = k.accel_m_s2;
    Ok((t1s * (g + a) / g + g1 * a / n, t2s * (g - a) / g - g2 * a / n))
}

/// [`rigid_tensions_n`] at kinematics a run of `p` has already checked (`p` validated, the
/// lengths at `k.x_m` in range), without checking them again: the same operations in the same
/// order, `T_s = (M_s + ρL_s)·g/n` at rest, then `T1 = T1s(g + a)/g + m_g1·a/n`,
/// `T2 = T2s(g − a)/g − m_g2·a/n`, with `[g1, g2]` the guide sheaves' `J_g/R_g²`
/// ([`Design::guide_mass_kg`]). For a whole trip's samples, where checking every sample would
/// cost more than the tensions.
pub fn rigid_tensions_of_checked_n(p: &HoistParams, [g1, g2]: [f64; 2], k: &Kinematics) -> (f64, f64) {
    let (g, n, a) = (p.g_m_s2, p.ropes as f64, k.accel_m_s2);
    let at_rest = |side| (p.end_mass_kg(side, k.x_m) + p.rho_kg_m() * p.hanging_length_m(side, k.x_m)) * g / n;
    let (t1s, t2s) = (at_rest(crate::design::Side::One), at_rest(crate::design::Side::Two));
    (t1s * (g + a) / g + g1 * a / n, t2s * (g - a) / g - g2 * a / n)
}

/// The level-0 (rigid-rope) kinematics of a trip whose brake trips at `at_s`: the profile up to
/// the trip, then [`braking::rigid_stop`] to standstill.
pub fn rigid_braked_kinematics(
    design: &Design,
    params: &HoistParams,
    stages: &[Stage],
    at_s: f64,
    brake: &Brake,
) -> Result<(MotionProfile, Vec<(f64, Kinematics)>), Level4Error> {
    let profile = profile_until(stages, at_s)?;
    let inertia = braking::pulley_body_kg(design) + design.guide_mass_kg().iter().sum::<f64>();
    let stop = braking::rigid_stop(params, &profile, at_s, inertia, brake)?;
    Ok((profile, stop))
}

/// The trips of [`braked_ropes`]: the stages, the instants the brake trips at (ascending), the
/// time step, and the start of the trip shared with other scenes to continue from, if any
/// ([`super::shared`]).
#[derive(Debug, Clone, Copy)]
pub struct BrakedTrip<'a> {
    /// The trip's stages.
    pub stages: &'a [Stage],
    /// When the brake trips, ascending (s).
    pub trips_s: &'a [f64],
    /// The suspended ropes' time step (s).
    pub time_step_s: f64,
    /// The shared start of the trip, before the first trip.
    pub from: Option<&'a RopePrefix>,
}

/// The runs of [`braked_ropes`]: per trip, the samples from the start to standstill, and the
/// suspended ropes' time steps integrated up to the trips (their work; the stops with the pulley
/// as a body are not counted).
#[derive(Debug, Clone, Default)]
pub struct BrakedRopes {
    /// Per trip, the samples from the start to standstill, tensions at the friction pulley
    /// (guide sheave included).
    pub trips: Vec<Vec<DynSample>>,
    /// Time steps of the suspended ropes integrated (not those of a shared start continued from).
    pub steps: u64,
}

/// The level-4 samples of a trip whose brake trips at each of `trip.trips_s`: the suspended
/// ropes over the profile up to each trip (one run, continued from trip to trip, and from
/// `trip.from` when given), then each stop with the pulley as a body
/// ([`dynamics::braked_stop`]). Returns, per trip, the samples from the start to standstill,
/// tensions at the friction pulley (guide sheave included), and the steps integrated.
pub fn braked_ropes(
    design: &Design,
    params: &HoistParams,
    trip: BrakedTrip,
    brake: &Brake,
) -> Result<BrakedRopes, Level4Error> {
    let BrakedTrip { stages, trips_s, time_step_s, from } = trip;
    let record_every = ((WRAP_SAMPLE_S / time_step_s).round() as usize).max(1);
    let options = SimOptions { record_every, energy: false, ..SimOptions::new(time_step_s, ELEMENTS_PER_SIDE) };
    let force = |tau: f64| braking::brake_force_n(brake, tau);
    let body = PulleyBody {
        pulley_kg: braking::pulley_body_kg(design),
        guide_kg: design.guide_mass_kg(),
        brake_force_n: &force,
        max_stop_s: braking::MAX_STOP_S,
    };
    let mut out = BrakedRopes { trips: Vec::with_capacity(trips_s.len()), steps: 0 };
    let mut before: Vec<DynSample> = from.map(|p| p.samples().to_vec()).unwrap_or_default();
    let mut checkpoint = from.map(|p| p.checkpoint().clone());
    for &at_s in trips_s {
        let profile = profile_until(stages, at_s)?;
        let run = dynamics::simulate_streamed(
            params,
            &profile,
            &options,
            checkpoint.as_ref(),
            Some(f64::INFINITY),
            &mut |_| {},
        )?;
        out.steps += run.steps;
        let (samples, cp) = (run.samples, run.checkpoint);
        let cp = cp.ok_or(Level4Error::EmergencyAtRest { at_s })?;
        // The samples of a continued run start at its checkpoint, which the previous run (or
        // the shared start) ended with; a run that started afresh replaces those.
        match (checkpoint.as_ref(), samples.first()) {
            (Some(c), Some(first)) if first.t_s == c.t_s() => before.extend(samples.into_iter().skip(1)),
            _ => before = samples,
        }
        let stop = dynamics::braked_stop(params, &options, &cp, profile.end(), &body)?;
        let mut trip = before.clone();
        trip.extend(stop.into_iter().skip(1).map(|mut s| {
            s.t_s = s.t_s.max(at_s);
            s
        }));
        with_guide(design, &mut trip);
        out.trips.push(trip);
        checkpoint = Some(cp);
    }
    Ok(out)
}

/// The first instant at which a trip slips grossly, `(T_hi − m'v²)/(T_lo − m'v²) > e^{μα}`:
/// from there on the rope no longer moves with the pulley, the model's coupling does not hold
/// and the rest of the trip is not valid.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct SlipOnset {
    /// Time of the first slipping instant (s).
    pub t_s: f64,
    /// Tension ratio `(T_hi − m'v²)/(T_lo − m'v²)` there.
    pub ratio: f64,
}

/// The onset of gross slip among `states` (time, state), if any.
pub fn slip_onset(design: &Design, states: &[(f64, EndState)]) -> Option<SlipOnset> {
    let limit = euler_limit(design.pulley.mu, design.pulley.wrap_angle_rad);
    states.iter().find(|(_, s)| s.tension_ratio() > limit).map(|(t, s)| SlipOnset { t_s: *t, ratio: s.tension_ratio() })
}

/// How an emergency stop brakes; serialised as `brake` or `imposed deceleration`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
pub enum StopMode {
    /// The brake's force on the pulley as a body.
    #[serde(rename = "brake")]
    Brake,
    /// A deceleration imposed on the pulley.
    #[serde(rename = "imposed deceleration")]
    Imposed,
}

impl StopMode {
    /// The mode's word in reports.
    pub fn word(self) -> &'static str {
        match self {
            StopMode::Brake => "brake",
            StopMode::Imposed => "imposed deceleration",
        }
    }
}

/// What an emergency stop reached.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct StopReport {
    /// `brake` (the pulley as a body) or `imposed deceleration`.
    pub mode: StopMode,
    /// Lifting or lowering side 1 when the stop trips.
    pub lifting: bool,
    /// A stop in time (from a trip through idle and build-up to standstill); `false` for the
    /// closed form at one position with the full force from the trip on.
    pub timed: bool,
    /// Time of the trip (s).
    pub trip_s: f64,
    /// Travel at the trip, in the trip's own coordinates (m).
    pub trip_x_m: f64,
    /// Time of standstill (s).
    pub stop_s: f64,
    /// Speed at the trip, positive side 1 → side 2 (m/s).
    pub speed_at_trip_m_s: f64,
    /// Speed when the full brake force is reached, `v(t_full)` (the trip's speed for an imposed
    /// deceleration or a stop with the full force from the trip on; m/s).
    pub speed_at_full_force_m_s: f64,
    /// The deceleration reached: mean from full brake force (the trip for an imposed
    /// deceleration) to standstill, `v(t_full)/(t_stop − t_full)` (m/s²).
    pub decel_m_s2: f64,
    /// Largest deceleration of the pulley during the stop (m/s²).
    pub peak_decel_m_s2: f64,
    /// Travel from the trip to standstill (m, ≥ 0).
    pub distance_m: f64,
    /// Rigid-rope deceleration at which the rope would slip grossly at the trip's position and
    /// speed ([`braking::slip_limited_decel_m_s2`]).
    pub slip_limited_decel_m_s2: f64,
    /// The masses of the stop at the trip's position.
    pub masses: StopMasses,
}

/// The report of a stop from the pulley's kinematics from the trip to standstill (`kin`: time
/// and kinematics, ascending). `full_force_after_s`: the brake's idle plus build-up time (0 for
/// an imposed deceleration).
pub fn stop_report(
    design: &Design,
    params: &HoistParams,
    kin: &[(f64, Kinematics)],
    full_force_after_s: f64,
    mode: StopMode,
) -> Result<StopReport, DynamicsError> {
    let (trip_s, trip) = kin.first().copied().unwrap_or_default();
    let (stop_s, stop) = kin.last().copied().unwrap_or_default();
    let s = trip.speed_m_s.signum();
    let t_full = trip_s + full_force_after_s;
    let v_full = interpolate_speed(kin, t_full.min(stop_s));
    let decel =
        if stop_s > t_full { v_full.abs() / (stop_s - t_full) } else { trip.speed_m_s.abs() / (stop_s - trip_s) };
    let peak = kin.iter().map(|(_, k)| -s * k.accel_m_s2).fold(0.0, f64::max);
    let (t1s, t2s) = dynamics::static_tensions_n(params, trip.x_m)?;
    let n = params.ropes as f64;
    let g = params.g_m_s2;
    let masses = StopMasses::of(design, t1s * n / g, t2s * n / g);
    let direction = if s > 0.0 { Direction::Lift } else { Direction::Lower };
    let limit = euler_limit(design.pulley.mu, design.pulley.wrap_angle_rad);
    let c = design.rope.mass_per_m_kg * trip.speed_m_s * trip.speed_m_s;
    Ok(StopReport {
        mode,
        lifting: s > 0.0,
        timed: true,
        trip_s,
        trip_x_m: trip.x_m,
        stop_s,
        speed_at_trip_m_s: trip.speed_m_s,
        speed_at_full_force_m_s: v_full,
        decel_m_s2: if decel.is_finite() { decel } else { 0.0 },
        peak_decel_m_s2: peak,
        distance_m: (stop.x_m - trip.x_m).abs(),
        slip_limited_decel_m_s2: braking::slip_limited_decel_m_s2(&masses, g, n, c, limit, direction),
        masses,
    })
}

/// The speed at `t_s` by linear interpolation of `kin`.
fn interpolate_speed(kin: &[(f64, Kinematics)], t_s: f64) -> f64 {
    let i = kin.partition_point(|(t, _)| *t <= t_s);
    match (i.checked_sub(1).and_then(|j| kin.get(j)), kin.get(i)) {
        (Some(a), Some(b)) if b.0 > a.0 => {
            let w = (t_s - a.0) / (b.0 - a.0);
            a.1.speed_m_s + w * (b.1.speed_m_s - a.1.speed_m_s)
        }
        (Some(a), _) => a.1.speed_m_s,
        (None, Some(b)) => b.1.speed_m_s,
        (None, None) => 0.0,
    }
}

/// The kinematics of level-4 samples from `from_s` on.
pub fn kinematics_from(samples: &[DynSample], from_s: f64) -> Vec<(f64, Kinematics)> {
    samples
        .iter()
        .filter(|s| s.t_s >= from_s)
        .map(|s| (s.t_s, Kinematics { x_m: s.x_m, speed_m_s: s.speed_m_s, accel_m_s2: s.accel_m_s2 }))
        .collect()
}

/// Rigid-rope history samples of the kinematics `kin` (tensions by [`rigid_tensions_n`]).
pub fn rigid_samples(
    design: &Design,
    params: &HoistParams,
    kin: &[(f64, Kinematics)],
) -> Result<Vec<HistorySample>, DynamicsError> {
    kin.iter()
        .map(|(t, k)| {
            let (t1_n, t2_n) = rigid_tensions_n(design, params, k)?;
            Ok(HistorySample {
                t_s: *t,
                t1_n,
                t2_n,
                speed_m_s: if k.speed_m_s.abs() < 1e-9 { 0.0 } else { k.speed_m_s },
            })
        })
        .collect()
}
