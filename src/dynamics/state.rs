//! The integrator's state and what a run records of it: the options of a run, each side's
//! state with its coefficients, the checkpoint a run continues from, the recorded samples, and
//! the step of both sides to the coefficients of an instant ([`super::sweep::step_pair`]). The
//! runners ([`super::simulate`], the two-thread [`super::split`] and the braked stop) build on
//! these.

use serde::Serialize;

use super::rope::{Coeffs, SideState};
use super::{DynamicsError, HoistParams, Side, damping_coefficient_s};

/// Options of a run beyond the time step and the mesh.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SimOptions {
    /// Time step, s (the last step is shortened to end exactly at the profile's end).
    pub dt_s: f64,
    /// Finite elements per side (≥ 1).
    pub elements: usize,
    /// Keep every `record_every`-th step (the first and the last sample are always kept; 0 is
    /// taken as 1).
    pub record_every: usize,
    /// Initial elastic displacement of each end mass added to the static equilibrium (side 1,
    /// side 2), m, with the static shape of an extra end force (linear along the rope): starts
    /// a free vibration. Zero for the usual start in static equilibrium.
    pub initial_offset_m: [f64; 2],
    /// Whether to keep the energy balance (`energy_j`, `work_j`, `dissipated_j` of the samples; 0
    /// without).
    pub energy: bool,
    /// Whether to step the two sides on two threads (without the energy balance only): the
    /// same numbers, in about half the time when a second core is idle.
    pub parallel_sides: bool,
}

impl SimOptions {
    /// `dt_s`, `elements`, every step recorded, start in equilibrium, the energy balance kept.
    pub fn new(dt_s: f64, elements: usize) -> Self {
        Self { dt_s, elements, record_every: 1, initial_offset_m: [0.0; 2], energy: true, parallel_sides: false }
    }
}

/// One recorded instant of a run.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct DynSample {
    /// Time from the start of the run, s.
    pub t_s: f64,
    /// Pulley surface travel, m.
    pub x_m: f64,
    /// Pulley surface speed, m/s (v > 0 lifts side 1).
    pub speed_m_s: f64,
    /// Pulley surface acceleration, m/s².
    pub accel_m_s2: f64,
    /// Tension per rope at the side-1 tangent point, N.
    pub t1_n: f64,
    /// Tension per rope at the side-2 tangent point, N.
    pub t2_n: f64,
    /// Tension per rope at the side-1 conveyance (its anchor: it carries the conveyance and the
    /// tail rope below it), N.
    pub anchor1_n: f64,
    /// Tension per rope at the side-2 anchor, N.
    pub anchor2_n: f64,
    /// Tension per rope halfway down the side-1 hanging rope, N.
    pub mid1_n: f64,
    /// Tension per rope halfway down the side-2 hanging rope, N.
    pub mid2_n: f64,
    /// Elastic elongation of the side-1 ropes at the conveyance (downward displacement of the
    /// conveyance relative to the rigid motion), m.
    pub stretch1_m: f64,
    /// The same for side 2, m.
    pub stretch2_m: f64,
    /// Mechanical energy of the motion relative to the rigid (pulley-driven) motion, both sides:
    /// `Σ ½vᵀMv + ½qᵀKq − Fᵀq` (kinetic, strain, and the potential of the weight and the
    /// inertial load of the prescribed acceleration), J. 0 in a run without the energy balance
    /// ([`SimOptions::energy`] false), as `work_j` and `dissipated_j` are.
    pub energy_j: f64,
    /// Work done on the relative motion since the start by the prescribed motion: the changing
    /// length (rope entering or leaving a side changes M and K) and the changing loads (jerk,
    /// tail weight), `∫ (½q̇ᵀṀq̇ + ½qᵀK̇q − Ḟᵀq) dt`, J. Undamped: `energy_j − energy₀ = work_j`.
    pub work_j: f64,
    /// Energy dissipated by the rope damping since the start, `∫ q̇ᵀCq̇ dt`, J.
    pub dissipated_j: f64,
}

#[derive(Debug, Clone, PartialEq)]
pub(super) struct Side2 {
    pub side: Side,
    pub state: SideState,
    pub coeffs: Coeffs,
}

/// The integrator's state after one step of a run. A run over a profile that agrees with the
/// first one up to that instant (the same stages, time step and mesh: e.g. emergency stops
/// setting in at the same time with different decelerations) continues from it instead of
/// integrating that stretch again; the result is the same to the last bit.
#[derive(Debug, Clone, PartialEq)]
pub struct Checkpoint {
    pub(super) step: usize,
    pub(super) t_s: f64,
    pub(super) dt_s: f64,
    pub(super) elements: usize,
    pub(super) sides: Vec<Side2>,
    pub(super) work_j: f64,
    pub(super) dissipated_j: f64,
}

impl Checkpoint {
    /// Time of the step it was taken at, s.
    pub fn t_s(&self) -> f64 {
        self.t_s
    }

    /// The step it was taken after (0: the start).
    pub fn step(&self) -> usize {
        self.step
    }
}

/// Coefficients of a side at time `t_s` for the kinematics `x_m`, `accel_m_s2`.
pub(super) fn coeffs(
    p: &HoistParams,
    side: Side,
    n: usize,
    t_s: f64,
    x_m: f64,
    accel_m_s2: f64,
) -> Result<Coeffs, DynamicsError> {
    let (length_m, end_mass_kg) = p.side_at(side, x_m, Some(t_s))?;
    // a_s: downward rigid acceleration of the side's rope (a_1 = −ẍ, a_2 = +ẍ)
    let a_s = side.down_sign() * accel_m_s2;
    Ok(Coeffs::new(p, n, length_m, end_mass_kg, p.g_m_s2 - a_s, damping_coefficient_s(p, length_m, end_mass_kg)))
}

