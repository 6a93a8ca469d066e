//! What the run's verdict rests on, in words: the governing check (a failure first, then a
//! warning, then the judged check nearest its limit) and, for every warning, failure and
//! unjudged check, one sentence in engineering terms — what it means for the hoist, what would
//! make it binding, what margin remains. The terminal, summary.json and the first page of
//! report.html print these same records beside the headline of [`super::checklist`].

use super::check_text::number as num;
use super::checklist::{self, CheckRow};
use crate::check::{Check, Relation, Verdict};
use crate::model::level4::ROPE_DYNAMICS_CHECK;
use crate::run::RunResult;
use serde::Serialize;

/// One check named in the verdict, with its sentence.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Entry {
    /// The scene's name, or `design` for a check of the design as a whole.
    pub group: String,
    /// The check's name, as in the report.
    pub check: String,
    /// Its typed outcome.
    pub verdict: Verdict,
    /// Its value (`None`: unbounded or not evaluated).
    pub value: Option<f64>,
    /// Its limit (`None`: no requirement given).
    pub limit: Option<f64>,
    /// The unit of value and limit.
    pub unit: String,
    /// `value/limit − 1` for a minimum, `1 − value/limit` for a maximum.
    pub margin: Option<f64>,
    /// The case that governs it, where it is taken over several.
    pub governing_case: Option<String>,
    /// What the verdict means for the hoist.
    pub explanation: String,
}

/// The checks the verdict names: the governing one and those that are not plain passes.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Overview {
    /// The failing check with the least margin, else the warning with the least, else the
    /// passing check nearest its limit.
    pub governing: Option<Entry>,
    /// Failures, then warnings, each with its sentence.
    pub attention: Vec<Entry>,
    /// The checks not judged (no requirement given, not evaluated), each saying why.
    pub unjudged: Vec<Entry>,
}

impl Overview {
    /// The overview of `run`.
    pub fn of(run: &RunResult) -> Self {
        let rows = checklist::rows(run);
        let rank = |v: Verdict| match v {
            Verdict::Fail => 0,
            Verdict::Warning => 1,
            _ => 2,
        };
        let key = |r: &&CheckRow| (rank(r.check.verdict), checklist::margin(r.check).unwrap_or(f64::INFINITY));
        let governing = rows
            .iter()
            .filter(|r| matches!(r.check.verdict, Verdict::Pass | Verdict::Fail | Verdict::Warning))
            .filter(|r| checklist::margin(r.check).is_some_and(f64::is_finite))
            .min_by(|a, b| {
                let (ra, ma) = key(a);
                let (rb, mb) = key(b);
                ra.cmp(&rb).then(ma.total_cmp(&mb))
            })
            .map(entry);
        let mut attention: Vec<_> =
            rows.iter().filter(|r| matches!(r.check.verdict, Verdict::Fail | Verdict::Warning)).collect();
        attention.sort_by_key(|r| rank(r.check.verdict));
        let unjudged = rows
            .iter()
            .filter(|r| matches!(r.check.verdict, Verdict::NoRequirement | Verdict::NotEvaluated))
            .map(entry)
            .collect();
        Self { governing, attention: attention.into_iter().map(entry).collect(), unjudged }
    }

    /// The governing check in one line, e.g. "governing check: dynamic safety factor \[design\],
    /// 1.7398 ≥ 1.2500, margin +39.2 %, at payload 30000 kg, …".
    pub fn governing_line(&self) -> Option<String> {
        let g = self.governing.as_ref()?;
        let margin = g.margin.map_or_else(String::new, |m| format!(", margin {:+.1} %", 100.0 * m));
        let case = g.governing_case.as_deref().map_or_else(String::new, |c| format!(", at {c}"));
        Some(format!(
            "governing check: {} [{}], {} {}{margin}{case}",
            g.check,
            g.group,
            g.value.map_or_else(|| "—".into(), num),
            g.verdict.label()
        ))
    }
}

