//! Diagnostics that point at the value in the sheet: file, line:column, scene, key, the bad
//! value and what is allowed.

use std::fmt;
use std::ops::Range;

/// One problem found in a sheet.
#[derive(Debug, Clone, PartialEq)]
pub struct Diagnostic {
    /// The sheet's path as given (used in the message only).
    pub file: String,
    /// 1-based line and column of the value (0 when the file could not be read at all).
    pub line: usize,
    /// 1-based column of the value, counted in characters (0 with `line`).
    pub column: usize,
    /// Name of the `[[scene]]` the value belongs to; `None` outside the scenes.
    pub scene: Option<String>,
    /// Dotted key path, e.g. `pulley.mu` or `scene[2].m1_kg`.
    pub key: String,
    /// The offending value as written in the sheet, when there is one.
    pub value: Option<String>,
    /// What is wrong and what is allowed.
    pub message: String,
}

impl fmt::Display for Diagnostic {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", self.file)?;
        if self.line > 0 {
            write!(f, ":{}:{}", self.line, self.column)?;
        }
        if let Some(scene) = &self.scene {
            write!(f, ": scene \"{scene}\"")?;
        }
        if !self.key.is_empty() {
            write!(f, ": {}", self.key)?;
        }
        if let Some(value) = &self.value {
            write!(f, " = {value}")?;
        }
        write!(f, ": {}", self.message)
    }
}

/// Every problem found in a sheet (never empty).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub struct SheetError {
    /// The problems in the order they were found.
    pub diagnostics: Vec<Diagnostic>,
}

impl fmt::Display for SheetError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        for (i, d) in self.diagnostics.iter().enumerate() {
            if i > 0 {
                writeln!(f)?;
            }
            write!(f, "{d}")?;
        }
        if self.diagnostics.len() > 1 {
            write!(f, "\n{} errors in the sheet", self.diagnostics.len())?;
        }
        Ok(())
    }
}

/// Collects diagnostics for one sheet, turning byte spans into line:column.
pub(crate) struct Collector<'a> {
    pub file: &'a str,
    pub text: &'a str,
    pub diagnostics: Vec<Diagnostic>,
    /// Byte offsets of values already reported (a text with a unit that could not be read):
    /// later messages at them would repeat the error in other words.
    pub silenced: Vec<usize>,
}

impl<'a> Collector<'a> {
    pub fn new(file: &'a str, text: &'a str) -> Self {
        Self { file, text, diagnostics: Vec::new(), silenced: Vec::new() }
    }

    /// 1-based line and column (in characters) of a byte offset.
    pub fn line_col(&self, offset: usize) -> (usize, usize) {
        let offset = offset.min(self.text.len());
        let before = self.text.get(..offset).unwrap_or(self.text);
        let line = before.matches('\n').count() + 1;
        let line_start = before.rfind('\n').map_or(0, |i| i + 1);
        let column = before[line_start..].chars().count() + 1;
        (line, column)
    }

    /// The sheet's text at a span, trimmed and shortened for a message.
    pub fn snippet(&self, span: &Range<usize>) -> Option<String> {
        let s = self.text.get(span.clone())?.trim();
        if s.is_empty() {
            return None;
        }
        let mut out: String = s.chars().take(60).collect();
        if s.chars().count() > 60 {
            out.push('…');
        }
        Some(out)
    }

    /// Drops later messages at the value starting at `offset` (already reported).
    pub fn silence(&mut self, offset: usize) {
        self.silenced.push(offset);
    }

    fn is_silenced(&self, span: &Option<Range<usize>>) -> bool {
        span.as_ref().is_some_and(|s| self.silenced.contains(&s.start))
    }

    pub fn push(&mut self, span: Option<Range<usize>>, scene: Option<&str>, key: &str, message: impl Into<String>) {
        if self.is_silenced(&span) {
            return;
        }
        let (line, column) = span.as_ref().map_or((0, 0), |s| self.line_col(s.start));
        let value = span.as_ref().and_then(|s| self.snippet(s));
        self.diagnostics.push(Diagnostic {
            file: self.file.to_string(),
            line,
            column,
            scene: scene.map(str::to_string),
            key: key.to_string(),
            value,
            message: message.into(),
        });
    }

