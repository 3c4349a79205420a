//! A file's lines as a [`Document`], from the lossless syntax: every line is kept.
//!
//! A line is placed by its id, whatever its key: a known key, a key in the wrong case and an
//! unknown key all go to the block of their id. An entry without a valid id (other than the
//! tour) cannot be placed: it goes, as written, to a section of its own at the top. The one
//! thing [`Document::parse`] refuses is a line ending in a stray carriage return, which
//! cannot be written before an LF without turning into a CRLF line ending.

use std::borrow::Cow;
use std::collections::HashMap;
use std::fmt;

use super::{known_key, slot, Document, Entry, Written};
use crate::model::build::{parse_id, tour_items};
use crate::model::{Key, ValueKind};
use crate::render::escape::escape;
use crate::rewrite::name_lines;
use crate::suppression;
use crate::syntax::{self, Body, Line, Span};

/// Lines ending in a carriage return that is not part of a CRLF: written before the
/// layout's LF, it would turn into a line ending and vanish from the value.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct Unformattable {
    /// Each line's number and text (escaped, shortened).
    pub lines: Vec<(u32, String)>,
}

impl fmt::Display for Unformattable {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{} {} in a stray carriage return, which the layout's line ending would swallow; \
             remove it (see `ekb check`) and run again",
            name_lines(&self.lines),
            if self.lines.len() == 1 { "ends" } else { "end" },
        )
    }
}

impl std::error::Error for Unformattable {}

impl<'a> Document<'a> {
    /// Lays out the lines of `text` canonically.
    pub fn parse(text: &'a str) -> Result<Document<'a>, Unformattable> {
        let mut document = Document {
            text: Cow::Borrowed(text),
            ..Document::default()
        };
        let mut blocks: HashMap<u32, u32> = HashMap::new();
        let mut located: Vec<Located> = Vec::new();
        let mut seen_entry = false;
        let mut stray_returns = Vec::new();
        for line in syntax::lines(text) {
            if ends_in_stray_return(text, &line) {
                let content: String = line
                    .content()
                    .text(text)
                    .trim_matches([' ', '\t'])
                    .chars()
                    .take(40)
                    .collect();
                stray_returns.push((line.number, escape(&content).into_owned()));
                continue;
            }
            let (key, args) = match line.body {
                Body::Blank => {
                    if !seen_entry {
                        document.header = document.comments.len() as u32;
                    }
                    continue;
                }
                Body::Comment(comment) => {
                    document.comments.push(comment);
                    continue;
                }
                Body::Entry { key, args } => (key, args),
            };
            seen_entry = true;
            let index = document.entries.len() as u32;
            let read = read(text, key, args);
            let (id, value) = match read.place {
                Place::Tour(value) => {
                    document.tour.push(index);
                    (None, value)
                }
                Place::Unplaced(value) => {
                    document.unplaced.push(index);
                    (None, value.into())
                }
                Place::Located { id, id_text, value } => {
                    let next = blocks.len() as u32;
                    let block = *blocks.entry(id).or_insert(next);
                    located.push(Located {
                        entry: index,
                        block,
                        slot: slot(read.known),
                    });
                    (Some(Span::of(id_text, text)), value)
                }
            };
            let value = document.span_of(value);
            document.entries.push(Entry {
                comments_end: document.comments.len() as u32,
                key,
                id,
                value,
            });
        }
        if !stray_returns.is_empty() {
            return Err(Unformattable {
                lines: stray_returns,
            });
        }
        if !seen_entry {
            // Without entries there is nothing to set a header apart from: it is all footer.
            document.header = 0;
        }
        // A suppression is for the line below it, blank lines or not: never the header's.
        let header = &document.comments[..document.header as usize];
        if let Some(first) = header
            .iter()
            .position(|comment| suppression::is_for_next_line(comment.text(text)))
        {
            document.header = first as u32;
        }
        (document.order, document.block_ends) = arrange(&located, blocks.len());
        Ok(document)
    }
}

/// A line that goes to a location's block.
struct Located {
    /// Its index in the document's entries.
    entry: u32,
    /// Its block, numbered in order of first appearance.
    block: u32,
    /// Where it goes inside the block.
    slot: u8,
}

/// The located entries in canonical order, and where each block ends in it: grouped by block
/// by a counting sort (linear), then each block in key order, keeping the order of equal
/// keys (a block is usually in order already, and small).
fn arrange(located: &[Located], block_count: usize) -> (Vec<u32>, Vec<u32>) {
    let mut starts = vec![0u32; block_count + 1];
    for line in located {
        starts[line.block as usize + 1] += 1;
    }
    for block in 0..block_count {
        starts[block + 1] += starts[block];
    }
    let ends = starts[1..].to_vec();
    // Positions in `located` first, to sort by slot; entries once sorted.
    let mut order = vec![0u32; located.len()];
    for (position, line) in located.iter().enumerate() {
        let at = &mut starts[line.block as usize];
        order[*at as usize] = position as u32;
        *at += 1;
    }
    let mut start = 0;
    for &end in &ends {
        let block = &mut order[start as usize..end as usize];
        let slot = |&position: &u32| located[position as usize].slot;
        if !block.is_sorted_by_key(slot) {
            block.sort_by_key(slot);
        }
        start = end;
    }
    order
        .iter_mut()
        .for_each(|position| *position = located[*position as usize].entry);
    (order, ends)
}

/// Whether a line that is not blank ends in a carriage return that is not part of a CRLF.
pub(super) fn ends_in_stray_return(text: &str, line: &Line) -> bool {
    line.body != Body::Blank && text.as_bytes()[line.trailing.start as usize - 1] == b'\r'
}

/// How an entry line reads: its key, and where it goes with what value.
pub(super) struct Read<'t> {
    known: Option<Key>,
    place: Place<'t>,
}

