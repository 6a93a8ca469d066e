//! A lift run and what it writes: the checks and each traction case's wrap
//! ([`evaluate`]); summary.json (the checks with value and limit, one entry per case under
//! `scenes`), summary.csv (a row per case), `<case>/distribution.csv` (and `.png`), and the
//! terminal table. The report directory is put in place whole or not at all, as a hoist's.

use super::cases::Case;
use super::checks::{self, Limits, Traction};
use super::rope::{self, SheaveSource};
use super::verdict;
use super::wrap::{CaseWrap, Margins, case_wrap, margins};
use crate::check::Check;
use crate::design::lift::{Lift, RULE_SET};
use crate::report::checklist::headline;
use crate::report::verdict::Overview;
use serde::Serialize;
use std::fmt::Write as _;

/// Output grid pitches of a case's distribution.
pub const NODES: usize = 720;

/// One traction case in the summary (the hoist's scene fields where they apply).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CaseSummary {
    /// The case's name.
    pub name: &'static str,
    /// Always `"traction-case"`.
    pub kind: &'static str,
    /// The model level: 0 (`check`: the capstan law only), 1 (`run`: the distribution by creep theory).
    pub level: u8,
    /// Side-1 tension per rope at the sheave (N).
    pub t1_n: f64,
    /// Side-2 tension per rope (N).
    pub t2_n: f64,
    /// Rope speed at the sheave, positive side 1 → side 2 (m/s).
    pub speed_m_s: f64,
    /// Rope acceleration at the sheave, positive when side 1 accelerates up (m/s²).
    pub accel_m_s2: f64,
    /// The case's friction coefficient μ (rule set en81-50).
    pub mu: f64,
    /// The groove factor f that stands for μ in the capstan law.
    pub groove_factor: f64,
    /// Wrap angle α (deg).
    pub wrap_angle_deg: f64,
    /// `e^{fα}`.
    pub euler_limit: f64,
    /// `T_hi/T_lo` (null when the lower tension is 0).
    pub tension_ratio: Option<f64>,
    /// Active (creep) arc ln(T_hi/T_lo)/f (deg).
    pub dynamic_angle_deg: Option<f64>,
    /// α − ln(T_hi/T_lo)/f (deg; negative: arc missing to hold).
    pub reserve_angle_deg: Option<f64>,
    /// Idle (stick) arc (deg; level 1).
    pub idle_arc_deg: Option<f64>,
    /// Arc of positive friction (deg; level 1).
    pub positive_arc_deg: Option<f64>,
    /// Arc of reverse friction (deg; level 1).
    pub reverse_arc_deg: Option<f64>,
    /// Demarcation point (deg from the side-1 tangent point; level 1), null without one.
    pub jdp_deg: Option<f64>,
    /// Peak friction utilization |q|/(fn) (level 1).
    pub max_utilization: Option<f64>,
    /// Whether the ropes slide over the whole wrap (the ratio exceeds e^{fα}).
    pub gross_slip: bool,
    /// Whether the case requires the ropes to slip (car stalled).
    pub must_slip: bool,
    /// The friction coefficient μ at which the state starts to slip.
    pub critical_mu: Option<f64>,
    /// The load in the car at which traction is lost in this case (loaded-car cases).
    pub traction_loss_load_kg: Option<f64>,
    /// Whether the case meets its requirement (holds, or slips for the stalled car).
    pub checks_pass: bool,
}

/// One traction case of a run.
#[derive(Debug, Clone)]
pub struct LiftCase {
    /// The case's tensions and verdict.
    pub traction: Traction,
    /// Its margins (level 0).
    pub margins: Margins,
    /// Its wrap at level 1 (`None` for `check`).
    pub wrap: Option<CaseWrap>,
}

/// A lift run: the checks and the cases with their wraps.
#[derive(Debug, Clone)]
pub struct LiftRun {
    /// Every check, in report order.
    pub checks: Vec<Check>,
    /// The traction cases: each with its margins and, at level 1, its wrap.
    pub cases: Vec<LiftCase>,
    /// Run time (ms).
    pub runtime_ms: f64,
}

impl LiftRun {
    /// Whether every binding check passes.
    pub fn all_checks_pass(&self) -> bool {
        crate::check::all_pass(&self.checks)
    }
}

