//! The `[document]` section: the title block of the calculation report (project, title,
//! revision, author, checker, date), and whether the report carries its appendix of further
//! figures (`appendix_figures`, a boolean, default true). Every title key is optional text; a
//! TOML date (`date = 2024-05-01`) is taken as written.

use super::diag::Collector;
use crate::design::Document;
use serde::Deserialize;
use toml::Spanned;

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RawDocument {
    pub project: Option<Spanned<toml::Value>>,
    pub title: Option<Spanned<toml::Value>>,
    pub revision: Option<Spanned<toml::Value>>,
    pub author: Option<Spanned<toml::Value>>,
    pub checker: Option<Spanned<toml::Value>>,
    pub date: Option<Spanned<toml::Value>>,
    pub appendix_figures: Option<Spanned<toml::Value>>,
}

/// The validated title block (empty when the sheet has no `[document]`).
pub fn document(c: &mut Collector, raw: &Option<Spanned<RawDocument>>) -> Document {
    let Some(raw) = raw.as_ref().map(Spanned::get_ref) else { return Document::default() };
    let appendix_figures = match raw.appendix_figures.as_ref() {
        None => true,
        Some(v) => match v.get_ref() {
            toml::Value::Boolean(b) => *b,
            _ => {
                c.push(
                    Some(v.span()),
                    None,
                    "document.appendix_figures",
                    "expected true or false (whether the report ends with the appendix of further figures)",
                );
                true
            }
        },
    };
    let mut text = |key: &str, v: &Option<Spanned<toml::Value>>| -> Option<String> {
        let v = v.as_ref()?;
        match v.get_ref() {
            toml::Value::String(s) => Some(s.clone()),
            toml::Value::Datetime(d) if key == "date" => Some(d.to_string()),
            toml::Value::Integer(i) if key == "revision" => Some(i.to_string()),
            _ => {
                let allowed = if key == "date" { "a text or a TOML date" } else { "a text in quotes" };
                c.push(Some(v.span()), None, &format!("document.{key}"), format!("expected {allowed}"));
                None
            }
        }
    };
    Document {
        appendix_figures,
        project: text("project", &raw.project),
        title: text("title", &raw.title),
        revision: text("revision", &raw.revision),
        author: text("author", &raw.author),
        checker: text("checker", &raw.checker),
        date: text("date", &raw.date),
    }
}
