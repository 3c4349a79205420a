//! `textDocument/completion`: keys (of the file's dialect; those the location above lacks
//! first, with its id), location ids (after a key, and in the tour), `left` / `right` for
//! `gestureArm`, and the culture knowledge base's keys for `culturalKnowledge` (when the
//! workspace knows the robot's configuration folder: [`crate::lsp::workspace::Workspace::culture_keys`]).

use lsp_types::{
    CompletionItem, CompletionItemKind, CompletionList, CompletionParams, CompletionResponse,
    CompletionTextEdit, Documentation, TextEdit,
};

use super::{Answer, Snapshot};
use crate::canonical::VALUE_COLUMN;
use crate::lsp::lines::{line_at, Entry};
use crate::model::{Arm, Key, Location};
use crate::syntax::{self, Body, Span};

/// The most location ids offered at once (a large file has 100,000): the rest come as the
/// user types more of the id.
const MAX_IDS: usize = 1000;

pub fn completion(
    snapshot: &Snapshot<'_, '_>,
    params: &CompletionParams,
) -> Answer<Option<CompletionResponse>> {
    let text = snapshot.text();
    let offset = snapshot
        .positions
        .offset(params.text_document_position.position);
    let Some(line) = line_at(text, offset) else {
        return Ok(None);
    };
    if matches!(line.body, Body::Comment(_)) {
        return Ok(None);
    }
    let before = &text[line.span.start as usize..offset as usize];
    let first = before.split(syntax::is_blank_char).find(|t| !t.is_empty());
    let is_tour = first.is_some_and(|key| key.eq_ignore_ascii_case(Key::TourSpecification.name()));
    let separators = |c: char| syntax::is_blank_char(c) || (is_tour && c == ',');
    let typed = &before[before.rfind(separators).map_or(0, |at| at + 1)..];
    let done = before[..before.len() - typed.len()]
        .split(separators)
        .filter(|t| !t.is_empty())
        .count();
    let replace = Span::new(offset as usize - typed.len(), offset as usize);
    let at = Completer {
        snapshot,
        replace,
        typed,
    };
    let (items, incomplete) = match (done, first) {
        (0, _) => (at.keys(location_above(snapshot, line.span.start)), false),
        (_, _) if is_tour && done >= 2 => at.ids(),
        (1, _) if !is_tour => at.ids_with_a_new_one(),
        (2, Some(key)) if Key::from_name(key) == Some(Key::GestureArm) => (at.arms(), false),
        (2.., Some(key)) if Key::from_name(key) == Some(Key::CulturalKnowledge) => {
            let written = before[..before.len() - typed.len()].split(separators);
            (at.culture_words(written.collect()), false)
        }
        _ => return Ok(None),
    };
    Ok(Some(CompletionResponse::List(CompletionList {
        is_incomplete: incomplete,
        items,
    })))
}

/// The location whose line is just above `line_start` (the block being written).
fn location_above<'s>(snapshot: &'s Snapshot<'_, '_>, line_start: u32) -> Option<&'s Location<'s>> {
    let text = snapshot.text();
    let above = line_at(text, line_start.checked_sub(1)?)?;
    let id = Entry::of(text, &above)?.location_id(text)?;
    snapshot.analysed.checked.kb.location(id)
}

/// Completion items that replace what is typed of the word at the cursor.
struct Completer<'s, 'a, 'q> {
    snapshot: &'s Snapshot<'a, 'q>,
    replace: Span,
    typed: &'s str,
}

