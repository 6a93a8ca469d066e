//! Level 4: a hoisting cycle. The suspended ropes ([`crate::dynamics`]) turn the motion profile
//! of the `[hoist]` into the end tensions T1(t), T2(t) at the tangent points, which drive the
//! discrete wrap model of level 2 step by step (MODEL §6).
//!
//! Coupling is one-way: the drive imposes the pulley's surface motion, and the rope's creep on
//! the lining (micrometres per increment, a creep speed of order v·ΔT/EA ≈ 1 mm/s against a rope
//! speed of metres per second) changes the suspended ropes' length by a relative amount below
//! 1e-3, far below what moves their tensions. The wrap therefore does not feed back into the
//! suspended ropes, and each side's tension is what its rope column pulls with.

use crate::design::{Design, Direction, DutyCycleScene, EmergencyStop, HistorySample, Hoist};
use crate::dynamics::{self, Checkpoint, DynSample, DynamicsError, HoistParams, MotionProfile, SimOptions, Stage};
use crate::margins::{self, Margin};
use crate::model::level0::{EndState, euler_limit};
use crate::roots::RootStats;

/// Finite elements per side of the suspended ropes (the first mode converges to well under 1 %
/// with far fewer; more elements resolve the higher modes a jerk excites).
pub const ELEMENTS_PER_SIDE: usize = 24;

/// Why a duty cycle could not run.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum Level4Error {
    #[error(transparent)]
    Dynamics(#[from] DynamicsError),
    #[error("emergency_stop_s = {at_s} s is not before the end of the motion profile ({duration_s:.3} s)")]
    EmergencyAfterEnd { at_s: f64, duration_s: f64 },
    #[error("emergency_stop_s = {at_s} s: the hoist is at rest then, there is no motion to brake")]
    EmergencyAtRest { at_s: f64 },
    #[error("a duty-cycle scene needs the sheet's [hoist] section")]
    NoHoist,
}

/// Interval of the end tensions handed to the wrap (s). The dynamics integrate at the scene's
/// `time_step_s`; the wrap model takes every sample this far apart and interpolates linearly
/// between them, which follows the first longitudinal modes (about 1 Hz on the reference hoist)
/// to a relative error of (ωΔt)²/8 ≈ 1e-4 of their amplitude, and keeps the wrap's increments
/// (each with a new m'v² as the speed changes) at a few hundred per second.
pub const WRAP_SAMPLE_S: f64 = 0.005;

/// What the suspended-rope model needs of a design and a duty-cycle scene. A lowering trip
/// starts where the lift ends: side 1 at the top, every hanging length moved by the lift's
/// travel D (`L1 = L1₀ − D`, `L2 = L2₀ + D`, tails the other way).
pub fn hoist_params(design: &Design, hoist: &Hoist, scene: &DutyCycleScene) -> HoistParams {
    let d = match scene.direction {
        Direction::Lift => 0.0,
        Direction::Lower => lift_travel_m(hoist),
    };
    HoistParams {
        ropes: design.rope.count as usize,
        rope_mass_per_m_kg: design.rope.mass_per_m_kg,
        rope_ea_n: design.rope.ea_n,
        damping_ratio: hoist.rope_damping_ratio,
        tail_ropes: hoist.tail_count as usize,
        tail_mass_per_m_kg: hoist.tail_mass_per_m_kg,
        side1_mass_kg: hoist.conveyance1_kg + scene.payload_kg,
        side2_mass_kg: hoist.conveyance2_kg,
        side1_length0_m: hoist.side1_length_m - d,
        side2_length0_m: hoist.side2_length_m + d,
        tail1_length0_m: hoist.tail1_length_m + d,
        tail2_length0_m: hoist.tail2_length_m - d,
        g_m_s2: design.g_m_s2,
    }
}

/// Travel of the pulley surface over the `[hoist]` profile as given (a lift), m.
fn lift_travel_m(hoist: &Hoist) -> f64 {
    let stages: Vec<Stage> = hoist
        .stages
        .iter()
        .map(|s| Stage { duration_s: s.duration_s, accel_end_m_s2: s.accel_m_s2, step: s.step })
        .collect();
    MotionProfile::new(&stages).map_or(0.0, |p| p.at(p.duration_s()).x_m)
}

