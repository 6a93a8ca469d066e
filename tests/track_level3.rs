//! Rope elements followed through the wrap on the elastic lining (level 3) against references
//! that do not come from level 3: a rope at rest, creep theory's closed form of steady rolling
//! (the rigid-lining limit of a very stiff lining), the balance of friction impulse over a rope
//! that tiles the wrap, and the mirror image of a scene.
//!
//! Sheet of every test: pulley D = 5 m (R = 2.5 m), μ = 0.25, wrap 180° (α = π), rope
//! m' = 10 kg/m, EA = 1e8 N, one rope, on a lining of shear stiffness k_s (level 3, 180
//! segments of h = 1°).

mod track_common;

use std::f64::consts::PI;
use track_common::{
    RAMPS_IMPULSE_N_S, REST_SCENE, TURN_SCENE, assert_at_rest, ramps_scene, tiling_starts_deg, turn_down_s,
    turn_force_n,
};
use wrapcalc::design::Design;
use wrapcalc::model::track::Track;
use wrapcalc::run::{self, Options, SceneResult};
use wrapcalc::sheet;
use wrapcalc::wrap::contact::NodeState;

const MU: f64 = 0.25;
const R: f64 = 2.5;
const M: f64 = 10.0;
const EA: f64 = 1.0e8;

fn design(k_s: f64, scenes: &str) -> Design {
    let text = format!(
        "[pulley]\ndiameter_m = 5.0\nmu = {MU}\nwrap_angle_deg = 180.0\n\n\
         [rope]\ncount = 1\nmass_per_m_kg = {M}\nea_n = {EA:e}\n\n\
         [lining]\nshear_stiffness_n_per_m2 = {k_s:e}\n\n{scenes}"
    );
    sheet::parse("test.toml", &text).unwrap_or_else(|e| panic!("test sheet invalid:\n{e}\n{text}"))
}

fn run_one(d: &Design, nodes: usize) -> SceneResult {
    let scenes: Vec<_> = d.scenes.iter().collect();
    let mut r = run::run(d, &scenes, Options { nodes, ..Options::default() }).expect("runs");
    r.scenes.remove(0)
}

fn tracks(d: &Design) -> Vec<Track> {
    let scene = run_one(d, 180);
    assert_eq!(scene.plan.level, wrapcalc::model::Level::Elastic3, "the scene runs on the elastic lining");
    scene.tracks.expect("the scene follows elements").tracks
}

/// At rest the pulley does not turn: an element keeps its angle while T1 is raised from T0 to
/// 1.15·T0. Far from the side-1 slip zone (rigid limit [0, ln(1.15)/μ] = [0, 32°]; the sheared
/// lining spreads it over a few decay lengths λ = √(EA/k_s) = 0.1 m = 2.3° beyond that) the rope
/// keeps T0 and no friction.
#[test]
fn an_element_at_rest_stays_at_one_angle_on_the_elastic_lining() {
    let tracks = tracks(&design(1.0e10, REST_SCENE));
    assert_at_rest(&tracks);
    let slip = tracks[0].rows.last().expect("rows");
    // In the slip zone q = μn: the element carries friction along +θ at its bound.
    assert!(slip.friction_n_per_rad > 0.0 && slip.utilization > 0.99, "{slip:?}");
    let idle = tracks[1].rows.last().expect("rows");
    // 58° beyond the rigid zone's end is 25 decay lengths: e^{−25} of the 3e4 N step is nothing.
    assert!((idle.tension_n - 2.0e5).abs() < 1e-6 * 2.0e5 && idle.friction_force_n.abs() < 1e-6 * 2.0e5, "{idle:?}");
}

