//! How one conveyance shares its weight among its ropes: rigid attachment (every rope end moves
//! with the conveyance, each rope carries its own stretch) or hydraulic equalising cylinders
//! sharing one pressure (equal forces while every piston is within its stroke, rigid again at a
//! stroke end). Linear in the ropes' length deviations; docs/physics.md §13.2.

use crate::design::Attachment;

/// One side's state for the sharing: the mean rope and each rope's deviations.
#[derive(Debug, Clone, Copy)]
pub struct SideLoad<'a> {
    /// Mean tension along the hanging ropes, per rope: tangent-point tension − w·L/2 (N).
    pub mean_tension_n: f64,
    /// Hanging length tangent point → conveyance (m).
    pub length_m: f64,
    /// Each rope's axial stiffness EA (N).
    pub ea_n: &'a [f64],
    /// Each rope's unstretched-length deviation on this side from the reference rope (m).
    pub dev_m: &'a [f64],
}

/// The sharing's answer on one side.
#[derive(Debug, Clone, PartialEq)]
pub struct Shared {
    /// Each rope's mean tension along its hanging part minus the mean rope's (N).
    pub delta_n: Vec<f64>,
    /// Each cylinder's piston position from mid-stroke (m; 0 with rigid attachment).
    pub piston_m: Vec<f64>,
}

/// The tensions of the ropes at one conveyance for the given attachment.
pub fn share(load: SideLoad<'_>, attachment: Attachment) -> Shared {
    let n = load.ea_n.len();
    let spring: Vec<f64> = load
        .ea_n
        .iter()
        .map(|ea| {
            let k_rope = ea / load.length_m;
            match attachment {
                Attachment::Rigid => k_rope,
                Attachment::Equalising { stiffness_n_per_m: kc, .. } if kc.is_finite() => k_rope * kc / (k_rope + kc),
                Attachment::Equalising { .. } => k_rope,
            }
        })
        .collect();
    let half = match attachment {
        Attachment::Rigid => 0.0,
        Attachment::Equalising { stroke_m, .. } => 0.5 * stroke_m,
    };
    // Piston i: None = free (force = common pressure), Some(c) = held at a stroke end c.
    let mut held: Vec<Option<f64>> = vec![if half == 0.0 { Some(0.0) } else { None }; n];
    let mut answer = solve(&load, &spring, &held);
    for _ in 0..(2 * n + 2) {
        let mut changed = false;
        for (i, h) in held.iter_mut().enumerate() {
            match *h {
                None if answer.piston[i].abs() > half => {
                    *h = Some(half.copysign(answer.piston[i]));
                    changed = true;
                }
                // A held piston leaves its stop when the rope's force passes the pressure's way.
                Some(c) if half > 0.0 && answer.pressure.is_some_and(|p| (answer.tension[i] - p) * c > 0.0) => {
                    *h = None;
                    changed = true;
                }
                _ => {}
            }
        }
        if !changed {
            break;
        }
        answer = solve(&load, &spring, &held);
    }
    Shared { delta_n: answer.tension.iter().map(|t| t - load.mean_tension_n).collect(), piston_m: answer.piston }
}

struct Answer {
    tension: Vec<f64>,
    piston: Vec<f64>,
    pressure: Option<f64>,
}

