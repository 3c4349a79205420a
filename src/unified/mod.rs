//! Unified diffs written from where each new line came from, instead of by diffing two
//! whole texts: `ekb fmt --check` and `ekb fix --diff` on a file of any size.
//!
//! A new text is given as its lines in order ([`NewLines`]), each with the start of the
//! old line it was made from, if any (its *origin*). The diff pairs each new line with its
//! origin where the origins ascend, so that lines that moved (a block put in order, the
//! tour moved to the end) are shown as taken out and put in, and every other line in
//! place: equal, or changed. Three readings of the new lines at most, none holding the new
//! text:
//!
//! 1. [`align::first_reading`]: the new lines that keep their place, the longest ascending
//!    chain of runs of consecutive origins (weighted by their equal lines); when the runs
//!    all ascend (nothing moved), the changes too, and there is no second reading. New
//!    lines read once and kept ([`Recorded`]) found their runs as they were read, in parts
//!    on the cores;
//! 2. [`align::changes`]: the changes, each a range of old lines replaced by a range of new
//!    ones, with what is equal between them; in a large text, found on another thread as
//!    the hunks are printed ([`follow`]), or, of lines read once, found and printed in
//!    parts on the cores ([`in_parts`]);
//! 3. [`print`]: the hunks, with three lines of context, written as they come (old lines
//!    from the old text, new ones as the third reading reaches them).
//!
//! The memory is a few words per run and per change, however large the file: never the
//! new text, nor the diff. Any origins give a correct diff (a line is only shown equal when
//! it is equal); good origins give a small one.

mod align;
mod follow;
mod in_order;
mod in_parts;
mod print;
mod recorded;

pub use in_order::{InOrder, Origins, Through};
pub use recorded::Recorded;

use std::io::{self, Write};
use std::ops::ControlFlow;

use crate::parallel;
use crate::syntax::newline;

/// One line of a new text.
#[derive(Debug, Clone, Copy)]
pub struct NewLine<'t> {
    /// The line with its line ending (the last line of a text may have none).
    pub text: &'t str,
    /// Where the old line it was made from starts in the old text, if it was made from one.
    pub origin: Option<u32>,
}

/// A new text, line by line, as many times as asked: the same lines every time.
pub trait NewLines {
    /// Visits each line in order until `visit` breaks.
    fn each_line(&self, visit: &mut dyn FnMut(NewLine<'_>) -> ControlFlow<()>) -> ControlFlow<()>;

    /// Whether the lines' origins ascend (nothing moved), known without reading the lines:
    /// then the changes can be printed as they are found.
    fn origins_ascend(&self) -> bool {
        false
    }

    /// These lines, if they were read once already ([`Recorded`]): then the diff's first
    /// reading is done too.
    fn as_recorded(&self) -> Option<&Recorded<'_>> {
        None
    }

    /// The lines read once ([`Recorded`]) against `old`, the text they were made from. A new
    /// text that can lay out its lines in parts on the cores does so.
    fn record<'o>(&self, old: &'o str) -> Recorded<'o>
    where
        Self: Sized,
    {
        Recorded::new(old, self)
    }

    /// Visits the lines whose index (0-based) `wanted` takes, in order, each with its index,
    /// until `visit` breaks; `wanted` is asked of each index in order. A new text that can
    /// pass over a line more cheaply than it writes it does so for the others.
    fn each_wanted_line(
        &self,
        wanted: &mut dyn FnMut(u32) -> bool,
        visit: &mut dyn FnMut(u32, NewLine<'_>) -> ControlFlow<()>,
    ) -> ControlFlow<()> {
        let mut index = 0;
        self.each_line(&mut |line| {
            index += 1;
            match wanted(index - 1) {
                true => visit(index - 1, line),
                false => ControlFlow::Continue(()),
            }
        })
    }
}

/// How the diff is printed.
#[derive(Debug, Clone, Copy)]
pub struct Style<'n> {
    /// The file's name in the headers (escaped as they are printed).
    pub name: &'n str,
    /// ANSI colours: `+` lines green, `-` lines red, hunk headers cyan.
    pub color: bool,
}