/// The scene's motion profile: the hoist's stages (mirrored when lowering side 1), cut at the
/// emergency stop and followed by constant braking to rest when the scene has one.
pub fn motion_profile(hoist: &Hoist, scene: &DutyCycleScene) -> Result<MotionProfile, Level4Error> {
    let sign = match scene.direction {
        Direction::Lift => 1.0,
        Direction::Lower => -1.0,
    };
    let trip = |sign: f64| {
        hoist.stages.iter().map(move |s| Stage {
            duration_s: s.duration_s,
            accel_end_m_s2: sign * s.accel_m_s2,
            step: s.step,
        })
    };
    let mut stages: Vec<Stage> = trip(sign).collect();
    if let Some(rest_s) = scene.return_after_s {
        // A round trip: rest, then the same trip back the other way.
        if rest_s > 0.0 {
            stages.push(Stage { duration_s: Some(rest_s), accel_end_m_s2: 0.0, step: true });
        }
        stages.extend(trip(-sign));
    }
    let Some(stop) = scene.emergency else {
        return Ok(MotionProfile::new(&stages)?);
    };
    let full = MotionProfile::new(&stages)?;
    if stop.at_s >= full.duration_s() {
        return Err(Level4Error::EmergencyAfterEnd { at_s: stop.at_s, duration_s: full.duration_s() });
    }
    // The stages up to the stop; the stage it falls in ends there, at the acceleration the
    // profile has at that instant.
    let mut cut = Vec::new();
    let mut t = 0.0;
    for s in &stages {
        let d = s.duration_s.unwrap_or(f64::INFINITY);
        if t + d >= stop.at_s {
            let accel = full.at(stop.at_s).accel_m_s2;
            cut.push(Stage { duration_s: Some(stop.at_s - t), accel_end_m_s2: accel, step: s.step });
            break;
        }
        cut.push(*s);
        t += d;
    }
    let v = full.at(stop.at_s).speed_m_s;
    if v == 0.0 {
        return Err(Level4Error::EmergencyAtRest { at_s: stop.at_s });
    }
    cut.push(Stage::step_until_stop(-v.signum() * stop.decel_m_s2));
    Ok(MotionProfile::new(&cut)?)
}

/// Runs the suspended ropes through the scene and returns their samples (one every
/// [`WRAP_SAMPLE_S`]).
pub fn suspended_ropes(design: &Design, hoist: &Hoist, scene: &DutyCycleScene) -> Result<Vec<DynSample>, Level4Error> {
    Ok(resumable_ropes(design, hoist, scene, None, None)?.0)
}

/// [`suspended_ropes`] from a checkpoint and/or keeping one ([`dynamics::simulate_resumable`]).
fn resumable_ropes(
    design: &Design,
    hoist: &Hoist,
    scene: &DutyCycleScene,
    from: Option<&Checkpoint>,
    keep_at_s: Option<f64>,
) -> Result<(Vec<DynSample>, Option<Checkpoint>), Level4Error> {
    let params = hoist_params(design, hoist, scene);
    let profile = motion_profile(hoist, scene)?;
    let record_every = ((WRAP_SAMPLE_S / scene.time_step_s).round() as usize).max(1);
    let options = SimOptions { record_every, ..SimOptions::new(scene.time_step_s, ELEMENTS_PER_SIDE) };
    Ok(dynamics::simulate_resumable(&params, &profile, &options, from, keep_at_s)?)
}

/// The end tensions of the classical design check (level 0 of a duty cycle): rigid ropes, so
/// everything hanging below each tangent point moves with the conveyance:
///
/// `T1 = T1s(x)·(g + a)/g`, `T2 = T2s(x)·(g − a)/g`, with `T1s, T2s` the static tensions at the
/// travel x ([`dynamics::static_tensions_n`]: conveyance, payload, hoisting and tail ropes),
///
/// sampled along the motion profile every `output_step_s` and at its end. Returns the samples and
/// the acceleration at each. No rope stretch, no oscillation: the level-4 tensions swing about
/// these values with the ropes' first longitudinal mode.
pub fn rigid_ropes(
    design: &Design,
    hoist: &Hoist,
    scene: &DutyCycleScene,
) -> Result<(Vec<HistorySample>, Vec<f64>), Level4Error> {
    let params = hoist_params(design, hoist, scene);
    let profile = motion_profile(hoist, scene)?;
    let g = design.g_m_s2;
    let steps = (profile.duration_s() / scene.output_step_s).ceil() as usize;
    let mut samples = Vec::with_capacity(steps + 1);
    let mut accel = Vec::with_capacity(steps + 1);
    for i in 0..=steps {
        let t_s = (i as f64 * scene.output_step_s).min(profile.duration_s());
        let k = profile.at(t_s);
        let (t1s, t2s) = dynamics::static_tensions_n(&params, k.x_m)?;
        samples.push(HistorySample {
            t_s,
            t1_n: t1s * (g + k.accel_m_s2) / g,
            t2_n: t2s * (g - k.accel_m_s2) / g,
            speed_m_s: at_rest_snapped(k.speed_m_s),
        });
        accel.push(k.accel_m_s2);
    }
    Ok((samples, accel))
}

