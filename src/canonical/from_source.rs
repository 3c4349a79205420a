//! A file's lines as a [`Document`], from the lossless syntax: every line is kept.
//!
//! A line is placed by its id, whatever its key: a known key, a key in the wrong case and an
//! unknown key all go to the block of their id. An entry without a valid id (other than the
//! tour) cannot be placed: it goes, as written, to a section of its own at the top. The one
//! thing [`Document::parse`] refuses is a line ending in a stray carriage return, which
//! cannot be written before an LF without turning into a CRLF line ending.

use std::borrow::Cow;
use std::fmt;

use super::{
    balance, known_key, padding, slot, BlockOrder, Document, Written, PADDING, UNKNOWN_SLOT,
};
use super::{name_lines, NAMED_LINES};
use crate::model::build::{parse_id, tour_items};
use crate::model::{IdMap, Key, ValueKind};
use crate::render::escape::escape;
use crate::syntax::suppression;
use crate::syntax::{self, is_blank, Body, Line, LineEnding, Span};

/// Lines ending in a carriage return that is not part of a CRLF: written before the
/// layout's LF, it would turn into a line ending and vanish from the value.
#[derive(Debug, Clone, PartialEq, Eq, Default)]
pub struct Unformattable {
    /// The first few such lines: each one's number and text (escaped, shortened).
    pub lines: Vec<(u32, String)>,
    /// How many such lines there are in all.
    pub count: usize,
}

impl fmt::Display for Unformattable {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let more = self.count - self.lines.len();
        write!(
            f,
            "{}{} {} in a stray carriage return, which the layout's line ending would swallow; \
             remove it (see `ekb check`) and run again",
            name_lines(&self.lines),
            if more > 0 {
                format!(" and {more} more")
            } else {
                String::new()
            },
            if self.count == 1 { "ends" } else { "end" },
        )
    }
}

impl std::error::Error for Unformattable {}

impl<'a> Document<'a> {
    /// Lays out the lines of `text` canonically.
    pub fn parse(text: &'a str) -> Result<Document<'a>, Unformattable> {
        Document::parse_text(Cow::Borrowed(text), BlockOrder::FirstSeen)
    }

    /// Lays out the lines of `text`, which the document keeps, the blocks in `block_order`.
    ///
    /// Memory is what matters on a huge file: the lines are read twice rather than each
    /// line's block kept. The first reading counts the lines of each block, the second puts
    /// each line's start in its place, block after block; then each block is put in key
    /// order where it is not already, by reading its lines a third time.
    pub(super) fn parse_text(
        text: Cow<'a, str>,
        block_order: BlockOrder,
    ) -> Result<Document<'a>, Unformattable> {
        let layout = Layout::read(&text)?;
        Ok(Document::laid_out(text, layout, block_order))
    }

