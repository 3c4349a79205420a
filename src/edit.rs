//! Lossless edits of values, for `ekb set` and `ekb import --po`: only the bytes of the
//! values that change are replaced, and a value with no line gets one, added to its
//! location's lines in the order of SPEC §1's table and aligned as its neighbour is.
//!
//! Then [`new_errors`] tells what the chosen reader would make of the edited lines, so that a
//! value it would misread (a leading quote, a line longer than its buffer) is refused.

use std::collections::{HashMap, HashSet};

use crate::check::{check, Checked as CheckedFile};
use crate::diagnostic::{Diagnostic, Edit};
use crate::model::build::parse_id;
use crate::model::build::Options;
use crate::model::Key;
use crate::source::LineIndex;
use crate::source::SourceFile;
use crate::syntax::{self, Body, Line, LineEnding, Span};
use crate::Severity;

/// A new value for one key of one location.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ValueEdit {
    pub id: u32,
    pub key: Key,
    /// One line of text, without blanks at either end.
    pub value: String,
}

/// Why an edit cannot be made.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum EditError {
    /// No line of the file has this location's id.
    NoLocation(u32),
}

impl std::fmt::Display for EditError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            EditError::NoLocation(id) => write!(
                f,
                "the file has no location {id}: ekb edits the values of existing locations \
                 (add a new location's lines with an editor, or with `ekb import`)"
            ),
        }
    }
}

/// The edits made: the new text, and for each edit (in the order given) the 1-based line it
/// changed, in the old text (`None`: a line added) and in the new.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Edited {
    pub text: String,
    pub lines: Vec<(Option<u32>, u32)>,
}

/// Where each location's lines are.
struct LineMap {
    /// The line the robot reads for an id and key: the last one of that key, exactly spelled.
    read: HashMap<(u32, Key), Line>,
    /// Every line with a valid id and a known key (in any case), by id, in file order, with
    /// the key's slot ([`Key::order`]).
    by_id: HashMap<u32, Vec<(Line, usize)>>,
}

impl LineMap {
    /// The lines of the locations `ids` (the others are not kept: `ekb set` of one value in
    /// a 100 MB file maps one location's lines).
    fn new(text: &str, ids: &HashSet<u32>) -> LineMap {
        let mut map = LineMap {
            read: HashMap::new(),
            by_id: HashMap::new(),
        };
        for line in syntax::lines(text) {
            let Body::Entry { key, args } = line.body else {
                continue;
            };
            let key_text = key.text(text);
            let Some(known) = Key::from_name_ignoring_case(key_text) else {
                continue;
            };
            let (id, _) = syntax::first_token(text, args);
            let Some(id) = parse_id(id.text(text)).filter(|id| ids.contains(id)) else {
                continue;
            };
            if Key::from_name(key_text).is_some() {
                map.read.insert((id, known), line);
            }
            map.by_id.entry(id).or_default().push((line, known.order()));
        }
        map
    }
}

/// Makes `edits` in `text`. Two edits of one key of one location: the later wins.
pub fn apply(text: &str, edits: &[ValueEdit]) -> Result<Edited, EditError> {
    let ids: HashSet<u32> = edits.iter().map(|edit| edit.id).collect();
    let map = LineMap::new(text, &ids);
    let mut changes: Vec<(Edit, usize)> = Vec::new();
    for edit in edits {
        changes.push((change(text, &map, edit)?, edit.key.order()));
    }
    // Lines added at one place go in key order, as one insertion.
    changes.sort_by_key(|(change, order)| (change.span.start, change.span.end, *order));
    let mut merged: Vec<Edit> = Vec::new();
    for (change, _) in changes {
        match merged.last_mut() {
            Some(last) if last.span == change.span && change.span.is_empty() => {
                last.replacement.push_str(&change.replacement)
            }
            Some(last) if last.span == change.span => *last = change,
            _ => merged.push(change),
        }
    }
    let new_text = crate::fixing::splice(text, &merged);
    let old_index = LineIndex::new(text);
    let old_lines: Vec<Option<u32>> = edits
        .iter()
        .map(|edit| {
            map.read
                .get(&(edit.id, edit.key))
                .map(|line| old_index.line(line.span.start))
        })
        .collect();
    drop(map);
    let new_map = LineMap::new(&new_text, &ids);
    let new_index = LineIndex::new(&new_text);
    let lines = edits
        .iter()
        .zip(old_lines)
        .map(|(edit, old)| {
            let new = new_map
                .read
                .get(&(edit.id, edit.key))
                .map_or(0, |line| new_index.line(line.span.start));
            (old, new)
        })
        .collect();
    Ok(Edited {
        text: new_text,
        lines,
    })
}

