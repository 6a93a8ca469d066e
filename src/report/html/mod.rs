//! `report.html`: the calculation report as one self-contained, printable document (figures
//! inline as base64 PNG, no external assets; a print stylesheet with page breaks and page
//! numbers). Its numbered sections: project and revision (the sheet's `[document]`); basis
//! (the requirements and their sources); inputs (every sheet value with its unit, and the derived
//! values); assumptions and limits of the model levels used; load cases and the governing case of
//! each check; verdicts (the pass/fail table with margins); the checks with formula, inputs and
//! intermediate values, each check once; the figures that decide a check; software (version, the
//! sheet's SHA-256, the command line, and accuracy evidence computed by this build). Then,
//! unless `[document] appendix_figures = false`, Appendix A: every other figure, two to a page;
//! then Appendix B: the tables looked up rather than read (the defaults used, the sensitivity).
//!
//! Every check is rendered from the same [`crate::check::Check`] records as the terminal table.

mod appendix_tables;
mod by_hand;
mod checks;
mod confirm;
mod dynamic_front;
mod figures;
mod front;
mod inputs;
mod keys;
mod sections;
mod software;
pub(crate) mod style;

pub use checks::verdict_html;

use super::accuracy::Evidence;
use crate::design::Design;
use crate::run::RunResult;
use sha2::{Digest, Sha256};
use std::fmt::Write;
use std::path::Path;

/// Where the report comes from: the sheet as read, and the command that ran it.
#[derive(Debug, Clone, PartialEq)]
pub struct Provenance {
    /// The sheet's text (its values are echoed under "inputs").
    pub sheet_text: String,
    /// SHA-256 of the sheet file's bytes, in lowercase hex.
    pub sheet_sha256: String,
    /// The command line that ran the sheet, one argument per entry (shown shell-quoted under
    /// "software").
    pub command_line: Vec<String>,
    /// The accuracy evidence of the build that writes the report (the bench's closed-form
    /// cases and their errors), shown under "software"; empty when not computed.
    pub accuracy: Vec<Evidence>,
}

impl Provenance {
    /// Reads the sheet file again for its hash and text.
    pub fn of(sheet: &Path, command_line: Vec<String>) -> std::io::Result<Self> {
        let bytes = std::fs::read(sheet)?;
        Ok(Self::from_bytes(&bytes, command_line))
    }

    /// The provenance of a sheet whose file held `bytes`: its hash and (lossy UTF-8) text.
    pub fn from_bytes(bytes: &[u8], command_line: Vec<String>) -> Self {
        let digest = Sha256::digest(bytes);
        let sheet_sha256 = digest.iter().fold(String::new(), |mut s, b| {
            let _ = write!(s, "{b:02x}");
            s
        });
        Self {
            sheet_text: String::from_utf8_lossy(bytes).into_owned(),
            sheet_sha256,
            command_line,
            accuracy: Vec::new(),
        }
    }

    /// The same provenance with the build's accuracy evidence.
    pub fn with_accuracy(self, accuracy: Vec<Evidence>) -> Self {
        Self { accuracy, ..self }
    }
}

/// What the report is made of; `dir` is the report directory the figures were written to.
#[derive(Clone, Copy)]
pub struct Context<'a> {
    /// The validated design the report describes.
    pub design: &'a Design,
    /// The results of the run: scenes, checks and load cases.
    pub run: &'a RunResult,
    /// The sheet and command the run came from.
    pub provenance: &'a Provenance,
    /// The report directory; each scene's figures are read from its subdirectory.
    pub dir: &'a Path,
}

/// The sections in order: (anchor, title, renderer).
type Renderer = fn(&mut String, &Context) -> std::io::Result<()>;
const SECTIONS: [(&str, &str, Renderer); 9] = [
    ("project", "Project and revision", sections::project),
    ("basis", "Basis: requirements and their sources", sections::basis),
    ("inputs", "Inputs", inputs::inputs),
    ("assumptions", "Assumptions and limits of the models used", sections::assumptions),
    ("load-cases", "Load cases and governing cases", checks::load_cases),
    ("verdicts", "Verdicts", checks::verdicts),
    ("checks", "The checks, to be redone by hand", by_hand::details),
    ("figures", "Figures that decide a check", figures::figures),
    ("software", "Software and accuracy", software::software),
];

