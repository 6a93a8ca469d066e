//! One side of the hoist as a stretched-mesh finite-element model: `n` linear elements over the
//! current hanging length, nodes `1..=n` free (node 0, the tangent point, is fixed in the frame
//! moving with the pulley surface), the end mass on node `n`.
//!
//! Matrices of the whole side (all ropes together), `h = L/n`, `k_e = EA/h`, `m_e = ρh/6`:
//! `K` tridiagonal with diagonal `2k_e` (node n: `k_e`) and off-diagonal `−k_e`;
//! `M` tridiagonal with diagonal `4m_e` (node n: `2m_e + M_s`) and off-diagonal `m_e`;
//! `C = βK`; the consistent load `F_i = w` (node n: `w/2 + M_s(g − a_s)`) with the element load
//! `w = ρ(g − a_s)h`.

use super::HoistParams;

/// The per-instant coefficients of one side.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Coeffs {
    /// Element stiffness `EA/h`, N/m.
    pub ke: f64,
    /// A sixth of the element mass, `ρh/6`, kg.
    pub me: f64,
    /// End mass `M_s` (conveyance + lumped tail rope), kg.
    pub end_mass_kg: f64,
    /// Stiffness-proportional damping coefficient β, s.
    pub beta_s: f64,
    /// Load of one element, `ρ(g − a_s)h`, N.
    pub w_n: f64,
    /// Load of the end mass, `M_s(g − a_s)`, N.
    pub end_load_n: f64,
}

impl Coeffs {
    /// Coefficients for hanging length `length_m`, end mass `end_mass_kg`, net downward field
    /// `g − a_s` (`field_m_s2`) and damping coefficient `beta_s`.
    pub fn new(p: &HoistParams, n: usize, length_m: f64, end_mass_kg: f64, field_m_s2: f64, beta_s: f64) -> Self {
        // h and k_e = EA·n/L as two independent divisions (not k_e = EA/h after h).
        let h = length_m / n as f64;
        let rho = p.rho_kg_m();
        Self {
            ke: p.ea_total_n() * n as f64 / length_m,
            me: rho * h / 6.0,
            end_mass_kg,
            beta_s,
            w_n: rho * field_m_s2 * h,
            end_load_n: end_mass_kg * field_m_s2,
        }
    }

    /// `K y` into `out`.
    fn k_times(&self, y: &[f64], out: &mut [f64]) {
        let n = y.len();
        let mut left = 0.0;
        for i in 0..n - 1 {
            out[i] = self.ke * (2.0 * y[i] - left - y[i + 1]);
            left = y[i];
        }
        out[n - 1] = self.ke * (y[n - 1] - left);
    }

    /// `F − K y` into `out` (the consistent loads minus the elastic forces).
    fn load_minus_k_times(&self, y: &[f64], out: &mut [f64]) {
        let n = y.len();
        let mut left = 0.0;
        for i in 0..n - 1 {
            out[i] = self.w_n - self.ke * (2.0 * y[i] - left - y[i + 1]);
            left = y[i];
        }
        out[n - 1] = 0.5 * self.w_n + self.end_load_n - self.ke * (y[n - 1] - left);
    }

    /// `F_i`, the consistent load of free node `i + 1`.
    fn load(&self, i: usize, n: usize) -> f64 {
        if i + 1 < n { self.w_n } else { 0.5 * self.w_n + self.end_load_n }
    }

    /// `½ vᵀMv + ½ qᵀKq − Fᵀq`, J.
    pub fn energy_j(&self, q: &[f64], v: &[f64]) -> f64 {
        self.energy_of(&Forms::new(q, v))
    }

    /// `E = ½q̇ᵀMq̇ + ½qᵀKq − g·μᵀq + V·μᵀq̇`, the side's energy relative to the rigid motion
    /// (the energy ledger's, [`super::energy_ledger`]): μ the column sums of the mass matrix with
    /// the tangent point's row (`6m_e` at an inner node, `3m_e + M_s` at the end), `speed_down` V
    /// the side's rigid downward speed, g the gravity, J.
    pub fn relative_energy_j(&self, g: f64, speed_down: f64, q: &[f64], v: &[f64]) -> f64 {
        self.relative_energy_of(&Forms::new(q, v), g, speed_down)
    }

