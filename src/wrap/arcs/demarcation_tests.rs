//! The tally's demarcations, their weights and the principal one, against values by hand and
//! their mirrors.

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
                Demarcation { at_rad: at + 0.5 * gap, sign_change_rad: (at, at + gap), weight: base * (1.0 + nudge) }
            })
            .collect();
        assert_eq!(principal(&ds, 3.0), rule(&ds, 3.0), "{ds:?}");
    }
}
