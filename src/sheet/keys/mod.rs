//! The sheet's keys, defined once: every table and key a design sheet may hold, with its type,
//! unit, default, whether it is required, its constraint and its meaning. The reference
//! (`docs/sheet.md`) and the JSON Schema (`wrapcalc schema`) are generated from this registry,
//! and tests hold it equal to what the parser accepts.

mod drive;
mod lift;
mod ropes;
mod scene;
mod sections;
mod sensitivity;

use std::fmt::Write as _;

/// What a key's value is in TOML.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Type {
    /// A number (a TOML float or integer).
    Number,
    /// A whole number.
    Integer,
    /// `true` or `false`.
    Bool,
    /// A text in quotes.
    Text,
    /// A text, or a TOML date.
    TextOrDate,
    /// A text, or a whole number.
    TextOrInteger,
    /// An array of numbers.
    Numbers,
    /// An array of texts.
    Texts,
    /// A number, or an array of numbers (which one depends on the scene's kind).
    NumberOrNumbers,
    /// A limit: a number or an inline table `{ value = number, source = "text" }`.
    Limit,
    /// A table (a section of its own).
    Table,
    /// An array of tables (`[[…]]`).
    Tables,
}

impl Type {
    /// The type as the reference names it.
    pub fn name(self) -> &'static str {
        match self {
            Type::Number => "number",
            Type::Integer => "integer",
            Type::Bool => "boolean",
            Type::Text => "text",
            Type::TextOrDate => "text or date",
            Type::TextOrInteger => "text or integer",
            Type::Numbers => "array of numbers",
            Type::Texts => "array of texts",
            Type::NumberOrNumbers => "number or array of numbers",
            Type::Limit => "number or { value, source }",
            Type::Table => "table",
            Type::Tables => "array of tables",
        }
    }
}

/// One end of an allowed range: the bound and whether it is allowed itself.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bound {
    /// The bound.
    pub value: f64,
    /// Whether the bound itself is allowed.
    pub inclusive: bool,
}

/// The numbers a key (or each item of an array key) may take; both ends open when `None`.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Range {
    /// The lower end.
    pub min: Option<Bound>,
    /// The upper end.
    pub max: Option<Bound>,
}

impl Range {
    /// The range in words, e.g. `> 0`, `0 < x ≤ 2`, `|x| ≤ 100`; empty when unbounded.
    pub fn describe(&self) -> String {
        let n = |b: Bound| format_number(b.value);
        match (self.min, self.max) {
            (None, None) => String::new(),
            (Some(lo), None) => format!("{} {}", if lo.inclusive { "≥" } else { ">" }, n(lo)),
            (None, Some(hi)) => format!("{} {}", if hi.inclusive { "≤" } else { "<" }, n(hi)),
            (Some(lo), Some(hi)) if lo.value == -hi.value && lo.inclusive == hi.inclusive => {
                format!("|x| {} {}", if hi.inclusive { "≤" } else { "<" }, n(hi))
            }
            (Some(lo), Some(hi)) => format!(
                "{} {} x {} {}",
                n(lo),
                if lo.inclusive { "≤" } else { "<" },
                if hi.inclusive { "≤" } else { "<" },
                n(hi)
            ),
        }
    }
}

/// A number as the reference prints it (shortest form that reads back the same).
pub fn format_number(x: f64) -> String {
    if x.fract() == 0.0 && x.abs() < 1e15 { format!("{}", x as i64) } else { format!("{x}") }
}

