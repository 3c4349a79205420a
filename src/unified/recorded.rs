//! New lines read once and given again as often as asked, for new lines that cost more to
//! make than to keep: `ekb fix --diff` lays out a whole file, which the diff reads up to
//! three times ([`super::write_diff`]).

use std::ops::{ControlFlow, Range};

use super::align::{FirstReading, Kept, Runs, Start};
use super::{old_line, NewLine, NewLines};

/// A line's origin when it has none.
const NO_ORIGIN: u32 = u32::MAX;

/// The bit of a line's length that says it is its origin's line, read from the old text
/// again (a file is at most [`crate::source::MAX_FILE_SIZE`], far shorter than 2^31 bytes).
const AS_ITS_ORIGIN: u32 = 1 << 31;

/// New lines, each kept as its origin, its length and, if it differs from its origin's
/// line, its text: 8 bytes a line, and the text of the lines that changed (a layout changes
/// few lines of a file written in it, if any).
pub struct Recorded<'o> {
    old: &'o str,
    /// Each line's origin ([`NO_ORIGIN`]: none) and its length, with [`AS_ITS_ORIGIN`] if
    /// its text is its origin's line (else it is next in `changed`).
    lines: Vec<(u32, u32)>,
    /// The text of the lines that are not their origin's, one after the other.
    changed: String,
    /// The runs of lines, found as they are recorded (in parts, on the cores): the diff's
    /// first reading, done.
    runs: Runs,
}

