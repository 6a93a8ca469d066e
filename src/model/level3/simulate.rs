//! A level-3 run through a history: time stepping, and each increment handed to the active-set
//! solver or to clarabel (the [module doc](super) has the formulation).

use super::active_set::{ActiveSet, Problem, Termination};
use super::bending::{Bending, ContactGrid};
use super::limit::{Slide, gross_slip, sliding_field};
use super::qp::{Loads, Program, Verdict};
use super::stats::Level3Stats;
use super::{Level3Error, Params, State, normal};
use crate::model::history::HistorySample;
use crate::model::history::sample::interpolate;
use crate::model::level2::Solver;
use crate::model::numerics::Numerics;

/// A level-3 run through a history (a clone carries the state and rebuilds clarabel's workspace
/// on its first solve).
#[derive(Debug, Clone)]
pub struct Simulation<'a> {
    /// The run's parameters.
    pub params: Params,
    samples: &'a [HistorySample],
    /// Time of the current state (s).
    pub t_s: f64,
    /// The rope on the lining now.
    pub state: State,
    /// Whether the last increment slipped grossly (no admissible field).
    pub gross_slip: bool,
    /// The solver counters of the run.
    pub level3: Level3Stats,
    /// Duration of the last increment (s), for slip velocities.
    pub last_dt_s: f64,
    program: Program,
    solver: ActiveSet,
    /// Pitches the lattice moved in the last increment (its displacements start the next
    /// increment only when this one moves as far).
    last_pitches: u64,
    /// End tensions of the last increment: rope entering during the next one comes in between
    /// these and the new ones.
    last_ends_n: (f64, f64),
    x_old: Vec<f64>,
    f_old: Vec<f64>,
    scratch: Vec<f64>,
    old_tension: Vec<f64>,
    old_friction: Vec<f64>,
}

/// One increment of a run: its end sample, pulley travel (rad), rope acceleration and duration.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PlannedIncrement {
    /// The history sample at the increment's end.
    pub sample: HistorySample,
    /// Pulley travel over the increment (rad, positive in +θ).
    pub delta_rad: f64,
    /// Rope acceleration over the increment (m/s²).
    pub accel_m_s2: f64,
    /// Duration of the increment (s).
    pub dt_s: f64,
}

/// Everything an increment's solvers share.
struct Step {
    loads: Loads,
    centrifugal_n: f64,
    grid: ContactGrid,
    scale_n: f64,
}

impl<'a> Simulation<'a> {
    /// A run through `samples` from `state`; fails with fewer than two segments.
    pub fn new(params: Params, samples: &'a [HistorySample], state: State) -> Result<Self, Level3Error> {
        let n = state.segments();
        if n < 2 {
            return Err(Level3Error::Segments(n));
        }
        let program = Program::new(
            n,
            state.pitch_rad,
            params.wrap.radius_m,
            params.wrap.ea_n,
            params.shear_stiffness_n_per_m2,
            params.numerics.max_iter,
        )
        .map_err(|source| Level3Error::Solve { t_s: 0.0, source })?;
        let t_s = samples.first().map_or(0.0, |s| s.t_s);
        let last_ends_n = (state.tension_n[0], state.tension_n[n]);
        Ok(Self {
            params,
            samples,
            t_s,
            state,
            gross_slip: false,
            level3: Level3Stats::default(),
            last_dt_s: 0.0,
            program,
            solver: ActiveSet::default(),
            last_pitches: 0,
            last_ends_n,
            x_old: Vec::new(),
            f_old: Vec::new(),
            scratch: Vec::new(),
            old_tension: Vec::new(),
            old_friction: Vec::new(),
        })
    }

    /// The history sample at `t` (s), interpolated linearly.
    pub fn at(&self, t: f64) -> HistorySample {
        interpolate(self.samples, t)
    }