/// The largest differences of an element's (F, J, T at its centre) from creep theory in steady
/// rolling (v = 5 m/s, ω = 2 rad/s, T1 = 2e5 N, T2 = 1.6e5 N), and its impulse over the passage.
/// Creep theory (docs/physics.md §4): idle arc T = T1 on [0, α − β], active arc [α − β, α] with
/// n = T − m'v² = n1·e^{−μ(θ − (α − β))}, m'v² = 250 N, β = ln(n1/n2)/μ = 51.22°.
fn off_creep_theory(k_s: f64, nodes: usize) -> (f64, f64, f64) {
    let d = design(
        k_s,
        "[[scene]]\nname = \"rolling\"\nkind = \"history\"\nt_s = [0.0, 3.0]\nt1_n = [2.0e5, 2.0e5]\n\
         t2_n = [1.6e5, 1.6e5]\nspeed_m_s = [5.0, 5.0]\ntrack_entry_s = [0.5]\ntrack_length_m = 1.0\n\
         track_step_s = 0.001\n",
    );
    let (t1, t2, c, w) = (2.0e5, 1.6e5, M * 25.0, 2.0);
    let (n1, n2) = (t1 - c, t2 - c);
    let start = PI - (n1 / n2).ln() / MU;
    let tension = |theta: f64| {
        let th = theta.clamp(0.0, PI);
        if th <= start { t1 } else { c + n1 * (-MU * (th - start)).exp() }
    };
    let h = 0.5 / R;
    let scene = run_one(&d, nodes);
    let track = &scene.tracks.expect("tracks").tracks[0];
    let (mut worst_f, mut worst_t): (f64, f64) = (0.0, 0.0);
    for r in &track.rows {
        let theta = w * (r.t_s - 0.5);
        assert!((r.theta_deg.to_radians() - theta).abs() < 1e-12, "θ at {} s", r.t_s);
        worst_f = worst_f.max((r.friction_force_n - (tension(theta - h) - tension(theta + h))).abs());
        worst_t = worst_t.max((r.tension_n - tension(theta)).abs());
        assert!(r.friction_n_per_rad.abs() <= MU * r.normal_n_per_rad * (1.0 + 1e-12), "Coulomb at {} s", r.t_s);
    }
    // The whole passage: ∫F dt = ℓ(T1 − T2)/v = 8000 N·s for any field that is steady in the wrap's frame.
    let total = 1.0 * (t1 - t2) / 5.0;
    (worst_f, worst_t, (track.impulse_n_s() - total).abs() / total)
}

/// A lining so stiff that its decay length λ = √(EA/k_s) = 3.2 mm is a fourteenth of a segment
/// (R h = 43.6 mm) behaves as the rigid lining: the tracks follow creep theory's closed form to
/// the level-3 grid's resolution, and closer on a finer grid.
#[test]
fn a_very_stiff_lining_gives_the_rigid_lining_tracks() {
    let k_s = 1.0e13;
    let (f180, t180, j180) = off_creep_theory(k_s, 180);
    let (f720, t720, j720) = off_creep_theory(k_s, 720);
    println!(
        "180 segments: |ΔF| ≤ {f180:.1} N, |ΔT| ≤ {t180:.1} N, ΔJ {j180:e}; 720: {f720:.1} N, {t720:.1} N, {j720:e}"
    );
    // The level-3 state is carried in whole pitches (within h/2 of its material position) and is
    // linear between the cuts, so T at a point is off by at most the tension change over one
    // pitch, μ n1 h = 0.25 · 2e5 · π/180 = 873 N at h = 1° (218 N at 0.25°), and F = T(a) − T(b)
    // by twice that. (The lining's own shear lag adds about μ n1 λ/R = 63 N at most.)
    let pitch_n = |nodes: f64| MU * 2.0e5 * PI / nodes;
    assert!(t180 < pitch_n(180.0) && f180 < 2.0 * pitch_n(180.0), "ΔT {t180} N, ΔF {f180} N at h = 1°");
    assert!(t720 < pitch_n(720.0) && f720 < 2.0 * pitch_n(720.0), "ΔT {t720} N, ΔF {f720} N at h = 0.25°");
    // Converging: a quarter of the pitch at least halves the error (not exactly a quarter: the
    // whole-pitch moves jitter with the phase of the rows against the lattice).
    assert!(t720 < 0.5 * t180 && f720 < 0.5 * f180, "ΔT {t720} N, ΔF {f720} N at h = 0.25°");
    // The passage impulse ℓ(T1 − T2)/v holds for any field steady in the wrap's frame; what is
    // left is the trapezoidal rule's, bounded as on the rigid lining (tests/track.rs) by 1e-5.
    assert!(j180 < 1e-5 && j720 < 1e-5, "passage impulse off by {j180:e}, {j720:e}");
}

/// The ramps scene of the shared track tests on a lining of λ = √(EA/k_s) = 0.1 m.
fn tiled(speeds: &str, start_deg: &[f64], mirrored: bool) -> Design {
    design(1.0e10, &ramps_scene(speeds, start_deg, mirrored))
}