    /// [`Self::relative_energy_j`] of one state with these coefficients less with `before`'s:
    /// the work a change of coefficients does on the state, with one pass over the nodes.
    pub fn relative_energy_change_j(&self, before: &Coeffs, g: f64, speed_down: f64, q: &[f64], v: &[f64]) -> f64 {
        let f = Forms::new(q, v);
        self.relative_energy_of(&f, g, speed_down) - before.relative_energy_of(&f, g, speed_down)
    }

    fn relative_energy_of(&self, f: &Forms, g: f64, speed_down: f64) -> f64 {
        let (inner, end) = (6.0 * self.me, 3.0 * self.me + self.end_mass_kg);
        let mu_q = inner * (f.q_sum - f.q_end) + end * f.q_end;
        let mu_v = inner * (f.v_sum - f.v_end) + end * f.v_end;
        self.me * f.mass + 0.5 * self.end_mass_kg * f.v_end * f.v_end + 0.5 * self.ke * f.strain - g * mu_q
            + speed_down * mu_v
    }

    /// The energy from the coefficient-free forms of a state.
    fn energy_of(&self, f: &Forms) -> f64 {
        self.me * f.mass + 0.5 * self.end_mass_kg * f.v_end * f.v_end + 0.5 * self.ke * f.strain
            - self.w_n * (f.q_sum - 0.5 * f.q_end)
            - self.end_load_n * f.q_end
    }
}

/// The sums of a state `(q, v)` the energy and the dissipation are made of, so that they can be
/// evaluated for several coefficient sets with one pass over the nodes (`q₀ = v₀ = 0`).
#[derive(Debug, Clone, Copy, Default, PartialEq)]
struct Forms {
    /// `Σ_elements (v_a² + v_a v_b + v_b²)`, so that `½vᵀMv = m_e·mass + ½M_s v_n²`.
    mass: f64,
    /// `Σ_elements (q_b − q_a)²`, so that `½qᵀKq = ½k_e·strain`.
    strain: f64,
    /// `Σ_elements (v_b − v_a)²`, so that `vᵀCv = βk_e·strain_rate`.
    strain_rate: f64,
    /// `Σ_{i=1..n} q_i`.
    q_sum: f64,
    /// `Σ_{i=1..n} v_i`.
    v_sum: f64,
    q_end: f64,
    v_end: f64,
}

impl Forms {
    fn new(q: &[f64], v: &[f64]) -> Self {
        let mut f = Forms::default();
        let (mut q_prev, mut v_prev) = (0.0, 0.0);
        for (&qi, &vi) in q.iter().zip(v) {
            f.mass += v_prev * v_prev + v_prev * vi + vi * vi;
            f.strain += (qi - q_prev) * (qi - q_prev);
            f.strain_rate += (vi - v_prev) * (vi - v_prev);
            f.q_sum += qi;
            f.v_sum += vi;
            (q_prev, v_prev) = (qi, vi);
        }
        (f.q_end, f.v_end) = (q_prev, v_prev);
        f
    }
}

/// Solves the symmetric tridiagonal system with diagonal `d_int` (rows `0..n−1`), `d_last`
/// (row `n−1`) and constant off-diagonal `off` in place (Thomas algorithm; the matrices here are
/// symmetric positive definite, so no pivoting is needed). `scratch` has length `n`.
fn solve_tridiag(d_int: f64, d_last: f64, off: f64, rhs: &mut [f64], scratch: &mut [f64]) {
    solve_tridiag_k([((d_int, d_last, off), rhs, scratch)]);
}

/// The steps of two sides ([`SideState::step`] each) with the energy balance, their nodes
/// visited side by side when their element counts are equal: each side's elimination is a
/// chain of dependent operations, and independent chains in one loop keep the processor busy
/// while any one waits. Without the energy balance [`super::sweep::step_pair`] takes the sweep
/// instead; the results are those of each side stepped alone, bit for bit.
pub(crate) fn step_pair_energy(
    sides: [(&mut SideState, &Coeffs, &Coeffs); 2],
    dt: f64,
    energy: bool,
) -> [(f64, f64); 2] {
    let [(a, a_before, a_c), (b, b_before, b_c)] = sides;
    if a.q.len() != b.q.len() || a.q.len() < 2 {
        return [a.step(a_before, a_c, dt, energy), b.step(b_before, b_c, dt, energy)];
    }
    let ma = a.predict(a_c, dt);
    let mb = b.predict(b_c, dt);
    solve_tridiag_k([(ma, &mut a.rhs, &mut a.scratch), (mb, &mut b.rhs, &mut b.scratch)]);
    [a.finish(a_before, a_c, dt, energy), b.finish(b_before, b_c, dt, energy)]
}