    /// The document of `text`, whose first reading found `layout`.
    fn laid_out(text: Cow<'a, str>, layout: Layout, block_order: BlockOrder) -> Document<'a> {
        let sequence = match block_order {
            BlockOrder::FirstSeen => None,
            BlockOrder::Balanced => Some(balance::balanced(&layout.blocks.ids())),
        };
        let (order, written, block_ends) = arrange(
            &text,
            layout.blocks,
            layout.located,
            layout.placed,
            sequence.as_deref(),
        );
        Document {
            text,
            header_end: layout.header_end,
            footer_start: layout.footer_start,
            unplaced: layout.unplaced,
            order,
            written,
            block_ends,
            tour: layout.tour,
        }
    }
}

/// What the first reading of a file finds.
#[derive(Default)]
struct Layout {
    header_end: u32,
    footer_start: u32,
    unplaced: Vec<u32>,
    tour: Vec<u32>,
    /// The located entries' blocks, and how many lines each has.
    blocks: Blocks,
    located: usize,
    /// Each located line, in file order, kept while they take at most a quarter of the
    /// text's size (lines of a usual length): then the lines are not read again to be put
    /// in order.
    placed: Option<Vec<Placed>>,
}

/// The most bytes [`Layout::placed`] takes, as a share of the text's size.
const PLACED_SHARE: usize = 4;

/// A located line as the first reading found it.
struct Placed {
    start: u32,
    block: u32,
    /// Its length if it is written as the layout writes it (see [`Document::written`]).
    written: u16,
}

/// What the first reading of a file needs of a line. Blank and comment lines matter only
/// before the first entry (for the header): a part of the file read on its own tells those
/// before its own first entry, and the whole reading drops those after the file's.
enum Seen {
    StrayReturn,
    Blank {
        end: u32,
    },
    /// A comment `# ekb: ignore[…]` for the next line.
    Suppression {
        start: u32,
    },
    Entry {
        start: u32,
        end: u32,
        placement: Placement,
    },
}

/// What the first reading needs of the lines from `lines` up to `end` (see [`Seen`]).
fn seen_lines(text: &str, lines: syntax::Lines<'_>, end: usize) -> Vec<Seen> {
    let mut seen_entry = false;
    // Whether no comment line came after the last entry line read.
    let mut no_comment_since_entry = false;
    lines
        .take_while(|line| (line.span.start as usize) < end)
        .filter_map(|line| {
            if ends_in_stray_return(text, &line) {
                return Some(Seen::StrayReturn);
            }
            match line.body {
                Body::Blank if !seen_entry => Some(Seen::Blank { end: line.span.end }),
                Body::Comment(comment)
                    if !seen_entry && suppression::is_for_next_line(comment.text(text)) =>
                {
                    Some(Seen::Suppression {
                        start: line.span.start,
                    })
                }
                Body::Blank => None,
                Body::Comment(_) => {
                    no_comment_since_entry = false;
                    None
                }
                Body::Entry { key, args } => {
                    seen_entry = true;
                    let mut placement = placement(text, &line, key, args);
                    // A line with comments above it is not marked: they are found from it.
                    if let Placement::Located { as_written, .. } = &mut placement {
                        *as_written &= no_comment_since_entry;
                    }
                    no_comment_since_entry = true;
                    Some(Seen::Entry {
                        start: line.span.start,
                        end: line.span.end,
                        placement,
                    })
                }
            }
        })
        .collect()
}

/// The lines of `text` that end in a stray carriage return, named.
fn stray_returns(text: &str) -> Unformattable {
    let mut stray_returns = Unformattable::default();
    for line in syntax::lines(text).filter(|line| ends_in_stray_return(text, line)) {
        stray_returns.count += 1;
        if stray_returns.lines.len() < NAMED_LINES {
            let content: String = line
                .content()
                .text(text)
                .trim_matches([' ', '\t'])
                .chars()
                .take(40)
                .collect();
            stray_returns
                .lines
                .push((line.number, escape(&content).into_owned()));
        }
    }
    stray_returns
}

impl Layout {
    /// The first reading of `text`, its lines read in pieces.
    fn read(text: &str) -> Result<Layout, Unformattable> {
        let most_placed = text.len() / PLACED_SHARE / std::mem::size_of::<Placed>();
        let mut layout = Layout {
            placed: Some(Vec::with_capacity(most_placed)),
            ..Layout::default()
        };
        let mut seen_entry = false;
        // Where the first `# ekb: ignore[…]` comment before any entry starts.
        let mut first_suppression = None;
        let mut any_stray_return = false;
        let each = |seen: Seen| match seen {
            Seen::StrayReturn => any_stray_return = true,
            Seen::Blank { end } if !seen_entry => layout.header_end = end,
            Seen::Suppression { start } if !seen_entry && first_suppression.is_none() => {
                first_suppression = Some(start);
            }
            Seen::Blank { .. } | Seen::Suppression { .. } => {}
            Seen::Entry {
                start,
                end,
                placement,
            } => {
                seen_entry = true;
                layout.footer_start = end;
                match placement {
                    Placement::Tour => layout.tour.push(start),
                    Placement::Unplaced => layout.unplaced.push(start),
                    Placement::Located {
                        id,
                        slot,
                        as_written,
                    } => {
                        let block = layout.blocks.count(id, slot);
                        match &mut layout.placed {
                            Some(placed) if placed.len() < most_placed => {
                                // A line too long for the count is laid out as any other.
                                let length = u16::try_from(end - start).unwrap_or(0);
                                placed.push(Placed {
                                    start,
                                    block,
                                    written: if as_written { length } else { 0 },
                                });
                            }
                            _ => layout.placed = None,
                        }
                        layout.located += 1;
                    }
                }
            }
        };
        read_in_pieces(text, |lines, end| seen_lines(text, lines, end), each);
        if any_stray_return {
            return Err(stray_returns(text));
        }
        if !seen_entry {
            // Without entries there is nothing to set a header apart from: it is all footer.
            layout.header_end = 0;
        }
        // A suppression is for the line below it, blank lines or not: never the header's.
        if let Some(start) = first_suppression {
            layout.header_end = layout.header_end.min(start);
        }
        Ok(layout)
    }
}

/// The blocks of a file, numbered in order of first appearance, with how many lines each
/// has; the block of an id found without a map while the ids of new blocks ascend (as in
/// nearly every file), by a map once they do not.
#[derive(Default)]
struct Blocks {
    /// The ids of the first blocks, ascending.
    ascending: Vec<u32>,
    /// The block of each id after those.
    others: IdMap<u32>,
    /// The lines of each block.
    lines: Vec<u32>,
    /// The slot of each block's last line so far, and whether its slots ascend so far
    /// ([`IN_ORDER`]): a block in key order already (nearly every one) is not read again to
    /// be sorted.
    last_slots: Vec<u8>,
    /// The last id and its block: a block's lines usually follow one another.
    last: Option<(u32, u32)>,
}

impl Blocks {
    /// The block of `id`, if it has one yet.
    fn find(&mut self, id: u32) -> Option<u32> {
        if let Some((last, block)) = self.last.filter(|&(last, _)| last == id) {
            debug_assert_eq!(last, id);
            return Some(block);
        }
        let block = match self.ascending.binary_search(&id) {
            Ok(block) => Some(block as u32),
            Err(_) => self.others.get(&id).copied(),
        }?;
        self.last = Some((id, block));
        Some(block)
    }