#[test]
fn impulse_over_elements_tiling_the_rope_balances_the_end_tensions_on_the_elastic_lining() {
    let tracks = tracks(&tiled("[0.0, 1.0, 3.0, 3.0, 1.0, 0.0]", &tiling_starts_deg(), false));
    let sum: f64 = tracks.iter().map(Track::impulse_n_s).sum();
    println!("{} elements: Σ impulse − ∫(T1 − T2) dt = {:e} relative", tracks.len(), sum / RAMPS_IMPULSE_N_S - 1.0);
    // At every row the elements' forces telescope to T(0) − T(α) = T1 − T2 (the state's end
    // cuts hold the history's end tensions at the row), and the rows include every sample, so the
    // trapezoidal rule on their sum is exact for the piecewise-linear T1 − T2: what is left is
    // round-off, 1e-9 of the impulse, whatever the level-3 discretisation.
    assert!(
        (sum - RAMPS_IMPULSE_N_S).abs() < 1e-9 * RAMPS_IMPULSE_N_S,
        "Σ impulse = {sum}, ∫(T1 − T2) dt = {RAMPS_IMPULSE_N_S}"
    );
    for t in &tracks {
        for r in &t.rows {
            // Coulomb per segment, |q| ≤ μn, at the element's centre.
            assert!(r.friction_n_per_rad.abs() <= MU * r.normal_n_per_rad * (1.0 + 1e-12), "Coulomb on {}", t.label);
        }
    }
}

/// Swapping the sides (T1 ↔ T2, v → −v, θ → α − θ) mirrors every track at level 3: the element
/// at θ₀ maps to the one at α − θ₀, its friction and impulse change sign, its angle becomes α − θ.
#[test]
fn level3_tracks_mirror_when_the_sides_swap() {
    let degs = [20.0, 100.0, 170.0, -60.0, -200.0];
    let mirror_degs: Vec<f64> = degs.iter().map(|d| 180.0 - d).collect();
    let a = tracks(&tiled("[0.0, 1.0, 3.0, 3.0, 1.0, 0.0]", &degs, false));
    let b = tracks(&tiled("[0.0, -1.0, -3.0, -3.0, -1.0, 0.0]", &mirror_degs, true));
    // The level-3 increments of a history and of its mirror are mirror images to round-off
    // (tests/level3_limits.rs); 1e-7 of the tension covers its accumulation over the rows.
    let scale = 2.0e5;
    let mut turns = 0;
    for (x, y) in a.iter().zip(&b) {
        assert_eq!(x.rows.len(), y.rows.len(), "{} vs {}", x.label, y.label);
        for (p, q) in x.rows.iter().zip(&y.rows) {
            assert!((p.t_s - q.t_s).abs() < 1e-9);
            assert!((p.theta_deg - (180.0 - q.theta_deg)).abs() < 1e-9, "θ {} vs {}", p.theta_deg, q.theta_deg);
            assert!((p.friction_force_n + q.friction_force_n).abs() < 1e-7 * scale, "{p:?} {q:?}");
            assert!((p.friction_n_per_rad + q.friction_n_per_rad).abs() < 1e-7 * scale);
            assert!((p.contact_force_n - q.contact_force_n).abs() < 1e-7 * scale);
            assert!((p.impulse_n_s + q.impulse_n_s).abs() < 1e-7 * scale);
            let mirrored = match p.state {
                NodeState::SlipPositive => NodeState::SlipNegative,
                NodeState::SlipNegative => NodeState::SlipPositive,
                NodeState::Stick => NodeState::Stick,
            };
            assert_eq!(mirrored, q.state, "state of {} at {} s", x.label, p.t_s);
        }
        match (x.turn_down, y.turn_down) {
            (Some(s), Some(t)) => {
                turns += 1;
                assert!((s.t_s - t.t_s).abs() < 1e-6 && (s.impulse_n_s + t.impulse_n_s).abs() < 1e-7 * scale);
            }
            (None, None) => {}
            other => panic!("turn-down of {} not mirrored: {other:?}", x.label),
        }
    }
    println!("{turns} mirrored turn-downs");
}