/// One system of [`solve_tridiag_k`]: (interior diagonal, last diagonal, off-diagonal), the
/// right-hand side (solved in place) and the scratch row.
type Tridiag<'a> = ((f64, f64, f64), &'a mut [f64], &'a mut [f64]);

/// `K` systems of [`solve_tridiag`] of the same size, row by row together: each is a chain of
/// dependent operations, and independent chains in one loop keep the processor busy while any
/// one waits (the same operations on each, so the results are those of separate solves).
///
/// The elimination factors `c_i = off/(d_int − off·c_{i−1})` of the constant interior rows
/// converge geometrically (diagonal dominance); once one repeats to the last bit, every later
/// one is the same number, so they are not recomputed: the result is bit for bit that of the
/// full recurrence, with one division per row only until then.
fn solve_tridiag_k<const K: usize>(mut systems: [Tridiag; K]) {
    let n = systems.first().map_or(0, |s| s.1.len());
    if n == 0 {
        return;
    }
    if n == 1 {
        for ((_, last, _), rhs, _) in systems.iter_mut() {
            rhs[0] /= *last;
        }
        return;
    }
    let mut inv = [0.0; K];
    let mut settled = [false; K];
    for (k, ((d, _, off), rhs, scratch)) in systems.iter_mut().enumerate() {
        inv[k] = 1.0 / *d;
        scratch[0] = *off * inv[k];
        rhs[0] *= inv[k];
    }
    for i in 1..n - 1 {
        for (k, ((d, _, off), rhs, scratch)) in systems.iter_mut().enumerate() {
            if settled[k] {
                scratch[i] = scratch[i - 1];
            } else {
                inv[k] = 1.0 / (*d - *off * scratch[i - 1]);
                scratch[i] = *off * inv[k];
                settled[k] = scratch[i] == scratch[i - 1];
            }
            rhs[i] = (rhs[i] - *off * rhs[i - 1]) * inv[k];
        }
    }
    for ((_, last, off), rhs, scratch) in systems.iter_mut() {
        let inv_last = 1.0 / (*last - *off * scratch[n - 2]);
        scratch[n - 1] = *off * inv_last;
        rhs[n - 1] = (rhs[n - 1] - *off * rhs[n - 2]) * inv_last;
    }
    for i in (0..n - 1).rev() {
        for (_, rhs, scratch) in systems.iter_mut() {
            rhs[i] -= scratch[i] * rhs[i + 1];
        }
    }
}

/// The smallest `ω` (rad/s) of `K φ = ω² M φ` by inverse iteration.
pub(crate) fn fundamental_omega(c: &Coeffs, n: usize) -> f64 {
    let mut phi: Vec<f64> = (1..=n).map(|i| i as f64 / n as f64).collect();
    let mut y = vec![0.0; n];
    let mut scratch = vec![0.0; n];
    let mut kphi = vec![0.0; n];
    let zeros = vec![0.0; n];
    let mut omega2 = f64::NAN;
    for _ in 0..500 {
        // y = M φ
        for i in 0..n {
            let left = if i == 0 { 0.0 } else { phi[i - 1] };
            let right = if i + 1 < n { phi[i + 1] } else { 0.0 };
            let diag = if i + 1 < n { 4.0 * c.me } else { 2.0 * c.me + c.end_mass_kg };
            y[i] = diag * phi[i] + c.me * (left + right);
        }
        solve_tridiag(2.0 * c.ke, c.ke, -c.ke, &mut y, &mut scratch);
        let norm = y.iter().map(|v| v * v).sum::<f64>().sqrt();
        for (p, v) in phi.iter_mut().zip(&y) {
            *p = v / norm;
        }
        c.k_times(&phi, &mut kphi);
        let num: f64 = phi.iter().zip(&kphi).map(|(a, b)| a * b).sum();
        let den = 2.0 * c.energy_j(&zeros, &phi); // φᵀMφ
        let next = num / den;
        let done = (next - omega2).abs() <= 1e-15 * next;
        omega2 = next;
        if done {
            break;
        }
    }
    omega2.sqrt()
}

