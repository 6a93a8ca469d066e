//! Arc measures and demarcation points of a wrap, tallied stretch by stretch in θ order: the
//! positive, reverse and idle arcs, the runs of each sign of friction, every demarcation (a
//! positive run that a reverse run follows) and the principal one, the JDP, chosen by a rule
//! that does not depend on the frame (docs/physics.md, JDP).

use std::cell::Cell;

/// Sign class of friction on a stretch of wrap.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
enum Sign {
    #[default]
    Neutral = 0,
    Reverse = 1,
    Positive = 2,
}

/// Arc measures and the demarcation points, accumulated stretch by stretch in θ order (shared
/// by every summary of the wrap).
#[derive(Debug, Default, Clone)]
pub struct ArcTally {
    /// Measure of each [`Sign`] class (indexed by its discriminant).
    measure_rad: [f64; 3],
    /// The runs of one sign of friction, in θ order (idle stretches between them are gaps),
    /// but the last one, `open`.
    runs: Vec<SignRun>,
    /// The run the last stretch of friction belongs to, apart so that a stretch that extends it
    /// writes three words and reads no vector; of sign `open_sign` (`Neutral`: no run yet).
    open: SignRun,
    open_sign: Sign,
    /// The end of the last stretch added: the wrap angle once the whole wrap is tallied.
    extent_rad: f64,
    /// What the runs' ends ([`SignRun::end_at`]) hold: the stretches of one tally are of one kind.
    ends: TensionAt,
    /// The end of the last stretch of positive friction, above the arc threshold or not (rad).
    last_positive_rad: f64,
    /// The start of the first stretch of reverse friction since the last stretch of positive
    /// friction above the arc threshold (rad); NaN where none has come since.
    first_reverse_rad: f64,
}

thread_local! {
    /// The run buffer of the thread's last finished tally, for its next ([`ArcTally::new`]).
    static SPARE_RUNS: Cell<Vec<SignRun>> = const { Cell::new(Vec::new()) };
    /// The demarcations of the thread's last summary, once used ([`ArcTally::recycle`]).
    static SPARE_MARKS: Cell<Vec<Demarcation>> = const { Cell::new(Vec::new()) };
}

impl Drop for ArcTally {
    fn drop(&mut self) {
        if self.runs.capacity() > 0 {
            SPARE_RUNS.set(std::mem::take(&mut self.runs));
        }
    }
}

/// A run of friction of one sign above the arc threshold: idle stretches inside it count
/// towards its extent, not its measure. Small (no piece inside), since a run's end moves with
/// every stretch added to it.
#[derive(Debug, Clone, Copy, Default)]
struct SignRun {
    start_rad: f64,
    end_rad: f64,
    measure_rad: f64,
    /// The tension at the run's start (N), evaluated when the run starts; NaN where the
    /// stretches gave none.
    start_tension_n: f64,
    /// For a reverse run that a positive run precedes, where q changes sign between them (rad):
    /// the end of the last stretch of positive friction before the run and the start of the
    /// first stretch of reverse friction after the positive run ([`Demarcation::sign_change_rad`]).
    sign_change_rad: (f64, f64),
    /// Where the tension at the run's end comes from, as the tally's [`TensionAt`] reads it: a
    /// piece's index or a tension's bits (one word written as the run grows; evaluated only
    /// for the runs' ends that the next run does not start at, and only where there are two
    /// demarcations or more to choose from).
    end_at: u64,
    positive: bool,
}

/// Where the tension at a run's end is known from: a piece of the summarized state by its index
/// (evaluated at the run's end by the caller's [`HeldTension`]), a value, or nowhere (the
/// stretches gave none).
#[derive(Debug, Clone, Copy, Default)]
enum TensionAt {
    /// Not given.
    #[default]
    Unknown,
    /// The tension of the state's piece whose index is the run's `end_at`.
    Held,
    /// The tension (N) whose bits are the run's `end_at`.
    Value,
}

/// The tension of the summarized state's piece `i` at θ (rad), for [`ArcTally::add_held`].
pub type HeldTension<'h> = &'h dyn Fn(usize, f64) -> f64;

