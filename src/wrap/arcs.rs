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
mod demarcation_tests {
    use super::*;

    /// Tallies `(start, end, sign)` stretches (sign +1, −1 or 0 for idle), in θ order.
    fn tally(stretches: &[(f64, f64, i8)]) -> ArcTally {
        let mut t = ArcTally::default();
        for &(a, b, s) in stretches {
            t.add(a, b, s != 0, s);
        }
        t
    }

    /// The mirror θ → α − θ with the friction's sign flipped: the stretches in reverse order.
    fn mirrored(stretches: &[(f64, f64, i8)], alpha: f64) -> Vec<(f64, f64, i8)> {
        stretches.iter().rev().map(|&(a, b, s)| (alpha - b, alpha - a, -s)).collect()
    }

    /// Friction + − + − over α = 3: positive [0, 0.2], reverse [0.2, 0.9], positive [0.9, 2.5],
    /// reverse [2.5, 3]. Two demarcations, at 0.2 (runs 0.2 + 0.7 = 0.9 rad) and at 2.5 (runs
    /// 1.6 + 0.5 = 2.1 rad): the JDP is 2.5, the one between the longer runs. Mirrored, the
    /// demarcations are 3 − 2.5 = 0.5 and 3 − 0.2 = 2.8 and the JDP 0.5 = 3 − 2.5: the same
    /// demarcation in both frames (reading from θ = 0 took 0.2 here and 0.5 in the mirror).
    #[test]
    fn the_jdp_of_alternating_friction_is_the_same_point_in_both_frames() {
        let alpha = 3.0;
        let field = [(0.0, 0.2, 1), (0.2, 0.9, -1), (0.9, 2.5, 1), (2.5, 3.0, -1)];
        let mut t = tally(&field);
        let at: Vec<f64> = t.demarcations().iter().map(|d| d.at_rad).collect();
        assert_eq!(at, vec![0.2, 2.5]);
        assert_eq!(t.jdp_rad(), Some(2.5));
        let mut m = tally(&mirrored(&field, alpha));
        let at_m: Vec<f64> = m.demarcations().iter().map(|d| d.at_rad).collect();
        assert!((at_m[0] - 0.5).abs() < 1e-15 && (at_m[1] - 2.8).abs() < 1e-15, "{at_m:?}");
        assert!((m.jdp_rad().expect("a JDP") - (alpha - 2.5)).abs() < 1e-15);
    }