    /// The history the run steps through.
    pub fn samples(&self) -> &'a [HistorySample] {
        self.samples
    }

    /// Applies the first sample's ends without motion.
    pub fn settle(&mut self) -> Result<(), Level3Error> {
        let s = self.at(self.t_s);
        self.increment(&s, 0.0, 0.0, 0.0)
    }

    /// Steps to `t_end` through the increments of [`Self::plan`].
    pub fn advance_to(&mut self, t_end: f64) -> Result<(), Level3Error> {
        for step in self.plan(t_end) {
            self.increment(&step.sample, step.delta_rad, step.accel_m_s2, step.dt_s)?;
        }
        self.t_s = self.t_s.max(t_end);
        Ok(())
    }

    /// The increments from the current time to `t_end`. A sample interval is split into
    /// increments that change an end's contact force by at most [`Numerics::load_step`] of it and move the
    /// pulley at most one pitch, or, where the ends and the speed are constant over the interval
    /// (steady loading), at most [`Numerics::travel_step_rad`] when that is larger.
    ///
    /// [`Numerics::load_step`]: crate::model::numerics::Numerics::load_step
    /// [`Numerics::travel_step_rad`]: crate::model::numerics::Numerics::travel_step_rad
    pub fn plan(&self, t_end: f64) -> Vec<PlannedIncrement> {
        let radius_m = self.params.wrap.radius_m;
        let mut out = Vec::new();
        let mut t_s = self.t_s;
        while t_s < t_end {
            let k = self.samples.partition_point(|s| s.t_s <= t_s);
            let seg_end = self.samples.get(k).map_or(t_end, |s| s.t_s).min(t_end);
            let (s0, s1) = (self.at(t_s), self.at(seg_end));
            let span = seg_end - t_s;
            let travel = 0.5 * (s0.speed_m_s + s1.speed_m_s) * span / radius_m;
            let c0 = self.params.wrap.mass_per_m_kg * s0.speed_m_s.powi(2);
            let n_lo = (s0.t1_n.min(s0.t2_n) - c0).max(f64::MIN_POSITIVE);
            let load =
                (s1.t1_n - s0.t1_n).abs().max((s1.t2_n - s0.t2_n).abs()) / (self.params.numerics.load_step * n_lo);
            let steady = s0.t1_n == s1.t1_n && s0.t2_n == s1.t2_n && s0.speed_m_s == s1.speed_m_s;
            let travel_step = if steady {
                self.params.numerics.travel_step_rad.max(self.state.pitch_rad)
            } else {
                self.state.pitch_rad
            };
            let steps = (travel.abs() / travel_step).max(load).ceil().clamp(1.0, 1e6) as usize;
            let accel = if span > 0.0 { (s1.speed_m_s - s0.speed_m_s) / span } else { 0.0 };
            let mut t_prev = t_s;
            for i in 1..=steps {
                let t = if i == steps { seg_end } else { t_s + span * i as f64 / steps as f64 };
                let sample = self.at(t);
                let v_prev = self.at(t_prev).speed_m_s;
                let delta_rad = 0.5 * (v_prev + sample.speed_m_s) * (t - t_prev) / radius_m;
                out.push(PlannedIncrement { sample, delta_rad, accel_m_s2: accel, dt_s: t - t_prev });
                t_prev = t;
            }
            t_s = seg_end;
        }
        out
    }

    /// One increment: advect by `delta_rad` (pulley travel, rad), then solve for the ends of
    /// `s` at rope acceleration `accel_m_s2` over `dt_s`.
    pub fn increment(
        &mut self,
        s: &HistorySample,
        delta_rad: f64,
        accel_m_s2: f64,
        dt_s: f64,
    ) -> Result<(), Level3Error> {
        let p = self.params;
        let c = p.wrap.mass_per_m_kg * s.speed_m_s * s.speed_m_s;
        let lo = s.t1_n.min(s.t2_n);
        if lo <= c {
            return Err(Level3Error::ContactLoss { t_s: s.t_s, centrifugal_n: c, tension_n: lo });
        }
        let (entry_from, entry_to) =
            if delta_rad >= 0.0 { (self.last_ends_n.0, s.t1_n) } else { (self.last_ends_n.1, s.t2_n) };
        let pitches = self.state.advect(delta_rad, entry_from, entry_to);
        self.level3.pitches_moved += pitches;
        let n = self.state.segments();
        self.state.tension_n[0] = s.t1_n;
        self.state.tension_n[n] = s.t2_n;
        self.last_ends_n = (s.t1_n, s.t2_n);
        let bending =
            Bending::new(p.bending_stiffness_n_m2, p.wrap.radius_m, s.t1_n - c, s.t2_n - c, p.wrap.wrap_angle_rad);
        if !bending.has_contact() {
            let (a, b) = bending.contact_arc_rad();
            return Err(Level3Error::NoContact {
                t_s: s.t_s,
                lift_off_deg: (a.to_degrees(), (p.wrap.wrap_angle_rad - b).to_degrees()),
            });
        }
        let inertia = if p.rope_inertia {
            p.wrap.mass_per_m_kg * p.wrap.radius_m * self.state.pitch_rad * accel_m_s2
        } else {
            0.0
        };
        let step = Step {
            loads: Loads { t1_n: s.t1_n, t2_n: s.t2_n, inertia_n: inertia, mu: p.wrap.mu },
            centrifugal_n: c,
            grid: bending.on_lattice(n),
            scale_n: s.t1_n.max(s.t2_n),
        };
        self.state.touch_lining(|k| step.grid.lining_share(k));
        self.gross_slip = false;
        match p.wrap.solver {
            Solver::Fast => self.solve_fast(&step, s.t_s, pitches)?,
            Solver::Clarabel => self.solve_clarabel(&step, s.t_s)?,
        }
        self.last_pitches = pitches;
        self.level3.increments += 1;
        if self.gross_slip {
            self.level3.gross_slip_increments += 1;
        }
        self.last_dt_s = dt_s;
        Ok(())
    }

    /// The old tensions and lining forces of the (advected) state, scaled by the step's scale.
    fn scale_old(&mut self, step: &Step) {
        let s = step.scale_n;
        self.x_old.clear();
        self.x_old.extend(self.state.tension_n.iter().map(|t| t / s));
        self.f_old.clear();
        self.f_old.extend(self.state.friction_n.iter().map(|f| f / s));
    }

    /// The active-set solver; gross slip when it finds no field and the bound chains agree;
    /// clarabel when it does not converge on an admissible state.
    fn solve_fast(&mut self, step: &Step, t_s: f64, pitches: u64) -> Result<(), Level3Error> {
        // The last increment's displacements start this one: as they are when the lattice moved
        // as far (steady rolling repeats itself, load steps at rest resemble each other), scaled
        // by the travel when it moved a different number of pitches, none after a standstill.
        if pitches != self.last_pitches {
            if pitches == 0 || self.last_pitches == 0 {
                self.solver.v.clear();
            } else {
                let ratio = pitches as f64 / self.last_pitches as f64;
                self.solver.v.iter_mut().for_each(|v| *v *= ratio);
            }
        }
        let mut solver = std::mem::take(&mut self.solver);
        let mut scratch = std::mem::take(&mut self.scratch);
        self.scale_old(step);
        let problem = problem(&self.x_old, &self.f_old, step, self.state.pitch_rad, self.program.rho());
        let (termination, steps) = solver.solve(&problem);
        let slide = if termination == Termination::Converged { None } else { gross_slip(&problem, &mut scratch) };
        if let Some(slide) = slide {
            sliding_field(&problem, slide, &mut solver.x, &mut solver.normal, &mut solver.f);
        }
        let (rh, ea, rho) = (self.params.wrap.radius_m * self.state.pitch_rad, self.params.wrap.ea_n, problem.rho);
        self.level3.active_set.record(termination);
        self.level3.newton_steps += u64::from(steps);
        self.level3.max_newton_steps = self.level3.max_newton_steps.max(steps);
        let converged = termination == Termination::Converged;
        if converged || slide.is_some() {
            let s = step.scale_n;
            // Slip of each lining slider, s_k = (R h s/EA)(v_k − ρ (f°_k − f_k)/w_k); none where the
            // rope is off the lining.
            for (k, out) in self.state.slip_m.iter_mut().enumerate() {
                let share = step.grid.lining_share(k);
                *out = if converged && share > 0.0 {
                    rh * s / ea * (solver.v[k] - rho * (self.f_old[k] - solver.f[k]) / share)
                } else {
                    0.0
                };
            }
            self.state.set_scaled(s, &solver.x, &solver.normal, &solver.f);
            if converged && solver.active == 0 {
                self.level3.elastic_increments += 1;
            }
        }
        if !converged {
            solver.v.clear();
        }
        self.solver = solver;
        self.scratch = scratch;
        self.gross_slip = slide.is_some();
        if converged || slide.is_some() {
            return Ok(());
        }
        self.level3.handed_to_clarabel += 1;
        self.solve_clarabel(step, t_s)
    }

    /// clarabel with the fixed point on the contact forces: the program is solved with N of the
    /// state before the increment, then again with N of its solution until N agrees.
    fn solve_clarabel(&mut self, step: &Step, t_s: f64) -> Result<(), Level3Error> {
        let c = step.centrifugal_n;
        let h = self.state.pitch_rad;
        self.old_tension.clone_from(&self.state.tension_n);
        self.old_friction.clone_from(&self.state.friction_n);
        let mut used = std::mem::take(&mut self.state.normal_n);
        let mut next = std::mem::take(&mut self.scratch);
        normal::normal_forces(&self.state.tension_n, c, h, &step.grid, &mut used);
        let shares: Vec<f64> = (0..self.state.segments()).map(|k| step.grid.lining_share(k)).collect();
        for pass in 1.. {
            if pass > self.params.numerics.max_normal_passes {
                return Err(Level3Error::NormalForces { t_s, passes: self.params.numerics.max_normal_passes });
            }
            self.level3.max_clarabel_solves = self.level3.max_clarabel_solves.max(pass);
            // Each pass starts from the state before the increment.
            self.state.tension_n.copy_from_slice(&self.old_tension);
            self.state.friction_n.copy_from_slice(&self.old_friction);
            let verdict = self
                .program
                .solve(&mut self.state, &step.loads, &used, &shares)
                .map_err(|source| Level3Error::Solve { t_s, source })?;
            self.level3.clarabel.record(verdict);
            if verdict == Verdict::Infeasible {
                self.state.tension_n.copy_from_slice(&self.old_tension);
                self.state.friction_n.copy_from_slice(&self.old_friction);
                match self.after_infeasible(step) {
                    // Gross slip: the state holds the sliding field.
                    None => {
                        self.scratch = next;
                        return Ok(());
                    }
                    // The program was infeasible only for the contact forces it was given.
                    Some(seed) => {
                        used = seed;
                        self.level3.normal_force_passes += 1;
                        continue;
                    }
                }
            }
            normal::normal_forces(&self.state.tension_n, c, h, &step.grid, &mut next);
            let settled = settled(&self.state.friction_n, &used, &next, step.loads.mu, &self.params.numerics);
            std::mem::swap(&mut used, &mut next);
            if settled {
                break;
            }
            self.level3.fixed_point_passes += 1;
            self.level3.normal_force_passes += 1;
        }
        // Coulomb exactly: clarabel's interior point meets an active bound to its tolerance.
        for (f, nk) in self.state.friction_n.iter_mut().zip(&used) {
            let cap = step.loads.mu * nk;
            *f = f.clamp(-cap, cap);
        }
        self.state.normal_n = used;
        self.scratch = next;
        self.solver.v.clear();
        Ok(())
    }

    /// clarabel found no admissible field for the contact forces it was given. The bound chains
    /// decide: gross slip (the sliding field is written to the state, `None`), or an admissible
    /// field exists for the forces of the chain at the bound in the direction of the net load,
    /// which are returned for the next pass (with them the program is feasible: that chain's
    /// friction is at least the end difference).
    fn after_infeasible(&mut self, step: &Step) -> Option<Vec<f64>> {
        let (mut x, mut nn, mut f, mut scratch) = (Vec::new(), Vec::new(), Vec::new(), Vec::new());
        self.scale_old(step);
        let problem = problem(&self.x_old, &self.f_old, step, self.state.pitch_rad, self.program.rho());
        let slide = gross_slip(&problem, &mut scratch);
        let net = problem.x_first - problem.x_last + problem.iota * problem.segments() as f64;
        let towards = if net >= 0.0 { Slide::TowardsSide1 } else { Slide::TowardsSide2 };
        sliding_field(&problem, slide.unwrap_or(towards), &mut x, &mut nn, &mut f);
        let s = step.scale_n;
        if slide.is_none() {
            return Some(nn.iter().map(|v| v * s).collect());
        }
        self.state.set_scaled(s, &x, &nn, &f);
        self.state.slip_m.fill(0.0);
        self.gross_slip = true;
        self.solver.v.clear();
        None
    }
}