impl TensionAt {
    fn value(self, at: u64, theta_rad: f64, held: Option<HeldTension>) -> Option<f64> {
        match self {
            Self::Held => Some(held.expect("held tensions are resolved by their summary")(at as usize, theta_rad)),
            Self::Value => Some(f64::from_bits(at)),
            Self::Unknown => None,
        }
    }
}

/// A demarcation: where friction changes sign between a positive run and the reverse run after
/// it (downstream, in +θ), found on the stretches themselves: the last point of positive
/// friction before the reverse run, `a`, and the first point of reverse friction after the
/// positive run, `b`. Where q jumps or crosses zero, `a = b`; where a stick gap holds q = 0
/// exactly between them, the gap is [a, b] and the demarcation its middle. (Where sub-threshold
/// friction alternates inside the idle stretch, `b < a`: the gap is then [b, a].) The mirror
/// θ → α − θ maps a to the mirrored wrap's b and b to its a, so the gap and its middle mirror
/// exactly.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Demarcation {
    /// The demarcation point as reported (rad): the middle of [`Self::gap_rad`].
    pub at_rad: f64,
    /// `(a, b)`: the end of the last positive friction before the reverse run and the start of
    /// the first reverse friction after the positive run (rad); both `at_rad` where q changes
    /// sign at a point.
    pub sign_change_rad: (f64, f64),
    /// What the runs beside it carry: the tension change over the positive run before it plus
    /// that over the reverse run after it (N), the friction each run holds; where the stretches
    /// gave no tensions, their measures (rad).
    pub weight: f64,
}

impl Demarcation {
    /// The demarcation where the last positive friction ends at `a` and the first reverse
    /// friction starts at `b` (rad), unweighed: the gap between them and its middle.
    pub fn of_sign_change((a, b): (f64, f64)) -> Self {
        Self { at_rad: 0.5 * (a + b), sign_change_rad: (a, b), weight: 0.0 }
    }

    /// Where q is zero between the last positive and the first reverse friction,
    /// `[start, end]` (rad): the sign change's ends in θ order.
    pub fn gap_rad(&self) -> (f64, f64) {
        let (a, b) = self.sign_change_rad;
        (a.min(b), a.max(b))
    }
}

impl ArcTally {
    /// An empty tally that reuses the run buffer of the thread's last finished tally (a history
    /// summarizes its wrap at every row, and a wrap striped by its load history holds a hundred
    /// runs and more: allocating that buffer anew for every row cost more than tallying).
    pub fn new() -> Self {
        let mut runs = SPARE_RUNS.take();
        runs.clear();
        Self {
            measure_rad: [0.0; 3],
            runs,
            open: SignRun::default(),
            open_sign: Sign::Neutral,
            extent_rad: 0.0,
            ends: TensionAt::Unknown,
            last_positive_rad: f64::NAN,
            first_reverse_rad: f64::NAN,
        }
    }

    /// Adds the stretch [start, end] where friction has the sign `sign` (1, −1, or 0 where it
    /// is zero throughout) and is `above` the arc threshold (0.001 μn) or not; the demarcations
    /// are weighed by the runs' measures.
    pub fn add(&mut self, start: f64, end: f64, above: bool, sign: i8) {
        self.add_with((start, end), above, sign, || f64::NAN, (TensionAt::Unknown, 0));
    }

    /// [`Self::add`] of a stretch of the state's piece `i`: the demarcations are weighed by the
    /// friction the runs beside them hold, the tension change over each (`start_tension`, the
    /// piece's tension at `start`, evaluated where the stretch starts a run; where a run ends,
    /// the piece is evaluated by [`Self::demarcations_held`]).
    #[inline(always)]
    pub fn add_held(
        &mut self,
        (start, end): (f64, f64),
        above: bool,
        sign: i8,
        i: usize,
        start_tension: impl FnOnce() -> f64,
    ) {
        self.add_with((start, end), above, sign, start_tension, (TensionAt::Held, i as u64));
    }