/// The edit of the text that gives `edit.key` of location `edit.id` its new value.
fn change(text: &str, map: &LineMap, edit: &ValueEdit) -> Result<Edit, EditError> {
    if let Some(line) = map.read.get(&(edit.id, edit.key)) {
        let Body::Entry { key, args } = line.body else {
            unreachable!("the map holds entries only")
        };
        let (id, value) = syntax::first_token(text, args);
        let gap = Span::new(key.end as usize, args.start as usize);
        if is_padding(gap.text(text))
            && crate::canonical::padding(key.text(text), id.text(text), &edit.value) == 1
        {
            // The padding would make the robot cut the new line: one space, as `ekb fmt` writes.
            let end = if value.is_empty() { id.end } else { value.end };
            let kept = match value.is_empty() {
                true => format!("{} ", id.text(text)),
                false => Span::new(args.start as usize, value.start as usize)
                    .text(text)
                    .to_string(),
            };
            return Ok(Edit::replace(
                Span::new(gap.start as usize, end as usize),
                format!(" {kept}{}", edit.value),
            ));
        }
        return Ok(match value.is_empty() {
            true => Edit::insert(id.end, format!(" {}", edit.value)),
            false => Edit::replace(value, edit.value.clone()),
        });
    }
    let lines = map
        .by_id
        .get(&edit.id)
        .ok_or(EditError::NoLocation(edit.id))?;
    let order = edit.key.order();
    // After the last line of a key that comes before it, else before the first line.
    let (neighbour, after) = match lines.iter().rev().find(|(_, slot)| *slot <= order) {
        Some((line, _)) => (line, true),
        None => (&lines[0].0, false),
    };
    let new_line = aligned(text, neighbour, edit);
    let ending = match neighbour.ending {
        LineEnding::CrLf => "\r\n",
        LineEnding::Lf | LineEnding::None => "\n",
    };
    Ok(match (after, neighbour.ending) {
        // The last line of the file has no line ending: it gets one, and so does the new line
        // (a last text value without one loses its last letter, SPEC §2.3).
        (true, LineEnding::None) => Edit::insert(neighbour.span.end, format!("\n{new_line}\n")),
        (true, _) => Edit::insert(neighbour.span.end, format!("{new_line}{ending}")),
        (false, _) => Edit::insert(neighbour.span.start, format!("{new_line}{ending}")),
    })
}

/// `key id value`, with the id in the column of `neighbour`'s id when its key is padded up
/// to it (as `ekb fmt` writes) and the padding would not make the robot cut the line, else
/// after one space; the blanks between id and value as in
/// `neighbour`.
fn aligned(text: &str, neighbour: &Line, edit: &ValueEdit) -> String {
    let key = edit.key.name();
    let id = edit.id.to_string();
    let Body::Entry {
        key: neighbour_key,
        args,
    } = neighbour.body
    else {
        unreachable!("the map holds entries only")
    };
    let gap = Span::new(neighbour_key.end as usize, args.start as usize).text(text);
    let padded = is_padding(gap);
    let id_column = neighbour_key.text(text).chars().count() + gap.chars().count();
    let (neighbour_id, value) = syntax::first_token(text, args);
    // Padded as `ekb fmt` pads: not where the padding would make the robot cut the line.
    let spaces = match padded && crate::canonical::padding(key, &id, &edit.value) > 1 {
        true => id_column.saturating_sub(key.chars().count()).max(1),
        false => 1,
    };
    let separator = match value.is_empty() {
        true => " ",
        false => Span::new(neighbour_id.end as usize, value.start as usize).text(text),
    };
    format!("{key}{}{id}{separator}{}", " ".repeat(spaces), edit.value)
}

/// Whether the blanks between a key and its id are the spaces that align the ids.
fn is_padding(gap: &str) -> bool {
    gap.len() >= 2 && gap.bytes().all(|b| b == b' ')
}

/// An edit made and checked: the new text, and for each edit its line in the new text and
/// the errors the chosen reader's check finds there that were not there before.
#[derive(Debug)]
pub struct Checked {
    pub text: String,
    pub edits: Vec<CheckedEdit>,
    /// The errors in the whole new text, old ones included.
    pub errors: usize,
}

/// One edit of [`Checked`].
#[derive(Debug)]
pub struct CheckedEdit {
    /// Its line in the new text, 1-based.
    pub line: u32,
    /// What the robot's reader would misread or miss on that line: errors new to it.
    pub errors: Vec<Diagnostic>,
}

/// Makes `edits` in `source` (see [`apply`]) and checks the result as `options` say, against
/// the same reader as the file before. One check is held at a time: of the check before,
/// only the errors of the edited lines are kept.
pub fn apply_checked(
    source: &SourceFile,
    options: &Options,
    edits: &[ValueEdit],
) -> Result<Checked, EditError> {
    let edited = apply(source.text(), edits)?;
    let before = check(source, options);
    let had = errors_on(&before, edited.lines.iter().map(|&(old, _)| old));
    // The reader the file was checked against, even if the edit changes the dialect.
    let options = Options {
        reader: Some(before.reader),
        verbose: false,
        ..*options
    };
    drop(before);
    let after_source = SourceFile::from_bytes(source.name(), edited.text.into_bytes());
    let after = check(&after_source, &options);
    let now = errors_on(&after, edited.lines.iter().map(|&(_, new)| Some(new)));
    let edits = edited
        .lines
        .iter()
        .zip(had.into_iter().zip(now))
        .map(|(&(_, line), (had, now))| CheckedEdit {
            line,
            // What the edit would make the robot's reader misread or miss: the errors new
            // to the line (a line added had none).
            errors: now
                .into_iter()
                .filter(|error| !had.iter().any(|old| old.rule.name == error.rule.name))
                .collect(),
        })
        .collect();
    let errors = after.summary().errors;
    drop(after);
    Ok(Checked {
        text: after_source.into_text(),
        edits,
        errors,
    })
}

/// The errors `checked` finds on each of `lines` (1-based; `None`: no line, no error), in
/// one pass over its text and findings however many lines are asked for.
fn errors_on(
    checked: &CheckedFile<'_>,
    lines: impl Iterator<Item = Option<u32>>,
) -> Vec<Vec<Diagnostic>> {
    let lines: Vec<Option<u32>> = lines.collect();
    let mut found = vec![Vec::new(); lines.len()];
    let index = LineIndex::new(checked.source.text());
    for error in checked
        .diagnostics
        .iter()
        .filter(|d| d.severity() == Severity::Error)
    {
        let line = Some(index.line(error.span.start));
        for (at, _) in lines.iter().enumerate().filter(|(_, &l)| l == line) {
            found[at].push(error.clone());
        }
    }
    found
}