/// The scaled problem of an increment from the scaled old state `x_old`, `f_old`.
fn problem<'b>(x_old: &'b [f64], f_old: &'b [f64], step: &'b Step, pitch_rad: f64, rho: f64) -> Problem<'b> {
    let s = step.scale_n;
    Problem {
        x_old,
        f_old,
        x_first: step.loads.t1_n / s,
        x_last: step.loads.t2_n / s,
        iota: step.loads.inertia_n / s,
        centrifugal: step.centrifugal_n / s,
        mu: step.loads.mu,
        pitch_rad,
        rho,
        grid: &step.grid,
        inv_scale: 1.0 / s,
    }
}

/// Whether a clarabel solution found with the contact forces `used` is the fixed point for the
/// forces `new` of its own tensions. Only segments at the Coulomb bound see N in the optimality
/// conditions: there N must agree to [`Numerics::normal_tolerance`] (a segment within
/// [`Numerics::active_gap`] of its bound is at it); a segment inside the bound stays a solution
/// of the same program as long as it is inside the new bound too.
fn settled(friction_n: &[f64], used: &[f64], new: &[f64], mu: f64, numerics: &Numerics) -> bool {
    friction_n.iter().zip(used).zip(new).all(|((f, a), b)| {
        let at_bound = f.abs() >= mu * a * (1.0 - numerics.active_gap);
        if at_bound { (a - b).abs() <= numerics.normal_tolerance * b.abs() } else { f.abs() < mu * b }
    })
}