    /// [`Self::add`] with the tensions at the stretch's ends (N), as [`Self::add_held`].
    pub fn add_valued(&mut self, start: f64, end: f64, above: bool, sign: i8, tensions: (f64, f64)) {
        let end_at = (TensionAt::Value, tensions.1.to_bits());
        self.add_with((start, end), above, sign, || tensions.0, end_at);
    }

    /// Adds a stretch; `start_tension` is evaluated only where the stretch starts a run; `end_at`
    /// says where the tension at the stretch's end comes from.
    #[inline(always)]
    fn add_with(
        &mut self,
        (start, end): (f64, f64),
        above: bool,
        friction_sign: i8,
        start_tension: impl FnOnce() -> f64,
        (ends, end_at): (TensionAt, u64),
    ) {
        if end <= start {
            return;
        }
        let positive = friction_sign > 0;
        if positive {
            self.last_positive_rad = end;
            if above {
                self.first_reverse_rad = f64::NAN;
            }
        } else if friction_sign < 0 && self.first_reverse_rad.is_nan() {
            self.first_reverse_rad = start;
        }
        let sign = match u8::from(above) << u8::from(positive) {
            0 => Sign::Neutral,
            1 => Sign::Reverse,
            _ => Sign::Positive,
        };
        self.measure_rad[sign as usize] += end - start;
        // In θ order: the last end is the farthest.
        self.extent_rad = end;
        if sign == Sign::Neutral {
            return;
        }
        if sign == self.open_sign {
            self.open.end_rad = end;
            self.open.measure_rad += end - start;
            self.open.end_at = end_at;
        } else {
            if self.open_sign != Sign::Neutral {
                self.runs.push(self.open);
            }
            // A reverse run after a positive one: q changed sign between them.
            let first_reverse = if self.first_reverse_rad.is_nan() { start } else { self.first_reverse_rad };
            self.open = SignRun {
                start_rad: start,
                end_rad: end,
                measure_rad: end - start,
                sign_change_rad: (self.last_positive_rad, first_reverse),
                start_tension_n: start_tension(),
                end_at,
                positive: sign == Sign::Positive,
            };
            (self.open_sign, self.ends) = (sign, ends);
        }
    }

    /// Ends the tally: the open run joins the others (a stretch added after it starts a run of
    /// its own).
    fn close(&mut self) {
        if self.open_sign != Sign::Neutral {
            self.runs.push(self.open);
            self.open_sign = Sign::Neutral;
        }
    }

