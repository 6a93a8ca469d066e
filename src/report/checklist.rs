//! Every check of a run in report order: each scene's checks, then the design as a whole (the
//! checks beside anti-slip and the load-case matrix's checks at their governing cases). The
//! calculation report and the workbook list these same records.

use crate::check::Check;
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

/// The checks of `run`, scene by scene, then the design's.
pub fn rows(run: &RunResult) -> Vec<CheckRow<'_>> {
    let scenes =
        run.scenes.iter().flat_map(|s| s.classical.checks.iter().map(|check| CheckRow { group: &s.name, check }));
    let design = run.design.iter().flat_map(|d| d.checks.iter().map(|check| CheckRow { group: DESIGN_GROUP, check }));
    scenes.chain(design).collect()
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
