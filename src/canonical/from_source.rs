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

use super::{Block, Document, Entry};
use crate::model::build::{parse_id, tour_items};
use crate::model::{Key, ValueKind};
use crate::render::escape::escape;
use crate::rewrite::name_lines;
use crate::syntax::{self, Body, Span};

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
        let mut document = Document::default();
        let mut blocks: HashMap<u32, usize> = HashMap::new();
        let mut pending: Vec<Cow<'a, str>> = Vec::new();
        let mut seen_entry = false;
        let mut stray_returns = Vec::new();
        for line in syntax::lines(text) {
            if line.body != Body::Blank
                && text.as_bytes()[line.trailing.start as usize - 1] == b'\r'
            {
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
                        document.header.append(&mut pending);
                    }
                    continue;
                }
                Body::Comment(comment) => {
                    pending.push(comment.text(text).into());
                    continue;
                }
                Body::Entry { key, args } => (key.text(text), args),
            };
            seen_entry = true;
            let comments = std::mem::take(&mut pending);
            let known = Key::from_name_ignoring_case(key);
            if known == Some(Key::TourSpecification) {
                let items = args.text(text);
                document.tour.push(Entry {
                    comments,
                    key: key.into(),
                    id: None,
                    value: single_spaced(items, tour_items(items, 0).map(|(_, item)| item)),
                });
                continue;
            }
            let Some((id, id_text, value)) = split_id(text, args) else {
                document.unplaced.push(Entry {
                    comments,
                    key: key.into(),
                    id: None,
                    value: args.text(text).into(),
                });
                continue;
            };
            let value = match known.map(Key::value_kind) {
                Some(ValueKind::Pose | ValueKind::Point) => {
                    single_spaced(value, syntax::tokens(value, 0).map(|(_, token)| token))
                }
                _ => value.into(),
            };
            let index = *blocks.entry(id).or_insert_with(|| {
                document.blocks.push(Block::default());
                document.blocks.len() - 1
            });
            document.blocks[index].entries.push(Entry {
                comments,
                key: key.into(),
                id: Some(id_text.into()),
                value,
            });
        }
        if !stray_returns.is_empty() {
            return Err(Unformattable {
                lines: stray_returns,
            });
        }
        document.blocks.iter_mut().for_each(Block::sort);
        document.footer = pending;
        if !seen_entry {
            // Without entries there is nothing to set a header apart from.
            let footer = std::mem::take(&mut document.footer);
            document.footer = std::mem::take(&mut document.header);
            document.footer.extend(footer);
        }
        Ok(document)
    }
}

/// The id of a location line, its text, and the value after it (possibly empty).
fn split_id(text: &str, args: Span) -> Option<(u32, &str, &str)> {
    let args_text = args.text(text);
    let mut tokens = syntax::tokens(args_text, 0);
    let (id_span, id_text) = tokens.next()?;
    let id = parse_id(id_text)?;
    let value = args_text[id_span.end as usize..].trim_start_matches([' ', '\t']);
    Some((id, id_text, value))
}

/// `items` joined by single spaces; borrowed when `text` already is exactly that.
fn single_spaced<'a>(text: &'a str, items: impl Iterator<Item = &'a str>) -> Cow<'a, str> {
    let joined = items.collect::<Vec<_>>().join(" ");
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
