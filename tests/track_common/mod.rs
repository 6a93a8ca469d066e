//! What the track test files share: the closed form of the paper's turn-down case on the rigid
//! lining (pulley R = 2.5 m, μ = 0.25, α = π, m' = 10 kg/m).
#![allow(dead_code)]

use std::f64::consts::PI;

/// The turn-down scene's keys: rope entering at v = 2 m/s while T1 rises at 1000 N/s from
/// 1.8e5 N and T2 = 2e5 N holds; one element of ℓ = 0.5 m entering at 4 s.
pub const TURN_SCENE: &str = "[[scene]]\nname = \"turn\"\nkind = \"history\"\nt_s = [0.0, 12.0]\n\
    t1_n = [1.8e5, 1.92e5]\nt2_n = [2.0e5, 2.0e5]\nspeed_m_s = [2.0, 2.0]\ntrack_entry_s = [4.0]\n\
    track_length_m = 0.5\ntrack_step_s = 0.002\n";

/// Angular speed (rad/s) and entry time (s) of [`TURN_SCENE`].
pub const TURN_OMEGA: f64 = 0.8;
/// See [`TURN_OMEGA`].
pub const TURN_ENTRY_S: f64 = 4.0;

/// The root of `f` on [lo, hi] by 200 bisections.
pub fn bisect(f: &dyn Fn(f64) -> f64, mut lo: f64, mut hi: f64) -> f64 {
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if (f(mid) > 0.0) == (f(lo) > 0.0) { lo = mid } else { hi = mid }
    }
    0.5 * (lo + hi)
}

/// Friction force on the element of [`TURN_SCENE`] at `t` on the rigid lining (N). Stuck rope
/// keeps the entry tension of its instant, T = T1(t − θ/ω) (q = Ṫ1/ω, docs/physics.md §9); at the
/// exit the reverse slip zone holds T = c + n2·e^{−μ(α − θ)} from the stick boundary θ_b where the
/// two meet (the stuck rope lies below that envelope beyond it); F = T(a) − T(b), h = 0.1 rad.
pub fn turn_force_n(t: f64) -> f64 {
    let (mu, w, c, h, t_e) = (0.25, TURN_OMEGA, 10.0 * 4.0, 0.1, TURN_ENTRY_S);
    let n2 = 2.0e5 - c;
    let t1 = |t: f64| 1.8e5 + 1000.0 * t;
    let active = |theta: f64| c + n2 * (-mu * (PI - theta)).exp();
    let boundary = bisect(&|th: f64| active(th) - t1(t - th / w), 0.0, PI);
    let tension = |th: f64| if th < boundary { t1(t - th / w) } else { active(th) };
    let centre = w * (t - t_e);
    tension((centre - h).clamp(0.0, PI)) - tension((centre + h).clamp(0.0, PI))
}

/// The instant the impulse of [`TURN_SCENE`]'s element turns down on the rigid lining: F > 0
/// while the element is on the stuck part, < 0 once it is wholly in the reverse zone (s).
pub fn turn_down_s() -> f64 {
    bisect(&turn_force_n, TURN_ENTRY_S + 0.5, TURN_ENTRY_S + PI / TURN_OMEGA)
}

/// A history through start, ramps of both end tensions at changing speed, and a stop.
pub const RAMPS: &str = "t_s = [0.0, 1.0, 3.0, 4.0, 6.0, 7.0]\n\
    t1_n = [1.8e5, 1.9e5, 2.0e5, 2.05e5, 1.95e5, 1.9e5]\n\
    t2_n = [1.8e5, 1.75e5, 1.7e5, 1.72e5, 1.8e5, 1.85e5]\n";

/// The time integral of T1 − T2 over [`RAMPS`], exact for piecewise-linear tensions: with
/// d = T1 − T2 = 0, 15e3, 30e3, 33e3, 15e3, 5e3 at the samples, Σ Δt·(d_a + d_b)/2 =
/// 0.5·15e3 + 2·22.5e3 + 31.5e3 + 2·24e3 + 10e3 = 142 000 N·s.
pub const RAMPS_IMPULSE_N_S: f64 = 142_000.0;

/// The scene of [`RAMPS`] (sides swapped when `mirrored`) at the given speeds, following elements
/// of ℓ = 0.5 m (2h = 0.2 rad) given by the angle of their centre at the start (negative: rope
/// still on side 1).
pub fn ramps_scene(speeds: &str, start_deg: &[f64], mirrored: bool) -> String {
    let list: Vec<String> = start_deg.iter().map(|d| format!("{d:.17}")).collect();
    let ramps = if mirrored {
        RAMPS.replace("t1_n", "t_tmp").replace("t2_n", "t1_n").replace("t_tmp", "t2_n")
    } else {
        RAMPS.to_string()
    };
    format!(
        "[[scene]]\nname = \"ramps\"\nkind = \"history\"\n{ramps}speed_m_s = {speeds}\n\
         track_length_m = 0.5\ntrack_step_s = 0.002\ntrack_start_deg = [{}]\n",
        list.join(", ")
    )
}

/// Starts (deg) of elements 2h = 0.2 rad apart that tile the rope of [`RAMPS`] at speeds
/// 0 → 1 → 3 → 3 → 1 → 0 m/s, whose pulley turns φ_max = ∫v dt / R = (0.5 + 4 + 3 + 4 + 0.5)/2.5
/// = 4.8 rad: from θ₀ ∈ [α, α + 2h] (on side 2, never on the pulley) down past θ₀ = −φ_max (the
/// rope on the pulley at the end).
pub fn tiling_starts_deg() -> Vec<f64> {
    let h = 0.1;
    (0..).map(|k| PI + h - 2.0 * h * k as f64).take_while(|t| *t > -4.8 - 3.0 * h).map(f64::to_degrees).collect()
}

/// A scene at rest whose T1 rises from T0 = 2e5 N to 1.15·T0 over 1 s and holds, following the
/// elements whose centres are at 10° and 90°.
pub const REST_SCENE: &str = "[[scene]]\nname = \"rest\"\nkind = \"history\"\nt_s = [0.0, 1.0, 2.0]\n\
    t1_n = [2.0e5, 2.3e5, 2.3e5]\nt2_n = [2.0e5, 2.0e5, 2.0e5]\nspeed_m_s = [0.0, 0.0, 0.0]\n\
    track_start_deg = [10.0, 90.0]\n";

/// The elements of [`REST_SCENE`] keep their angles on every row (and have at least 1000 rows).
pub fn assert_at_rest(tracks: &[wrapcalc::model::track::Track]) {
    for (track, deg) in tracks.iter().zip([10.0, 90.0]) {
        assert!(track.rows.len() >= 1000);
        assert!(track.rows.iter().all(|r| r.theta_deg == deg), "{} moved", track.label);
    }
}