/// [`coeffs`] at a travel between the extremes of a profile whose lengths there are checked
/// ([`step_count`]): the lengths are linear in the travel, so they hold between, unchecked.
pub(super) fn coeffs_within(p: &HoistParams, side: Side, n: usize, x_m: f64, accel_m_s2: f64) -> Coeffs {
    let (length_m, end_mass_kg) = (p.hanging_length_m(side, x_m), p.end_mass_kg(side, x_m));
    debug_assert!(
        length_m > 0.0 && (p.tail_ropes == 0 || p.tail_length_m(side, x_m) >= 0.0),
        "a length beyond the profile's checks"
    );
    let a_s = side.down_sign() * accel_m_s2;
    Coeffs::new(p, n, length_m, end_mass_kg, p.g_m_s2 - a_s, damping_coefficient_s(p, length_m, end_mass_kg))
}

/// The instant step `step` of `steps` ends at: `step·dt`, the last at exactly `total_s`.
pub(super) fn step_time_s(step: usize, steps: usize, dt_s: f64, total_s: f64) -> f64 {
    if step == steps { total_s } else { (step as f64 * dt_s).min(total_s) }
}

/// The recorded sample of the sides' state at `t_s` with the pulley's kinematics `k` and the
/// run's `(work_j, dissipated_j)`; its energy only where the run keeps the energy balance
/// (`energy`), 0 elsewhere as the balance's other terms are.
pub(super) fn sample_of(
    p: &HoistParams,
    t_s: f64,
    k: super::Kinematics,
    sides: &[Side2],
    (work_j, dissipated_j): (f64, f64),
    energy: bool,
) -> DynSample {
    sample_from(p, t_s, k, [SideSample::of(&sides[0], energy), SideSample::of(&sides[1], energy)], work_j, dissipated_j)
}

/// What a sample takes from one side's state (totals of all its ropes).
#[derive(Debug, Clone, Copy)]
pub(super) struct SideSample {
    top_n: f64,
    anchor_n: f64,
    mid_n: f64,
    stretch_m: f64,
    energy_j: f64,
}

impl SideSample {
    /// The side's totals; its energy only with `energy` (0 without, as the work and the
    /// dissipation of a run without the energy balance are).
    pub(super) fn of(s: &Side2, energy: bool) -> Self {
        Self {
            top_n: s.state.top_tension_n(&s.coeffs),
            anchor_n: s.state.anchor_tension_n(&s.coeffs),
            mid_n: s.state.mid_tension_n(&s.coeffs),
            stretch_m: s.state.end_stretch_m(),
            energy_j: if energy { s.coeffs.energy_j(&s.state.q, &s.state.v) } else { 0.0 },
        }
    }
}

/// The sample of two sides' [`SideSample`]s (tensions per rope).
pub(super) fn sample_from(
    p: &HoistParams,
    t_s: f64,
    k: super::Kinematics,
    sides: [SideSample; 2],
    work_j: f64,
    dissipated_j: f64,
) -> DynSample {
    let ropes = p.ropes as f64;
    let [a, b] = sides;
    DynSample {
        t_s,
        x_m: k.x_m,
        speed_m_s: k.speed_m_s,
        accel_m_s2: k.accel_m_s2,
        t1_n: a.top_n / ropes,
        t2_n: b.top_n / ropes,
        anchor1_n: a.anchor_n / ropes,
        anchor2_n: b.anchor_n / ropes,
        mid1_n: a.mid_n / ropes,
        mid2_n: b.mid_n / ropes,
        stretch1_m: a.stretch_m,
        stretch2_m: b.stretch_m,
        energy_j: [a.energy_j, b.energy_j].iter().sum::<f64>(),
        work_j,
        dissipated_j,
    }
}

/// Steps both sides by `h` to the coefficients of time `t` at travel `x_m` and rigid acceleration
/// `accel_m_s2` ([`super::sweep::step_pair`]); returns the work and the dissipation of the step
/// (0 without `energy`).
pub(super) fn step_sides(
    p: &HoistParams,
    sides: &mut [Side2],
    t: f64,
    x_m: f64,
    accel_m_s2: f64,
    h: f64,
    energy: bool,
) -> Result<(f64, f64), DynamicsError> {
    let [a, b] = &sides[..] else { return Err(DynamicsError::NoElements) };
    let n = a.state.q.len();
    let c = [coeffs(p, a.side, n, t, x_m, accel_m_s2)?, coeffs(p, b.side, n, t, x_m, accel_m_s2)?];
    step_sides_to(sides, c, t, h, energy)
}

/// [`step_sides`] to the coefficients `c` of the step's end at `t`.
pub(super) fn step_sides_to(
    sides: &mut [Side2],
    [c0, c1]: [Coeffs; 2],
    t: f64,
    h: f64,
    energy: bool,
) -> Result<(f64, f64), DynamicsError> {
    let [s0, s1] = sides else {
        return Err(DynamicsError::NoElements);
    };
    let [(w0, d0), (w1, d1)] =
        super::sweep::step_pair([(&mut s0.state, &s0.coeffs, &c0), (&mut s1.state, &s1.coeffs, &c1)], h, energy);
    (s0.coeffs, s1.coeffs) = (c0, c1);
    if !(s0.state.is_finite() && s1.state.is_finite()) {
        return Err(DynamicsError::Diverged { t_s: t });
    }
    Ok((w0 + w1, d0 + d1))
}
