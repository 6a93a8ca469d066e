//! `[[compare]]` tables: a figure overlaying one quantity of several time scenes
//! (`compare/<name>.png`): `name`, `scenes` (names of time scenes of the sheet) and `quantity`
//! (`"track"`, the first followed element of each, or a column of history.csv).

use super::diag::{Collector, join_key};
use super::raw::RawCompare;
use super::rules::valid_scene_name;
use crate::design::{Compare, CompareQuantity, Scene, SceneKind, compare_columns};
use toml::Spanned;

/// The sheet's compare figures: `None` when one is wrong (or the section failed to read).
pub(super) fn compare(
    c: &mut Collector,
    raw: &Option<Spanned<Vec<Spanned<RawCompare>>>>,
    present: bool,
    scenes: Option<&[Scene]>,
) -> Option<Vec<Compare>> {
    let Some(tables) = raw else {
        return (!present).then(Vec::new);
    };
    let mut out: Vec<Compare> = Vec::new();
    let mut ok = true;
    for (i, table) in tables.get_ref().iter().enumerate() {
        let label = format!("compare[{}]", i + 1);
        match one(c, &label, table, scenes) {
            Some(figure) if out.iter().any(|f| f.name == figure.name) => {
                let span = table.get_ref().name.as_ref().map(|n| n.span());
                c.push(
                    span,
                    None,
                    &join_key(&label, "name"),
                    "another [[compare]] has this name; names must be unique",
                );
                ok = false;
            }
            Some(figure) => out.push(figure),
            None => ok = false,
        }
    }
    ok.then_some(out)
}

fn one(c: &mut Collector, label: &str, table: &Spanned<RawCompare>, scenes: Option<&[Scene]>) -> Option<Compare> {
    let raw = table.get_ref();
    let key = |k: &str| join_key(label, k);
    let missing = |c: &mut Collector, k: &str, what: &str| {
        c.push_at(Some(table.span()), None, &key(k), format!("missing; expected {what}"));
    };
    let name = match &raw.name {
        Some(n) if valid_scene_name(n.get_ref()) => Some(n.get_ref().clone()),
        Some(n) => {
            let msg = "expected a name of letters, digits, '-', '_' or '.', not starting with '.' (it names the figure's file)";
            c.push(Some(n.span()), None, &key("name"), msg);
            None
        }
        None => {
            missing(c, "name", "a name for the figure's file");
            None
        }
    };
    let quantity = match &raw.quantity {
        Some(q) if q.get_ref() == "track" => Some(CompareQuantity::Track),
        Some(q) => match compare_columns().find(|col| *col == q.get_ref().as_str()) {
            Some(col) => Some(CompareQuantity::History(col)),
            None => {
                let msg = format!(
                    "unknown quantity; expected \"track\" or a history.csv column: {}",
                    compare_columns().collect::<Vec<_>>().join(", ")
                );
                c.push(Some(q.span()), None, &key("quantity"), msg);
                None
            }
        },
        None => {
            missing(c, "quantity", "\"track\" or a history.csv column");
            None
        }
    };
    let list = match &raw.scenes {
        Some(list) if !list.get_ref().is_empty() => Some(list),
        Some(list) => {
            c.push(Some(list.span()), None, &key("scenes"), "empty; expected the names of time scenes to overlay");
            None
        }
        None => {
            missing(c, "scenes", "the names of time scenes to overlay");
            None
        }
    };
    let (name, quantity, list) = (name?, quantity?, list?);
    let mut ok = true;
    for (j, s) in list.get_ref().iter().enumerate() {
        let k = format!("{}[{j}]", key("scenes"));
        let Some(all) = scenes else { continue };
        match all.iter().find(|x| x.name == *s.get_ref()) {
            None => {
                let known: Vec<&str> = all.iter().map(|x| x.name.as_str()).collect();
                c.push(Some(s.span()), None, &k, format!("no scene of this name; the sheet has {}", known.join(", ")));
                ok = false;
            }
            Some(x) if matches!(x.kind, SceneKind::Loads(_)) => {
                c.push(Some(s.span()), None, &k, "a loads scene has no history to compare; expected a time scene");
                ok = false;
            }
            Some(x) if quantity == CompareQuantity::Track && x.tracks.is_none() => {
                let msg =
                    "this scene follows no rope element; give it track_entry_s, track_start_deg or track_anchor_m";
                c.push(Some(s.span()), Some(&x.name), &k, msg);
                ok = false;
            }
            Some(_) => {}
        }
    }
    let scenes = list.get_ref().iter().map(|s| s.get_ref().clone()).collect();
    ok.then_some(Compare { name, scenes, quantity })
}