/// The state of one side: nodal displacement, velocity and acceleration of the free nodes
/// (downward, relative to the rigid motion), with work buffers (not part of the state: two
/// states are equal when their nodes' q, v and a are).
#[derive(Debug, Clone)]
pub(crate) struct SideState {
    pub q: Vec<f64>,
    pub v: Vec<f64>,
    pub a: Vec<f64>,
    pub(super) rhs: Vec<f64>,
    pub(super) scratch: Vec<f64>,
    pub(super) mid_q: Vec<f64>,
    pub(super) mid_v: Vec<f64>,
}

impl PartialEq for SideState {
    fn eq(&self, other: &Self) -> bool {
        self.q == other.q && self.v == other.v && self.a == other.a
    }
}

impl SideState {
    /// Static equilibrium `K q = F` at rest; the nodal accelerations solve `M a = F − K q = 0`
    /// up to round-off (computed, so a start with a load step is consistent).
    pub fn at_equilibrium(c: &Coeffs, n: usize) -> Self {
        let mut s = Self {
            q: vec![0.0; n],
            v: vec![0.0; n],
            a: vec![0.0; n],
            rhs: vec![0.0; n],
            scratch: vec![0.0; n],
            mid_q: vec![0.0; n],
            mid_v: vec![0.0; n],
        };
        for i in 0..n {
            s.q[i] = c.load(i, n);
        }
        solve_tridiag(2.0 * c.ke, c.ke, -c.ke, &mut s.q, &mut s.scratch);
        s.refresh_accel(c);
        s
    }

    /// Adds `offset_m · ξ_i` to the displacements (the static shape of an extra end force) and
    /// recomputes the accelerations.
    pub fn displace(&mut self, c: &Coeffs, offset_m: f64) {
        let n = self.q.len();
        for (i, q) in self.q.iter_mut().enumerate() {
            *q += offset_m * (i + 1) as f64 / n as f64;
        }
        self.refresh_accel(c);
    }

    /// `M a = F − K(q + βv)`.
    pub fn refresh_accel(&mut self, c: &Coeffs) {
        let n = self.q.len();
        for i in 0..n {
            self.mid_q[i] = self.q[i] + c.beta_s * self.v[i];
        }
        c.k_times(&self.mid_q, &mut self.rhs);
        for i in 0..n {
            self.rhs[i] = c.load(i, n) - self.rhs[i];
        }
        solve_tridiag(4.0 * c.me, 2.0 * c.me + c.end_mass_kg, c.me, &mut self.rhs, &mut self.scratch);
        self.a.copy_from_slice(&self.rhs);
    }

    /// One trapezoidal (Newmark average-acceleration) step of length `dt` to the coefficients
    /// `c` of the step end:
    /// `(M + (dt/2)C + (dt²/4)K) a⁺ = F⁺ − C(v + (dt/2)a) − K(q + dt·v + (dt²/4)a)`,
    /// `v⁺ = v + (dt/2)(a + a⁺)`, `q⁺ = q + dt·v + (dt²/4)(a + a⁺)`.
    /// Returns the work the changing coefficients did over the step,
    /// `E(c⁺; q̄, v̄) − E(c⁻; q̄, v̄)` at the mid-step state, and the dissipated energy
    /// `dt·v̄ᵀ C̄ v̄`.
    /// With `energy` false the work and dissipation are not computed (returned as 0).
    pub fn step(&mut self, before: &Coeffs, c: &Coeffs, dt: f64, energy: bool) -> (f64, f64) {
        let m = self.predict(c, dt);
        solve_tridiag(m.0, m.1, m.2, &mut self.rhs, &mut self.scratch);
        self.finish(before, c, dt, energy)
    }

    /// The predictor of [`Self::step`] and its right-hand side `F − K(q_pred + β v_pred)` (in
    /// `rhs`); returns the effective matrix's interior diagonal, last diagonal and off-diagonal.
    fn predict(&mut self, c: &Coeffs, dt: f64) -> (f64, f64, f64) {
        let n = self.q.len();
        let h2 = 0.25 * dt * dt;
        for i in 0..n {
            let vp = self.v[i] + 0.5 * dt * self.a[i];
            let qp = self.q[i] + dt * self.v[i] + h2 * self.a[i];
            self.mid_v[i] = vp;
            self.mid_q[i] = qp;
            self.scratch[i] = qp + c.beta_s * vp;
        }
        c.load_minus_k_times(&self.scratch, &mut self.rhs);
        let gamma = 0.5 * dt * c.beta_s + h2;
        (4.0 * c.me + 2.0 * gamma * c.ke, 2.0 * c.me + c.end_mass_kg + gamma * c.ke, c.me - gamma * c.ke)
    }

