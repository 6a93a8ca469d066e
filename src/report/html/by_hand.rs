//! Section 7: the checks to be redone by hand, each once. A check is evaluated in many cases
//! (every scene, and the design as a whole over the load-case matrix); the same formula is
//! printed once, with the inputs and intermediate values of its governing case — the case with
//! the least margin to its limit — and the values it has in the other cases listed beside it.
//! The scenes whose cases govern a check are the ones whose figures the main body shows.

use super::checks::{limit_text, value_text, verdict_html};
use super::{Context, esc};
use crate::check::{Check, Quantity};
use crate::report::checklist::{DESIGN_GROUP, margin};
use crate::report::table::state_label;
use crate::run::RunResult;
use std::fmt::Write;
use std::io;

/// Where a check was evaluated: a scene (its index in the run) or the design as a whole.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Case {
    /// The scene of this index in [`RunResult::scenes`].
    Scene(usize),
    /// The design as a whole (the load-case matrix and the checks beside anti-slip).
    Design,
}

/// One check, all the cases it was evaluated in, and the one that governs.
pub struct Evaluated<'a> {
    /// The governing case's record (least margin to the limit).
    pub governing: (Case, &'a Check),
    /// Every case, the governing one included, in report order.
    pub cases: Vec<(Case, &'a Check)>,
}

/// Every check of the run once: the records of the same name and formula gathered, in the order
/// first met (scenes first, then the design), each with its governing case.
pub fn evaluated(run: &RunResult) -> Vec<Evaluated<'_>> {
    let scenes =
        run.scenes.iter().enumerate().flat_map(|(i, s)| s.classical.checks.iter().map(move |c| (Case::Scene(i), c)));
    let design = run.design.iter().flat_map(|d| d.checks.iter().map(|c| (Case::Design, c)));
    let mut all: Vec<Vec<(Case, &Check)>> = Vec::new();
    for (case, c) in scenes.chain(design) {
        match all.iter_mut().find(|g| g[0].1.name == c.name && g[0].1.formula == c.formula) {
            Some(g) => g.push((case, c)),
            None => all.push(vec![(case, c)]),
        }
    }
    all.into_iter()
        .map(|cases| {
            // Least margin first; a record without a margin (no limit, not evaluated) last.
            let governing = *cases
                .iter()
                .min_by(|a, b| {
                    let (ma, mb) = (margin(a.1).unwrap_or(f64::INFINITY), margin(b.1).unwrap_or(f64::INFINITY));
                    ma.total_cmp(&mb)
                })
                .unwrap_or(&cases[0]);
            Evaluated { governing, cases }
        })
        .collect()
}

/// The scenes whose cases govern a check, each with the names of the checks it governs, in
/// scene order.
pub fn governing_scenes(run: &RunResult) -> Vec<(usize, Vec<&'static str>)> {
    let mut scenes: Vec<(usize, Vec<&'static str>)> = Vec::new();
    for e in evaluated(run) {
        let (Case::Scene(i), c) = e.governing else { continue };
        if margin(c).is_none() {
            continue;
        }
        match scenes.iter_mut().find(|(j, _)| *j == i) {
            Some((_, names)) => names.push(c.name),
            None => scenes.push((i, vec![c.name])),
        }
    }
    scenes.sort_by_key(|(i, _)| *i);
    scenes
}

/// The name of a case as the report prints it.
fn case_name(run: &RunResult, case: Case) -> &str {
    match case {
        Case::Scene(i) => run.scenes.get(i).map_or("", |s| s.name.as_str()),
        Case::Design => DESIGN_GROUP,
    }
}

/// 7. Every check once, with everything needed to redo it by hand.
pub fn details(out: &mut String, ctx: &Context) -> io::Result<()> {
    out.push_str("<p>Each check once, with the inputs and intermediate values of its governing case (the least margin to its limit); its values in the other cases follow it, and every case's verdict is in Appendix B, table B.4. Tensions per rope; σ = ∞ when T1 = T2.</p>\n");
    for e in evaluated(ctx.run) {
        let (case, c) = e.governing;
        let where_ = match case {
            Case::Scene(i) => {
                let s = &ctx.run.scenes[i];
                let at = c.governing_case.clone().unwrap_or_else(|| state_label(&s.classical.state));
                format!("scene {} (level {}): {}", s.name, s.plan.level, at)
            }
            Case::Design => format!("the design as a whole: {}", c.governing_case.as_deref().unwrap_or("—")),
        };
        let others: Vec<String> = e
            .cases
            .iter()
            .filter(|(k, _)| *k != case)
            .map(|(k, o)| format!("{} {}", case_name(ctx.run, *k), value_text(o)))
            .collect();
        check_block(out, c, &where_, &others.join("; "));
    }
    Ok(())
}

fn check_block(out: &mut String, c: &Check, case: &str, others: &str) {
    let fmt_q = |qs: &[Quantity]| qs.iter().map(|q| esc(&q.display())).collect::<Vec<_>>().join("; ");
    let _ = write!(
        out,
        "<div class=\"check\"><p><b>{}</b>: <span class=\"mono\">{} {}</span> {}</p><dl><dt>governing case</dt><dd>{}</dd><dt>formula</dt><dd class=\"mono\">{}</dd>",
        esc(c.name),
        value_text(c),
        if c.limit.is_some() { limit_text(c) } else { String::new() },
        verdict_html(c.verdict),
        esc(case),
        esc(c.formula)
    );
    let rows: [(&str, String); 6] = [
        ("inputs", fmt_q(&c.inputs)),
        ("values", fmt_q(&c.intermediates)),
        ("rule", esc(&format!("{}: {}", c.code, c.clause))),
        ("limit", c.limit_source.as_deref().map(esc).unwrap_or_default()),
        ("note", c.note.as_deref().map(esc).unwrap_or_default()),
        ("other cases", esc(others)),
    ];
    for (k, v) in rows.iter().filter(|(_, v)| !v.is_empty()) {
        let class = if *k == "other cases" { "small" } else { "mono" };
        let _ = write!(out, "<dt>{k}</dt><dd class=\"{class}\">{v}</dd>");
    }
    out.push_str("</dl></div>\n");
}
