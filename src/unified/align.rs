//! Which new lines keep their place ([`first_reading`]), and the changes around them
//! ([`changes`]).

use std::ops::{ControlFlow, Range};

use super::follow::Finder;
use super::{old_line, NewLine, NewLines};

/// New lines whose origins follow one another in the old text (blank old lines between
/// them, which the layout drops, and new lines without an origin do not end a run).
#[derive(Debug, Clone, Copy)]
struct Run {
    /// The first and last origins.
    first: u32,
    last: u32,
    /// Where the old line after the last origin starts.
    next: u32,
    /// The new lines it spans: its first line with an origin to its last.
    lines: (u32, u32),
    /// How many of its lines are equal to their origin.
    equal: u32,
}

/// The new lines (by index, ascending ranges) that keep their place.
#[derive(Debug, PartialEq, Eq)]
pub(super) struct Kept(Vec<Range<u32>>);

impl Kept {
    /// The ranges, ascending.
    pub(super) fn ranges(&self) -> &[Range<u32>] {
        &self.0
    }

    /// The ranges from the one that holds new line `index`, or the next.
    fn from(&self, index: u32) -> &[Range<u32>] {
        &self.0[self.0.partition_point(|range| range.end <= index)..]
    }
}

/// What the first reading of the new lines finds.
#[derive(Debug, PartialEq, Eq)]
pub(super) enum FirstReading {
    /// The origins ascend, so every line with one keeps its place: the changes, found on
    /// the way (no second reading).
    InOrder(Changes),
    /// Lines moved: which keep their place.
    Moved(Kept),
}

/// The runs of new lines, then the chain of runs whose origins ascend from one to the next
/// that keeps the most equal lines (a longest increasing subsequence, of runs weighted by
/// their equal lines). When the runs all ascend (a text that only changed in place, or
/// moved nothing), the chain is every run, and the changes are found in the same reading.
pub(super) fn first_reading(old: &str, new: &impl NewLines) -> FirstReading {
    let mut runs = Runs::default();
    let mut pairing = Pairing::new(old, Start::TEXT);
    let mut index = 0u32;
    let _ = new.each_line(&mut |line| {
        if let Some(origin) = line.origin {
            let old_text = old_line(old, origin as usize);
            runs.line(
                old,
                index,
                origin,
                old_text.len() as u32,
                old_text == line.text,
            );
        }
        if runs.in_order {
            pairing.line(line, true);
        }
        index += 1;
        ControlFlow::Continue(())
    });
    match runs.in_order {
        true => FirstReading::InOrder(pairing.finish()),
        false => FirstReading::Moved(runs.kept()),
    }
}

/// The runs of new lines read so far, and whether they ascend.
#[derive(Debug, Clone)]
pub(super) struct Runs {
    runs: Vec<Run>,
    in_order: bool,
}

impl Default for Runs {
    fn default() -> Runs {
        Runs {
            runs: Vec::new(),
            in_order: true,
        }
    }
}

impl Runs {
    /// New line `index`, made from the old line that starts at `origin` and is
    /// `old_length` bytes long (`equal` to it or not).
    pub(super) fn line(
        &mut self,
        old: &str,
        index: u32,
        origin: u32,
        old_length: u32,
        equal: bool,
    ) {
        let (next, equal) = (origin + old_length, u32::from(equal));
        match self.runs.last_mut() {
            Some(run) if follows(old, run.next, origin) => {
                run.last = origin;
                run.next = next;
                run.lines.1 = index + 1;
                run.equal += equal;
            }
            previous => {
                self.in_order &= previous.is_none_or(|run| run.last < origin);
                self.runs.push(Run {
                    first: origin,
                    last: origin,
                    next,
                    lines: (index, index + 1),
                    equal,
                });
            }
        }
    }