pub(super) enum Place<'t> {
    /// A `tourSpecification` line, its items single-spaced.
    Tour(Cow<'t, str>),
    /// A line of location `id`, written `id_text`, with its value as the layout writes it.
    Located {
        id: u32,
        id_text: &'t str,
        value: Cow<'t, str>,
    },
    /// A line without a valid id, and everything after its key.
    Unplaced(&'t str),
}

impl Read<'_> {
    /// Whether this is the line `written`.
    pub(super) fn is(&self, written: Written<'_>) -> bool {
        match &self.place {
            Place::Tour(value) => written.tour && written.id.is_none() && value == written.value,
            Place::Located { id_text, value, .. } => {
                !written.tour && written.id == Some(id_text) && value == written.value
            }
            Place::Unplaced(value) => {
                !written.tour && written.id.is_none() && *value == written.value
            }
        }
    }
}

/// Reads the entry line `key args` of `text`.
pub(super) fn read(text: &str, key: Span, args: Span) -> Read<'_> {
    let known = known_key(key.text(text));
    let args = args.text(text);
    let place = if known == Some(Key::TourSpecification) {
        Place::Tour(single_spaced(args, || tour_items(args, 0)))
    } else if let Some((id, id_text, value)) = split_id(args) {
        let value = match known.map(Key::value_kind) {
            Some(ValueKind::Pose | ValueKind::Point) => {
                single_spaced(value, || syntax::tokens(value, 0))
            }
            _ => value.into(),
        };
        Place::Located { id, id_text, value }
    } else {
        Place::Unplaced(args)
    };
    Read { known, place }
}

/// The id of a location line's arguments, its text, and the value after it (possibly empty).
fn split_id(args: &str) -> Option<(u32, &str, &str)> {
    let (id_span, id_text) = syntax::tokens(args, 0).next()?;
    let id = parse_id(id_text)?;
    let value = args[id_span.end as usize..].trim_start_matches([' ', '\t']);
    Some((id, id_text, value))
}

