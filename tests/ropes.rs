//! Multi-rope load sharing (docs/physics.md §13) against closed forms derived by hand: identical
//! ropes, conservation at the conveyances, the steady limit of one larger groove, the rigid
//! build-up over a short travel, equalising cylinders within and past their stroke, mirror and
//! permutation symmetry, Coulomb's law per rope.

use wrapcalc::design::{Attachment, RopeSet};
use wrapcalc::ropes::trip::{RopeState, run, run_trip, tensions};
use wrapcalc::ropes::{Hoisting, MeanRow};

const EA: f64 = 2.634e8;
const R: f64 = 2.5;

fn hoisting() -> Hoisting {
    Hoisting {
        radius_m: R,
        mu: 0.25,
        wrap_angle_rad: 187.42f64.to_radians(),
        mass_per_m_kg: 10.81,
        g_m_s2: 9.81,
        ea_ref_n: EA,
    }
}

/// Constant mean tensions and hanging lengths rolling at `v` for `travel_m` (a rope loop: the
/// conveyances do not move, so the model's own steady state can be reached), `rows` rows.
fn rolling(t1: f64, t2: f64, v: f64, length_m: [f64; 2], travel_m: f64, rows: usize) -> Vec<MeanRow> {
    let dt = travel_m / v.abs() / (rows - 1) as f64;
    (0..rows).map(|i| MeanRow { t_s: i as f64 * dt, t1_n: t1, t2_n: t2, speed_m_s: v, length_m }).collect()
}

/// A lift then the way back (real hanging lengths, L1 + L2 constant), mean tensions varying.
fn round_trip(rows: usize) -> Vec<MeanRow> {
    let travel = 400.0;
    let half = rows / 2;
    (0..rows)
        .map(|i| {
            let (x, v) = if i <= half {
                (travel * i as f64 / half as f64, 10.0)
            } else {
                (travel * (rows - 1 - i) as f64 / (rows - 1 - half) as f64, -10.0)
            };
            let t_s = if i <= half { x / 10.0 } else { 40.0 + (travel - x) / 10.0 };
            MeanRow {
                t_s,
                t1_n: 2.05e5 - 20.0 * x,
                t2_n: 1.95e5 + 15.0 * x,
                speed_m_s: if i == 0 || i == rows - 1 { 0.0 } else { v },
                length_m: [460.0 - x, 50.0 + x],
            }
        })
        .collect()
}

fn deviating(n: usize) -> RopeSet {
    let mut set = RopeSet::identical(n, EA);
    set.groove_diameter_dev_m[0] = 0.0001;
    set.length_dev_m[1] = 0.01;
    set.ea_n[n - 1] = 0.95 * EA;
    set
}

#[test]
fn identical_ropes_carry_the_mean_rope() {
    let rows = round_trip(201);
    let sharing = run(&hoisting(), &RopeSet::identical(6, EA), &rows);
    for (r, m) in sharing.rows.iter().zip(&rows) {
        for i in 0..6 {
            // Round-off: the sharing's sums of six springs of 5e5 N/m times elongations of 0.4 m
            // cancel to ~1e-10 of 2e5 N; 1e-6 N is far below any physical effect.
            assert!((r.tension_n[0][i] - m.t1_n).abs() < 1e-6, "t1 {} vs {}", r.tension_n[0][i], m.t1_n);
            assert!((r.tension_n[1][i] - m.t2_n).abs() < 1e-6);
        }
    }
    assert!(sharing.max_deviation_pct() < 1e-9);
}

#[test]
fn conveyances_carry_their_weight_at_every_row() {
    let rows = round_trip(201);
    for attachment in [
        Attachment::Rigid,
        Attachment::Equalising { stroke_m: 0.05, stiffness_n_per_m: 5e7 },
        Attachment::Equalising { stroke_m: 0.002, stiffness_n_per_m: f64::INFINITY },
    ] {
        let mut set = deviating(6);
        set.attachment = [attachment, Attachment::Rigid];
        let sharing = run(&hoisting(), &set, &rows);
        for (r, m) in sharing.rows.iter().zip(&rows) {
            // Σ T_i = n·T̄ (the conveyance's weight per rope times n), to round-off of 1.2e6 N.
            let s1: f64 = r.tension_n[0].iter().sum();
            let s2: f64 = r.tension_n[1].iter().sum();
            assert!((s1 - 6.0 * m.t1_n).abs() < 1e-6, "{attachment:?}: {s1} vs {}", 6.0 * m.t1_n);
            assert!((s2 - 6.0 * m.t2_n).abs() < 1e-6);
        }
    }
}