    /// With a stick gap [1.0, 1.4] (q = 0 exactly) between positive [0, 1.0] and reverse
    /// [1.4, 3]: the JDP is the gap's middle, 1.2; in the mirror the gap is [1.6, 2.0] and its
    /// JDP 1.8 = 3 − 1.2, the same point. Where the idle stretch holds faint friction of each
    /// sign instead (+ on [1.0, 1.1], − on [1.1, 1.3], + on [1.3, 1.4]), the sign changes between
    /// the last positive friction (1.4) and the first reverse (1.1): the gap [1.1, 1.4] and its
    /// middle 1.25, in the mirror [1.6, 1.9] and 1.75. Equal weights (runs 0.5 + 0.5 either side
    /// of α/2 = 1.5): the demarcation nearer the middle wins, in both frames.
    #[test]
    fn a_stick_gap_and_equal_runs_choose_the_same_demarcation() {
        let alpha = 3.0;
        let gap = [(0.0, 1.0, 1), (1.0, 1.4, 0), (1.4, 3.0, -1)];
        let marks = tally(&gap).demarcations();
        assert_eq!(marks[0].gap_rad(), (1.0, 1.4));
        assert!((marks[0].at_rad - 1.2).abs() < 1e-15, "{marks:?}");
        let marks = tally(&mirrored(&gap, alpha)).demarcations();
        assert!((marks[0].gap_rad().0 - 1.6).abs() < 1e-15 && (marks[0].gap_rad().1 - 2.0).abs() < 1e-15);
        assert!((marks[0].at_rad - 1.8).abs() < 1e-15, "{marks:?}");
        // Faint friction of both signs in the idle stretch: stretches below the arc threshold.
        let faint = |t: &mut ArcTally, stretches: &[(f64, f64, i8)]| {
            for &(a, b, s) in stretches {
                t.add(a, b, a == 0.0 || b == alpha, s);
            }
        };
        let striped = [(0.0, 1.0, 1), (1.0, 1.1, 1), (1.1, 1.3, -1), (1.3, 1.4, 1), (1.4, 3.0, -1)];
        let mut t = ArcTally::default();
        faint(&mut t, &striped);
        let marks = t.demarcations();
        assert_eq!(marks.len(), 1);
        assert_eq!(marks[0].gap_rad(), (1.1, 1.4));
        assert!((marks[0].at_rad - 1.25).abs() < 1e-15);
        let mut m = ArcTally::default();
        faint(&mut m, &mirrored(&striped, alpha));
        let marks = m.demarcations();
        assert!((marks[0].gap_rad().0 - 1.6).abs() < 1e-15 && (marks[0].gap_rad().1 - 1.9).abs() < 1e-15);
        assert!((marks[0].at_rad - 1.75).abs() < 1e-15, "{marks:?}");
        // + − idle + −: demarcations at 0.5 (runs 0.5 + 0.5, gap middle 0.5, 1.0 from α/2) and
        // at 2.1 (runs 0.5 + 0.5, middle 2.1, 0.6 from α/2): the second is nearer the middle.
        let equal = [(0.0, 0.5, 1), (0.5, 1.0, -1), (1.0, 1.6, 0), (1.6, 2.1, 1), (2.1, 2.6, -1), (2.6, 3.0, 0)];
        assert_eq!(tally(&equal).jdp_rad(), Some(2.1));
        let m = tally(&mirrored(&equal, alpha)).jdp_rad().expect("a JDP");
        assert!((m - (alpha - 2.1)).abs() < 1e-15, "{m}");
    }

    /// Weights from the tensions: runs + (T 100 → 80), − (80 → 95), + (95 → 60), − (60 → 70)
    /// over [0, 1], [1, 2], [2, 3], [3, 4], each run made of two stretches. By hand the
    /// demarcation at 1 weighs |80 − 100| + |95 − 80| = 35 N and the one at 3 weighs
    /// |60 − 95| + |70 − 60| = 45 N: the JDP is 3 (by the runs' measures, 2 rad each, they tie
    /// and the one nearer the middle, α/2 = 2, would be taken: 1 and 3 are equally far, so the
    /// first). With an idle gap [1, 1.5] before the first reverse run (its start now at
    /// T = 82), the first weighs |80 − 100| + |95 − 82| = 33 N.
    #[test]
    fn demarcations_are_weighed_by_the_tension_change_over_their_runs() {
        let runs: [(f64, f64, f64, i8); 4] =
            [(0.0, 100.0, 80.0, 1), (1.0, 80.0, 95.0, -1), (2.0, 95.0, 60.0, 1), (3.0, 60.0, 70.0, -1)];
        let weights = |gap: bool| {
            let mut t = ArcTally::new();
            for &(a, t0, t1, s) in &runs {
                let (a, t0) = if gap && a == 1.0 {
                    t.add(1.0, 1.5, false, -1);
                    (1.5, 82.0)
                } else {
                    (a, t0)
                };
                let (b, tm) = (a.floor() + 1.0, 0.5 * (t0 + t1));
                t.add_valued(a, 0.5 * (a + b), true, s, (t0, tm));
                t.add_valued(0.5 * (a + b), b, true, s, (tm, t1));
            }
            let marks = t.demarcations();
            (marks.iter().map(|d| (d.at_rad, d.weight)).collect::<Vec<_>>(), t.jdp_rad())
        };
        let (marks, jdp) = weights(false);
        assert_eq!(marks, vec![(1.0, 35.0), (3.0, 45.0)]);
        assert_eq!(jdp, Some(3.0));
        let (marks, _) = weights(true);
        assert_eq!(marks[0], (1.0, 33.0));
        assert!(tally(&[(0.0, 1.0, 1), (1.0, 2.0, -1), (2.0, 3.0, 1), (3.0, 4.0, -1)]).jdp_rad() == Some(1.0));
    }

