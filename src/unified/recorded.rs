//! New lines read once and given again as often as asked, for new lines that cost more to
//! make than to keep: `ekb fix --diff` lays out a whole file, which the diff reads up to
//! three times ([`super::write_diff`]).

use std::ops::ControlFlow;

use super::align::{FirstReading, Runs};
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

    /// Records the lines of `part` (recorded apart, as on another core) after these.
    pub fn append(&mut self, part: Recorded<'_>) {
        let offset = self.lines.len() as u32;
        self.runs.append(self.old, part.runs, offset);
        self.lines.extend_from_slice(&part.lines);
        self.changed.push_str(&part.changed);
    }
}

impl Recorded<'_> {
    /// What the diff's first reading of these lines finds, from the runs found as they were
    /// recorded.
    pub(super) fn first_reading(&self) -> FirstReading {
        self.runs.reading(self.old, self)
    }
}

impl NewLines for Recorded<'_> {
    fn as_recorded(&self) -> Option<&Recorded<'_>> {
        Some(self)
    }

    fn each_line(&self, visit: &mut dyn FnMut(NewLine<'_>) -> ControlFlow<()>) -> ControlFlow<()> {
        let mut changed_at = 0;
        for &(origin, length) in &self.lines {
            let text = match length & AS_ITS_ORIGIN != 0 {
                true => {
                    let start = origin as usize;
                    &self.old[start..start + (length & !AS_ITS_ORIGIN) as usize]
                }
                false => {
                    let start = changed_at;
                    changed_at += length as usize;
                    &self.changed[start..changed_at]
                }
            };
            let origin = (origin != NO_ORIGIN).then_some(origin);
            visit(NewLine { text, origin })?;
        }
        ControlFlow::Continue(())
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