/// Whether a key must be given.
#[derive(Debug, Clone, PartialEq)]
pub enum Need {
    /// Always required.
    Required,
    /// May be left out.
    Optional,
    /// Required in some cases, said in words (e.g. "required (or `csv`)").
    When(&'static str),
}

/// A key's default when it is absent.
#[derive(Debug, Clone, PartialEq)]
pub enum Default {
    /// No default: the key's effect is off (or the key is required).
    None,
    /// A number.
    Number(f64),
    /// A boolean.
    Bool(bool),
    /// A keyword.
    Word(&'static str),
    /// An array of numbers.
    Numbers(Vec<f64>),
    /// An array of keywords.
    Words(Vec<&'static str>),
    /// A default that depends on other values, in words.
    Described(String),
}

impl Default {
    /// The default as the reference prints it.
    pub fn describe(&self) -> String {
        let list = |items: Vec<String>| format!("[{}]", items.join(", "));
        match self {
            Default::None => String::new(),
            Default::Number(x) => format_number(*x),
            Default::Bool(b) => b.to_string(),
            Default::Word(w) => format!("\"{w}\""),
            Default::Numbers(xs) => list(xs.iter().map(|x| format!("{x:?}")).collect()),
            Default::Words(ws) => list(ws.iter().map(|w| format!("\"{w}\"")).collect()),
            Default::Described(text) => text.clone(),
        }
    }
}

/// One key of a table.
#[derive(Debug, Clone, PartialEq)]
pub struct Key {
    /// The key as written in the sheet.
    pub name: &'static str,
    /// What its value is.
    pub ty: Type,
    /// The unit of the number(s), empty for none.
    pub unit: &'static str,
    /// Whether it must be given.
    pub need: Need,
    /// Its value when absent.
    pub default: Default,
    /// Allowed numbers (of each item, for arrays).
    pub range: Range,
    /// Allowed words (of each item, for arrays); empty for any text.
    pub words: Vec<&'static str>,
    /// Allowed number of items of an array key.
    pub items: Option<(usize, usize)>,
    /// What else the value must satisfy, in words (besides `range` and `words`).
    pub note: String,
    /// What the key means (one line).
    pub meaning: String,
    /// The scene kinds that use the key (scene keys only; empty elsewhere).
    pub kinds: Vec<&'static str>,
    /// The key's type in particular scene kinds, where it differs from `ty`.
    pub kind_types: Vec<(&'static str, Type)>,
}

impl Key {
    /// An optional key without default, range or note.
    pub fn new(name: &'static str, ty: Type, unit: &'static str, meaning: impl Into<String>) -> Self {
        Key {
            name,
            ty,
            unit,
            need: Need::Optional,
            default: Default::None,
            range: Range::default(),
            words: Vec::new(),
            items: None,
            note: String::new(),
            meaning: meaning.into(),
            kinds: Vec::new(),
            kind_types: Vec::new(),
        }
    }
    /// Marks the key required.
    pub fn required(mut self) -> Self {
        self.need = Need::Required;
        self
    }
    /// Marks the key required in some cases, said in words.
    pub fn when(mut self, text: &'static str) -> Self {
        self.need = Need::When(text);
        self
    }
    /// Sets the default.
    pub fn default(mut self, d: Default) -> Self {
        self.default = d;
        self
    }
    /// Sets the lower end of the range.
    pub fn min(mut self, value: f64, inclusive: bool) -> Self {
        self.range.min = Some(Bound { value, inclusive });
        self
    }
    /// Sets the upper end of the range.
    pub fn max(mut self, value: f64, inclusive: bool) -> Self {
        self.range.max = Some(Bound { value, inclusive });
        self
    }
    /// `> 0`.
    pub fn positive(self) -> Self {
        self.min(0.0, false)
    }
    /// `≥ 0`.
    pub fn non_negative(self) -> Self {
        self.min(0.0, true)
    }
    /// Sets the allowed words.
    pub fn words(mut self, words: &[&'static str]) -> Self {
        self.words = words.to_vec();
        self
    }
    /// Sets the allowed number of items.
    pub fn items(mut self, min: usize, max: usize) -> Self {
        self.items = Some((min, max));
        self
    }
    /// Sets the constraint beyond range and words, in words.
    pub fn note(mut self, text: impl Into<String>) -> Self {
        self.note = text.into();
        self
    }
    /// Sets the scene kinds that use the key.
    pub fn kinds(mut self, kinds: &[&'static str]) -> Self {
        self.kinds = kinds.to_vec();
        self
    }
    /// Sets the key's type in one scene kind.
    pub fn kind_type(mut self, kind: &'static str, ty: Type) -> Self {
        self.kind_types.push((kind, ty));
        self
    }

    /// The key's constraint in words: its range, its words, its item count and its note.
    pub fn constraint(&self) -> String {
        let mut parts = Vec::new();
        let range = self.range.describe();
        if !range.is_empty() {
            parts.push(range);
        }
        if !self.words.is_empty() {
            let words: Vec<String> = self.words.iter().map(|w| format!("\"{w}\"")).collect();
            let lead = if matches!(self.ty, Type::Texts) { "some of" } else { "one of" };
            parts.push(format!("{lead} {}", words.join(", ")));
        }
        if let Some((lo, hi)) = self.items {
            parts.push(format!("{lo} … {hi} items"));
        }
        if !self.note.is_empty() {
            parts.push(self.note.clone());
        }
        parts.join("; ")
    }

    /// The key's type in a scene of `kind`.
    pub fn type_in(&self, kind: &str) -> Type {
        self.kind_types.iter().find(|(k, _)| *k == kind).map_or(self.ty, |(_, t)| *t)
    }
}

/// A table of the sheet: `[pulley]`, `[[scene]]`, … (`path` is the dotted key, `""` the top level).
#[derive(Debug, Clone, PartialEq)]
pub struct Table {
    /// The dotted path (`""` for the top level).
    pub path: &'static str,
    /// Written `[[path]]`: an array of tables.
    pub array: bool,
    /// What the table holds.
    pub meaning: &'static str,
    /// Its keys, in the reference's order.
    pub keys: Vec<Key>,
    /// Groups of keys of which at least one must be given whole (e.g. masses or tensions).
    pub one_of: Vec<Vec<&'static str>>,
}

impl Table {
    /// The key of this name.
    pub fn key(&self, name: &str) -> Option<&Key> {
        self.keys.iter().find(|k| k.name == name)
    }
    /// How the table is written in a sheet: `[pulley]`, `[[scene]]`, or "top level".
    pub fn header(&self) -> String {
        match (self.path, self.array) {
            ("", _) => "top level".into(),
            (p, true) => format!("[[{p}]]"),
            (p, false) => format!("[{p}]"),
        }
    }
}

/// A kind of `[[scene]]`: its keyword, meaning, and the groups of keys it needs one of.
#[derive(Debug, Clone, PartialEq)]
pub struct SceneKind {
    /// The `kind` keyword.
    pub name: &'static str,
    /// What a scene of this kind describes.
    pub meaning: &'static str,
    /// Groups of keys of which at least one must be given whole.
    pub one_of: Vec<Vec<&'static str>>,
}

/// Every table of the sheet, the top level first, in the order of the reference.
pub fn tables() -> Vec<Table> {
    let mut out = sections::tables();
    out.extend(ropes::tables());
    out.extend(sensitivity::tables());
    out.push(scene::table());
    out.extend(lift::tables());
    out
}

/// The kinds of `[[scene]]`.
pub fn scene_kinds() -> Vec<SceneKind> {
    scene::kinds()
}

/// The scene keys a kind uses.
pub fn keys_of_kind<'a>(scene: &'a Table, kind: &str) -> Vec<&'a Key> {
    scene.keys.iter().filter(|k| k.kinds.contains(&kind)).collect()
}

/// A one-line description of a key: its meaning, unit, constraint and default.
pub fn describe(key: &Key) -> String {
    let mut s = key.meaning.clone();
    if !key.unit.is_empty() {
        let _ = write!(s, " [{}]", key.unit);
    }
    let c = key.constraint();
    if !c.is_empty() {
        let _ = write!(s, ". Allowed: {c}");
    }
    match &key.need {
        Need::Required => s.push_str(". Required"),
        Need::When(text) => {
            let _ = write!(s, ". {}", capitalize(text));
        }
        Need::Optional => {}
    }
    let d = key.default.describe();
    if !d.is_empty() {
        let _ = write!(s, ". Default: {d}");
    }
    if !key.kinds.is_empty() {
        let _ = write!(s, ". Scene kinds: {}", key.kinds.join(", "));
    }
    s
}

fn capitalize(text: &str) -> String {
    let mut chars = text.chars();
    chars.next().map_or_else(String::new, |c| c.to_uppercase().chain(chars).collect())
}

#[cfg(test)]
mod tests;