    /// Adds the runs of the new lines after these, read apart (their indices counted from
    /// 0 there, from `offset` here): the first goes on with the last one here if it follows
    /// it, as it would have if they had been read here.
    pub(super) fn append(&mut self, old: &str, mut after: Runs, offset: u32) {
        for run in &mut after.runs {
            run.lines = (run.lines.0 + offset, run.lines.1 + offset);
        }
        let mut rest = after.runs.into_iter().peekable();
        if let (Some(last), Some(first)) = (self.runs.last_mut(), rest.peek()) {
            match follows(old, last.next, first.first) {
                true => {
                    (last.last, last.next, last.lines.1) = (first.last, first.next, first.lines.1);
                    last.equal += first.equal;
                    rest.next();
                }
                false => self.in_order &= last.last < first.first,
            }
        }
        self.in_order &= after.in_order;
        self.runs.extend(rest);
    }

    /// What the first reading of `new`, whose runs these are, finds: when the runs
    /// ascend, the changes are found in a second reading (the runs were read apart).
    pub(super) fn reading(&self, old: &str, new: &impl NewLines) -> FirstReading {
        match self.in_order {
            true => FirstReading::InOrder(pair(old, new, None, Start::TEXT, |_| {}).finish()),
            false => FirstReading::Moved(self.kept()),
        }
    }

    /// The new lines of the heaviest chain of runs.
    fn kept(&self) -> Kept {
        let chain = heaviest_chain(&self.runs);
        Kept(
            chain
                .into_iter()
                .map(|run| self.runs[run].lines.0..self.runs[run].lines.1)
                .collect(),
        )
    }
}

/// The changes, found in one reading as [`first_reading`] finds them when nothing moved,
/// else as [`changes`] finds them from the lines `kept`, and handed to `finder` every
/// `hand_over_every` lines.
pub(super) fn find(
    old: &str,
    new: &impl NewLines,
    kept: Option<&Kept>,
    mut finder: Finder<'_>,
    hand_over_every: u32,
) {
    let changes = pair(old, new, kept, Start::TEXT, |pairing| {
        if pairing.index % hand_over_every == 0 {
            // Every change not found yet starts at the one open, or at the lines to come.
            let settled = match pairing.open {
                Some((old_start, new_start)) => (new_start, old_start),
                None => (pairing.index, pairing.line),
            };
            finder.hand_over(&mut pairing.changes.regions, settled);
        }
    });
    finder.finish(changes.finish());
}

/// Whether the old line at `origin` follows the one that ends at `next`: nothing but blank
/// lines between them. (Runs of lines that follow one another, rather than merely ascend,
/// make a line moved far ahead a run of its own, which the chain can leave out.)
fn follows(old: &str, next: u32, origin: u32) -> bool {
    origin >= next
        && old.as_bytes()[next as usize..origin as usize]
            .iter()
            .all(|byte| matches!(byte, b'\n' | b'\r' | b' ' | b'\t'))
}

/// The indices of the runs, ascending, of the chain whose origins ascend from run to run
/// with the most equal lines: of the chains as heavy, the one that ends at the lowest
/// origin, and of those the one whose last run comes first; each run's chain goes on from
/// the chain chosen so among those that end before it starts.
///
/// A longest increasing subsequence, weighted, in O(n log n): the runs' last origins are
/// numbered in order, and a [`BestBefore`] tree keeps the best chain ending at or below each.
fn heaviest_chain(runs: &[Run]) -> Vec<usize> {
    const NONE: u32 = u32::MAX;
    if runs.len() <= 1 {
        return (0..runs.len()).collect();
    }
    let mut lasts: Vec<u32> = runs.iter().map(|run| run.last).collect();
    // A merge sort, fast on the few long ascending stretches that lines moved in order
    // make (blocks in a tree's order ascend level by level).
    lasts.sort();
    lasts.dedup();
    let mut best = BestBefore::new(lasts.len());
    let mut previous = vec![NONE; runs.len()];
    for (index, run) in runs.iter().enumerate() {
        let first = lasts.partition_point(|&last| last < run.first);
        let before = best.before(first);
        previous[index] = before.run().unwrap_or(NONE);
        let chain = Chain::new(
            u64::from(run.equal) + before.weight(),
            run.last,
            index as u32,
        );
        // The run's own last origin is next, unless another run's ends within it.
        let place = match lasts[first] == run.last {
            true => first,
            false => first + lasts[first..].partition_point(|&last| last < run.last),
        };
        best.offer(place, chain);
    }
    let mut chain = Vec::new();
    let mut at = best.before(lasts.len()).run().unwrap_or(NONE);
    while at != NONE {
        chain.push(at as usize);
        at = previous[at as usize];
    }
    chain.reverse();
    chain
}

