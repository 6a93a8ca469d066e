//! A scene's `outputs` key: what it asks for (docs/physics.md §7), checked against what its kind can give.

use super::diag::Collector;
use super::rules::At;
use crate::design::{Output, Outputs, SceneKind};
use toml::Spanned;

/// The scene's outputs: the listed keywords (the checks are always given), or everything its
/// kind can give when the key is absent.
pub(super) fn outputs(
    c: &mut Collector,
    at: At,
    raw: &Option<Spanned<Vec<Spanned<String>>>>,
    kind: &SceneKind,
) -> Option<Outputs> {
    let can_give = Outputs::all_for(kind);
    let Some(list) = raw else {
        return Some(can_give);
    };
    let allowed = || {
        let words: Vec<String> = can_give.iter().map(|o| format!("\"{}\"", o.keyword())).collect();
        words.join(", ")
    };
    if list.get_ref().is_empty() {
        let msg = format!("empty; list what the scene asks for, from {}", allowed());
        c.push(Some(list.span()), at.scene, &at.key("outputs"), msg);
        return None;
    }
    let mut set = Outputs::of(&[Output::Checks]);
    let mut ok = true;
    for word in list.get_ref() {
        match Output::from_keyword(word.get_ref()) {
            Some(o) if can_give.contains(o) => set = set.with(o),
            Some(o) => {
                ok = false;
                let msg =
                    format!("a {} scene cannot give \"{}\"; expected some of {}", kind.name(), o.keyword(), allowed());
                c.push(Some(word.span()), at.scene, &at.key("outputs"), msg);
            }
            None => {
                ok = false;
                c.push(
                    Some(word.span()),
                    at.scene,
                    &at.key("outputs"),
                    format!("unknown output; expected some of {}", allowed()),
                );
            }
        }
    }
    ok.then_some(set)
}
