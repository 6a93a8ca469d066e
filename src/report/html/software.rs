//! Section 9: the software — version, the sheet's SHA-256, the command line, the run time, and
//! the accuracy evidence this build computes as it writes the report ([`crate::report::accuracy`]).

use super::{Context, esc, table};
use crate::report::accuracy;
use std::fmt::Write;
use std::io;

/// An error is accepted as reproducing its closed form below this (relative); the levels 0–2
/// are exact to rounding and level 3 is second order in the pitch (6e-5 of ΔT at N = 180).
pub const REPRODUCED_BELOW: f64 = 1e-3;

/// 9. Software and accuracy.
pub fn software(out: &mut String, ctx: &Context) -> io::Result<()> {
    let p = ctx.provenance;
    let command: Vec<String> = p.command_line.iter().map(|a| shell_word(a)).collect();
    let rows = vec![
        vec!["program".into(), format!("wrapcalc {}", env!("CARGO_PKG_VERSION"))],
        vec!["sheet".into(), format!("<code>{}</code>", esc(&ctx.design.sheet))],
        vec!["SHA-256 of the sheet".into(), format!("<code>{}</code>", p.sheet_sha256)],
        vec!["command line".into(), format!("<code>{}</code>", esc(&command.join(" ")))],
        vec!["run time".into(), format!("{:.1} ms for {} scene(s)", ctx.run.runtime_ms, ctx.run.scenes.len())],
    ];
    table(out, "", &["", ""], rows);
    out.push_str("<h3>Accuracy evidence</h3>\n");
    let _ = writeln!(
        out,
        "<p>Computed while this report was written, by this build: the closed-form cases of the bench run through the same code as the sheet's scenes, on N = {} nodes, with their errors against the closed forms.</p>",
        accuracy::NODES
    );
    let rows = ctx.provenance.accuracy.iter().map(|e| {
        let (err, ok) = match (e.error, &e.failure) {
            (Some(x), _) => (format!("{x:.2e}"), x < REPRODUCED_BELOW),
            (None, Some(f)) => (esc(f), false),
            (None, None) => ("—".into(), false),
        };
        vec![
            esc(e.case),
            e.level.to_string(),
            esc(e.reference),
            esc(e.metric),
            format!("<span class=\"mono\">{err}</span>"),
            if ok {
                "<span class=\"pass\">reproduced</span>".into()
            } else {
                "<span class=\"fail\">NOT reproduced</span>".into()
            },
        ]
    });
    table(out, "small", &["case", "level", "closed form", "error metric", "error", "verdict"], rows);
    let _ = writeln!(
        out,
        "<p class=\"note\">Reproduced: error below {REPRODUCED_BELOW:e}. The full run-time-against-error study is <code>wrapcalc bench</code>.</p>"
    );
    Ok(())
}

/// A command-line word quoted for a POSIX shell where it needs it.
fn shell_word(w: &str) -> String {
    if !w.is_empty() && w.chars().all(|c| c.is_ascii_alphanumeric() || "-_./=:,+@".contains(c)) {
        w.to_string()
    } else {
        format!("'{}'", w.replace('\'', "'\\''"))
    }
}