/// Runs the checks and, with `wraps`, each case's level-1 wrap.
pub fn evaluate(lift: &Lift, wraps: bool) -> Result<LiftRun, String> {
    let start = std::time::Instant::now();
    let limits = Limits::of(lift)?;
    let (checks, cases) = checks::all(lift, &limits);
    let cases = cases
        .into_iter()
        .map(|t| {
            let wrap = if wraps { Some(case_wrap(lift, &t, NODES)?) } else { None };
            Ok(LiftCase { margins: margins(lift, &t), traction: t, wrap })
        })
        .collect::<Result<Vec<_>, String>>()?;
    Ok(LiftRun { checks, cases, runtime_ms: start.elapsed().as_secs_f64() * 1e3 })
}

fn case_summary(lift: &Lift, case: &LiftCase) -> CaseSummary {
    let deg = f64::to_degrees;
    let (t, m, w) = (&case.traction, &case.margins, case.wrap.as_ref());
    CaseSummary {
        name: t.case.name(),
        kind: "traction-case",
        level: u8::from(w.is_some()),
        t1_n: t.tensions.t1_n,
        t2_n: t.tensions.t2_n,
        speed_m_s: t.tensions.speed_m_s,
        accel_m_s2: t.tensions.accel_m_s2,
        mu: t.mu,
        groove_factor: t.f,
        wrap_angle_deg: deg(lift.wrap_angle_rad),
        euler_limit: t.euler_limit,
        tension_ratio: t.ratio,
        dynamic_angle_deg: m.reserve_arc_rad.map(|r| deg(lift.wrap_angle_rad - r)),
        reserve_angle_deg: m.reserve_arc_rad.map(deg),
        idle_arc_deg: w.map(|w| deg(w.summary.idle_arc_rad)),
        positive_arc_deg: w.map(|w| deg(w.summary.positive_arc_rad)),
        reverse_arc_deg: w.map(|w| deg(w.summary.reverse_arc_rad)),
        jdp_deg: w.and_then(|w| w.summary.jdp_rad.map(deg)),
        max_utilization: w.map(|w| w.summary.max_utilization),
        gross_slip: t.ratio.is_none_or(|r| r > t.euler_limit),
        must_slip: t.case.must_slip(),
        critical_mu: m.critical_mu,
        traction_loss_load_kg: m.traction_loss_load_kg,
        checks_pass: t.holds(),
    }
}

/// The rule set a lift is judged by.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CodeRef {
    /// Its id.
    pub id: &'static str,
    /// The code's name.
    pub code: String,
    /// The edition.
    pub edition: String,
}

/// summary.json of a lift run.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LiftSummary {
    /// The sheet as given.
    pub sheet: String,
    /// The design's title.
    pub title: String,
    /// Program version.
    pub version: &'static str,
    /// Always `"lift"`.
    pub kind: &'static str,
    /// Whether every binding check passes (exit status 0).
    pub all_checks_pass: bool,
    /// One line: the verdicts counted, as a hoist's headline.
    pub headline: String,
    /// How many checks are warnings.
    pub warnings: usize,
    /// How many checks are not judged (not evaluated, with the reason in the check's note).
    pub unjudged: usize,
    /// What the verdict rests on: the governing check, each failure and warning with its
    /// sentence, the checks not judged with their reason (as a hoist's `verdict`).
    pub verdict: Overview,
    /// How the ropes wrap the sheave: `"single"` or `"double"`.
    pub wrap: &'static str,
    /// What stops the machine hauling a stalled car or counterweight: `"ropes-slip"` (the
    /// stalled cases judged) or `"electric-safety-device"` (declared; reported, not judged).
    pub stalled_protection: &'static str,
    /// N_equiv(t) of the traction sheave, all passes (null where neither given nor in Table 2).
    pub n_equiv_t: Option<f64>,
    /// Where N_equiv(t) comes from: `"table"` (EN 81-50 Table 2), `"sheet"` (lift.n_equiv_t,
    /// overriding the table) or `"none"`.
    pub n_equiv_t_source: &'static str,
    /// Run time (ms).
    pub runtime_ms: f64,
    /// The rule set.
    pub code: Option<CodeRef>,
    /// The traction cases.
    pub scenes: Vec<CaseSummary>,
    /// Every check with value and limit.
    pub checks: Vec<Check>,
}