impl<'o> Recorded<'o> {
    /// Reads the lines of `new`, made from `old`, once.
    pub fn new(old: &'o str, new: &impl NewLines) -> Recorded<'o> {
        let mut recorded = Recorded::none(old);
        let _ = new.each_line(&mut |line| {
            recorded.push(line);
            ControlFlow::Continue(())
        });
        recorded
    }

    /// No lines yet, of a new text made from `old`: lines are pushed, or parts appended.
    pub fn none(old: &'o str) -> Recorded<'o> {
        Recorded {
            old,
            lines: Vec::new(),
            changed: String::new(),
            runs: Runs::default(),
        }
    }

    /// Records the next line.
    pub fn push(&mut self, line: NewLine<'_>) {
        let origin = line.origin.unwrap_or(NO_ORIGIN);
        let same = line.origin.is_some_and(|origin| {
            let old_text = old_line(self.old, origin as usize);
            let same = old_text == line.text;
            let index = self.lines.len() as u32;
            self.runs
                .line(self.old, index, origin, old_text.len() as u32, same);
            same
        });
        let length = line.text.len() as u32;
        let length = match same {
            true => length | AS_ITS_ORIGIN,
            false => {
                self.changed.push_str(line.text);
                length
            }
        };
        self.lines.push((origin, length));
    }

    /// Records the next line, known to be the old line that starts at `origin`, `length`
    /// bytes with its line ending: [`Recorded::push`] without comparing them, nor reading
    /// the old line.
    ///
    /// # Safety
    ///
    /// `origin..origin + length` is a line of the old text, with its line ending: the
    /// line is taken from there unchecked.
    pub unsafe fn push_its_origin(&mut self, origin: u32, length: u32) {
        debug_assert_eq!(
            length as usize,
            old_line(self.old, origin as usize).len(),
            "a line's length"
        );
        let index = self.lines.len() as u32;
        self.runs.line(self.old, index, origin, length, true);
        self.lines.push((origin, length | AS_ITS_ORIGIN));
    }

    /// Records the lines of `part` (recorded apart, as on another core) after these.
    ///
    /// # Panics
    ///
    /// If `part` is of lines made from another old text.
    pub fn append(&mut self, part: Recorded<'_>) {
        assert!(std::ptr::eq(self.old, part.old), "lines of another text");
        let offset = self.lines.len() as u32;
        self.runs.append(self.old, part.runs, offset);
        self.lines.extend_from_slice(&part.lines);
        self.changed.push_str(&part.changed);
    }
}

/// The fewest lines in a row, equal to their origins' and from old lines in a row, that
/// keep their place, around where the lines are cut into parts: seven, so that the hunks
/// of a diff (three lines of context, and one hunk for changes up to six lines apart) never
/// span two parts.
const EQUAL_AROUND_A_CUT: u32 = 7;

/// Where a part of the lines starts: its first line, which keeps its place and is equal to
/// its origin, as the three before it, and where the text of its first changed line is in
/// [`Recorded::changed`].
#[derive(Debug, Clone, Copy)]
pub(super) struct Cut {
    pub start: Start,
    changed_at: usize,
}

impl Recorded<'_> {
    /// What the diff's first reading of these lines finds, from the runs found as they were
    /// recorded.
    pub(super) fn first_reading(&self) -> FirstReading {
        self.runs.reading(self.old, self)
    }

    /// Where to cut these lines, of which `kept` keep their place, into parts of about
    /// `lines` lines (at least) that a diff can read apart: each part starts amid
    /// [`EQUAL_AROUND_A_CUT`] lines in a row that keep their place, equal to their origins,
    /// which follow one another. The first part starts at the start.
    pub(super) fn cuts(&self, kept: &Kept, lines: u32) -> Vec<Cut> {
        let mut cuts = vec![Cut {
            start: Start::TEXT,
            changed_at: 0,
        }];
        let mut kept = kept.ranges().iter().peekable();
        let mut changed_at = 0;
        // The lines in a row so far, and where the old line after the last one starts.
        let (mut in_a_row, mut next) = (0, 0);
        // The origins of the last four lines, by index modulo 4.
        let mut origins = [0; 4];
        for (index, &(origin, length)) in (0u32..).zip(&self.lines) {
            while kept.next_if(|range| range.end <= index).is_some() {}
            let same = length & AS_ITS_ORIGIN != 0;
            let length = length & !AS_ITS_ORIGIN;
            if !same {
                changed_at += length as usize;
            }
            let in_place = same && kept.peek().is_some_and(|range| range.contains(&index));
            in_a_row = match in_place {
                true if in_a_row > 0 && origin == next => in_a_row + 1,
                true => 1,
                false => 0,
            };
            next = origin.wrapping_add(length);
            origins[index as usize % 4] = origin;
            let middle = index.wrapping_sub(EQUAL_AROUND_A_CUT / 2);
            let last = cuts[cuts.len() - 1].start.index;
            if in_a_row >= EQUAL_AROUND_A_CUT && middle >= last + lines {
                // The lines from the middle on are equal to their origins: none changed.
                cuts.push(Cut {
                    start: Start {
                        index: middle,
                        at: origins[middle as usize % 4] as usize,
                    },
                    changed_at,
                });
            }
        }
        cuts
    }

    /// The lines from cut `from` to cut `to` (the end if none).
    pub(super) fn part<'r>(&'r self, from: Cut, to: Option<Cut>) -> Part<'r, 'r> {
        let end = to.map_or(self.len(), |to| to.start.index);
        Part {
            recorded: self,
            lines: from.start.index..end,
            changed_at: from.changed_at,
        }
    }

    /// The lines up to `end`.
    pub(super) fn first_lines<'r>(&'r self, end: u32) -> Part<'r, 'r> {
        Part {
            recorded: self,
            lines: 0..end,
            changed_at: 0,
        }
    }

    /// How many lines there are.
    pub(super) fn len(&self) -> u32 {
        self.lines.len() as u32
    }

    /// Visits the lines `range`, the first changed one's text at `changed_at` in
    /// [`Recorded::changed`], each with its index, until `visit` breaks.
    fn each_line_in(
        &self,
        range: Range<u32>,
        mut changed_at: usize,
        visit: &mut dyn FnMut(u32, NewLine<'_>) -> ControlFlow<()>,
    ) -> ControlFlow<()> {
        let lines = &self.lines[range.start as usize..range.end as usize];
        for (index, &(origin, length)) in range.zip(lines) {
            let text = match length & AS_ITS_ORIGIN != 0 {
                true => {
                    let line = origin as usize..(origin + (length & !AS_ITS_ORIGIN)) as usize;
                    debug_assert!(
                        self.old.is_char_boundary(line.start)
                            && self.old.is_char_boundary(line.end)
                    );
                    // SAFETY: the range is a line of the old text with its line ending, as
                    // recorded (by `push`, or by `push_its_origin`, whose caller vouches for
                    // it): it starts and ends where lines do, on character boundaries.
                    // Unchecked, the line is not read until it is used: a diff's reading of
                    // half a file's lines moved compares only their lengths, and checking
                    // the boundaries read each one at a random place in the old text (8%
                    // of `fix --diff`'s time on the 100k file).
                    unsafe { self.old.get_unchecked(line) }
                }
                false => {
                    let start = changed_at;
                    changed_at += length as usize;
                    &self.changed[start..changed_at]
                }
            };
            let origin = (origin != NO_ORIGIN).then_some(origin);
            visit(index, NewLine { text, origin })?;
        }
        ControlFlow::Continue(())
    }
}