    /// Counts a line of `id`'s block, made if it is new, whose key goes in `slot`; returns
    /// the block.
    fn count(&mut self, id: u32, slot: u8) -> u32 {
        let block = self.find(id).unwrap_or_else(|| {
            let block = self.lines.len() as u32;
            self.lines.push(0);
            self.last_slots.push(IN_ORDER);
            if self.others.is_empty() && self.ascending.last().is_none_or(|&last| last < id) {
                self.ascending.push(id);
            } else {
                self.others.insert(id, block);
            }
            self.last = Some((id, block));
            block
        });
        self.lines[block as usize] += 1;
        let last = &mut self.last_slots[block as usize];
        *last = match *last & IN_ORDER != 0 && *last & !IN_ORDER <= slot {
            true => slot | IN_ORDER,
            false => slot,
        };
        block
    }

    /// The id of each block.
    fn ids(&self) -> Vec<u32> {
        let mut ids = self.ascending.clone();
        ids.resize(self.lines.len(), 0);
        for (&id, &block) in &self.others {
            ids[block as usize] = id;
        }
        ids
    }

    /// Whether the lines of `block` are in key order.
    fn in_order(&self, block: usize) -> bool {
        self.last_slots[block] & IN_ORDER != 0
    }
}

/// The bit of [`Blocks::last_slots`] that says a block's slots ascend (no slot is as high).
const IN_ORDER: u8 = 0x80;
const _: () = assert!(UNKNOWN_SLOT < IN_ORDER);

/// The located entries' line starts in canonical order ([`Document::order`]), the lengths
/// of those written as the layout writes them ([`Document::written`]), and where each block
/// ends, the blocks in the order of `sequence` (by number; else as first seen): put in
/// place by block (a counting sort, linear), as `placed` says or read again, then each
/// block put in key order, keeping the order of equal keys (a block is usually in order
/// already).
fn arrange(
    text: &str,
    mut blocks: Blocks,
    located: usize,
    placed: Option<Vec<Placed>>,
    sequence: Option<&[u32]>,
) -> (Vec<u32>, Vec<u16>, Vec<u32>) {
    let line_counts = std::mem::take(&mut blocks.lines);
    let block_at = |n: usize| sequence.map_or(n, |sequence| sequence[n] as usize);
    // Where each block's next line goes; once all are placed, where the block ends.
    let mut next = vec![0; line_counts.len()];
    let mut sum = 0;
    for n in 0..line_counts.len() {
        let block = block_at(n);
        (next[block], sum) = (sum, sum + line_counts[block]);
    }
    let mut order = vec![0u32; located];
    let mut written = Vec::new();
    let mut place = |start: u32, block: u32| {
        let at = next[block as usize] as usize;
        order[at] = start;
        next[block as usize] += 1;
        at
    };
    match placed {
        Some(placed) => {
            written = vec![0u16; located];
            for line in placed {
                written[place(line.start, line.block)] = line.written;
            }
        }
        None => each_located(text, |(start, id)| {
            let block = blocks.find(id).expect("counted in the first reading");
            place(start, block);
        }),
    }
    let block_ends: Vec<u32> = (0..line_counts.len()).map(|n| next[block_at(n)]).collect();
    for n in 0..line_counts.len() {
        let block = block_at(n);
        if !blocks.in_order(block) {
            let end = next[block] as usize;
            let range = end - line_counts[block] as usize..end;
            let written = written.get_mut(range.clone()).unwrap_or_default();
            sort_by_slot(text, &mut order[range], written);
        }
    }
    (order, written, block_ends)
}

/// How many bytes of text [`read_in_pieces`] reads at a time.
const READ_AT_A_TIME: usize = 8 << 20;

/// What `part` makes of each piece of lines of `text` (a starting offset and an end),
/// given to `each` in order, [`READ_AT_A_TIME`] bytes at a time: only what `part` makes of
/// one piece is held.
fn read_in_pieces<T>(
    text: &str,
    part: impl Fn(syntax::Lines<'_>, usize) -> Vec<T>,
    each: impl FnMut(T),
) {
    read_in_pieces_of(text, READ_AT_A_TIME, part, each);
}

/// [`read_in_pieces`], `at_a_time` bytes at a time.
fn read_in_pieces_of<T>(
    text: &str,
    at_a_time: usize,
    part: impl Fn(syntax::Lines<'_>, usize) -> Vec<T>,
    mut each: impl FnMut(T),
) {
    let bytes = text.as_bytes();
    let mut at = 0;
    while at < bytes.len() {
        let newline = bytes
            .get(at + at_a_time..)
            .and_then(|rest| memchr::memchr(b'\n', rest));
        let end = newline.map_or(bytes.len(), |newline| at + at_a_time + newline + 1);
        part(syntax::lines_from(text, at), end)
            .into_iter()
            .for_each(&mut each);
        at = end;
    }
}

/// Where each located entry line of `text` starts, and its id, given to `each` in order
/// (read in pieces).
fn each_located(text: &str, each: impl FnMut((u32, u32))) {
    let part = |lines: syntax::Lines<'_>, end: usize| {
        lines
            .take_while(|line| (line.span.start as usize) < end)
            .filter_map(|line| match line.body {
                Body::Entry { key, args } => match placement(text, &line, key, args) {
                    Placement::Located { id, .. } => Some((line.span.start, id)),
                    _ => None,
                },
                _ => None,
            })
            .collect()
    };
    read_in_pieces(text, part, each);
}

/// Puts the lines starting at `block` in key order ([`slot`]), keeping the order of lines of
/// the same slot: a counting sort over the few slots. `written`, the lengths of the block's
/// lines as written (or empty), moves with them.
fn sort_by_slot(text: &str, block: &mut [u32], written: &mut [u16]) {
    let slot_at = |start: u32| {
        let line = syntax::lines_from(text, start as usize).next();
        match line.map(|line| line.body) {
            Some(Body::Entry { key, .. }) => slot(known_key(key.text(text))),
            _ => unreachable!("an entry line starts there"),
        }
    };
    let slots: Vec<u8> = block.iter().map(|&start| slot_at(start)).collect();
    let mut next = [0usize; UNKNOWN_SLOT as usize + 2];
    for &slot in &slots {
        next[slot as usize + 1] += 1;
    }
    for slot in 1..next.len() {
        next[slot] += next[slot - 1];
    }
    let mut by_slot = vec![0usize; block.len()];
    for (line, &slot) in slots.iter().enumerate() {
        by_slot[next[slot as usize]] = line;
        next[slot as usize] += 1;
    }
    let starts: Vec<u32> = by_slot.iter().map(|&line| block[line]).collect();
    block.copy_from_slice(&starts);
    if !written.is_empty() {
        let lengths: Vec<u16> = by_slot.iter().map(|&line| written[line]).collect();
        written.copy_from_slice(&lengths);
    }
}

/// Where an entry line goes: with the tour, first as written (no valid id), or in the block
/// of its location.
enum Placement {
    Tour,
    Unplaced,
    Located {
        id: u32,
        slot: u8,
        /// Whether the line is written as the layout writes it.
        as_written: bool,
    },
}

/// Where the entry line `line` (`key args`) of `text` goes ([`read`] without making its
/// value).
fn placement(text: &str, line: &Line, key: Span, args: Span) -> Placement {
    let known = known_key(key.text(text));
    if known == Some(Key::TourSpecification) {
        return Placement::Tour;
    }
    match split_id(args.text(text)) {
        Some((id, id_text, value)) => Placement::Located {
            id,
            slot: slot(known),
            as_written: is_as_written(text, line, known, (key, args), id_text, value),
        },
        None => Placement::Unplaced,
    }
}

/// Whether the located entry line `line` of `text`, whose `key` and `args` [`split_id`] cut
/// into `id_text` and `value`, is written as the layout writes it ([`read`] and
/// [`push_entry`](super::push_entry)): the key, id and value are the line's own, so it is
/// when what is between them is, and the value is as [`read`] makes it.
fn is_as_written(
    text: &str,
    line: &Line,
    known: Option<Key>,
    (key, args): (Span, Span),
    id_text: &str,
    value: &str,
) -> bool {
    let bytes = text.as_bytes();
    let id_end = args.start as usize + id_text.len();
    let gap = &bytes[key.end as usize..args.start as usize];
    // A value of numbers is written single-spaced: it is so if no blank is next to another
    // (it starts and ends with none).
    let single_spaced = || {
        let value = value.as_bytes();
        !value.contains(&b'\t') && !value.windows(2).any(|pair| pair == b"  ")
    };
    line.indent.is_empty()
        && line.trailing.is_empty()
        && line.ending == LineEnding::Lf
        && match value.is_empty() {
            true => id_end == args.end as usize,
            false => bytes[id_end] == b' ' && id_end + 1 + value.len() == args.end as usize,
        }
        && gap == &PADDING.as_bytes()[..padding(key.text(text), id_text, value)]
        && match known.map(Key::value_kind) {
            Some(ValueKind::Pose | ValueKind::Point) => single_spaced(),
            _ => true,
        }
}

/// Whether a line that is not blank ends in a carriage return that is not part of a CRLF.
pub(super) fn ends_in_stray_return(text: &str, line: &Line) -> bool {
    line.body != Body::Blank && text.as_bytes()[line.trailing.start as usize - 1] == b'\r'
}

/// Where an entry line goes, with what value.
pub(super) enum Place<'t> {
    /// A `tourSpecification` line, its items single-spaced.
    Tour(Cow<'t, str>),
    /// A line of a location whose id is written `id_text`, with its value as the layout
    /// writes it.
    Located {
        id_text: &'t str,
        value: Cow<'t, str>,
    },
    /// A line without a valid id, and everything after its key.
    Unplaced(&'t str),
}

impl Place<'_> {
    /// Whether this is the line `written`.
    pub(super) fn is(&self, written: &Written<'_>) -> bool {
        match self {
            Place::Tour(value) => written.tour && written.id.is_none() && *value == written.value,
            Place::Located { id_text, value } => {
                !written.tour && written.id == Some(id_text) && *value == written.value
            }
            Place::Unplaced(value) => {
                !written.tour && written.id.is_none() && written.value == *value
            }
        }
    }
}

/// Reads the entry line `key args` of `text`.
pub(super) fn read(text: &str, key: Span, args: Span) -> Place<'_> {
    let known = known_key(key.text(text));
    let args = args.text(text);
    if known == Some(Key::TourSpecification) {
        Place::Tour(single_spaced(args, || tour_items(args, 0)))
    } else if let Some((_, id_text, value)) = split_id(args) {
        let value = match known.map(Key::value_kind) {
            Some(ValueKind::Pose | ValueKind::Point) => {
                single_spaced(value, || syntax::tokens(value, 0))
            }
            _ => value.into(),
        };
        Place::Located { id_text, value }
    } else {
        Place::Unplaced(args)
    }
}

/// The id of a location line's arguments, its text, and the value after it (possibly empty).
/// (Byte by byte: an id is a few bytes, and this is done for every line.)
fn split_id(args: &str) -> Option<(u32, &str, &str)> {
    let bytes = args.as_bytes();
    let blanks_end = |mut at: usize| {
        while at < bytes.len() && is_blank(bytes[at]) {
            at += 1;
        }
        at
    };
    let start = blanks_end(0);
    let mut end = start;
    while end < bytes.len() && !is_blank(bytes[end]) {
        end += 1;
    }
    let id_text = &args[start..end];
    let id = parse_id(id_text)?;
    Some((id, id_text, &args[blanks_end(end)..]))
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
    fn lines_read_a_few_bytes_at_a_time_come_in_order() {
        let text: String = (0..200).map(|n| format!("k {n}\n")).collect();
        let starts = |lines: syntax::Lines<'_>, end: usize| -> Vec<u32> {
            let lines = lines.take_while(|line| (line.span.start as usize) < end);
            lines.map(|line| line.span.start).collect()
        };
        let expected: Vec<u32> = syntax::lines(&text).map(|line| line.span.start).collect();
        for at_a_time in [1, 10, 100, 10_000] {
            let mut seen = Vec::new();
            read_in_pieces_of(&text, at_a_time, starts, |start| seen.push(start));
            assert_eq!(seen, expected, "{at_a_time}");
        }
    }