/// A chain of runs as [`heaviest_chain`] weighs them, in one number that orders them so:
/// the heavier is better, then the one that ends at the lower origin, then the one whose
/// last run comes first. 0 is no chain.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
struct Chain(u128);

impl Chain {
    const NONE: Chain = Chain(0);

    /// The chain of `weight` whose last run, `run`, ends at origin `last`.
    fn new(weight: u64, last: u32, run: u32) -> Chain {
        Chain(u128::from(weight) << 64 | u128::from(!last) << 32 | u128::from(!run))
    }

    fn weight(self) -> u64 {
        (self.0 >> 64) as u64
    }

    /// The chain's last run, if it is a chain.
    fn run(self) -> Option<u32> {
        (self != Chain::NONE).then_some(!(self.0 as u32))
    }
}

/// The best chain ending at each of `n` places (the last origins, numbered in order), asked
/// of the places below one: a Fenwick tree of maxima.
struct BestBefore(Vec<Chain>);

impl BestBefore {
    fn new(places: usize) -> BestBefore {
        BestBefore(vec![Chain::NONE; places])
    }

    /// The best chain ending at a place below `end` ([`Chain::NONE`] if none).
    fn before(&self, mut end: usize) -> Chain {
        let mut best = Chain::NONE;
        while end > 0 {
            best = best.max(self.0[end - 1]);
            end &= end - 1;
        }
        best
    }

    /// A chain ending at `place`.
    fn offer(&mut self, mut place: usize, chain: Chain) {
        while place < self.0.len() {
            let best = &mut self.0[place];
            *best = (*best).max(chain);
            place |= place + 1;
        }
    }
}

/// A change: old lines (0-based, end excluded) replaced by new lines.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(super) struct Region {
    pub old: Range<u32>,
    pub new: Range<u32>,
}

/// Every change, in order, and how many lines the old text has. Between two changes, and
/// before the first and after the last, the lines are equal.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub(super) struct Changes {
    pub regions: Vec<Region>,
    pub old_lines: u32,
}

/// The changes when lines moved: a second reading, which pairs the lines that `kept` says
/// keep their place.
pub(super) fn changes(old: &str, new: &impl NewLines, kept: &Kept) -> Changes {
    pair(old, new, Some(kept), Start::TEXT, |_| {}).finish()
}

/// Where a reading of some of the new lines starts: at new line `index`, whose origin
/// starts at byte `at` of the old text, the lines before it paired up to there with nothing
/// left open (the line before it kept its place, equal to the old line before `at`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) struct Start {
    pub index: u32,
    pub at: usize,
}

impl Start {
    /// The start of the texts.
    pub(super) const TEXT: Start = Start { index: 0, at: 0 };
}