/// Writes the unified diff of `old` and `new` to `out` (nothing if they are equal), each
/// printed line escaped as every output of ekb is. Returns whether they differ.
pub fn write_diff(
    out: &mut impl Write,
    old: &str,
    new: &(impl NewLines + Sync),
    style: Style<'_>,
) -> io::Result<bool> {
    let large = parallel::parts_for_text(old.len()) > 1;
    if new.origins_ascend() && large {
        return write_as_found(out, old, new, None, style, HAND_OVER_EVERY);
    }
    let reading = match new.as_recorded() {
        Some(recorded) => recorded.first_reading(),
        None => align::first_reading(old, new),
    };
    let changes = match reading {
        align::FirstReading::InOrder(changes) => changes,
        align::FirstReading::Moved(kept) if large => {
            let in_parts = new.as_recorded().and_then(|recorded| {
                in_parts::write_diff(out, old, recorded, &kept, style, in_parts::SIZES)
            });
            return in_parts.unwrap_or_else(|| {
                write_as_found(out, old, new, Some(&kept), style, HAND_OVER_EVERY)
            });
        }
        align::FirstReading::Moved(kept) => align::changes(old, new, &kept),
    };
    print::print(out, old, new, follow::Known::all(changes), style)
}

/// How many new lines the finder of [`write_as_found`] reads between two hand-overs.
const HAND_OVER_EVERY: u32 = 4096;

/// [`write_diff`] of new lines whose origins ascend (nothing moved), or whose lines `kept`
/// keep their place: the changes are found on another thread, handed over every
/// `hand_over_every` lines, as the diff is printed.
fn write_as_found(
    out: &mut impl Write,
    old: &str,
    new: &(impl NewLines + Sync),
    kept: Option<&align::Kept>,
    style: Style<'_>,
    hand_over_every: u32,
) -> io::Result<bool> {
    let shared = follow::Shared::default();
    std::thread::scope(|scope| {
        let find = || align::find(old, new, kept, shared.finder(), hand_over_every);
        if std::thread::Builder::new()
            .spawn_scoped(scope, find)
            .is_err()
        {
            // Without a thread, they are all found first.
            align::find(old, new, kept, shared.finder(), hand_over_every);
        }
        print::print(out, old, new, follow::Known::following(&shared), style)
    })
}

/// The lines of `text` with their line endings, each with where it starts.
pub(crate) fn lines_inclusive(text: &str) -> impl Iterator<Item = (usize, &str)> + '_ {
    let mut start = 0;
    std::iter::from_fn(move || {
        if start >= text.len() {
            return None;
        }
        let end = newline::find(&text.as_bytes()[start..]).map_or(text.len(), |i| start + i + 1);
        let line = (start, &text[start..end]);
        start = end;
        Some(line)
    })
}

/// The lines of `new`, each with its origin: for tests that compare two ways of making
/// them.
#[cfg(test)]
pub(crate) fn lines_of(new: &impl NewLines) -> Vec<(String, Option<u32>)> {
    let mut lines = Vec::new();
    let _ = new.each_line(&mut |line| {
        lines.push((line.text.to_string(), line.origin));
        ControlFlow::Continue(())
    });
    lines
}

