//! A duty cycle on the rigid lining with its wrap run beside its suspended ropes: the ropes step
//! on a thread of their own and hand their samples over as they make them, and the wrap
//! (level 2) works through them as they come, instead of waiting for the whole trip.
//!
//! The sequential run fixes two things from the whole end history before the wrap starts: the
//! spacing of the m'v² lattice ([`level2::lattice::centrifugal_step_n`]: the larger of a
//! fraction of the largest end tension and a fraction of the largest m'v²) and the end of the
//! trip (at the onset of gross slip, or where a rope goes slack). The run beside the ropes
//! takes the spacing from the largest m'v² of the motion profile at the samples' instants (the
//! tensions' share is far smaller on a hoist: 1e-6 of the tension against 1e-3 of m'v²) and the
//! profile's end, and its result is kept only when the whole history confirms both
//! ([`Beside::confirmed`]): it is then the sequential run's to the last bit; otherwise the wrap
//! runs again through the confirmed history.

use crate::design::{Design, Direction, DutyCycleScene, HistorySample, Hoist, Scene};
use crate::dynamics::{self, DynSample, MotionProfile, SimOptions};
use crate::model::Level;
use crate::model::history::{self, HistoryRun, Output};
use crate::model::level0::EndState;
use crate::model::level2::{Simulation, lattice};
use crate::model::level4::{self, Level4Error, RopeRun};
use crate::model::numerics::Numerics;
use crate::plan::{self, Plan};
use crate::run::wrap_run::{Initial, level2_initial, rolling_initial};
use crate::run::{Options, params};
use std::sync::mpsc;

/// The ropes' run and the wrap's run made beside it.
pub(in crate::run) struct Beside {
    /// The suspended ropes' run (the same as [`level4::scene_ropes`]'s).
    ropes: RopeRun,
    wrap: Option<HistoryRun>,
    /// The m'v² lattice spacing the wrap ran with (N).
    centrifugal_step_n: f64,
    /// Samples the wrap was handed.
    fed: usize,
}

impl Beside {
    /// The ropes' run, and the wrap's run still to be confirmed.
    pub fn split(self) -> (RopeRun, Unconfirmed) {
        let Self { ropes, wrap, centrifugal_step_n, fed } = self;
        (ropes, Unconfirmed { wrap, centrifugal_step_n, fed })
    }
}

/// The wrap's run beside the ropes, before the whole history confirms it.
pub(in crate::run) struct Unconfirmed {
    wrap: Option<HistoryRun>,
    centrifugal_step_n: f64,
    fed: usize,
}

impl Unconfirmed {
    /// The wrap's run when the whole end history `samples` (the trip's valid part, from
    /// `ropes_len` samples of the ropes) confirms what it ran on: all of the ropes' samples (no
    /// gross slip ended the trip early; a slack rope is refused before) and the lattice spacing
    /// of the whole history (from its largest end tension and the profile's largest m'v²,
    /// `centrifugal_max_n`, as the run after the ropes spaces it). It is then the run through
    /// `samples` to the last bit.
    pub fn confirmed(self, samples: &[HistorySample], ropes_len: usize, centrifugal_max_n: f64) -> Option<HistoryRun> {
        let spacing = lattice::spacing_n(samples, centrifugal_max_n, &Numerics::default());
        let whole = samples.len() == ropes_len && self.fed == samples.len();
        self.wrap.filter(|_| whole && spacing == self.centrifugal_step_n)
    }
}

/// Whether a duty cycle's wrap can run beside its ropes: the wrap at level 2 (the rigid
/// lining), the hoist's motion (not a stop by the `[brake]`), no rope elements to follow, and
/// a core to spare.
pub(in crate::run) fn applies(
    design: &Design,
    scene: &Scene,
    cycle: &DutyCycleScene,
    plan: &Plan,
    spare_core: bool,
) -> bool {
    let rigid = design.lining.is_none() && plan::wrap_level(plan, false) == Level::Rigid2;
    spare_core && rigid && cycle.brake_stop_s.is_none() && scene.tracks.is_none()
}