#[test]
fn one_larger_groove_tends_to_equal_rope_flows() {
    // n ropes, rope 1's groove radius larger by ΔR (ρ = ΔR/R). Steady state: every rope passes
    // the same unstretched length per turn, R_i/(1 + T_i/EA) equal, so with u = EA + T_other:
    // EA + T_1 = (1 + ρ)u and T_1 + (n − 1)T_other = n·T̄, i.e. u = n(EA + T̄)/(n + ρ) and
    //   T_1 − T_other = ρ·u = n·ρ(EA + T̄)/(n + ρ)  (≈ EA·ΔR/R for T̄ ≪ EA, ρ ≪ n).
    // ΔD = 0.02 mm: ρ = 1e-5/2.5 = 4e-6; n = 3, T̄ = 2e5: ΔT = 3·4e-6·(2.634e8 + 2e5)/(3 + 4e-6)
    // = 1054.4 N, with equal end tensions far from the Euler limit.
    let n = 3;
    let t_mean = 2.0e5;
    let mut set = RopeSet::identical(n, EA);
    set.groove_diameter_dev_m[0] = 2.0e-5;
    let rho = 1.0e-5 / R;
    let expected = n as f64 * rho * (EA + t_mean) / (n as f64 + rho);
    assert!((expected - 1054.4).abs() < 0.1);
    // The imbalance relaxes over a rope travel of the hanging length (500 m): 30 lengths leave
    // e^-30 of it.
    let rows = rolling(t_mean, t_mean, 5.0, [500.0, 500.0], 15_000.0, 301);
    let sharing = run(&hoisting(), &set, &rows);
    let last = sharing.rows.last().unwrap();
    let d_entry = last.tension_n[0][0] - last.tension_n[0][1];
    // Tolerance 1e-4 relative: Heun's O((h/L)²) error at h = L/50 over a decaying transient.
    assert!((d_entry - expected).abs() < 1e-4 * expected, "{d_entry} vs {expected}");
    // Exit side: the same rope lengths moved with the opposite sign, equal lengths: −ΔT.
    let d_exit = last.tension_n[1][0] - last.tension_n[1][1];
    assert!((d_exit + expected).abs() < 1e-4 * expected, "{d_exit}");
}

#[test]
fn rigid_build_up_over_a_short_travel() {
    // No creep back yet: over x = 1 m the larger groove pulls ρ·x/(1 + T̄/EA) more unstretched rope
    // off side 1 onto side 2 than the other rope; rigid ends stretch that into L1 and L2:
    //   T_1 − T_2 = EA·ρx/((1 + ε̄)L1) on side 1 and −EA·ρx/((1 + ε̄)L2) on side 2.
    // ρ = 2e-4 (ΔD = 1 mm), L1 = 400 m, L2 = 100 m, T̄ = 2e5: 131.6 N and −526.6 N.
    let mut set = RopeSet::identical(2, EA);
    set.groove_diameter_dev_m[0] = 0.001;
    let rho = 0.0005 / R;
    let eps = 2.0e5 / EA;
    let rows = rolling(2.0e5, 2.0e5, 1.0, [400.0, 100.0], 1.0, 11);
    let last = run(&hoisting(), &set, &rows).rows.pop().unwrap();
    let e1 = EA * rho / ((1.0 + eps) * 400.0);
    let e2 = -EA * rho / ((1.0 + eps) * 100.0);
    let d1 = last.tension_n[0][0] - last.tension_n[0][1];
    let d2 = last.tension_n[1][0] - last.tension_n[1][1];
    // The creep back already started: relative x/L ≈ 1/100 on side 2 (its stretch feeds back
    // only through the entry side 1: x/(2·L1) = 1.3e-3 on the rate): tolerance 0.5 %.
    assert!((d1 - e1).abs() < 5e-3 * e1.abs(), "{d1} vs {e1}");
    assert!((d2 - e2).abs() < 5e-3 * e2.abs(), "{d2} vs {e2}");
}

