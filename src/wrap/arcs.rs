//! Arc measures and demarcation points of a wrap, tallied stretch by stretch in θ order: the
//! positive, reverse and idle arcs, the runs of each sign of friction, every demarcation (a
//! positive run that a reverse run follows) and the principal one, the JDP, chosen by a rule
//! that does not depend on the frame (docs/physics.md, JDP).

use super::piece::Piece;

/// Sign class of friction on a stretch of wrap.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Sign {
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
    /// The runs of one sign of friction, in θ order (idle stretches between them are gaps).
    runs: Vec<SignRun>,
    /// The end of the last stretch added: the wrap angle once the whole wrap is tallied.
    extent_rad: f64,
}

/// A run of friction of one sign above the arc threshold: idle stretches inside it count
/// towards its extent, not its measure.
#[derive(Debug, Clone, Copy)]
struct SignRun {
    positive: bool,
    start_rad: f64,
    end_rad: f64,
    measure_rad: f64,
    /// Where the tension at the run's start and end comes from, when the stretches gave it.
    start_tension: Option<TensionAt>,
    end_tension: Option<TensionAt>,
}

/// A tension known lazily: a piece to evaluate at an angle, a piece of the summarized state by
/// its index (evaluated by the caller's [`HeldTension`]), or a value. A run's end is known only
/// when the next run starts, so the piece is kept and evaluated only for the runs' ends, two
/// per run, and only where there are two demarcations or more to choose from.
#[derive(Debug, Clone, Copy)]
pub enum TensionAt {
    /// The piece's tension at the angle (rad).
    Piece(Piece, f64),
    /// The tension of the state's piece `.0` at the angle `.1` (rad).
    Held(usize, f64),
    /// A tension (N).
    Value(f64),
}

/// The tension of the summarized state's piece `i` at θ (rad), for [`TensionAt::Held`].
pub type HeldTension<'h> = &'h dyn Fn(usize, f64) -> f64;

impl TensionAt {
    fn value(self, held: Option<HeldTension>) -> f64 {
        match self {
            Self::Piece(p, theta) => p.tension_n(theta),
            Self::Held(i, theta) => held.expect("held tensions are resolved by their summary")(i, theta),
            Self::Value(t) => t,
        }
    }
}

/// A demarcation: where a positive run ends and the reverse run after it (downstream, in +θ)
/// starts, with an idle gap between them or none.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Demarcation {
    /// The end of the positive run (rad): the demarcation point as reported.
    pub at_rad: f64,
    /// The start of the reverse run (rad); `at_rad` without a gap.
    pub gap_end_rad: f64,
    /// What the runs beside it carry: the tension change over the positive run before it plus
    /// that over the reverse run after it (N), the friction each run holds; where the stretches
    /// gave no tensions, their measures (rad).
    pub weight: f64,
}

impl ArcTally {
    /// An empty tally with room for a few runs (most wraps hold a handful).
    pub fn new() -> Self {
        Self { runs: Vec::with_capacity(8), ..Self::default() }
    }

    /// Adds the stretch [start, end] where friction has the sign of `positive` and is
    /// `above` the arc threshold (0.001 μn) or not; the demarcations are weighed by the runs'
    /// measures.
    pub fn add(&mut self, start: f64, end: f64, above: bool, positive: bool) {
        self.add_with(start, end, above, positive, None);
    }

    /// [`Self::add`] of a stretch of `piece`: the demarcations are weighed by the friction the
    /// runs beside them hold, the tension change over each.
    #[inline]
    pub fn add_piece(&mut self, start: f64, end: f64, above: bool, positive: bool, piece: &Piece) {
        let ends = (TensionAt::Piece(*piece, start), TensionAt::Piece(*piece, end));
        self.add_with(start, end, above, positive, Some(ends));
    }

    /// [`Self::add`] of a stretch of the state's piece `i` (resolved by
    /// [`Self::demarcations_held`]).
    #[inline]
    pub fn add_held(&mut self, start: f64, end: f64, above: bool, positive: bool, i: usize) {
        self.add_with(start, end, above, positive, Some((TensionAt::Held(i, start), TensionAt::Held(i, end))));
    }

    /// [`Self::add`] with the tensions at the stretch's ends (N), as [`Self::add_piece`].
    pub fn add_valued(&mut self, start: f64, end: f64, above: bool, positive: bool, tensions: (f64, f64)) {
        let ends = (TensionAt::Value(tensions.0), TensionAt::Value(tensions.1));
        self.add_with(start, end, above, positive, Some(ends));
    }

    #[inline(always)]
    fn add_with(&mut self, start: f64, end: f64, above: bool, positive: bool, ends: Option<(TensionAt, TensionAt)>) {
        if end <= start {
            return;
        }
        let sign = match u8::from(above) << u8::from(positive) {
            0 => Sign::Neutral,
            1 => Sign::Reverse,
            _ => Sign::Positive,
        };
        self.measure_rad[sign as usize] += end - start;
        self.extent_rad = self.extent_rad.max(end);
        if sign == Sign::Neutral {
            return;
        }
        let positive = sign == Sign::Positive;
        match self.runs.last_mut() {
            Some(run) if run.positive == positive => {
                run.end_rad = end;
                run.measure_rad += end - start;
                run.end_tension = ends.map(|e| e.1);
            }
            _ => self.runs.push(SignRun {
                positive,
                start_rad: start,
                end_rad: end,
                measure_rad: end - start,
                start_tension: ends.map(|e| e.0),
                end_tension: ends.map(|e| e.1),
            }),
        }
    }