impl Completer<'_, '_, '_> {
    fn item(&self, label: String, insert: String, kind: CompletionItemKind) -> CompletionItem {
        CompletionItem {
            text_edit: Some(CompletionTextEdit::Edit(TextEdit::new(
                self.snapshot.positions.range(self.replace),
                insert,
            ))),
            label,
            kind: Some(kind),
            ..CompletionItem::default()
        }
    }

    /// The keys of the file's dialect. Those `above` lacks come first and complete the
    /// whole start of its line, padded as `ekb fmt` pads it: `key    ID `.
    fn keys(&self, above: Option<&Location<'_>>) -> Vec<CompletionItem> {
        let dialect = self.snapshot.analysed.checked.kb.dialect;
        let of_dialect =
            |key: &Key| key.dialect().is_none() || dialect.is_none_or(|d| key.dialect() == Some(d));
        Key::ALL
            .into_iter()
            .filter(of_dialect)
            .map(|key| {
                let lacking = above
                    .filter(|location| key != Key::TourSpecification && !location.has_line(key));
                let insert = match lacking {
                    Some(location) => {
                        let padding = VALUE_COLUMN.saturating_sub(key.name().len() + 1).max(1);
                        format!("{}{}{} ", key.name(), " ".repeat(padding), location.id)
                    }
                    None => key.name().to_string(),
                };
                let mut item = self.item(key.name().into(), insert, CompletionItemKind::PROPERTY);
                item.detail = Some(match lacking {
                    Some(location) => {
                        format!("{} (location {} has none)", key.value_syntax(), location.id)
                    }
                    None => key.value_syntax().into(),
                });
                item.documentation = Some(Documentation::String(key.meaning().into()));
                item.sort_text = Some(format!(
                    "{}{:02}",
                    u8::from(lacking.is_none()),
                    key as usize
                ));
                item.filter_text = Some(key.name().into());
                item
            })
            .collect()
    }

    /// The locations whose id starts with what is typed (at most [`MAX_IDS`]; whether there
    /// are more), those the tour does not visit first.
    fn ids(&self) -> (Vec<CompletionItem>, bool) {
        let kb = &self.snapshot.analysed.checked.kb;
        let visited: std::collections::HashSet<u32> = kb.tour_stops().collect();
        let mut matching = kb
            .locations()
            .iter()
            .filter(|location| location.id.to_string().starts_with(self.typed));
        let items = matching
            .by_ref()
            .take(MAX_IDS)
            .map(|location| {
                let id = location.id.to_string();
                let mut item = self.item(id.clone(), id, CompletionItemKind::REFERENCE);
                item.detail = location.description().map(|d| d.value.to_string());
                let on_tour = visited.contains(&location.id);
                item.sort_text = Some(format!("{}{:010}", u8::from(on_tour), location.id));
                item
            })
            .collect();
        (items, matching.next().is_some())
    }

    /// [`Completer::ids`], and the next free id for a new location.
    fn ids_with_a_new_one(&self) -> (Vec<CompletionItem>, bool) {
        let (mut items, incomplete) = self.ids();
        let kb = &self.snapshot.analysed.checked.kb;
        let next = kb
            .locations()
            .iter()
            .last()
            .map_or(1, |last| last.id.saturating_add(1));
        if i32::try_from(next).is_ok() {
            let id = next.to_string();
            let mut item = self.item(id.clone(), id, CompletionItemKind::VALUE);
            item.detail = Some("a new location".into());
            item.sort_text = Some("2".into());
            items.push(item);
        }
        (items, incomplete)
    }

    /// The culture knowledge base's keys that the line does not name yet.
    fn culture_words(&self, written: Vec<&str>) -> Vec<CompletionItem> {
        let keys = self.snapshot.workspace.culture_keys(self.snapshot.path);
        keys.into_iter()
            .filter(|key| !written.contains(&key.as_str()))
            .map(|key| {
                let mut item = self.item(key.clone(), key, CompletionItemKind::ENUM_MEMBER);
                item.detail = Some("a key of the culture knowledge base".into());
                item
            })
            .collect()
    }

    fn arms(&self) -> Vec<CompletionItem> {
        [Arm::Left, Arm::Right]
            .map(|arm| {
                let name = arm.name().to_string();
                self.item(name.clone(), name, CompletionItemKind::ENUM_MEMBER)
            })
            .into()
    }
}