/// Free pistons carry the common force P; held ones a rigid rope's k(E + c − d). Unknowns: the
/// conveyance's common elongation E and P, from the weight Σ T = n T̄ and the oil volume Σ c = 0.
fn solve(load: &SideLoad<'_>, k: &[f64], held: &[Option<f64>]) -> Answer {
    let n = k.len();
    let d = load.dev_m;
    let total = n as f64 * load.mean_tension_n;
    let (mut free, mut inv_k, mut free_d, mut held_c, mut held_k, mut held_kcd) = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
    for i in 0..n {
        match held[i] {
            None => {
                free += 1.0;
                inv_k += 1.0 / k[i];
                free_d += d[i];
            }
            Some(c) => {
                held_c += c;
                held_k += k[i];
                held_kcd += k[i] * (c - d[i]);
            }
        }
    }
    let (e, p) = if free == 0.0 {
        ((total - held_kcd) / held_k, None)
    } else {
        // P·Σ1/k − E·n_free = −Σd_free − Σc_held;  P·n_free + E·Σk_held = n T̄ − Σk(c − d)_held.
        let (a11, a12, b1) = (inv_k, -free, -free_d - held_c);
        let (a21, a22, b2) = (free, held_k, total - held_kcd);
        let det = a11 * a22 - a12 * a21;
        let p = (b1 * a22 - a12 * b2) / det;
        let e = (a11 * b2 - a21 * b1) / det;
        (e, Some(p))
    };
    let mut tension = Vec::with_capacity(n);
    let mut piston = Vec::with_capacity(n);
    for i in 0..n {
        match (held[i], p) {
            (None, Some(p)) => {
                tension.push(p);
                piston.push(p / k[i] - e + d[i]);
            }
            (stop, _) => {
                let c = stop.unwrap_or_default();
                tension.push(k[i] * (e + c - d[i]));
                piston.push(c);
            }
        }
    }
    Answer { tension, piston, pressure: p }
}

#[cfg(test)]
mod tests {
    use super::*;

    const EA: f64 = 2.634e8;

    #[test]
    fn rigid_two_ropes_by_hand() {
        // Two ropes, L = 500 m, k = EA/L = 526 800 N/m; rope 2 is 2 mm longer on this side.
        // E = (2·T̄ + k·0.002)/(2k); ΔT₁ = k(E − 0) − T̄ = +k·0.001 = 526.8 N, ΔT₂ = −526.8 N.
        let load = SideLoad { mean_tension_n: 2.0e5, length_m: 500.0, ea_n: &[EA, EA], dev_m: &[0.0, 0.002] };
        let s = share(load, Attachment::Rigid);
        let k = EA / 500.0;
        // Tolerance: round-off on tensions of 2e5 N (1e-9 relative).
        assert!((s.delta_n[0] - k * 0.001).abs() < 1e-6 * 2.0e5, "{:?}", s.delta_n);
        assert!((s.delta_n[1] + k * 0.001).abs() < 1e-6 * 2.0e5);
    }

    #[test]
    fn equalising_within_stroke_equal_then_rigid_past_it() {
        let ea = [EA; 3];
        // Within the stroke: equal forces, pistons take up the deviations about their mean:
        // c_i = d_i − mean(d) = (−1, 0, +1) mm.
        let dev = [0.0, 0.001, 0.002];
        let load = SideLoad { mean_tension_n: 2.0e5, length_m: 500.0, ea_n: &ea, dev_m: &dev };
        let eq = Attachment::Equalising { stroke_m: 0.1, stiffness_n_per_m: f64::INFINITY };
        let s = share(load, eq);
        for (i, dt) in s.delta_n.iter().enumerate() {
            assert!(dt.abs() < 1e-6, "rope {i}: {dt}");
            assert!((s.piston_m[i] - (dev[i] - 0.001)).abs() < 1e-12);
        }
        // Past the stroke (±1 mm available, ±50 mm asked): the outer pistons rest at their stops
        // (c = −1, +1 mm; the shortest rope pulls hardest and holds its piston at −1 mm), the
        // middle one stays free.
        let dev = [0.0, 0.05, 0.1];
        let load = SideLoad { dev_m: &dev, ..load };
        let small = Attachment::Equalising { stroke_m: 0.002, stiffness_n_per_m: f64::INFINITY };
        let s = share(load, small);
        assert_eq!(s.piston_m[0], -0.001);
        assert_eq!(s.piston_m[2], 0.001);
        // Oil volume Σc = 0 keeps the middle piston at 0: T₂ = P = k(E − 0.05); the held ropes
        // T₁ = k(E − 0.001), T₃ = k(E + 0.001 − 0.1); ΣT = 3T̄ gives E = T̄/k + 0.05, so
        // ΔT₁ = k(0.05 − 0.001) = +0.049k and ΔT₃ = −0.049k.
        let k = EA / 500.0;
        assert!(s.piston_m[1].abs() < 1e-12);
        assert!((s.delta_n[0] - k * 0.049).abs() < 1e-6 * k, "{:?}", s.delta_n);
        assert!((s.delta_n[2] + k * 0.049).abs() < 1e-6 * k);
    }
}
