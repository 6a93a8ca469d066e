//! The commented template sheets `wrapcalc new KIND` writes: each a complete sheet that runs as
//! written (the hoists' and a lift's), embedded in the binary so that it needs no files beside it.

use std::io::Write;
use std::path::Path;

/// One template: the kind the user names and its text.
#[derive(Debug, Clone, Copy)]
pub struct Template {
    /// The name given to `wrapcalc new`.
    pub kind: &'static str,
    /// One line saying what hoist or lift it describes.
    pub summary: &'static str,
    /// The sheet's text.
    pub text: &'static str,
}

/// Every template, in the order they are listed.
pub const TEMPLATES: &[Template] = &[
    Template {
        kind: "tower-cage",
        summary: "tower-mounted multi-rope hoist with guide sheave, cage and counterweight",
        text: include_str!("../../templates/tower-cage.toml"),
    },
    Template {
        kind: "ground-skips",
        summary: "ground-mounted multi-rope hoist with two skips (wrap angle given directly)",
        text: include_str!("../../templates/ground-skips.toml"),
    },
    Template {
        kind: "lift",
        summary: "electric traction lift (car, counterweight, grooved sheave) judged by EN 81-50",
        text: include_str!("../../templates/lift.toml"),
    },
];

/// What `wrapcalc new` can fail with.
#[derive(Debug, thiserror::Error)]
pub enum TemplateError {
    /// No kind, or one that is not a template.
    #[error("{}", unknown_message(.0.as_deref()))]
    UnknownKind(Option<String>),
    /// `--out` names a file that exists and `--force` was not given.
    #[error("{0}: exists; not overwritten (give --force to replace it, or another --out)")]
    Exists(String),
    /// The file could not be written.
    #[error("{path}: cannot write the template: {source}")]
    Write {
        /// The file.
        path: String,
        /// The I/O error.
        source: std::io::Error,
    },
}

/// The listing of the kinds, one per line with its summary.
pub fn listing() -> String {
    let width = TEMPLATES.iter().map(|t| t.kind.len()).max().unwrap_or(0);
    TEMPLATES.iter().map(|t| format!("  {:width$}  {}\n", t.kind, t.summary)).collect()
}

fn unknown_message(kind: Option<&str>) -> String {
    let head = match kind {
        Some(k) => format!("no template \"{k}\"; the kinds are:"),
        None => "name a template: wrapcalc new KIND [--out FILE]; the kinds are:".to_string(),
    };
    format!("{head}\n{}", listing().trim_end())
}

/// The template of a kind.
pub fn find(kind: Option<&str>) -> Result<&'static Template, TemplateError> {
    let name = kind.ok_or(TemplateError::UnknownKind(None))?;
    TEMPLATES.iter().find(|t| t.kind == name).ok_or_else(|| TemplateError::UnknownKind(Some(name.to_string())))
}

/// Writes a template to `out`, refusing an existing file unless `force`; without `force` the
/// file is created anew (`create_new`), so a file appearing meanwhile is not overwritten either.
pub fn write(template: &Template, out: &Path, force: bool) -> Result<(), TemplateError> {
    let shown = out.display().to_string();
    let opened = if force {
        std::fs::File::create(out)
    } else {
        std::fs::OpenOptions::new().write(true).create_new(true).open(out)
    };
    let mut file = opened.map_err(|e| match e.kind() {
        std::io::ErrorKind::AlreadyExists => TemplateError::Exists(shown.clone()),
        _ => TemplateError::Write { path: shown.clone(), source: e },
    })?;
    file.write_all(template.text.as_bytes()).map_err(|source| TemplateError::Write { path: shown, source })
}