/// Runs the ropes of `cycle` on a thread of their own and the wrap through their samples as
/// they come; `profile` is the trip's motion ([`level4::motion_profile`]), the rope running the
/// other way before it. The ropes' thread then makes `also`'s result, while the wrap works
/// through the last samples.
pub(in crate::run) fn run<R: Send>(
    design: &Design,
    (hoist, cycle): (&Hoist, &DutyCycleScene),
    profile: &MotionProfile,
    options: Options,
    output: Output,
    also: impl FnOnce() -> R + Send,
) -> (Result<Beside, Level4Error>, R) {
    let direction_before = cycle.direction.reversed();
    let (tx, rx) = mpsc::channel::<Vec<DynSample>>();
    let (ropes, (wrap_run, centrifugal_step_n)) = std::thread::scope(|s| {
        let producer = s.spawn(move || {
            let ropes = level4::scene_ropes_streamed(design, hoist, cycle, &mut |chunk| {
                // A wrap that stopped early no longer listens; the ropes run on.
                let _ = tx.send(chunk.to_vec());
            });
            drop(tx);
            (ropes, also())
        });
        // The samples' instants and the lattice spacing are worked out while the ropes make
        // their first samples.
        let instants = sample_instants(cycle, profile);
        let centrifugal_step_n = spacing_from_profile(design, profile, &instants);
        let lattice = (centrifugal_step_n, profile.duration_s(), &instants[..]);
        let wrap_run = wrap_beside(design, &rx, direction_before, lattice, options, output);
        drop(rx);
        (producer.join(), (wrap_run, centrifugal_step_n))
    });
    let (ropes, also) = ropes.unwrap_or_else(|panic| std::panic::resume_unwind(panic));
    let (wrap, fed) = match wrap_run {
        Some((run, fed)) => (Some(run), fed),
        None => (None, 0),
    };
    (ropes.map(|ropes| Beside { ropes, wrap, centrifugal_step_n, fed }), also)
}

/// The wrap through the samples from `rx`, with the lattice spacing given; `None` when the
/// history stops before it has two samples or the wrap fails (the confirmed history then
/// decides, run again). Returns the run and the number of samples it was handed.
fn wrap_beside(
    design: &Design,
    rx: &mpsc::Receiver<Vec<DynSample>>,
    direction_before: Direction,
    (centrifugal_step_n, t_end_s, instants): (f64, f64, &[f64]),
    options: Options,
    output: Output,
) -> Option<(HistoryRun, usize)> {
    let first = rx.recv().ok()?;
    let s0 = *first.first()?;
    let samples = level4::end_history(&first);
    let start = EndState::of_sample(&samples[0], s0.accel_m_s2, design.rope.mass_per_m_kg);
    let rolling = rolling_initial(design, &start, direction_before);
    let initial = level2_initial(design, Initial::of(&rolling, start, direction_before));
    let mut fed = samples.len();
    let sim = Simulation::growing(params(design, options.solver), samples, initial, centrifugal_step_n);
    let mut next = || {
        let chunk = rx.recv().ok()?;
        fed += chunk.len();
        Some(level4::end_history(&chunk))
    };
    let range = (s0.t_s, t_end_s, instants);
    // The ropes hold the other core: the rows' summaries are made in place.
    let (run, _) = history::run_growing(sim, &mut next, range, output, options.nodes, false).ok()?;
    Some((run, fed))
}

/// The instants of the samples the ropes will make (those of [`dynamics::simulate_streamed`]:
/// the start, every `record_every`-th step and the end).
fn sample_instants(cycle: &DutyCycleScene, profile: &MotionProfile) -> Vec<f64> {
    let every = ((level4::WRAP_SAMPLE_S / cycle.time_step_s).round() as usize).max(1);
    let opt = SimOptions { record_every: every, ..SimOptions::new(cycle.time_step_s, level4::ELEMENTS_PER_SIDE) };
    dynamics::recorded_times(profile.duration_s(), &opt)
}

/// The m'v² lattice spacing of the samples the ropes will make, from the motion profile at
/// their `instants`, with the tensions' share left out.
fn spacing_from_profile(design: &Design, profile: &MotionProfile, instants: &[f64]) -> f64 {
    let c_max = profile_centrifugal_max_n(design.rope.mass_per_m_kg, profile, instants.iter().copied());
    Numerics::default().centrifugal_step_of_range * c_max
}

/// The largest m'v² (N) of a motion profile at `instants` (beyond its end, the profile's at
/// its end: a stop by the `[brake]` goes on from there), speeds at rest snapped to 0 as the
/// end history has them ([`level4::at_rest_snapped`]): it spaces a duty cycle's m'v² lattice,
/// so that trips that agree up to an instant step alike up to it whatever speed their own
/// stop reaches after it.
pub(in crate::run) fn profile_centrifugal_max_n(
    mass_per_m_kg: f64,
    profile: &MotionProfile,
    instants: impl Iterator<Item = f64>,
) -> f64 {
    let end = profile.duration_s();
    let c = |t: f64| {
        let v = level4::at_rest_snapped(profile.at(t.min(end)).speed_m_s);
        mass_per_m_kg * v * v
    };
    instants.map(c).fold(0.0, f64::max)
}