fn entry(r: &CheckRow) -> Entry {
    let c = r.check;
    Entry {
        group: r.group.to_string(),
        check: c.name.to_string(),
        verdict: c.verdict,
        value: c.value,
        limit: c.limit,
        unit: c.unit.to_string(),
        margin: checklist::margin(c),
        governing_case: c.governing_case.clone(),
        explanation: explain(c),
    }
}

/// The sentence a check's verdict carries.
pub fn explain(c: &Check) -> String {
    let unit = if c.unit.is_empty() { String::new() } else { format!(" {}", c.unit) };
    let at = c.governing_case.as_deref().map_or_else(String::new, |g| format!(" at {g}"));
    match (c.verdict, c.value, c.limit) {
        (Verdict::NoRequirement, _, _) => "No requirement given: reported, not judged; a limit under \
             [requirements] or a rule set's would judge it."
            .into(),
        (Verdict::NotEvaluated, _, _) => {
            format!("Not evaluated: {}.", c.note.as_deref().unwrap_or("an input the check needs is missing"))
        }
        (Verdict::Warning, Some(v), Some(l)) if c.name == ROPE_DYNAMICS_CHECK => with_margin(
            format!(
                "With the suspended ropes' dynamics the grip's reserve{at} is σ = {v:.3}, below the minimum {l:.3}: \
                 the tension difference there could grow by {:.1} % before the ropes slip on the pulley, less \
                 than the code's reserve asks. The design is judged on the code's rigid-rope factor \
                 (requirements.dynamic_safety_factor_basis = \"code\"); with the basis \"rope-dynamics\" this check \
                 is binding and fails.",
                100.0 * (v - 1.0).max(0.0)
            ),
            c,
        ),
        (Verdict::Warning, Some(v), Some(l)) => with_margin(
            format!(
                "{} = {}{unit}{at} is beyond {} {}{unit}, a limit that does not decide the design{}.",
                c.name,
                num(v),
                c.relation.symbol(),
                num(l),
                c.note.as_deref().map_or_else(String::new, |n| format!(": {n}")),
            ),
            c,
        ),
        (Verdict::Fail, Some(v), Some(l)) => with_margin(
            format!(
                "{} = {}{unit}{at} violates the binding limit {} {}{unit}: the design fails.",
                c.name,
                num(v),
                c.relation.symbol(),
                num(l)
            ),
            c,
        ),
        (Verdict::Fail, _, _) => {
            format!("{} fails{at}{}.", c.name, c.note.as_deref().map_or_else(String::new, |n| format!(": {n}")))
        }
        (v, _, _) => format!("{}{at}: {}.", c.name, v.label()),
    }
}

/// Appends the margin to the limit, in words.
fn with_margin(text: String, c: &Check) -> String {
    match checklist::margin(c) {
        Some(m) if m < 0.0 => {
            let side = if c.relation == Relation::AtLeast { "below the minimum" } else { "above the maximum" };
            format!("{text} It is {:.1} % {side}.", -100.0 * m)
        }
        Some(m) => format!("{text} Margin to the limit: {:+.1} %.", 100.0 * m),
        None => text,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::Check;
    use crate::design::Limit;

    fn check(value: f64, limit: f64, binding: bool) -> Check {
        Check::new("dynamic safety factor", "σ", Some(value), "").against(
            Relation::AtLeast,
            Some(&Limit::computed(limit, "test")),
            binding,
        )
    }

    #[test]
    fn a_warning_says_how_far_it_is_from_its_limit() {
        // 1.026 against 1.25: 1 − 1.026/1.25 = 17.92 % below the minimum.
        let w = check(1.026, 1.25, false);
        assert_eq!(w.verdict, Verdict::Warning);
        let s = explain(&w);
        assert!(s.contains("does not decide the design") && s.contains("17.9 % below the minimum"), "{s}");
        let f = check(1.026, 1.25, true);
        assert!(explain(&f).contains("the design fails"), "{}", explain(&f));
        // A pass is no warning: 1.5 against 1.25 gives +20.0 % margin, said as such.
        let mut p = check(1.5, 1.25, false);
        p.verdict = Verdict::Warning;
        assert!(explain(&p).contains("Margin to the limit: +20.0 %"), "{}", explain(&p));
    }
}