/// Speeds below 1 nm/s are round-off of a profile that has come to rest: exactly 0.
fn at_rest_snapped(speed_m_s: f64) -> f64 {
    if speed_m_s.abs() < 1e-9 { 0.0 } else { speed_m_s }
}

/// The end tensions and speed the wrap sees, per rope (the dynamics' samples as a history).
pub fn end_history(samples: &[DynSample]) -> Vec<HistorySample> {
    samples
        .iter()
        .map(|s| HistorySample { t_s: s.t_s, t1_n: s.t1_n, t2_n: s.t2_n, speed_m_s: at_rest_snapped(s.speed_m_s) })
        .collect()
}

/// Tension per rope at the two conveyance anchors at time `t_s` (N), interpolated linearly
/// between the dynamics' samples (clamped to the first and last sample).
pub fn anchors_at(samples: &[DynSample], t_s: f64) -> [f64; 2] {
    let i = samples.partition_point(|s| s.t_s <= t_s);
    match (i.checked_sub(1).and_then(|j| samples.get(j)), samples.get(i)) {
        (Some(a), Some(b)) if b.t_s > a.t_s => {
            let w = (t_s - a.t_s) / (b.t_s - a.t_s);
            [a.anchor1_n + w * (b.anchor1_n - a.anchor1_n), a.anchor2_n + w * (b.anchor2_n - a.anchor2_n)]
        }
        (Some(s), _) | (None, Some(s)) => [s.anchor1_n, s.anchor2_n],
        (None, None) => [f64::NAN, f64::NAN],
    }
}

/// The largest emergency deceleration of a duty-cycle scene with an emergency stop before gross
/// slip, and before the dynamic safety factor falls to `dynamic_safety_factor_min`, with the
/// ropes' dynamics: each trial deceleration d runs the scene's suspended ropes
/// ([`suspended_ropes`]) and takes the worst sample of the run,
///
/// `h_slip(d) = min_t [(T_lo − m'v²)·e^{μα} − (T_hi − m'v²)]`, `h_σ(d) = min_t [(T_lo − m'v²)(e^{μα} − 1) − σ_min(T_hi − T_lo)]`,
///
/// whose roots in d (Brent, on [d₀/2, 0.999 g], d₀ the scene's own deceleration: a much gentler
/// brake would run the conveyance past the end of the shaft) are the margins. `None` for a scene without
/// an emergency stop. A trial that cannot run (e.g. a hanging length reaching 0 during a long
/// stop) is a failure of that margin's search, reported as its verdict.
pub fn emergency_margins(
    design: &Design,
    hoist: &Hoist,
    scene: &DutyCycleScene,
    stats: &mut RootStats,
) -> Option<(Margin, Margin)> {
    let stop = scene.emergency?;
    let limit = euler_limit(design.pulley.mu, design.pulley.wrap_angle_rad);
    let m_v2 = design.rope.mass_per_m_kg;
    let state = |s: &DynSample| EndState {
        t1_n: s.t1_n,
        t2_n: s.t2_n,
        speed_m_s: s.speed_m_s,
        accel_m_s2: s.accel_m_s2,
        centrifugal_n: m_v2 * s.speed_m_s * s.speed_m_s,
    };
    let slip = |s: &EndState| margins::slip_residual(s, limit);
    let sf_min = design.requirements.dynamic_safety_factor_min;
    let sf = |s: &EndState| margins::sf_residual(s, limit, sf_min);
    // The motion before the brake sets in is the same for every trial: integrated once.
    let (before, checkpoint) = match resumable_ropes(design, hoist, scene, None, Some(stop.at_s)) {
        Ok((samples, Some(cp))) => (samples, cp),
        _ => return None,
    };
    let worst_before = |residual: &dyn Fn(&EndState) -> f64| {
        before.iter().filter(|s| s.t_s <= checkpoint.t_s()).map(|s| residual(&state(s))).fold(f64::INFINITY, f64::min)
    };
    let (slip_before, sf_before) = (worst_before(&slip), worst_before(&sf));
    let worst = |d: f64, residual: &dyn Fn(&EndState) -> f64, before: f64| -> f64 {
        let trial = DutyCycleScene { emergency: Some(EmergencyStop { decel_m_s2: d, ..stop }), ..scene.clone() };
        match resumable_ropes(design, hoist, &trial, Some(&checkpoint), None) {
            Ok((samples, _)) => samples.iter().map(|s| residual(&state(s))).fold(before, f64::min),
            Err(_) => f64::NAN,
        }
    };
    let (lo, hi) = (0.5 * stop.decel_m_s2, 0.999 * design.g_m_s2);
    let to_slip = margins::largest_holding(|d| worst(d, &slip, slip_before), lo, hi, stats);
    let to_sf = margins::largest_holding(|d| worst(d, &sf, sf_before), lo, hi, stats);
    Some((to_slip, to_sf))
}