/// The `items` of `text` (with their spans in it) joined by single spaces; borrowed when
/// `text` already is exactly that, as almost always: then nothing is allocated.
fn single_spaced<'t, I>(text: &'t str, items: impl Fn() -> I) -> Cow<'t, str>
where
    I: Iterator<Item = (Span, &'t str)>,
{
    let mut end = None;
    let aligned = items().all(|(span, _)| {
        let at = end.map_or(0, |end| end + 1);
        let follows = end.is_none_or(|end| text.as_bytes()[end] == b' ');
        end = Some(span.end as usize);
        follows && span.start as usize == at
    });
    if aligned && end.unwrap_or(0) == text.len() {
        return Cow::Borrowed(text);
    }
    let joined = items().map(|(_, item)| item).collect::<Vec<_>>().join(" ");
    if joined == text {
        Cow::Borrowed(text)
    } else {
        Cow::Owned(joined)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn format(text: &str) -> String {
        Document::parse(text).unwrap().render()
    }

    #[test]
    fn groups_orders_and_aligns() {
        let text = "gestureTarget 2 1  2\t3\n\
                    robotLocationDescription\t1 One  two\n\
                    tourSpecification 2 1,2\n\
                    robotLocationDescription 2 Two\n\
                    robotLocation 1 1 2 3\n";
        assert_eq!(
            format(text),
            "robotLocationDescription      2 Two\n\
             gestureTarget                 2 1 2 3\n\
             \n\
             robotLocationDescription      1 One  two\n\
             robotLocation                 1 1 2 3\n\
             \n\
             tourSpecification 2 1 2\n"
        );
    }

    #[test]
    fn comments_move_with_the_line_below_them() {
        let text = "# header\n\n# pose of one\nrobotLocation 1 1 2 3\n# name\nrobotLocationDescription 1 A\n# end\n";
        assert_eq!(
            format(text),
            "# header\n\
             \n\
             # name\n\
             robotLocationDescription      1 A\n\
             # pose of one\n\
             robotLocation                 1 1 2 3\n\
             \n\
             # end\n"
        );
    }

    #[test]
    fn a_suppression_above_the_first_entry_moves_with_it() {
        let text = "# header\n# ekb: ignore-file[tour-missing]\n# ekb: ignore[repeated-word]\n\n\
                    robotLocation 2 1 2 3\nrobotLocationDescription 2 the the\n";
        assert_eq!(
            format(text),
            "# header\n\
             # ekb: ignore-file[tour-missing]\n\
             \n\
             robotLocationDescription      2 the the\n\
             # ekb: ignore[repeated-word]\n\
             robotLocation                 2 1 2 3\n"
        );
    }

    #[test]
    fn lines_with_odd_keys_stay_in_their_block() {
        let text = "zzz 1 unknown\nrobotlocationdescription 1 A\nrobotLocationDescription 1 B\n";
        assert_eq!(
            format(text),
            "robotlocationdescription      1 A\n\
             robotLocationDescription      1 B\n\
             zzz                           1 unknown\n"
        );
    }

    #[test]
    fn lines_without_an_id_go_first_as_written() {
        let text = "# header\n\ngestureTarget 1 0 0 0\n# typo\nrobotLocation 4a 1  2 3\nhello\n";
        assert_eq!(
            format(text),
            "# header\n\
             \n\
             # typo\n\
             robotLocation 4a 1  2 3\n\
             hello\n\
             \n\
             gestureTarget                 1 0 0 0\n"
        );
    }

    #[test]
    fn a_stray_carriage_return_at_the_end_of_a_line_is_refused() {
        for text in [
            "robotLocationDescription 1 A\r",
            "# note\r\r\n",
            "key 1 x\r  \n",
        ] {
            let error = Document::parse(text).unwrap_err();
            assert_eq!(error.lines.len(), 1, "{text:?}");
            assert!(error
                .to_string()
                .contains("ends in a stray carriage return"));
        }
        assert!(Document::parse("key 1 a\rb\r\n").is_ok());
    }

    #[test]
    fn a_file_of_comments_only_is_kept() {
        for text in ["# a\n\n# b\n", "# a\n# b\n", "# a\n"] {
            let once = format(text);
            assert_eq!(format(&once), once);
        }
        assert_eq!(format(""), "");
        assert_eq!(format("\n\n"), "");
    }
}