#[test]
fn equalising_cylinders_equal_within_stroke_rigid_past_it() {
    // Two ropes, ΔD = 1 mm on rope 1; side 1 on cylinders of stroke S (±S/2). Within the stroke
    // the forces are equal; the pistons take up c = ∓ρx/(2(1 + ε̄)) until |c| = S/2 at
    // x* = S(1 + ε̄)/ρ; past it the ropes are rigid from there: T_1 − T_2 = EA·ρ(x − x*)/((1 + ε̄)L1).
    let rho = 0.0005 / R;
    let eps = 2.0e5 / EA;
    let stroke = 0.0004;
    let x_star = stroke * (1.0 + eps) / rho;
    // x* = 0.0004·(1 + 7.593e-4)/2e-4 = 2.0015 m.
    assert!((x_star - 2.0015).abs() < 1e-4);
    let mut set = RopeSet::identical(2, EA);
    set.groove_diameter_dev_m[0] = 0.001;
    set.attachment[0] = Attachment::Equalising { stroke_m: stroke, stiffness_n_per_m: f64::INFINITY };
    let rows = rolling(2.0e5, 2.0e5, 1.0, [400.0, 100.0], 4.0, 41);
    let sharing = run(&hoisting(), &set, &rows);
    for r in &sharing.rows {
        let x = r.t_s;
        let d1 = r.tension_n[0][0] - r.tension_n[0][1];
        if x < x_star - 0.05 {
            assert!(d1.abs() < 1e-6, "x = {x}: {d1}");
        } else if x > x_star + 0.05 {
            let e = EA * rho * (x - x_star) / ((1.0 + eps) * 400.0);
            // As in the rigid build-up, plus the pistons' creep-back before x* (side 2's
            // feedback, ≈ x/L1): 1 % of the difference.
            assert!((d1 - e).abs() < 1e-2 * e, "x = {x}: {d1} vs {e}");
        }
    }
    // Stroke used: the full half stroke on side 1, none on side 2 (rigid).
    let used = sharing.stroke_used_m();
    assert!((used[0] - 0.5 * stroke).abs() < 1e-12 && used[1] == 0.0, "{used:?}");
}

#[test]
fn mirror_swaps_the_sides_of_every_rope() {
    let rows = round_trip(201);
    let mut set = deviating(4);
    set.attachment = [Attachment::Equalising { stroke_m: 0.004, stiffness_n_per_m: 1e8 }, Attachment::Rigid];
    let a = run(&hoisting(), &set, &rows);
    let mirrored: Vec<MeanRow> = rows
        .iter()
        .map(|r| MeanRow {
            t1_n: r.t2_n,
            t2_n: r.t1_n,
            speed_m_s: -r.speed_m_s,
            length_m: [r.length_m[1], r.length_m[0]],
            ..*r
        })
        .collect();
    let mut mset = set.clone();
    mset.attachment = [set.attachment[1], set.attachment[0]];
    let b = run(&hoisting(), &mset, &mirrored);
    for (x, y) in a.rows.iter().zip(&b.rows) {
        for i in 0..4 {
            // Round-off on 2e5 N tensions through ~1000 Heun steps.
            assert!((x.tension_n[0][i] - y.tension_n[1][i]).abs() < 1e-6 * 2e5);
            assert!((x.tension_n[1][i] - y.tension_n[0][i]).abs() < 1e-6 * 2e5);
        }
    }
    assert!((a.max_deviation_pct() - b.max_deviation_pct()).abs() < 1e-9);
}

#[test]
fn reordering_the_ropes_reorders_the_results() {
    let rows = round_trip(201);
    let set = deviating(5);
    let order = [3, 0, 4, 1, 2];
    let a = run(&hoisting(), &set, &rows);
    let b = run(&hoisting(), &set.permuted(&order), &rows);
    for (x, y) in a.rows.iter().zip(&b.rows) {
        for (j, &i) in order.iter().enumerate() {
            for s in 0..2 {
                // Sums taken in another order: round-off only.
                assert!((x.tension_n[s][i] - y.tension_n[s][j]).abs() < 1e-6);
            }
        }
    }
}

#[test]
fn coulomb_holds_per_rope_and_a_rope_past_the_limit_slides() {
    // ΔD = 5 mm on rope 1 with a short side 2 drives rope 1 past e^{μα} = 2.268 within the trip;
    // it must slide back to the limit at every row: (T_hi − m'v²) ≤ e^{μα}(T_lo − m'v²).
    let h = hoisting();
    let mut set = RopeSet::identical(3, EA);
    set.groove_diameter_dev_m[0] = 0.005;
    let rows = rolling(2.0e5, 1.6e5, 5.0, [400.0, 40.0], 400.0, 401);
    let (out, summary) = run_trip(&h, &set, &rows, RopeState::installed(&set, rows[0].length_m));
    let limit = (h.mu * h.wrap_angle_rad).exp();
    for r in &out {
        let c = h.mass_per_m_kg * r.speed_m_s * r.speed_m_s;
        for i in 0..3 {
            let (t1, t2) = (r.tension_n[0][i], r.tension_n[1][i]);
            let ratio = (t1.max(t2) - c) / (t1.min(t2) - c);
            // Newton on the slide length converges to ~1e-9 of the tensions.
            assert!(ratio <= limit * (1.0 + 1e-7), "t = {}: rope {} ratio {ratio}", r.t_s, i + 1);
        }
    }
    assert!(summary.ropes[0].slip_m > 0.0, "rope 1 must have slid");
    assert_eq!(summary.ropes[1].slip_m, 0.0);
    let (t, _) = tensions(&h, &set, &summary.end, rows.last().unwrap());
    assert!(t[0][0] > t[0][1], "the larger groove's rope is the tight one at the entry");
}