    /// A problem with no value to show (e.g. a missing key: the span is the enclosing table).
    pub fn push_at(&mut self, span: Option<Range<usize>>, scene: Option<&str>, key: &str, message: impl Into<String>) {
        if self.is_silenced(&span) {
            return;
        }
        let (line, column) = span.as_ref().map_or((0, 0), |s| self.line_col(s.start));
        self.diagnostics.push(Diagnostic {
            file: self.file.to_string(),
            line,
            column,
            scene: scene.map(str::to_string),
            key: key.to_string(),
            value: None,
            message: message.into(),
        });
    }

    /// A serde/TOML error from deserializing one section of the sheet.
    pub fn push_toml(&mut self, err: &toml::de::Error, scene: Option<&str>, section: &str) {
        let mut message = err.message().trim().to_string();
        if let Some(field) = unknown_field(&message) {
            // serde lists the keys it expected in backquotes after "expected".
            let expected = message.split_once("expected").map_or("", |(_, rest)| rest);
            let keys: Vec<&str> = expected.split('`').skip(1).step_by(2).collect();
            if let Some(best) = did_you_mean(&field, keys) {
                message = format!("{message}; did you mean `{best}`?");
            }
        }
        let field = unknown_field(&message).or_else(|| err.span().and_then(|s| self.key_before(s.start)));
        let key = field.map_or_else(|| section.to_string(), |f| join_key(section, &f));
        self.push(err.span(), scene, &key, in_toml_words(&message));
    }

    /// The bare key of a `key = value` line whose value starts at `offset` (serde's type errors
    /// point at the value but do not name the field).
    fn key_before(&self, offset: usize) -> Option<String> {
        let before = self.text.get(..offset)?;
        let line = &before[before.rfind('\n').map_or(0, |i| i + 1)..];
        let key = line.trim_end().strip_suffix('=')?.trim();
        let valid = !key.is_empty() && key.chars().all(|c| c.is_ascii_alphanumeric() || c == '_' || c == '-');
        valid.then(|| key.to_string())
    }

    pub fn into_error(self) -> SheetError {
        SheetError { diagnostics: self.diagnostics }
    }
}

/// `section.key`, or `key` at the top level.
pub(crate) fn join_key(section: &str, key: &str) -> String {
    if section.is_empty() { key.to_string() } else { format!("{section}.{key}") }
}

/// The candidate closest to `word` when it is close enough to be a typing slip: at most 2
/// edits (insertions, deletions, substitutions, transpositions of adjacent letters), or a third
/// of the word's length for a longer word; `None` when nothing is that close.
pub(crate) fn did_you_mean<'a>(word: &str, candidates: impl IntoIterator<Item = &'a str>) -> Option<&'a str> {
    let most = 2.max(word.chars().count() / 3);
    candidates
        .into_iter()
        .map(|c| (strsim::damerau_levenshtein(word, c), c))
        .filter(|&(d, _)| d <= most)
        .min_by_key(|&(d, _)| d)
        .map(|(_, c)| c)
}

/// The field name in serde's "unknown field `x`, expected ..." message.
fn unknown_field(message: &str) -> Option<String> {
    let rest = message.strip_prefix("unknown field `")?;
    Some(rest[..rest.find('`')?].to_string())
}

/// A serde type error in the sheet's words: TOML's names of the types (a number, a whole number,
/// an array, a table) for Rust's (`f64`, `u32`, sequence, map), and what would be valid.
pub fn in_toml_words(message: &str) -> String {
    if !message.starts_with("invalid type") {
        return message.to_string();
    }
    let words = [
        ("expected f64", "expected a number"),
        ("expected f32", "expected a number"),
        ("expected u8", "expected a whole number ≥ 0"),
        ("expected u16", "expected a whole number ≥ 0"),
        ("expected u32", "expected a whole number ≥ 0"),
        ("expected u64", "expected a whole number ≥ 0"),
        ("expected usize", "expected a whole number ≥ 0"),
        ("expected i64", "expected a whole number"),
        ("expected i32", "expected a whole number"),
        ("sequence", "array"),
        ("expected a map", "expected a table"),
        ("expected map", "expected a table"),
        ("floating point", "number with a decimal point"),
    ];
    let mut out = message.to_string();
    for (rust, toml) in words {
        out = out.replace(rust, toml);
    }
    if let Some(i) = out.find("expected struct ") {
        // `expected struct RawPulley`: a section or sub-table.
        let end = out[i + 16..].find(|c: char| !c.is_alphanumeric()).map_or(out.len(), |e| i + 16 + e);
        out.replace_range(i..end, "expected a table of keys");
    }
    out
}
