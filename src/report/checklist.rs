//! Every check of a run in report order: each scene's checks, then the design as a whole (the
//! checks beside anti-slip and the load-case matrix's checks at their governing cases). The
//! calculation report and the workbook list these same records.

use crate::check::{Check, Verdict};
use crate::run::RunResult;

/// Where the checks of the design as a whole are listed.
pub const DESIGN_GROUP: &str = "design";

/// One check and the scene (or [`DESIGN_GROUP`]) it belongs to.
#[derive(Debug, Clone, Copy)]
pub struct CheckRow<'a> {
    /// The scene's name, or [`DESIGN_GROUP`] for a check of the design as a whole.
    pub group: &'a str,
    /// The check record itself.
    pub check: &'a Check,
}

/// The checks of `run`, scene by scene, then the design's; an informational scene's checks
/// stand outside ([`informational_rows`]).
pub fn rows(run: &RunResult) -> Vec<CheckRow<'_>> {
    let scenes = run
        .scenes
        .iter()
        .filter(|s| !s.informational)
        .flat_map(|s| s.classical.checks.iter().map(|check| CheckRow { group: &s.name, check }));
    let design = run.design.iter().flat_map(|d| d.checks.iter().map(|check| CheckRow { group: DESIGN_GROUP, check }));
    scenes.chain(design).collect()
}

/// The checks of the informational (what-if) scenes, outside the verdict.
pub fn informational_rows(run: &RunResult) -> Vec<CheckRow<'_>> {
    run.scenes
        .iter()
        .filter(|s| s.informational)
        .flat_map(|s| s.classical.checks.iter().map(|check| CheckRow { group: &s.name, check }))
        .collect()
}

/// The margin of a check to its limit, relative to the limit: positive when it passes
/// (`value/limit − 1` for a minimum, `1 − value/limit` for a maximum); `None` without a value
/// or a limit.
pub fn margin(check: &Check) -> Option<f64> {
    let (v, l) = (check.value?, check.limit?);
    if l == 0.0 {
        return None;
    }
    Some(match check.relation {
        crate::check::Relation::AtLeast => v / l - 1.0,
        crate::check::Relation::AtMost => 1.0 - v / l,
    })
}

/// How many checks of a run end in each verdict, from their typed verdicts.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, serde::Serialize)]
pub struct Tally {
    /// Checks that meet their limit.
    pub pass: usize,
    /// Checks that violate a binding limit.
    pub fail: usize,
    /// Checks beyond a limit that does not decide the design.
    pub warnings: usize,
    /// Checks not judged: no requirement given, or not evaluated for a missing input.
    pub unjudged: usize,
}

/// The verdicts of every check of `run` counted (the scenes' and the design's).
pub fn tally(run: &RunResult) -> Tally {
    let mut t = Tally::default();
    for r in rows(run) {
        match r.check.verdict {
            Verdict::Pass => t.pass += 1,
            Verdict::Fail => t.fail += 1,
            Verdict::Warning => t.warnings += 1,
            Verdict::NoRequirement | Verdict::NotEvaluated => t.unjudged += 1,
        }
    }
    t
}

/// The run's headline: never "all checks pass" while a warning stands or a check is unjudged.
pub fn headline(all_binding_pass: bool, t: &Tally) -> String {
    let plural = |n: usize, one: &str, many: &str| format!("{n} {}", if n == 1 { one } else { many });
    let mut rest = Vec::new();
    if t.warnings > 0 {
        rest.push(plural(t.warnings, "warning", "warnings"));
    }
    if t.unjudged > 0 {
        rest.push(
            plural(t.unjudged, "check not judged", "checks not judged") + " (no requirement given or not evaluated)",
        );
    }
    match (all_binding_pass, rest.is_empty()) {
        (false, _) => {
            let mut s = format!("SOME CHECKS FAIL — {}", plural(t.fail, "failing check", "failing checks"));
            for r in rest {
                s.push_str(", ");
                s.push_str(&r);
            }
            s
        }
        (true, true) => "all checks pass".to_string(),
        (true, false) => format!("all binding checks pass — {}", rest.join(", ")),
    }
}

#[cfg(test)]
mod headline_tests {
    use super::*;

    #[test]
    fn a_warning_or_an_unjudged_check_never_reads_all_checks_pass() {
        let clean = Tally { pass: 3, ..Tally::default() };
        assert_eq!(headline(true, &clean), "all checks pass");
        let warned = Tally { pass: 3, warnings: 2, unjudged: 8, fail: 0 };
        assert_eq!(
            headline(true, &warned),
            "all binding checks pass — 2 warnings, 8 checks not judged (no requirement given or not evaluated)"
        );
        let one = Tally { pass: 3, warnings: 1, ..Tally::default() };
        assert_eq!(headline(true, &one), "all binding checks pass — 1 warning");
        let failed = Tally { pass: 1, fail: 1, warnings: 1, unjudged: 0 };
        assert_eq!(headline(false, &failed), "SOME CHECKS FAIL — 1 failing check, 1 warning");
        for t in [warned, one, failed] {
            assert!(!headline(t.fail == 0, &t).contains("all checks pass"));
        }
    }
}