/// The changes of the new lines `new`, some of the lines that `kept` is of, read from
/// `start` and made from the old lines from there up to the end of `old` (a text cut at a
/// line start where the next part starts, or the whole), their old lines counted from
/// `start` (new lines by index, as in the whole). `None` if the lines did not end paired up
/// to the end of `old` with nothing open, as a reading of all of them would have come to
/// the next part's start: then the parts cannot be read apart. (When `old` is whole, the
/// old lines left are taken out, as they are at the end.)
pub(super) fn changes_of_part(
    old: &str,
    new: &impl NewLines,
    kept: &Kept,
    start: Start,
    whole: bool,
) -> Option<Changes> {
    let pairing = pair(old, new, Some(kept), start, |_| {});
    let paired_to_the_end = pairing.at == old.len() && pairing.open.is_none();
    (whole || paired_to_the_end).then(|| pairing.finish())
}

/// Pairs every new line ([`Pairing`]) from `start`, each kept if `kept` says so (every one
/// if there is no `kept`: nothing moved), `after_line` called after each; the pairing is
/// left to be finished.
fn pair<'o>(
    old: &'o str,
    new: &impl NewLines,
    kept: Option<&Kept>,
    start: Start,
    mut after_line: impl FnMut(&mut Pairing<'_>),
) -> Pairing<'o> {
    let mut pairing = Pairing::new(old, start);
    let mut kept_ranges = kept.map(|kept| kept.from(start.index).iter().peekable());
    let _ = new.each_line(&mut |line| {
        let index = pairing.index;
        let is_kept = kept_ranges.as_mut().is_none_or(|ranges| {
            while ranges.next_if(|range| range.end <= index).is_some() {}
            ranges.peek().is_some_and(|range| range.contains(&index))
        });
        pairing.line(line, is_kept);
        after_line(&mut pairing);
        ControlFlow::Continue(())
    });
    pairing
}

/// Pairs the new lines with old ones, in order: a kept line with its origin (equal, or
/// changed in place), any other new line with the next old line if it is equal to it, else
/// it is put in; the old lines passed over are taken out.
struct Pairing<'o> {
    old: &'o str,
    changes: Changes,
    /// The next old line, by start and number.
    at: usize,
    line: u32,
    /// The next new line.
    index: u32,
    /// Where the change being found started (old line, new line).
    open: Option<(u32, u32)>,
    /// Whether the new line before was a blank line put in.
    blank_put_in: bool,
    /// The old line at `at`, once found: lines put in are compared with it, each in turn
    /// (half a file's lines, when its blocks are put in a balanced order).
    next_line: Option<(usize, &'o str)>,
}

impl<'o> Pairing<'o> {
    /// Pairs from `start`, counting the old lines from there.
    fn new(old: &'o str, start: Start) -> Pairing<'o> {
        Pairing {
            old,
            changes: Changes::default(),
            at: start.at,
            line: 0,
            index: start.index,
            open: None,
            blank_put_in: false,
            next_line: None,
        }
    }

    /// The old line at `at`, found once however many new lines are compared with it.
    fn next_line(&mut self) -> &'o str {
        match self.next_line {
            Some((at, line)) if at == self.at => line,
            _ => {
                let line = old_line(self.old, self.at);
                self.next_line = Some((self.at, line));
                line
            }
        }
    }

    /// Pairs the next new line, which keeps its place if `is_kept` and it has an origin.
    fn line(&mut self, new_line: NewLine<'_>, is_kept: bool) {
        let old = self.old;
        let origin = new_line.origin.map(|origin| origin as usize);
        let pair = match origin {
            Some(origin) if is_kept && origin >= self.at => {
                if origin > self.at {
                    let (old_start, new_start) = *self.open.get_or_insert((self.line, self.index));
                    let passed = &old.as_bytes()[self.at..origin];
                    self.line += memchr::memchr_iter(b'\n', passed).count() as u32;
                    self.at = origin;
                    // A blank line put in just before, where a blank line is taken out: the
                    // same line, left in place (the layout's blank line between blocks).
                    if self.blank_put_in && ends_with_blank_line(&old[..origin]) {
                        self.open = None;
                        self.close(old_start..self.line - 1, new_start..self.index - 1);
                    }
                }
                true
            }
            _ => self.at < old.len() && self.next_line() == new_line.text,
        };
        self.blank_put_in = !pair && new_line.text == "\n";
        if pair {
            let (old_text, equal) = match recorded_as(old, self.at, new_line.text) {
                Some(old_text) => (old_text, true),
                None => {
                    let old_text = self.next_line();
                    (old_text, old_text == new_line.text)
                }
            };
            if equal {
                if let Some((old_start, new_start)) = self.open.take() {
                    self.close(old_start..self.line, new_start..self.index);
                }
            } else {
                self.open.get_or_insert((self.line, self.index));
            }
            self.at += old_text.len();
            self.line += 1;
        } else {
            self.open.get_or_insert((self.line, self.index));
        }
        self.index += 1;
    }

