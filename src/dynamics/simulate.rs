//! Time integration of both sides over a motion profile.

use serde::Serialize;

use super::rope::{Coeffs, SideState};
use super::{DynamicsError, HoistParams, MotionProfile, Side, damping_coefficient_s};

/// Upper limit of time steps of one run (guards against a time step far too small).
const MAX_STEPS: usize = 200_000_000;

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

/// [`simulate_with`] with every step recorded and the start in static equilibrium.
pub fn simulate(
    p: &HoistParams,
    profile: &MotionProfile,
    dt_s: f64,
    elements: usize,
) -> Result<Vec<DynSample>, DynamicsError> {
    simulate_with(p, profile, &SimOptions::new(dt_s, elements))
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
fn coeffs_within(p: &HoistParams, side: Side, n: usize, x_m: f64, accel_m_s2: f64) -> Coeffs {
    let (length_m, end_mass_kg) = (p.hanging_length_m(side, x_m), p.end_mass_kg(side, x_m));
    debug_assert!(
        length_m > 0.0 && (p.tail_ropes == 0 || p.tail_length_m(side, x_m) >= 0.0),
        "a length beyond the profile's checks"
    );
    let a_s = side.down_sign() * accel_m_s2;
    Coeffs::new(p, n, length_m, end_mass_kg, p.g_m_s2 - a_s, damping_coefficient_s(p, length_m, end_mass_kg))
}

/// Simulates the rope dynamics of both sides over the profile (model and scheme: see the module
/// documentation). Starts in static equilibrium at `x = 0` (plus `initial_offset_m`) and steps
/// the trapezoidal rule with `dt_s` to the end of the profile.
///
/// Errors: invalid parameters, `dt_s` not finite and > 0, zero elements, a hanging length
/// reaching 0 or a tail length going negative during the profile (checked at every step and at
/// the stage ends and turning points of `x`), a non-finite solution.
pub fn simulate_with(
    p: &HoistParams,
    profile: &MotionProfile,
    opt: &SimOptions,
) -> Result<Vec<DynSample>, DynamicsError> {
    simulate_resumable(p, profile, opt, None, None).map(|(samples, _)| samples)
}

/// [`simulate_with`], starting from `from` (a checkpoint of a run with the same time step and
/// mesh whose profile agrees with `profile` up to the checkpoint; the samples then start at the
/// checkpoint's instant) and keeping a checkpoint at the last step strictly before `keep_at_s`
/// (at the last step, the end of the profile, when `keep_at_s` is at or beyond it).
pub fn simulate_resumable(
    p: &HoistParams,
    profile: &MotionProfile,
    opt: &SimOptions,
    from: Option<&Checkpoint>,
    keep_at_s: Option<f64>,
) -> Result<(Vec<DynSample>, Option<Checkpoint>), DynamicsError> {
    simulate_streamed(p, profile, opt, from, keep_at_s, &mut |_| {})
}

/// Samples handed on together by [`simulate_streamed`].
pub const STREAM_CHUNK: usize = 64;

/// [`simulate_resumable`], handing the samples to `sink` as they are made, [`STREAM_CHUNK`] at a
/// time and the rest at the end, in order (with `opt.parallel_sides`, all at the end): another
/// thread can work through them while the run goes on. The samples returned are the same.
pub fn simulate_streamed(
    p: &HoistParams,
    profile: &MotionProfile,
    opt: &SimOptions,
    from: Option<&Checkpoint>,
    keep_at_s: Option<f64>,
    sink: &mut dyn FnMut(&[DynSample]),
) -> Result<(Vec<DynSample>, Option<Checkpoint>), DynamicsError> {
    let steps = step_count(p, profile, opt)?;
    let (dt, n, total_s) = (opt.dt_s, opt.elements, profile.duration_s());
    let every = opt.record_every.max(1);
    let mut sides = initial_sides(p, profile, opt)?;
    let (mut work_j, mut dissipated_j) = (0.0, 0.0);
    let (mut t_prev, mut first_step) = (0.0, 1);
    if let Some(cp) = from.filter(|cp| cp.dt_s == dt && cp.elements == n && cp.step < steps) {
        sides = cp.sides.clone();
        (work_j, dissipated_j, t_prev, first_step) = (cp.work_j, cp.dissipated_j, cp.t_s, cp.step + 1);
    }
    let keep_step = keep_at_s.and_then(|t| keep_step(t, total_s, dt, steps));
    if opt.parallel_sides && !opt.energy {
        let plan = super::split::Plan { first_step, t_prev_s: t_prev, steps, keep_step, work_j, dissipated_j };
        let run = super::split::run(p, profile, opt, sides, plan)?;
        crate::tally::add_increments((steps + 1 - first_step) as u64);
        sink(&run.0);
        return Ok(run);
    }
    let mut out = Vec::with_capacity((steps + 1 - first_step) / every + 2);
    out.push(sample_of(p, t_prev, profile.at(t_prev), &sides, (work_j, dissipated_j), opt.energy));
    let mut run = Stepping { sides, work_j, dissipated_j, t_prev };
    let mut kept = (keep_step == Some(first_step - 1)).then(|| run.checkpoint(first_step - 1, opt));
    let mut sent = 0;
    run.steps(p, profile, opt, (first_step..=steps, steps), &mut out, &mut |step, run, out| {
        if out.len() - sent >= STREAM_CHUNK {
            sink(&out[sent..]);
            sent = out.len();
        }
        if keep_step == Some(step) {
            kept = Some(run.checkpoint(step, opt));
        }
    })?;
    if out.len() > sent {
        sink(&out[sent..]);
    }
    crate::tally::add_increments((steps + 1 - first_step) as u64);
    Ok((out, kept))
}

/// The start of a run over `profile` (from static equilibrium, on one thread) up to the last of
/// `keep_steps` (each before the run's last step; ascending), keeping a checkpoint at each:
/// the stretch that runs over profiles agreeing with `profile` up to those steps share
/// ([`MotionProfile::agrees_until`]); each continues from its checkpoint
/// ([`simulate_resumable`]). Returns the samples up to the last step kept (those of the whole
/// run, bit for bit) and the checkpoints.
pub fn simulate_prefix(
    p: &HoistParams,
    profile: &MotionProfile,
    opt: &SimOptions,
    keep_steps: &[usize],
) -> Result<(Vec<DynSample>, Vec<Checkpoint>), DynamicsError> {
    let steps = step_count(p, profile, opt)?;
    let last = keep_steps.iter().copied().filter(|k| *k < steps).max().unwrap_or(0);
    let sides = initial_sides(p, profile, opt)?;
    let mut out = Vec::with_capacity(last / opt.record_every.max(1) + 2);
    out.push(sample_of(p, 0.0, profile.at(0.0), &sides, (0.0, 0.0), opt.energy));
    let mut run = Stepping { sides, work_j: 0.0, dissipated_j: 0.0, t_prev: 0.0 };
    let mut kept: Vec<Checkpoint> = keep_steps.contains(&0).then(|| run.checkpoint(0, opt)).into_iter().collect();
    run.steps(p, profile, opt, (1..=last, steps), &mut out, &mut |step, run, _| {
        if keep_steps.contains(&step) {
            kept.push(run.checkpoint(step, opt));
        }
    })?;
    crate::tally::add_increments(last as u64);
    Ok((out, kept))
}

/// The integrator's state between steps of a sequential run.
struct Stepping {
    sides: Vec<Side2>,
    work_j: f64,
    dissipated_j: f64,
    /// The instant of the last step, s.
    t_prev: f64,
}

impl Stepping {
    /// The checkpoint of the state after step `step`.
    fn checkpoint(&self, step: usize, opt: &SimOptions) -> Checkpoint {
        Checkpoint {
            step,
            t_s: self.t_prev,
            dt_s: opt.dt_s,
            elements: opt.elements,
            sides: self.sides.clone(),
            work_j: self.work_j,
            dissipated_j: self.dissipated_j,
        }
    }

    /// Steps `range` of a run of `steps` steps, recording every `record_every`-th (and the last)
    /// into `out`; `after` sees the state after each step.
    fn steps(
        &mut self,
        p: &HoistParams,
        profile: &MotionProfile,
        opt: &SimOptions,
        (range, steps): (std::ops::RangeInclusive<usize>, usize),
        out: &mut Vec<DynSample>,
        after: &mut dyn FnMut(usize, &Self, &mut Vec<DynSample>),
    ) -> Result<(), DynamicsError> {
        let (dt, total_s, every) = (opt.dt_s, profile.duration_s(), opt.record_every.max(1));
        let mut motion = profile.cursor();
        for step in range {
            let t = step_time_s(step, steps, dt, total_s);
            let h = t - self.t_prev;
            if h <= 0.0 {
                continue;
            }
            let kin = motion.at(t);
            // The travel stays between the profile's extremes, whose lengths `step_count` checked.
            let [a, b] = &self.sides[..] else { return Err(DynamicsError::NoElements) };
            let c = [a, b].map(|s| coeffs_within(p, s.side, s.state.q.len(), kin.x_m, kin.accel_m_s2));
            let (w, d) = step_sides_to(&mut self.sides, c, t, h, opt.energy)?;
            self.work_j += w;
            self.dissipated_j += d;
            self.t_prev = t;
            if step % every == 0 || step == steps {
                out.push(sample_of(p, t, kin, &self.sides, (self.work_j, self.dissipated_j), opt.energy));
            }
            after(step, self, out);
        }
        Ok(())
    }
}

/// The instant step `step` of `steps` ends at: `step·dt`, the last at exactly `total_s`.
pub(super) fn step_time_s(step: usize, steps: usize, dt_s: f64, total_s: f64) -> f64 {
    if step == steps { total_s } else { (step as f64 * dt_s).min(total_s) }
}

/// The instants of the samples a run from the start of a profile of `duration_s` records
/// ([`simulate_streamed`], without a checkpoint): the start, every `record_every`-th step and
/// the last, the steps as the run takes them.
pub fn recorded_times(duration_s: f64, opt: &SimOptions) -> Vec<f64> {
    let (dt, every) = (opt.dt_s, opt.record_every.max(1));
    let steps = (duration_s / dt).ceil() as usize;
    let mut out = vec![0.0];
    let mut t_prev = 0.0;
    for step in 1..=steps {
        let t = step_time_s(step, steps, dt, duration_s);
        if t - t_prev <= 0.0 {
            continue;
        }
        t_prev = t;
        if step % every == 0 || step == steps {
            out.push(t);
        }
    }
    out
}

/// Checks the parameters, the time step, the mesh, the initial offsets and the rope lengths at
/// the extremes of the travel (exact, between the steps too), and returns the number of steps.
fn step_count(p: &HoistParams, profile: &MotionProfile, opt: &SimOptions) -> Result<usize, DynamicsError> {
    p.validate()?;
    let dt = opt.dt_s;
    if !(dt.is_finite() && dt > 0.0) {
        return Err(DynamicsError::TimeStep { dt_s: dt });
    }
    if opt.elements == 0 {
        return Err(DynamicsError::NoElements);
    }
    for (k, off) in opt.initial_offset_m.iter().enumerate() {
        super::finite(
            if k == 0 { "the initial rope offset of side 1" } else { "the initial rope offset of side 2" },
            *off,
        )?;
    }
    for t in profile.x_extreme_times() {
        let x = profile.at(t).x_m;
        for side in Side::BOTH {
            p.side_at(side, x, Some(t))?;
        }
    }
    let steps_f = (profile.duration_s() / dt).ceil();
    if steps_f > MAX_STEPS as f64 {
        return Err(DynamicsError::TooManySteps { steps: steps_f, limit: MAX_STEPS });
    }
    Ok(steps_f as usize)
}

/// Both sides at t = 0: in equilibrium under the loads at rest, then under the loads of t = 0 (a
/// step stage may start with a non-zero acceleration), displaced by the initial offsets.
fn initial_sides(p: &HoistParams, profile: &MotionProfile, opt: &SimOptions) -> Result<Vec<Side2>, DynamicsError> {
    let n = opt.elements;
    let k0 = profile.at(0.0);
    let mut sides: Vec<Side2> = Vec::with_capacity(2);
    for (k, side) in Side::BOTH.into_iter().enumerate() {
        let rest = coeffs(p, side, n, 0.0, 0.0, 0.0)?;
        let mut state = SideState::at_equilibrium(&rest, n);
        let c = coeffs(p, side, n, 0.0, k0.x_m, k0.accel_m_s2)?;
        state.displace(&c, opt.initial_offset_m[k]);
        sides.push(Side2 { side, state, coeffs: c });
    }
    Ok(sides)
}

/// The step a checkpoint is kept at: the last one strictly before `keep_at_s` (at that instant
/// a stage that steps in may already act); a time at or beyond the end keeps the final state.
fn keep_step(keep_at_s: f64, total_s: f64, dt: f64, steps: usize) -> Option<usize> {
    if keep_at_s.is_nan() || keep_at_s <= 0.0 {
        return None;
    }
    if keep_at_s >= total_s {
        return Some(steps);
    }
    let mut k = ((keep_at_s / dt).ceil() as usize).saturating_sub(1);
    while k > 0 && k as f64 * dt >= keep_at_s {
        k -= 1;
    }
    while ((k + 1) as f64 * dt) < keep_at_s {
        k += 1;
    }
    Some(k)
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
/// `accel_m_s2` ([`super::rope::step_pair`]); returns the work and the dissipation of the step
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
fn step_sides_to(
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
        super::rope::step_pair([(&mut s0.state, &s0.coeffs, &c0), (&mut s1.state, &s1.coeffs, &c1)], h, energy);
    (s0.coeffs, s1.coeffs) = (c0, c1);
    if !(s0.state.is_finite() && s1.state.is_finite()) {
        return Err(DynamicsError::Diverged { t_s: t });
    }
    Ok((w0 + w1, d0 + d1))
}