    /// The corrector of [`Self::step`], with the new accelerations in `rhs`.
    fn finish(&mut self, before: &Coeffs, c: &Coeffs, dt: f64, energy: bool) -> (f64, f64) {
        let n = self.q.len();
        let h2 = 0.25 * dt * dt;
        if !energy {
            for i in 0..n {
                let a_new = self.rhs[i];
                self.v[i] = self.mid_v[i] + 0.5 * dt * a_new;
                self.q[i] = self.mid_q[i] + h2 * a_new;
                self.a[i] = a_new;
            }
            return (0.0, 0.0);
        }
        for i in 0..n {
            let a_new = self.rhs[i];
            let v_new = self.mid_v[i] + 0.5 * dt * a_new;
            let q_new = self.mid_q[i] + h2 * a_new;
            // mid-step state for the work and dissipation
            self.mid_q[i] = 0.5 * (self.q[i] + q_new);
            self.mid_v[i] = 0.5 * (self.v[i] + v_new);
            self.q[i] = q_new;
            self.v[i] = v_new;
            self.a[i] = a_new;
        }
        let f = Forms::new(&self.mid_q, &self.mid_v);
        let work = c.energy_of(&f) - before.energy_of(&f);
        let dissipated = 0.5 * dt * (c.beta_s * c.ke + before.beta_s * before.ke) * f.strain_rate;
        (work, dissipated)
    }

    /// Total tension of the side at the tangent point (the reaction of node 0), N:
    /// `P₀ = k_e q₁ + βk_e v₁ − m_e a₁ + w/2`.
    pub fn top_tension_n(&self, c: &Coeffs) -> f64 {
        c.ke * (self.q[0] + c.beta_s * self.v[0]) - c.me * self.a[0] + 0.5 * c.w_n
    }

    /// Total tension of the side at the conveyance (the ropes' pull on the end mass), N, from the
    /// end mass's own equation of motion: `P(L) = M_s (g − a_s) − M_s ü_n`.
    pub fn anchor_tension_n(&self, c: &Coeffs) -> f64 {
        c.end_load_n - c.end_mass_kg * self.a.last().copied().unwrap_or(0.0)
    }

    /// Total tension of the side halfway down its hanging length, N: the element tension
    /// `P_i = k_e (q_i − q_{i−1}) + β k_e (v_i − v_{i−1})` (q₀ = 0 at the tangent point), the
    /// mean of the two elements meeting at the middle node for an even `n`, the middle
    /// element's for an odd `n`. Linear elements with consistent loads give the exact tension
    /// at an element's midpoint in static equilibrium (it varies linearly there), so the mean at
    /// the node is exact too.
    pub fn mid_tension_n(&self, c: &Coeffs) -> f64 {
        let n = self.q.len();
        let element = |i: usize| {
            // Element i (1-based) joins nodes i − 1 and i.
            let (q0, v0) = if i == 1 { (0.0, 0.0) } else { (self.q[i - 2], self.v[i - 2]) };
            c.ke * ((self.q[i - 1] - q0) + c.beta_s * (self.v[i - 1] - v0))
        };
        if n.is_multiple_of(2) { 0.5 * (element(n / 2) + element(n / 2 + 1)) } else { element(n / 2 + 1) }
    }

    /// Elastic displacement of the end mass (rope elongation at the conveyance), m.
    pub fn end_stretch_m(&self) -> f64 {
        self.q.last().copied().unwrap_or(0.0)
    }

    /// Whether the state is finite. Checking the first and the last node suffices after a step:
    /// the Thomas forward sweep carries any non-finite value into the last unknown and the back
    /// substitution carries that into every node.
    pub fn is_finite(&self) -> bool {
        let n = self.q.len();
        [self.q[0], self.q[n - 1], self.v[0], self.a[0]].iter().all(|x| x.is_finite())
    }
}