impl LiftSummary {
    /// The summary of `run`.
    pub fn of(lift: &Lift, run: &LiftRun) -> Self {
        let tally = verdict::tally(&run.checks);
        let eq = rope::equivalent(lift).ok();
        let n_equiv_t_source = match eq.as_ref().map(|e| &e.sheave_source) {
            Some(SheaveSource::Sheet) => "sheet",
            Some(SheaveSource::Table { .. }) => "table",
            None => "none",
        };
        Self {
            sheet: lift.sheet.clone(),
            title: lift.title.clone(),
            version: env!("CARGO_PKG_VERSION"),
            kind: "lift",
            all_checks_pass: run.all_checks_pass(),
            headline: headline(run.all_checks_pass(), &tally),
            warnings: tally.warnings,
            unjudged: tally.unjudged,
            verdict: verdict::overview(&run.checks),
            wrap: lift.wrap.word(),
            stalled_protection: lift.stalled_protection.word(),
            n_equiv_t: eq.map(|e| e.sheave),
            n_equiv_t_source,
            runtime_ms: run.runtime_ms,
            code: crate::codes::find(RULE_SET).map(|s| CodeRef { id: RULE_SET, code: s.code, edition: s.edition }),
            scenes: run.cases.iter().map(|c| case_summary(lift, c)).collect(),
            checks: run.checks.clone(),
        }
    }

    /// Pretty JSON.
    pub fn to_json(&self) -> String {
        serde_json::to_string_pretty(self).unwrap_or_else(|e| format!("{{\"error\": \"{e}\"}}"))
    }
}

/// The terminal table: every check with value, limit, verdict and clause, then each case's wrap.
pub fn table(lift: &Lift, run: &LiftRun) -> String {
    let mut out = format!("{} ({}), lift sheet, rule set {RULE_SET}\n\nChecks:\n", lift.title, lift.sheet);
    for c in &run.checks {
        let value = c.value.map_or_else(|| "—".to_string(), |v| format!("{v:.4}"));
        let limit = c.limit.map_or_else(|| "—".to_string(), |v| format!("{v:.4}"));
        let _ = writeln!(out, "  {:<8} {:<40} {value} {} {limit}", c.verdict.label(), c.name, c.relation.symbol());
        let _ = writeln!(out, "           {} [{}: {}]", c.formula, c.code, c.clause);
        if let Some(note) = &c.note {
            let _ = writeln!(out, "           note: {note}");
        }
    }
    let _ = writeln!(
        out,
        "\nCases (f in place of μ; arcs and JDP at level 1, by `run`):\n  {:<22} {:>9} {:>9} {:>8} {:>8} {:>9} {:>8} {:>8} {:>10}",
        "case", "T1/T2", "e^fα", "f", "idle°", "reserve°", "JDP°", "μ_crit", "slip"
    );
    for case in &run.cases {
        let s = case_summary(lift, case);
        let opt = |x: Option<f64>, p: usize| x.map_or_else(|| "—".to_string(), |v| format!("{v:.p$}"));
        let _ = writeln!(
            out,
            "  {:<22} {:>9} {:>9.4} {:>8.4} {:>8} {:>9} {:>8} {:>8} {:>10}",
            s.name,
            opt(s.tension_ratio, 4),
            s.euler_limit,
            s.groove_factor,
            opt(s.idle_arc_deg, 1),
            opt(s.reserve_angle_deg, 1),
            opt(s.jdp_deg, 1),
            opt(s.critical_mu, 4),
            if s.gross_slip { "gross slip" } else { "holds" }
        );
        if let Some(load) = s.traction_loss_load_kg {
            let _ = writeln!(out, "  {:<22} traction lost at {load:.1} kg in the car", "");
        }
    }
    let summary = LiftSummary::of(lift, run);
    let _ = writeln!(out, "\nVerdict:");
    if let Some(g) = summary.verdict.governing_line() {
        let _ = writeln!(out, "  {g}");
    }
    for e in summary.verdict.attention.iter().chain(&summary.verdict.unjudged) {
        let _ = writeln!(out, "  {} {}: {}", e.verdict.label(), e.check, e.explanation);
    }
    let _ = writeln!(out, "\n{}", summary.headline);
    out
}

/// The cases, for callers that list them.
pub fn case_names() -> Vec<&'static str> {
    Case::ALL.iter().map(|c| c.name()).collect()
}