    /// Each positive run with the reverse run that follows it, in θ order.
    fn demarcation_pairs(&self) -> impl Iterator<Item = (&SignRun, &SignRun)> {
        self.runs.windows(2).map(|w| (&w[0], &w[1])).filter(|(p, r)| p.positive && !r.positive)
    }

    /// Every demarcation, in θ order: each positive run that a reverse run follows. Their
    /// weights are worked out only where there is a choice, two or more (a lone demarcation
    /// weighs 0): the tensions at the runs' ends cost an exponential each.
    pub fn demarcations(&self) -> Vec<Demarcation> {
        self.demarcations_held(None)
    }

    /// [`Self::demarcations`] of a tally whose stretches were added by [`Self::add_held`]:
    /// `tension` evaluates the state's pieces.
    pub fn demarcations_held(&self, tension: Option<HeldTension>) -> Vec<Demarcation> {
        let mut marks: Vec<Demarcation> = self
            .demarcation_pairs()
            .map(|(p, r)| Demarcation { at_rad: p.end_rad, gap_end_rad: r.start_rad, weight: 0.0 })
            .collect();
        if marks.len() > 1 {
            // Where one run ends at the angle the next starts, the tension there is evaluated once
            // (it is continuous): one evaluation per run boundary.
            let mut last: Option<(f64, f64)> = None;
            let mut at = |theta: f64, t: TensionAt| match last {
                Some((th, v)) if th == theta => v,
                _ => {
                    let v = t.value(tension);
                    last = Some((theta, v));
                    v
                }
            };
            let mut held = |r: &SignRun| match (r.start_tension, r.end_tension) {
                (Some(a), Some(b)) => {
                    // In θ order, so that a run's end is the next one's start.
                    let start = at(r.start_rad, a);
                    Some((at(r.end_rad, b) - start).abs())
                }
                _ => None,
            };
            for (d, (p, r)) in marks.iter_mut().zip(self.demarcation_pairs()) {
                d.weight = match (held(p), held(r)) {
                    (Some(a), Some(b)) => a + b,
                    _ => p.measure_rad + r.measure_rad,
                };
            }
        }
        marks
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
    pub fn jdp_rad(&self) -> Option<f64> {
        self.principal_of(&self.demarcations()).map(|d| d.at_rad)
    }
}

/// "The" JDP among several demarcations, by a rule that does not depend on the frame (the
/// mirror θ → α − θ, T1 ↔ T2 maps each demarcation to one of the mirrored wrap's, the runs
/// beside it swapping roles): the one whose runs hold the most friction (the largest
/// [`Demarcation::weight`]), so that faint stripes of friction left behind by the load history
/// do not take it from the main positive and reverse zones; of equal ones (to 1e-6 of the
/// largest), the one whose gap's middle is nearest the middle of the wrap (`extent_rad` = α);
/// of two mirror images of each other, the one at the smaller θ.
pub fn principal(demarcations: &[Demarcation], extent_rad: f64) -> Option<Demarcation> {
    // Equal within what mirrored wraps agree to: their tensions to 1e-8, their arcs to 1e-6°.
    let same = 1e-6 * demarcations.iter().map(|d| d.weight).fold(0.0, f64::max);
    let off_middle = |d: &Demarcation| (0.5 * (d.at_rad + d.gap_end_rad) - 0.5 * extent_rad).abs();
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
            t.add(a, b, s != 0, s > 0);
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
        let t = tally(&field);
        let at: Vec<f64> = t.demarcations().iter().map(|d| d.at_rad).collect();
        assert_eq!(at, vec![0.2, 2.5]);
        assert_eq!(t.jdp_rad(), Some(2.5));
        let m = tally(&mirrored(&field, alpha));
        let at_m: Vec<f64> = m.demarcations().iter().map(|d| d.at_rad).collect();
        assert!((at_m[0] - 0.5).abs() < 1e-15 && (at_m[1] - 2.8).abs() < 1e-15, "{at_m:?}");
        assert!((m.jdp_rad().expect("a JDP") - (alpha - 2.5)).abs() < 1e-15);
    }

    /// With an idle gap [1.0, 1.4] between positive [0, 1.0] and reverse [1.4, 3]: the JDP is
    /// the gap's start, 1.0; in the mirror the gap is [1.6, 2.0] and its JDP 1.6 = 3 − 1.4,
    /// the same gap's other end. Equal weights (runs 0.5 + 0.5 either side of α/2 = 1.5):
    /// the demarcation nearer the middle wins, in both frames.
    #[test]
    fn a_stick_gap_and_equal_runs_choose_the_same_demarcation() {
        let alpha = 3.0;
        let gap = [(0.0, 1.0, 1), (1.0, 1.4, 0), (1.4, 3.0, -1)];
        assert_eq!(tally(&gap).jdp_rad(), Some(1.0));
        assert!((tally(&mirrored(&gap, alpha)).jdp_rad().expect("a JDP") - 1.6).abs() < 1e-15);
        // + − idle + −: demarcations at 0.5 (runs 0.5 + 0.5, gap middle 0.5, 1.0 from α/2) and
        // at 2.1 (runs 0.5 + 0.5, middle 2.1, 0.6 from α/2): the second is nearer the middle.
        let equal = [(0.0, 0.5, 1), (0.5, 1.0, -1), (1.0, 1.6, 0), (1.6, 2.1, 1), (2.1, 2.6, -1), (2.6, 3.0, 0)];
        assert_eq!(tally(&equal).jdp_rad(), Some(2.1));
        let m = tally(&mirrored(&equal, alpha)).jdp_rad().expect("a JDP");
        assert!((m - (alpha - 2.1)).abs() < 1e-15, "{m}");
    }
}