/// The old line that starts at `start`, with its line ending.
fn old_line(old: &str, start: usize) -> &str {
    let end = newline::find(&old.as_bytes()[start..]).map_or(old.len(), |i| start + i + 1);
    &old[start..end]
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// New lines given with their origins, as old line numbers (0-based) of `old`.
    struct Given<'a> {
        lines: Vec<(&'a str, Option<usize>)>,
        old: &'a str,
    }

    impl NewLines for Given<'_> {
        fn each_line(
            &self,
            visit: &mut dyn FnMut(NewLine<'_>) -> ControlFlow<()>,
        ) -> ControlFlow<()> {
            let starts: Vec<usize> = lines_inclusive(self.old).map(|(start, _)| start).collect();
            for &(text, origin) in &self.lines {
                visit(NewLine {
                    text,
                    origin: origin.map(|line| starts[line] as u32),
                })?;
            }
            ControlFlow::Continue(())
        }
    }

    const STYLE: Style = Style {
        name: "kb.dat",
        color: false,
    };

    fn diff(old: &str, new: &(impl NewLines + Sync)) -> String {
        let mut out = Vec::new();
        write_diff(&mut out, old, new, STYLE).unwrap();
        String::from_utf8(out).unwrap()
    }

    /// The diff printed as the changes are found, handed over every `every` lines.
    fn diff_as_found(old: &str, new: &(impl NewLines + Sync), every: u32) -> String {
        let mut out = Vec::new();
        write_as_found(&mut out, old, new, None, STYLE, every).unwrap();
        String::from_utf8(out).unwrap()
    }

    /// The diff of lines that moved printed as the changes are found, handed over every
    /// `every` lines; none if nothing moved.
    fn diff_moved_as_found(old: &str, new: &(impl NewLines + Sync), every: u32) -> Option<String> {
        let align::FirstReading::Moved(kept) = align::first_reading(old, new) else {
            return None;
        };
        let mut out = Vec::new();
        write_as_found(&mut out, old, new, Some(&kept), STYLE, every).unwrap();
        Some(String::from_utf8(out).unwrap())
    }

    /// The diff of the lines of `new`, recorded, that moved, found and printed in parts of
    /// `sizes`; none if nothing moved, or the parts cannot be read apart.
    fn diff_in_parts(old: &str, new: &impl NewLines, sizes: in_parts::Sizes) -> Option<String> {
        let recorded = Recorded::new(old, new);
        let align::FirstReading::Moved(kept) = recorded.first_reading() else {
            return None;
        };
        let mut out = Vec::new();
        in_parts::write_diff(&mut out, old, &recorded, &kept, STYLE, sizes)?.unwrap();
        Some(String::from_utf8(out).unwrap())
    }

    /// `blocks` blocks of lines (block `n` has `1 + n % 9` of them, one of which is
    /// blank), and the blocks in the `order` given, the lines that `edits` picks edited
    /// (when the pick is 1), or with a new blank line before them (2).
    fn moved_blocks(order: &[usize], edits: &[u8]) -> (String, Vec<(String, Option<usize>)>) {
        let lines_of = |block: usize| -> Vec<String> {
            (0..1 + block % 9)
                .map(|line| match line {
                    4 => String::new(),
                    line => format!("b{block} l{line}"),
                })
                .collect()
        };
        let mut starts = Vec::new();
        let mut old = String::new();
        for block in 0..order.len() {
            starts.push(old.lines().count());
            for line in lines_of(block) {
                old.push_str(&line);
                old.push('\n');
            }
        }
        let mut new = Vec::new();
        for &block in order {
            for (n, line) in lines_of(block).into_iter().enumerate() {
                let origin = Some(starts[block] + n);
                match edits[new.len() % edits.len()] {
                    1 => new.push((format!("{line} edited\n"), origin)),
                    2 => {
                        new.push(("\n".to_string(), None));
                        new.push((format!("{line}\n"), origin));
                    }
                    _ => new.push((format!("{line}\n"), origin)),
                }
            }
        }
        (old, new)
    }

    #[test]
    fn blocks_moved_in_a_large_text_are_diffed_in_parts_and_pieces() {
        // Half the blocks moved ahead of the others, as a balanced order moves them.
        let blocks = 400;
        let order: Vec<usize> = (0..blocks)
            .filter(|block| block % 2 == 1)
            .chain((0..blocks).filter(|block| block % 2 == 0))
            .collect();
        let (old, lines) = moved_blocks(&order, &[0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1]);
        let lines: Vec<(&str, Option<usize>)> = lines
            .iter()
            .map(|(text, origin)| (text.as_str(), *origin))
            .collect();
        let given = Given { lines, old: &old };
        let sizes = in_parts::Sizes {
            lines_per_part: 100,
            lines_per_piece: 50,
        };
        let in_parts = diff_in_parts(&old, &given, sizes).expect("read in parts");
        assert_eq!(in_parts, diff(&old, &given));
        let recorded = Recorded::new(&old, &given);
        let align::FirstReading::Moved(kept) = recorded.first_reading() else {
            panic!("the blocks moved");
        };
        let cuts = recorded.cuts(&kept, sizes.lines_per_part).len();
        assert!(cuts > 5, "{cuts} parts");
    }

    fn in_order(old: &str, new: &str) -> String {
        diff(old, &InOrder { old, new })
    }

    /// `old` with the unified diff `diff` applied, as `patch` does (hunks in order, each
    /// checked against `old`).
    fn apply(old: &str, diff: &str) -> String {
        let old_lines: Vec<&str> = lines_inclusive(old).map(|(_, line)| line).collect();
        let mut out = String::new();
        let mut next_old = 0;
        let mut lines = diff.lines().skip(2).peekable();
        while let Some(header) = lines.next() {
            let ranges: Vec<&str> = header
                .trim_start_matches("@@ -")
                .trim_end_matches(" @@")
                .split(" +")
                .collect();
            let start = |range: &str| -> (usize, usize) {
                let (start, length) = range.split_once(',').unwrap_or((range, "1"));
                let (start, length): (usize, usize) =
                    (start.parse().unwrap(), length.parse().unwrap());
                (if length == 0 { start } else { start - 1 }, length)
            };
            let (old_start, _) = start(ranges[0]);
            for line in &old_lines[next_old..old_start] {
                out.push_str(line);
            }
            next_old = old_start;
            while let Some(line) = lines.next_if(|line| !line.starts_with("@@")) {
                let (tag, text) = line.split_at(1);
                let ends = lines.next_if(|line| line.starts_with('\\')).is_none();
                let text = if ends {
                    format!("{text}\n")
                } else {
                    text.to_string()
                };
                if tag != "+" {
                    assert_eq!(old_lines[next_old], text, "{diff}");
                    next_old += 1;
                }
                if tag != "-" {
                    out.push_str(&text);
                }
            }
        }
        for line in &old_lines[next_old..] {
            out.push_str(line);
        }
        out
    }

    #[test]
    fn a_line_changed_in_place() {
        assert_eq!(
            in_order("a\nb\n", "a\nc\n"),
            "--- kb.dat\n+++ kb.dat\n@@ -1,2 +1,2 @@\n a\n-b\n+c\n"
        );
        assert_eq!(in_order("a\nb\n", "a\nb\n"), "");
    }

    #[test]
    fn a_text_without_a_final_newline_says_so() {
        assert_eq!(
            in_order("a\nb", "a\nb\n"),
            "--- kb.dat\n+++ kb.dat\n@@ -1,2 +1,2 @@\n a\n-b\n\\ No newline at end of file\n+b\n"
        );
    }

    #[test]
    fn an_empty_side_names_the_line_before() {
        assert_eq!(
            in_order("", "x\n"),
            "--- kb.dat\n+++ kb.dat\n@@ -0,0 +1 @@\n+x\n"
        );
        assert_eq!(
            in_order("x\n", ""),
            "--- kb.dat\n+++ kb.dat\n@@ -1 +0,0 @@\n-x\n"
        );
    }

    #[test]
    fn changes_six_lines_apart_share_a_hunk_and_seven_do_not() {
        let old: String = (0..20).map(|n| format!("{n}\n")).collect();
        let six = old.replace("\n3\n", "\n3x\n").replace("\n10\n", "\n10x\n");
        let diff = in_order(&old, &six);
        assert_eq!(diff.matches("@@ -").count(), 1, "{diff}");
        assert!(diff.contains("@@ -1,14 +1,14 @@"), "{diff}");
        let seven = old.replace("\n3\n", "\n3x\n").replace("\n11\n", "\n11x\n");
        let diff = in_order(&old, &seven);
        assert_eq!(diff.matches("@@ -").count(), 2, "{diff}");
        assert!(
            diff.contains("@@ -1,7 +1,7 @@") && diff.contains("@@ -9,7 +9,7 @@"),
            "{diff}"
        );
    }

    #[test]
    fn a_line_moved_is_taken_out_and_put_in() {
        let old = "1\n2\n3\n4\n";
        let new = Given {
            lines: vec![
                ("4\n", Some(3)),
                ("1\n", Some(0)),
                ("2\n", Some(1)),
                ("3\n", Some(2)),
            ],
            old,
        };
        assert_eq!(
            diff(old, &new),
            "--- kb.dat\n+++ kb.dat\n@@ -1,4 +1,4 @@\n+4\n 1\n 2\n 3\n-4\n"
        );
    }

    #[test]
    fn a_blank_line_the_layout_adds_where_one_was_is_left_alone() {
        let old = "a\n\nb\nc\n";
        let new = Given {
            lines: vec![
                ("c\n", Some(3)),
                ("a\n", Some(0)),
                ("\n", None),
                ("b\n", Some(2)),
            ],
            old,
        };
        assert_eq!(
            diff(old, &new),
            "--- kb.dat\n+++ kb.dat\n@@ -1,4 +1,4 @@\n+c\n a\n \n b\n-c\n"
        );
    }

    #[test]
    fn lines_put_in_and_taken_out_by_edits_are_found_again() {
        let old: String = (0..30).map(|n| format!("{n}\n")).collect();
        let new = old
            .replace("\n5\n", "\n5\nnew\n")
            .replace("\n20\n21\n", "\n");
        let diff = in_order(&old, &new);
        assert_eq!(diff.matches("@@ -").count(), 2, "{diff}");
        assert_eq!(apply(&old, &diff), new);
    }

    /// A few short lines, often equal to each other.
    fn text() -> impl Strategy<Value = String> {
        proptest::collection::vec(prop_oneof![Just(String::new()), "[abc]{1,2}"], 0..40)
            .prop_flat_map(|lines| {
                (Just(lines), any::<bool>()).prop_map(|(lines, last_newline)| {
                    let mut text = lines.join("\n");
                    if last_newline && !text.is_empty() {
                        text.push('\n');
                    }
                    text
                })
            })
    }

    /// The lines of `new`, each with the old line `picks` picks as its origin, if any.
    fn picked_origins<'n>(
        old: &str,
        new: &'n str,
        picks: &[Option<u8>],
    ) -> Vec<(&'n str, Option<usize>)> {
        let old_count = lines_inclusive(old).count();
        lines_inclusive(new)
            .zip(picks)
            .map(|((_, line), pick)| {
                let origin = pick
                    .filter(|_| old_count > 0)
                    .map(|pick| pick as usize % old_count);
                (line, origin)
            })
            .collect()
    }

    proptest! {
        #[test]
        fn the_diff_of_any_two_texts_gives_the_new_one(old in text(), new in text()) {
            let diff = in_order(&old, &new);
            prop_assert_eq!(diff.is_empty(), old == new);
            prop_assert_eq!(apply(&old, &diff), new);
        }

        #[test]
        fn the_diff_printed_as_the_changes_are_found_is_the_same(
            old in text(),
            new in text(),
            every in 1..5u32,
        ) {
            let new = InOrder { old: &old, new: &new };
            prop_assert_eq!(diff_as_found(&old, &new, every), diff(&old, &new));
        }

        #[test]
        fn lines_recorded_in_two_parts_are_read_first_as_they_are_given(
            old in text(),
            new in text(),
            picks in proptest::collection::vec(any::<Option<u8>>(), 40),
            cut in 0..40usize,
        ) {
            let lines = picked_origins(&old, &new, &picks);
            let cut = cut.min(lines.len());
            let part = |lines: &[(&str, Option<usize>)]| {
                Recorded::new(&old, &Given { lines: lines.to_vec(), old: &old })
            };
            let mut recorded = part(&lines[..cut]);
            recorded.append(part(&lines[cut..]));
            let given = Given { lines, old: &old };
            prop_assert_eq!(recorded.first_reading(), align::first_reading(&old, &given));
        }

        #[test]
        fn blocks_moved_are_diffed_in_parts_as_in_one(
            order in Just((0..30).collect::<Vec<usize>>()).prop_shuffle(),
            edits in proptest::collection::vec(0..8u8, 1..20),
            lines_per_part in 1..40u32,
            lines_per_piece in 1..10u32,
        ) {
            let (old, lines) = moved_blocks(&order, &edits);
            let lines: Vec<(&str, Option<usize>)> =
                lines.iter().map(|(text, origin)| (text.as_str(), *origin)).collect();
            let given = Given { lines, old: &old };
            let sizes = in_parts::Sizes { lines_per_part, lines_per_piece };
            let in_parts = diff_in_parts(&old, &given, sizes);
            prop_assert!(in_parts.is_none_or(|in_parts| in_parts == diff(&old, &given)));
        }

        #[test]
        fn any_origins_give_a_diff_that_gives_the_new_text(
            old in text(),
            new in text(),
            picks in proptest::collection::vec(any::<Option<u8>>(), 40),
        ) {
            let lines = picked_origins(&old, &new, &picks);
            let given = Given { lines, old: &old };
            let diff = diff(&old, &given);
            let as_found = diff_moved_as_found(&old, &given, 1 + picks[0].unwrap_or(0) as u32 % 4);
            prop_assert!(as_found.is_none_or(|as_found| as_found == diff));
            let sizes = in_parts::Sizes {
                lines_per_part: 1 + picks[1].unwrap_or(0) as u32 % 8,
                lines_per_piece: 1 + picks[2].unwrap_or(0) as u32 % 4,
            };
            let in_parts = diff_in_parts(&old, &given, sizes);
            prop_assert!(in_parts.is_none_or(|in_parts| in_parts == diff));
            prop_assert_eq!(apply(&old, &diff), new);
        }
    }
}