    /// Tallies made one after another on a thread reuse the last one's buffers: each lists
    /// only its own runs and demarcations (a wrap of five demarcations, then one of one, and
    /// one of none; the lists handed back in between).
    #[test]
    fn a_tally_after_another_holds_only_its_own_runs() {
        let mut striped = ArcTally::new();
        for k in 0..10 {
            let sign = if k % 2 == 0 { 1 } else { -1 };
            striped.add_held((k as f64, k as f64 + 1.0), true, sign, k, || 1e5 - 1e3 * k as f64);
        }
        let tension = |i: usize, theta: f64| 1e5 - 1e3 * i as f64 - 10.0 * theta;
        let marks = striped.demarcations_held(Some(&tension));
        assert_eq!(marks.iter().map(|d| d.at_rad).collect::<Vec<_>>(), vec![1.0, 3.0, 5.0, 7.0, 9.0]);
        ArcTally::recycle(marks);
        drop(striped);
        let mut plain = ArcTally::new();
        plain.add_held((0.0, 2.0), true, 1, 0, || 1e5);
        plain.add_held((2.0, 3.0), false, 0, 1, || 1e5);
        plain.add_held((3.0, 4.0), true, -1, 2, || 1e5);
        let marks = plain.demarcations_held(Some(&tension));
        assert_eq!(marks, vec![Demarcation { at_rad: 2.5, sign_change_rad: (2.0, 3.0), weight: 0.0 }]);
        assert_eq!((plain.positive_rad(), plain.idle_rad(), plain.reverse_rad()), (2.0, 1.0, 1.0));
        ArcTally::recycle(marks);
        drop(plain);
        let mut none = ArcTally::new();
        none.add_held((0.0, 4.0), true, -1, 0, || 1e5);
        assert!(none.demarcations_held(Some(&tension)).is_empty());
    }

    /// The principal demarcation against the rule stated step by step (the reduce of
    /// [`principal`]'s doc, written out here on its own) over 20 000 lists of up to 12
    /// demarcations whose weights are drawn from a few values and nudged within and beyond the
    /// 1e-6 tolerance (ties, near ties and clear winners), at random places.
    #[test]
    fn the_principal_demarcation_follows_the_stated_rule() {
        let rule = |ds: &[Demarcation], alpha: f64| {
            let same = 1e-6 * ds.iter().map(|d| d.weight).fold(0.0, f64::max);
            let off = |d: &Demarcation| (d.at_rad - 0.5 * alpha).abs();
            let mut best: Option<Demarcation> = None;
            for &d in ds {
                best = Some(match best {
                    None => d,
                    Some(b) if d.weight > b.weight + same => d,
                    Some(b) if (d.weight - b.weight).abs() <= same && off(&d) < off(&b) - 1e-7 => d,
                    Some(b) => b,
                });
            }
            best
        };
        let mut seed = 0x9e37_79b9_7f4a_7c15_u64;
        let mut draw = move || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed >> 11) as f64 / (1u64 << 53) as f64
        };
        for _ in 0..20_000 {
            let n = (draw() * 13.0) as usize;
            let ds: Vec<Demarcation> = (0..n)
                .map(|_| {
                    let at = draw() * 3.0;
                    let base = [1.0e4, 2.0e4, 2.0e4][(draw() * 3.0) as usize];
                    let nudge = [0.0, 0.4e-6, 0.9e-6, 1.1e-6, 1e-3][(draw() * 5.0) as usize];
                    let gap = 0.1 * draw();
                    Demarcation {
                        at_rad: at + 0.5 * gap,
                        sign_change_rad: (at, at + gap),
                        weight: base * (1.0 + nudge),
                    }
                })
                .collect();
            assert_eq!(principal(&ds, 3.0), rule(&ds, 3.0), "{ds:?}");
        }
    }
}
