//! A file's lines as a [`Document`], from the lossless syntax: every line is kept.
//!
//! A line is placed by its id, whatever its key: a known key, a key in the wrong case and an
//! unknown key all go to the block of their id. The only lines that cannot be placed are
//! entries (other than the tour) without a valid id: formatting such a file would have to
//! guess which location they belong to, so [`Document::parse`] refuses it instead.

use std::borrow::Cow;
use std::collections::HashMap;
use std::fmt;

use super::{Block, Document, Entry};
use crate::model::build::{parse_id, tour_items};
use crate::model::{Key, ValueKind};
use crate::render::escape::escape;
use crate::rewrite::name_lines;
use crate::syntax::{self, Body, Span};

/// Entries without a valid id: the file cannot be laid out without guessing.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Unplaceable {
    /// Line number and the line's text (escaped, shortened).
    pub lines: Vec<(u32, String)>,
}

impl fmt::Display for Unplaceable {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "{} {} no valid location id, so there is no telling which location {} to; \
             correct {} (see `ekb check`) and run again",
            name_lines(&self.lines),
            if self.lines.len() == 1 { "has" } else { "have" },
            if self.lines.len() == 1 {
                "it belongs"
            } else {
                "they belong"
            },
            if self.lines.len() == 1 { "it" } else { "them" },
        )
    }
}

impl std::error::Error for Unplaceable {}

impl<'a> Document<'a> {
    /// Lays out the lines of `text` canonically.
    pub fn parse(text: &'a str) -> Result<Document<'a>, Unplaceable> {
        let mut document = Document::default();
        let mut blocks: HashMap<u32, usize> = HashMap::new();
        let mut pending: Vec<Cow<'a, str>> = Vec::new();
        let mut seen_entry = false;
        let mut unplaceable = Vec::new();
        for line in syntax::lines(text) {
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
                let excerpt: String = line.content().text(text).trim().chars().take(40).collect();
                unplaceable.push((line.number, escape(&excerpt).into_owned()));
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
        if !unplaceable.is_empty() {
            return Err(Unplaceable { lines: unplaceable });
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
    fn lines_without_an_id_are_refused() {
        let error =
            Document::parse("gestureTarget 1 0 0 0\nrobotLocation 4a 1 2 3\nhello\n").unwrap_err();
        assert_eq!(
            error.lines,
            [(2, "robotLocation 4a 1 2 3".into()), (3, "hello".into())]
        );
        assert!(error
            .to_string()
            .starts_with("line 2 (`robotLocation 4a 1 2 3`), line 3"));
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