    proptest::proptest! {
        /// A line is marked as written exactly when laying it out gives it back: around each
        /// rule of the layout (the padding, the robot's line buffer, blanks in a value of
        /// numbers and of text, the line ending, the indentation, a key of other letters).
        #[test]
        fn a_line_is_marked_as_written_when_the_layout_writes_it_so(
            indent in proptest::sample::select(vec!["", "", "", " ", "\t"]),
            key in proptest::sample::select(vec![
                "robotLocation", "robotLocationDescription", "gestureTarget", "GESTURETARGET",
                "zzz", "clé", "postGestureMessageKinyarwanda", "aaaaaaaaaaaaaaaaaaaaaaaaaaaaaa",
                "bbbbbbbbbbbbbbbbbbbbbbbbbbbbbbb",
            ]),
            gap in proptest::sample::select(vec![" ", "\t", "  \t", " \t "]),
            spaces in proptest::option::of(0usize..32),
            id in proptest::sample::select(vec!["1", "42", "+7"]),
            separator in proptest::sample::select(vec!["", " ", " ", " ", "  ", "\t"]),
            value in proptest::sample::select(vec!["", "1 2 3", "1  2 3", "1 2\t3", "a  b"]),
            long in 0usize..200,
            end in proptest::sample::select(vec!["\n", "\n", "\n", " \n", "\r\n", ""]),
        ) {
            let value = match (value, long) {
                ("", 0) => String::new(),
                _ => format!("{value}{}", "v".repeat(long)),
            };
            let separator = if value.is_empty() { "" } else { separator };
            // The padding the layout writes, or another.
            let gap = match spaces {
                None => " ".repeat(padding(key, id, &value)),
                Some(0) => gap.to_string(),
                Some(spaces) => " ".repeat(spaces),
            };
            let text = format!("{indent}{key}{gap}{id}{separator}{value}{end}");
            let line = syntax::lines(&text).next().unwrap();
            let Body::Entry { key, args } = line.body else {
                panic!("an entry: {text:?}");
            };
            if let Placement::Located { as_written, .. } = placement(&text, &line, key, args) {
                let laid_out = Document::parse(&text).unwrap().render();
                proptest::prop_assert_eq!(as_written, laid_out == text, "{:?}", text);
            }
        }
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
