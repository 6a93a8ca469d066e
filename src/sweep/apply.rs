//! Setting varied values in a sheet. The sheet's own parser stays the judge of every value: a
//! point's values are written into the parsed TOML document, which is printed back to TOML and
//! read through [`sheet::parse`] like any sheet, so a value out of range (μ ≤ 0, a rope lifting
//! off the pulley, …) gets the same diagnostic as if it had been typed into the file.

use super::SweepError;
use super::grid::{KeyType, Vary};
use crate::design::Design;
use crate::sheet::{self, SheetError};
use toml::{Table, Value};

/// A validated sheet as a TOML document, ready to take a point's values.
#[derive(Debug, Clone)]
pub struct Template {
    /// The sheet's file name (messages, and the base of relative `csv` paths).
    file: String,
    doc: Table,
    /// The selected scenes (all scenes of the sheet when none selected), by name, in sheet order.
    scenes: Vec<String>,
    /// Their kinds, which decide the `scene.KEY` they take.
    kinds: Vec<&'static str>,
    /// Their 1-based numbers among the sheet's `[[scene]]` tables (for `scene[i]` in messages).
    numbers: Vec<usize>,
}

impl Template {
    /// Validates the sheet as written, then keeps the part of its document the sweep runs: the
    /// selected scenes (`scenes`, empty: all; each must exist), and the `[hoist]` only when a
    /// duty-cycle scene runs it or a `hoist.*` key is varied (never the `[load_cases]`: a sweep
    /// runs scenes). Checks the keys of `varies`.
    pub fn new(file: &str, text: &str, scenes: &[String], varies: &[Vary]) -> Result<Self, SweepError> {
        let design = sheet::parse(file, text)?;
        let selected = design
            .select_scenes(scenes)
            .map_err(|e| SweepError::Input { sheet: file.to_string(), message: e.to_string() })?;
        // The text parsed as a sheet, so it parses as a TOML table.
        let mut doc: Table = text.parse().map_err(|e: toml::de::Error| SweepError::Input {
            sheet: file.to_string(),
            message: e.message().to_string(),
        })?;
        let is_selected = |name: &str| scenes.is_empty() || scenes.iter().any(|s| s == name);
        // Only the selected scenes run, so only they are kept (and validated) at every point.
        let mut numbers = Vec::new();
        if let Some(Value::Array(tables)) = doc.get_mut("scene") {
            let mut i = 0;
            tables.retain(|t| {
                i += 1;
                let keep = t.get("name").and_then(Value::as_str).is_some_and(is_selected);
                if keep {
                    numbers.push(i);
                }
                keep
            });
        }
        let mut template = Self {
            file: file.to_string(),
            doc,
            scenes: selected.iter().map(|s| s.name.clone()).collect(),
            kinds: selected.iter().map(|s| s.kind.name()).collect(),
            numbers,
        };
        template.check_keys(varies)?;
        // A varied wrap angle replaces the guide-pulley geometry it is otherwise derived from.
        if varies.iter().any(|v| v.key == "pulley.wrap_angle_deg")
            && let Some(Value::Table(pulley)) = template.doc.get_mut("pulley")
        {
            pulley.remove("guide");
        }
        let hoist_used = template.kinds.contains(&"duty-cycle") || varies.iter().any(|v| v.key.starts_with("hoist."));
        if !hoist_used {
            // A rule set's H defaults to the longer hanging length of the [hoist]: kept as
            // `requirements.hanging_length_m` when the hoist leaves the sweep's sheet.
            let longer = template.doc.get("hoist").and_then(Value::as_table).and_then(|h| {
                let side = |k: &str| h.get(k).and_then(|v| v.as_float().or_else(|| v.as_integer().map(|i| i as f64)));
                Some(side("side1_length_m")?.max(side("side2_length_m")?))
            });
            if let (Some(h), Some(Value::Table(req))) = (longer, template.doc.get_mut("requirements")) {
                req.entry("hanging_length_m").or_insert(Value::Float(h));
            }
            template.doc.remove("hoist");
        }
        // A sweep runs scenes: the load-case matrix is not part of it.
        template.doc.remove("load_cases");
        // Nor are the scenes side by side (`[[compare]]`, figures of a report): they would name
        // scenes a `--scene` selection left out.
        template.doc.remove("compare");
        Ok(template)
    }