impl NewLines for Recorded<'_> {
    fn as_recorded(&self) -> Option<&Recorded<'_>> {
        Some(self)
    }

    fn each_line(&self, visit: &mut dyn FnMut(NewLine<'_>) -> ControlFlow<()>) -> ControlFlow<()> {
        self.each_line_in(0..self.lines.len() as u32, 0, &mut |_, line| visit(line))
    }
}

/// Some of the lines of a [`Recorded`], from one cut to the next, numbered as in the whole
/// (their first one is not line 0).
#[derive(Clone)]
pub(super) struct Part<'r, 'o> {
    recorded: &'r Recorded<'o>,
    lines: Range<u32>,
    changed_at: usize,
}

impl<'r, 'o> Part<'r, 'o> {
    /// The lines after these, up to `end`.
    pub(super) fn next_lines(&self, end: u32) -> Part<'r, 'o> {
        let lines = &self.recorded.lines[self.lines.start as usize..self.lines.end as usize];
        let changed: usize = lines
            .iter()
            .filter(|(_, length)| length & AS_ITS_ORIGIN == 0)
            .map(|&(_, length)| length as usize)
            .sum();
        Part {
            recorded: self.recorded,
            lines: self.lines.end..end,
            changed_at: self.changed_at + changed,
        }
    }
}

impl NewLines for Part<'_, '_> {
    fn each_line(&self, visit: &mut dyn FnMut(NewLine<'_>) -> ControlFlow<()>) -> ControlFlow<()> {
        self.each_wanted_line(&mut |_| true, &mut |_, line| visit(line))
    }

    fn each_wanted_line(
        &self,
        wanted: &mut dyn FnMut(u32) -> bool,
        visit: &mut dyn FnMut(u32, NewLine<'_>) -> ControlFlow<()>,
    ) -> ControlFlow<()> {
        let lines = self.lines.clone();
        self.recorded.each_line_in(
            lines,
            self.changed_at,
            &mut |index, line| match wanted(index) {
                true => visit(index, line),
                false => ControlFlow::Continue(()),
            },
        )
    }
}

#[cfg(test)]
mod tests {
    use super::super::lines_of as lines;
    use super::*;

    /// Lines given with their origins (as starts in the old text).
    struct Given(Vec<(&'static str, Option<u32>)>);

    impl NewLines for Given {
        fn each_line(
            &self,
            visit: &mut dyn FnMut(NewLine<'_>) -> ControlFlow<()>,
        ) -> ControlFlow<()> {
            for &(text, origin) in &self.0 {
                visit(NewLine { text, origin })?;
            }
            ControlFlow::Continue(())
        }
    }

    #[test]
    fn gives_the_lines_it_read_every_time() {
        let old = "a\nb\nc";
        let given = Given(vec![
            ("c\n", Some(4)),
            ("a\n", Some(0)),
            ("\n", None),
            ("B\n", Some(2)),
            ("c", Some(4)),
        ]);
        let recorded = Recorded::new(old, &given);
        assert_eq!(lines(&recorded), lines(&given));
        assert_eq!(lines(&recorded), lines(&given));
        // Only the lines unlike their origin's are kept.
        assert_eq!(recorded.changed, "c\n\nB\n");
    }

    #[test]
    fn stops_where_the_visit_breaks() {
        let given = Given(vec![("a\n", Some(0)), ("b\n", None)]);
        let recorded = Recorded::new("a\n", &given);
        let mut seen = 0;
        let _ = recorded.each_line(&mut |_| {
            seen += 1;
            ControlFlow::Break(())
        });
        assert_eq!(seen, 1);
    }
}