/// The heading of the appendix, the first words after the main body.
pub const APPENDIX: &str = "Appendix A. Further figures";

/// The whole document: the main body (the numbered sections), then the appendix of further
/// figures unless the sheet leaves it out.
pub fn render(ctx: &Context) -> std::io::Result<String> {
    let d = ctx.design;
    let title = d.document.title.clone().unwrap_or_else(|| d.title.clone());
    let mut out = String::new();
    let _ = write!(
        out,
        "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n<title>{}</title>\n<style>{}{}{}</style></head><body>\n",
        esc(&title),
        style::CSS,
        style::figure_css(),
        crate::report::figure_size::print_css()
    );
    let headline =
        crate::report::checklist::headline(ctx.run.all_checks_pass(), &crate::report::checklist::tally(ctx.run));
    let verdict = headline.as_str();
    let _ = writeln!(
        out,
        "<header><p class=\"kicker\">Friction hoist design calculation — wrapcalc {}</p><h1>{}</h1>\
         <p class=\"sheet\">sheet <code>{}</code></p><p class=\"overall {}\">{verdict}</p></header>",
        env!("CARGO_PKG_VERSION"),
        esc(&title),
        esc(&d.sheet),
        if ctx.run.all_checks_pass() { "pass" } else { "fail" },
    );
    front::verdict(&mut out, ctx);
    confirm::inputs_to_confirm(&mut out, ctx);
    confirm::informational_cases(&mut out, ctx);
    dynamic_front::notes(&mut out, ctx);
    out.push_str("<nav><h2>Contents</h2><ol>");
    for (anchor, name, _) in SECTIONS {
        let _ = write!(out, "<li><a href=\"#{anchor}\">{}</a></li>", esc(name));
    }
    out.push_str("</ol>");
    let appendix = figures::has_appendix(ctx);
    if appendix {
        let _ = write!(out, "<p><a href=\"#appendix\">{APPENDIX}</a></p>");
    }
    if appendix_tables::has_tables(ctx) {
        let _ = write!(out, "<p><a href=\"#appendix-tables\">{}</a></p>", appendix_tables::APPENDIX_B);
    }
    out.push_str("</nav>\n");
    for (i, (anchor, name, render)) in SECTIONS.iter().enumerate() {
        let _ = writeln!(out, "<section id=\"{anchor}\"><h2>{}. {}</h2>", i + 1, esc(name));
        render(&mut out, ctx)?;
        out.push_str("</section>\n");
    }
    // The main body ends here: the appendix opens on a page of its own under its heading.
    if appendix {
        let _ = writeln!(out, "<section id=\"appendix\" class=\"appendix\"><h2>{APPENDIX}</h2>");
        figures::appendix(&mut out, ctx)?;
        out.push_str("</section>\n");
    }
    appendix_tables::appendix(&mut out, ctx);
    out.push_str("</body></html>\n");
    Ok(out)
}

/// Writes `report.html` to `path`.
pub fn write(path: &Path, ctx: &Context) -> std::io::Result<()> {
    std::fs::write(path, render(ctx)?)
}

/// Text escaped for HTML.
pub fn esc(s: &str) -> String {
    s.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;").replace('"', "&quot;")
}

/// A table: header cells and rows of cells (already escaped HTML).
fn table(out: &mut String, class: &str, header: &[&str], rows: impl IntoIterator<Item = Vec<String>>) {
    let _ = write!(out, "<table class=\"{class}\"><thead><tr>");
    for h in header {
        let _ = write!(out, "<th>{}</th>", esc(h));
    }
    out.push_str("</tr></thead><tbody>\n");
    for row in rows {
        out.push_str("<tr>");
        for cell in row {
            let _ = write!(out, "<td>{cell}</td>");
        }
        out.push_str("</tr>\n");
    }
    out.push_str("</tbody></table>\n");
}