    /// A change found, unless it is empty.
    fn close(&mut self, old: Range<u32>, new: Range<u32>) {
        if !old.is_empty() || !new.is_empty() {
            self.changes.regions.push(Region { old, new });
        }
    }

    /// The changes, the old lines after the last new one taken out.
    fn finish(mut self) -> Changes {
        if self.at < self.old.len() {
            self.open.get_or_insert((self.line, self.index));
            self.line += super::lines_inclusive(&self.old[self.at..]).count() as u32;
        }
        if let Some((old_start, new_start)) = self.open.take() {
            self.close(old_start..self.line, new_start..self.index);
        }
        self.changes.old_lines = self.line;
        self.changes
    }
}

/// The old line that starts at `at`, if the new line `text` is that very line of `old` (a
/// line recorded as its origin's: nearly every line of a large diff): then its end is not
/// searched for, nor its bytes compared.
fn recorded_as<'o>(old: &'o str, at: usize, text: &str) -> Option<&'o str> {
    let end = at + text.len();
    let whole_line = text.ends_with('\n') || end == old.len();
    (std::ptr::eq(text.as_ptr(), old[at..].as_ptr()) && end <= old.len() && whole_line)
        .then(|| &old[at..end])
}

/// Whether `text` ends with a line that is only a line ending (`\n`), after another line or
/// at the start.
fn ends_with_blank_line(text: &str) -> bool {
    matches!(text.as_bytes(), [b'\n'] | [.., b'\n', b'\n'])
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// [`heaviest_chain`] as its doc says, run by run against every run before: O(n²).
    fn chain_by_definition(runs: &[Run]) -> Vec<usize> {
        use std::cmp::Reverse;
        /// A chain's weight, last origin and last run, ordered as its doc says.
        type Weighed = (u64, Reverse<u32>, Reverse<usize>);
        // Each run's chain, and the run before it in the chain.
        let mut chains: Vec<(Weighed, Option<usize>)> = Vec::new();
        for (index, run) in runs.iter().enumerate() {
            let before = (0..index)
                .filter(|&other| runs[other].last < run.first)
                .max_by_key(|&other| chains[other].0);
            let weight = u64::from(run.equal) + before.map_or(0, |other| chains[other].0 .0);
            chains.push(((weight, Reverse(run.last), Reverse(index)), before));
        }
        let mut at = (0..runs.len()).max_by_key(|&index| chains[index].0);
        let mut chain = Vec::new();
        while let Some(index) = at {
            chain.push(index);
            at = chains[index].1;
        }
        chain.reverse();
        chain
    }

    proptest! {
        #[test]
        fn the_heaviest_chain_is_the_one_its_doc_says(
            runs in proptest::collection::vec((0u32..40, 0u32..6, 0u32..4), 0..60),
        ) {
            let runs: Vec<Run> = runs
                .into_iter()
                .map(|(first, length, equal)| Run {
                    first,
                    last: first + length,
                    next: first + length + 1,
                    lines: (0, 0),
                    equal,
                })
                .collect();
            prop_assert_eq!(heaviest_chain(&runs), chain_by_definition(&runs));
        }
    }
}