    /// Each positive run with the reverse run that follows it, in θ order, by the index of the
    /// positive one: runs alternate in sign (a stretch of the last run's sign extends it), so
    /// every other run from the first positive one.
    fn demarcation_pairs(&self) -> impl Iterator<Item = usize> + '_ {
        let first = usize::from(self.runs.first().is_some_and(|r| !r.positive));
        (first..self.runs.len().saturating_sub(1)).step_by(2)
    }

    /// Every demarcation, in θ order: each positive run that a reverse run follows. Their
    /// weights are worked out only where there is a choice, two or more (a lone demarcation
    /// weighs 0): a run's end that no run starts at costs an evaluation of its piece.
    pub fn demarcations(&mut self) -> Vec<Demarcation> {
        self.demarcations_held(None)
    }

    /// [`Self::demarcations`] of a tally whose stretches were added by [`Self::add_held`]:
    /// `tension` evaluates the state's pieces. The list comes from the thread's spare one;
    /// [`Self::recycle`] hands it back once used.
    pub fn demarcations_held(&mut self, tension: Option<HeldTension>) -> Vec<Demarcation> {
        self.close();
        let runs = &self.runs;
        let mut marks = SPARE_MARKS.take();
        marks.clear();
        marks.extend(self.demarcation_pairs().map(|k| Demarcation::of_sign_change(runs[k + 1].sign_change_rad)));
        if marks.len() > 1 {
            self.weigh(&mut marks, tension);
        }
        marks
    }

    /// Weighs `marks`, made from this tally's runs in θ order: the tension change over each of
    /// the two runs beside a demarcation, or where the stretches gave no tensions, their measures.
    /// The tension is continuous: where a run ends at the angle the next one starts, the next
    /// one's start tension is its end's, so each boundary costs one evaluation at most.
    fn weigh(&self, marks: &mut [Demarcation], tension: Option<HeldTension>) {
        let runs = &self.runs;
        let start = |k: usize| runs[k].start_tension_n;
        let end = |k: usize| match runs.get(k + 1) {
            Some(next) if next.start_rad == runs[k].end_rad => next.start_tension_n,
            _ => self.ends.value(runs[k].end_at, runs[k].end_rad, tension).unwrap_or(f64::NAN),
        };
        for (d, k) in marks.iter_mut().zip(self.demarcation_pairs()) {
            let (p, r) = (&runs[k], &runs[k + 1]);
            let boundary = end(k);
            let r_start = if r.start_rad == p.end_rad { boundary } else { start(k + 1) };
            let held = (start(k) - boundary).abs() + (end(k + 1) - r_start).abs();
            // NaN where a tension was not given.
            d.weight = if held.is_nan() { p.measure_rad + r.measure_rad } else { held };
        }
    }

    /// Hands `marks` back for the thread's next [`Self::demarcations`] once the summary is made.
    pub fn recycle(marks: Vec<Demarcation>) {
        SPARE_MARKS.set(marks);
    }

    /// The principal one of `demarcations` (of this wrap, made by [`Self::demarcations`]).
    pub fn principal_of(&self, demarcations: &[Demarcation]) -> Option<Demarcation> {
        principal(demarcations, self.extent_rad)
    }

    /// Measure of the positive arc so far (rad).
    pub fn positive_rad(&self) -> f64 {
        self.measure_rad[Sign::Positive as usize]
    }

    /// Measure of the reverse arc so far (rad).
    pub fn reverse_rad(&self) -> f64 {
        self.measure_rad[Sign::Reverse as usize]
    }

    /// Measure of the idle arc so far, where |q| stays below 0.001 μn (rad).
    pub fn idle_rad(&self) -> f64 {
        self.measure_rad[Sign::Neutral as usize]
    }

    /// The JDP: the [`principal`] demarcation's point (rad from the side-1 tangent point);
    /// `None` where reverse friction never follows positive.
    pub fn jdp_rad(&mut self) -> Option<f64> {
        let marks = self.demarcations();
        self.principal_of(&marks).map(|d| d.at_rad)
    }
}

/// "The" JDP among several demarcations, by a rule that does not depend on the frame (the
/// mirror θ → α − θ, T1 ↔ T2 maps each demarcation to one of the mirrored wrap's, the runs
/// beside it swapping roles): the one whose runs hold the most friction (the largest
/// [`Demarcation::weight`]), so that faint stripes of friction left behind by the load history
/// do not take it from the main positive and reverse zones; of equal ones (to 1e-6 of the
/// largest), the one nearest the middle of the wrap (`extent_rad` = α; each one's point is the
/// middle of its sign change's gap);
/// of two mirror images of each other, the one at the smaller θ.
pub fn principal(demarcations: &[Demarcation], extent_rad: f64) -> Option<Demarcation> {
    // Equal within what mirrored wraps agree to: their tensions to 1e-8, their arcs to 1e-6°.
    let heaviest =
        (0..demarcations.len()).reduce(|m, k| if demarcations[k].weight > demarcations[m].weight { k } else { m });
    let same = 1e-6 * heaviest.map_or(0.0, |m| demarcations[m].weight.max(0.0));
    let off_middle = |d: &Demarcation| (d.at_rad - 0.5 * extent_rad).abs();
    // Where no other demarcation comes within `same` of the heaviest, the rule below picks it:
    // found in one pass without the comparisons' branches (a striped wrap holds a hundred).
    if let Some(m) = heaviest {
        let top = demarcations[m].weight;
        if demarcations.iter().filter(|d| d.weight >= top - same).count() == 1 {
            return Some(demarcations[m]);
        }
    }
    demarcations.iter().copied().reduce(|best, d| {
        if d.weight > best.weight + same
            || ((d.weight - best.weight).abs() <= same && off_middle(&d) < off_middle(&best) - 1e-7)
        {
            d
        } else {
            best
        }
    })
}

#[cfg(test)]
mod demarcation_tests;