/// The paper's picture on one element on a very stiff lining (λ = 3.2 mm): rope entering at
/// v = 2 m/s (ω = 0.8 rad/s) while T1 rises at 1000 N/s from 1.8e5 N and T2 = 2e5 N holds. In
/// the rigid limit stuck rope keeps the entry tension of its instant, T = T1(t − θ/ω), and the
/// reverse slip zone at the exit holds T = c + n2·e^{−μ(α − θ)} from the stick boundary where
/// the two meet; an element of ℓ = 0.5 m (h = 0.1 rad) feels F = T(a) − T(b), whose root the
/// level-3 track's turn-down (Brent's method on re-advanced copies) must find.
#[test]
fn the_impulse_turns_down_where_friction_reverses_on_a_stiff_lining() {
    let d = design(1.0e13, TURN_SCENE);
    let t_star = turn_down_s();
    let track = &tracks(&d)[0];
    let turn = track.turn_down.expect("the impulse turns down");
    // F is off the closed form by at most twice a pitch's tension change, 2 μ n h (h = 1°), so
    // its root by that over the rate |dF/dt| at the root (central difference of the closed form).
    let rate = (turn_force_n(t_star + 1e-3) - turn_force_n(t_star - 1e-3)).abs() / 2e-3;
    let tol_s = 2.0 * MU * 2.0e5 * PI / 180.0 / rate;
    println!("turn-down at {} s, closed form {t_star} s, tolerance {tol_s:e} s", turn.t_s);
    assert!((turn.t_s - t_star).abs() < tol_s, "turns down at {} s, closed form {t_star} s", turn.t_s);
    let before = track.rows.iter().rfind(|r| r.t_s < turn.t_s).expect("a row before");
    assert!(before.friction_force_n > 0.0);
    // The mirror image (T1 ↔ T2, v → −v: the element enters at θ = α) turns down at the same
    // instant with the opposite impulse, to the round-off of mirrored increments and of Brent's
    // tolerance (1e-9 s).
    let mirrored_scene = TURN_SCENE.replace("t1_n", "t_tmp").replace("t2_n", "t1_n").replace("t_tmp", "t2_n");
    let m = design(1.0e13, &mirrored_scene.replace("[2.0, 2.0]", "[-2.0, -2.0]"));
    let mirrored = tracks(&m)[0].turn_down.expect("the mirror turns down");
    assert!((mirrored.t_s - turn.t_s).abs() < 1e-6, "{} vs {} s", mirrored.t_s, turn.t_s);
    assert!((mirrored.theta_deg - (180.0 - turn.theta_deg)).abs() < 1e-6);
    assert!((mirrored.impulse_n_s + turn.impulse_n_s).abs() < 1e-7 * turn.impulse_n_s.abs());
}

/// On a soft lining (λ = √(EA/k_s) = 1 m against 7.9 m of wrap) the friction on the element of
/// the turn scene no longer jumps from positive to reverse: it passes through zero smoothly,
/// taking several rows to cross the band ±0.001·μN in which friction counts as none. The
/// impulse J = ∫F dt still turns down, at the zero of F: the instant found lies between the last
/// row with F > 0 and the first with F ≤ 0, and J there is the largest of the track: a row's J
/// differs from J at the zero by at most |F|·Δt over the row interval Δt around it, where |F| is
/// inside the band (2 ms rows). Both directions.
#[test]
fn the_impulse_turns_down_where_friction_reverses_smoothly_on_a_soft_lining() {
    let soft = EA / 1.0;
    let mirrored_scene = TURN_SCENE.replace("t1_n", "t_tmp").replace("t2_n", "t1_n").replace("t_tmp", "t2_n");
    for (scene, sign) in [(TURN_SCENE.to_string(), 1.0), (mirrored_scene.replace("[2.0, 2.0]", "[-2.0, -2.0]"), -1.0)] {
        let track = &tracks(&design(soft, &scene))[0];
        let turn = track.turn_down.expect("the impulse turns down");
        let rows = &track.rows;
        let k = rows.iter().position(|r| r.t_s > turn.t_s).expect("a row after the turn-down");
        let (before, after) = (&rows[k - 1], &rows[k]);
        assert!(sign * before.friction_force_n > 0.0 && sign * after.friction_force_n <= 0.0);
        // The reversal is smooth: the rows on either side of the zero are inside the band.
        let band = 1e-3 * MU * before.contact_force_n;
        assert!(sign * before.friction_force_n < band, "F = {} N before the zero: a jump", before.friction_force_n);
        let peak = rows.iter().map(|r| sign * r.impulse_n_s).fold(f64::NEG_INFINITY, f64::max);
        let dt = after.t_s - before.t_s;
        assert!(
            (sign * turn.impulse_n_s - peak).abs() <= band * dt,
            "J at the turn-down {} N·s, largest row {peak} N·s",
            turn.impulse_n_s
        );
    }
}