    /// The selected scene names, in sheet order.
    pub fn scenes(&self) -> &[String] {
        &self.scenes
    }

    /// Checks that every varied key has a place in this sheet: a `hoist.*` or
    /// `pulley.guide.*` key needs that section (the sweep would otherwise write a partial one),
    /// a `scene.KEY` a selected scene of a kind that has it.
    fn check_keys(&self, varies: &[Vary]) -> Result<(), SweepError> {
        for v in varies {
            if v.key.starts_with("scene.") && !self.kinds.iter().any(|k| v.kinds.contains(k)) {
                return Err(SweepError::Input {
                    sheet: self.file.clone(),
                    message: format!(
                        "--vary {}: no selected scene has this key (it belongs to {} scenes; selected: {})",
                        v.key,
                        v.kinds.join(", "),
                        self.scenes.join(", ")
                    ),
                });
            }
            for section in ["hoist", "pulley.guide", "lining"] {
                if v.key.strip_prefix(section).is_some_and(|rest| rest.starts_with('.'))
                    && table_at(&self.doc, section).is_none()
                {
                    return Err(SweepError::Input {
                        sheet: self.file.clone(),
                        message: format!("--vary {}: the sheet has no [{section}] section to vary", v.key),
                    });
                }
            }
        }
        Ok(())
    }

    /// The design with `values[i]` set at `varies[i].key`, validated by the sheet parser.
    /// Diagnostics name the key and value but no line (the text they refer to is generated).
    pub fn design(&self, varies: &[Vary], values: &[f64]) -> Result<Design, SheetError> {
        let mut doc = self.doc.clone();
        for (v, &x) in varies.iter().zip(values) {
            let value = match v.key_type {
                KeyType::Float => Value::Float(x),
                // Grid values of integer keys are whole (checked when the spec was parsed).
                KeyType::Integer => Value::Integer(x as i64),
            };
            match v.key.strip_prefix("scene.") {
                Some(key) => {
                    let scenes = doc.get_mut("scene").and_then(Value::as_array_mut).into_iter().flatten();
                    for scene in scenes.filter_map(Value::as_table_mut) {
                        let name = scene.get("name").and_then(Value::as_str);
                        let takes_key = self
                            .scenes
                            .iter()
                            .zip(&self.kinds)
                            .any(|(s, kind)| name == Some(s.as_str()) && v.kinds.contains(kind));
                        if takes_key {
                            scene.insert(key.to_string(), value.clone());
                        }
                    }
                }
                None => set(&mut doc, v.key, value),
            }
        }
        let text = toml::to_string(&doc).map_err(|e| SheetError {
            diagnostics: vec![sheet::Diagnostic {
                file: self.file.clone(),
                line: 0,
                column: 0,
                scene: None,
                key: String::new(),
                value: None,
                message: format!("cannot write the varied sheet: {e}"),
            }],
        })?;
        sheet::parse(&self.file, &text).map_err(|mut e| {
            for d in &mut e.diagnostics {
                (d.line, d.column) = (0, 0);
                d.key = self.renumber(&d.key);
            }
            e
        })
    }

    /// `scene[j].key` of the document of selected scenes → `scene[i].key` of the sheet.
    fn renumber(&self, key: &str) -> String {
        let parsed = key.strip_prefix("scene[").and_then(|rest| {
            let (j, tail) = rest.split_once(']')?;
            Some((self.numbers.get(j.parse::<usize>().ok()?.checked_sub(1)?)?, tail))
        });
        parsed.map_or_else(|| key.to_string(), |(i, tail)| format!("scene[{i}]{tail}"))
    }
}

fn table_at<'a>(doc: &'a Table, path: &str) -> Option<&'a Table> {
    path.split('.').try_fold(doc, |t, part| t.get(part)?.as_table())
}

/// Sets a dotted path, creating the tables on the way (e.g. a `[requirements]` the sheet leaves out).
fn set(doc: &mut Table, path: &str, value: Value) {
    let mut parts: Vec<&str> = path.split('.').collect();
    let Some(last) = parts.pop() else { return };
    let mut table = doc;
    for part in parts {
        let entry = table.entry(part.to_string()).or_insert_with(|| Value::Table(Table::new()));
        if !entry.is_table() {
            *entry = Value::Table(Table::new());
        }
        let Value::Table(t) = entry else { return };
        table = t;
    }
    table.insert(last.to_string(), value);
}
