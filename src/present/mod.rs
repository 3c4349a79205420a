//! Presenting a knowledge base to people: the pieces `locations`, `show`, `tour` and `diff`
//! share, so that a pose, a gesture or a message reads the same in every command.
//!
//! Every helper here that formats text from the file for people has passed it through
//! [`escape`], so callers may print what it returns. Raw values ([`Message::value`],
//! [`field::FieldValue`]) are for JSON, which [`safe_json::write`](crate::render::safe_json::write) makes just as safe.

pub mod field;
pub mod language;
pub mod robot;
pub mod table;
pub mod timeline;
pub mod wrap;

use std::borrow::Cow;
use std::collections::{HashMap, HashSet};
use std::fmt::Write as _;

use crate::check::Checked;
use crate::model::{
    is_placeholder, Arm, KnowledgeBase, Language, Location, Phase, Point, Pose, Value,
};
use crate::render::clip;
use crate::render::escape::escape;
use crate::source::LineIndex;
use crate::syntax::Span;

/// A number as engineers write it: `2.6`, `-90.0`, `0.82` (the shortest exact form, with a
/// decimal point so that it reads as a coordinate).
pub fn number(n: f64) -> String {
    let mut out = String::with_capacity(24);
    push_number(&mut out, n);
    out
}

/// Appends `n` as `{n:?}` writes it (the shortest decimal that reads back as `n`, with a
/// decimal point). zmij finds the digits several times faster than `core::fmt` (whose float
/// printing was a tenth of `ekb locations`), and writes them as `{:?}` does wherever `{:?}`
/// writes no exponent (from 1e-4 up to 1e16). The two choose differently only between two
/// shortest decimals equally near `n`, which must then lie within half a unit in the last
/// place of `n`, 2^-53 of it: 16 significant digits or more; with fewer, zmij's are the ones.
fn push_number(out: &mut String, n: f64) {
    if n.is_normal() && (1e-4..1e16).contains(&n.abs()) {
        let mut buffer = zmij::Buffer::new();
        let written = buffer.format_finite(n);
        if written.bytes().filter(u8::is_ascii_digit).count() <= 15 {
            out.push_str(written);
            return;
        }
    }
    write!(out, "{n:?}").expect("a String takes any text");
}

/// `2.6, 8.1, -90.0°` (each number as [`number`] writes it).
pub fn pose(pose: &Pose) -> String {
    numbers([pose.x, pose.y, pose.theta], "°")
}

/// `3.2, 8.4, 0.82` (each number as [`number`] writes it).
pub fn point(point: &Point) -> String {
    numbers([point.x, point.y, point.z], "")
}

/// Three numbers as [`number`] writes them, then `unit`; into a string made large enough at
/// once (`format!` grows it piece by piece).
fn numbers([a, b, c]: [f64; 3], unit: &str) -> String {
    let mut out = String::with_capacity(64);
    for (i, n) in [a, b, c].into_iter().enumerate() {
        if i > 0 {
            out.push_str(", ");
        }
        push_number(&mut out, n);
    }
    out.push_str(unit);
    out
}

/// Whether, and at what, the robot gestures at a location.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Gesture {
    /// `0 0 0`: no gesture, by design.
    None,
    /// A target the robot's reader skips because its coordinates sum to 0 (SPEC §2.9).
    Skipped(Point),
    /// The robot points at this target.
    At(Point),
}

impl Gesture {
    pub fn of(target: &Point) -> Gesture {
        if target.is_no_gesture() {
            Gesture::None
        } else if target.robot_sees_no_gesture() {
            Gesture::Skipped(*target)
        } else {
            Gesture::At(*target)
        }
    }

    /// `no gesture`, `3.2, 8.4, 0.82` or `1, -1, 0 (sums to 0: the robot does not point)`.
    pub fn short(&self) -> String {
        match self {
            Gesture::None => "no gesture".to_string(),
            Gesture::Skipped(target) => {
                format!("{} (sums to 0: the robot does not point)", point(target))
            }
            Gesture::At(target) => point(target),
        }
    }

    /// A sentence for the tour: what the robot does with its arm.
    pub fn sentence(&self, arm: Option<Arm>) -> String {
        match self {
            Gesture::None => "does not point (gesture target 0 0 0)".to_string(),
            Gesture::Skipped(target) => format!(
                "does not point: the target {} sums to 0, which the robot's reader takes for \"no gesture\"",
                point(target)
            ),
            Gesture::At(target) => match arm {
                Some(arm) => format!("points at {} with the {} arm", point(target), arm.name()),
                None => format!("points at {}", point(target)),
            },
        }
    }
}

/// What a location has for one message in one language.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Message<'a> {
    /// A real message.
    Written(Value<&'a str>),
    /// A placeholder such as `No message in isiZulu`: the robot would say it as it is.
    Placeholder(Value<&'a str>),
    /// No message: the robot says nothing.
    Missing,
}

impl<'a> Message<'a> {
    pub fn of(location: &Location<'a>, phase: Phase, language: Language) -> Message<'a> {
        match location.message(phase, language) {
            Some(value) if is_placeholder(value.value) => Message::Placeholder(value),
            Some(value) => Message::Written(value),
            None => Message::Missing,
        }
    }

    /// The mark of the locations table; see [`MESSAGE_LEGEND`].
    pub fn mark(&self) -> &'static str {
        match self {
            Message::Written(_) => "✓",
            Message::Placeholder(_) => "~",
            Message::Missing => "✗",
        }
    }

    /// `written`, `placeholder` or `missing`, as JSON outputs say it.
    pub fn status(&self) -> &'static str {
        match self {
            Message::Written(_) => "written",
            Message::Placeholder(_) => "placeholder",
            Message::Missing => "missing",
        }
    }

    /// The text in the file, if any (placeholders included).
    pub fn value(&self) -> Option<Value<&'a str>> {
        match self {
            Message::Written(value) | Message::Placeholder(value) => Some(*value),
            Message::Missing => None,
        }
    }
}

/// What the marks of [`Message::mark`] mean.
pub const MESSAGE_LEGEND: &str =
    "messages: ✓ written  ~ placeholder, untranslated  ✗ missing (the robot says nothing)";

/// A text value from the file, escaped and in double quotes, cut after a few hundred
/// characters ([`clip`]).
pub fn quoted(text: &str) -> String {
    clip::quoted(text)
}

/// A text value from the file, escaped, cut after a few hundred characters ([`clip`]).
pub fn text(text: &str) -> Cow<'_, str> {
    clip::shown(text)
}

/// The most items (tour stops, positions on the tour) that one line lists.
pub const MAX_LISTED: usize = 100;

/// `items` joined by `separator`, at most [`MAX_LISTED`] of them, then `… and N more` (a
/// million-stop tour is one line of a file, and must not be a megabyte line of output).
pub fn listed<T: std::fmt::Display>(mut items: impl Iterator<Item = T>, separator: &str) -> String {
    let first: Vec<T> = items.by_ref().take(MAX_LISTED).collect();
    let total = first.len() + items.count();
    listed_of(first.into_iter(), total, separator)
}

/// [`listed`] of a list of `total` items, of which `items` are the first (or all).
pub fn listed_of<T: std::fmt::Display>(
    items: impl Iterator<Item = T>,
    total: usize,
    separator: &str,
) -> String {
    let mut out = String::new();
    let mut shown = 0;
    for item in items.take(MAX_LISTED) {
        if shown > 0 {
            out.push_str(separator);
        }
        write!(out, "{item}").expect("a String takes any text");
        shown += 1;
    }
    let more = total.saturating_sub(shown);
    if more > 0 {
        write!(out, " … and {more} more").expect("a String takes any text");
    }
    out
}

/// The 1-based line numbers of spans in one file.
#[derive(Debug)]
pub struct Lines {
    index: LineIndex,
}

impl Lines {
    pub fn new(text: &str) -> Lines {
        Lines {
            index: LineIndex::new(text),
        }
    }

    /// The line a span starts on (its column is not counted: a view asks this of every
    /// value of every location).
    pub fn of(&self, span: Span) -> u32 {
        self.index.line(span.start)
    }

    /// The first and last lines that hold a value of `location`: those of its first and
    /// last values in the text (two lines looked up, not one a value).
    pub fn range(&self, location: &Location<'_>) -> (u32, u32) {
        let (first, last) = field::Field::ALL
            .iter()
            .filter_map(|field| field.get(location))
            .map(|(_, span)| span.start)
            .chain([location.first_line.start])
            .fold((u32::MAX, 0), |(low, high), start| {
                (low.min(start), high.max(start))
            });
        (self.index.line(first), self.index.line(last))
    }
}

/// `lines 28–36`, or `line 46` when it is one.
pub fn line_range((first, last): (u32, u32)) -> String {
    if first == last {
        format!("line {first}")
    } else {
        format!("lines {first}–{last}")
    }
}

/// Where each location is on the tour: 1-based positions (a location may be visited more
/// than once), computed once so that a long tour and many locations stay linear.
#[derive(Debug, Default)]
pub struct TourPositions(HashMap<u32, Positions>);

/// The positions of one location that are kept, and how many it has.
#[derive(Debug, Default)]
struct Positions {
    first: Vec<usize>,
    count: usize,
}

impl TourPositions {
    /// Every position of every location.
    pub fn new(kb: &KnowledgeBase<'_>) -> TourPositions {
        TourPositions::first(kb, usize::MAX)
    }

    /// The first `most` positions of each location, and how many it has: a view that lists
    /// [`MAX_LISTED`] need not hold every stop of a million-stop tour (8 MB).
    pub fn first(kb: &KnowledgeBase<'_>, most: usize) -> TourPositions {
        let mut positions: HashMap<u32, Positions> = HashMap::new();
        for (index, id) in kb.tour_stops().enumerate() {
            let location = positions.entry(id).or_default();
            if location.first.len() < most {
                location.first.push(index + 1);
            }
            location.count += 1;
        }
        TourPositions(positions)
    }

    /// The positions of location `id` (those kept), empty when the tour does not visit it.
    pub fn of(&self, id: u32) -> &[usize] {
        self.0.get(&id).map_or(&[], |positions| &positions.first)
    }

    /// How many times the tour visits location `id`.
    pub fn count(&self, id: u32) -> usize {
        self.0.get(&id).map_or(0, |positions| positions.count)
    }
}

/// Every position of every location on the tour, for a view that lists them all (the JSON
/// of `ekb locations`). Held, they cost 8 bytes a stop (a million-stop tour of 2 MB held
/// 8 MB): so they are read again from the tour's line for each location it visits, unless
/// that would read more than [`MOST_STOPS_READ_AGAIN`] stops in all (many locations on a
/// long tour), and then held.
pub enum AllTourPositions<'k> {
    Held(TourPositions),
    ReadAgain {
        kb: &'k KnowledgeBase<'k>,
        visited: HashSet<u32>,
    },
}

/// The most stops [`AllTourPositions`] reads to list them (a few tenths of a second).
const MOST_STOPS_READ_AGAIN: usize = 1 << 24;

impl<'k> AllTourPositions<'k> {
    pub fn new(kb: &'k KnowledgeBase<'k>) -> AllTourPositions<'k> {
        let mut visited = HashSet::new();
        let mut stops = 0;
        for id in kb.tour_stops() {
            visited.insert(id);
            stops += 1;
        }
        if visited.len().saturating_mul(stops) <= MOST_STOPS_READ_AGAIN {
            AllTourPositions::ReadAgain { kb, visited }
        } else {
            AllTourPositions::Held(TourPositions::new(kb))
        }
    }

    /// The 1-based positions of location `id`, written as a list.
    pub fn of(&self, id: u32) -> PositionsOf<'_, 'k> {
        PositionsOf { all: self, id }
    }
}

/// The positions of one location on the tour, serialized as a list.
pub struct PositionsOf<'a, 'k> {
    all: &'a AllTourPositions<'k>,
    id: u32,
}

impl serde::Serialize for PositionsOf<'_, '_> {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        match self.all {
            AllTourPositions::Held(held) => s.collect_seq(held.of(self.id)),
            AllTourPositions::ReadAgain { kb, visited } => {
                let visits = visited.contains(&self.id);
                let stops = kb.tour_stops().take_while(|_| visits);
                s.collect_seq(
                    (1..)
                        .zip(stops)
                        .filter(|&(_, stop)| stop == self.id)
                        .map(|(position, _)| position),
                )
            }
        }
    }
}

/// Tells the user, on standard error, that the file has errors, so that a view that looks
/// incomplete (a missing message, a pose at 0) is not taken for the whole story.
pub fn note_errors(checked: &Checked<'_>, quiet: bool) {
    let errors = checked.summary().errors;
    if errors > 0 && !quiet {
        let plural = if errors == 1 { "" } else { "s" };
        crate::stderr_line!(
            "ekb: note: {} has {errors} error{plural}; `ekb check` lists them",
            escape(checked.source.name())
        );
    }
}

#[cfg(test)]
pub(crate) use ekb_core::testing::random_bits;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_read_as_written() {
        assert_eq!(number(2.6), "2.6");
        assert_eq!(number(-90.0), "-90.0");
        assert_eq!(number(0.82), "0.82");
        assert_eq!(
            pose(&Pose {
                x: 2.6,
                y: 8.1,
                theta: -90.0
            }),
            "2.6, 8.1, -90.0°"
        );
    }

    #[test]
    fn numbers_read_as_debug_writes_them() {
        let mut samples = vec![
            // -1010.43829345703125: halfway between -1010.4382934570312 and …313.
            f64::from_bits(0xc08f_9381_a000_0000),
            0.0,
            -0.0,
            1e-4,
            -1e-4,
            9.999e-5,
            1e16,
            9_999_999_999_999_998.0,
            1e15,
            0.1,
            123456.0,
            f64::MIN_POSITIVE,
            f64::MAX,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NAN,
            5e-324,
        ];
        // Every exponent and sign, and decimals as a file writes them.
        for bits in random_bits(200_000) {
            samples.push(f64::from_bits(bits));
            samples.push((bits % 2_000_000) as f64 / 100.0 - 10_000.0);
            samples.push(f64::from(f32::from_bits(bits as u32)));
        }
        for n in samples {
            assert_eq!(number(n), format!("{n:?}"), "{:#x}", n.to_bits());
        }
    }

    #[test]
    fn long_lists_are_cut() {
        assert_eq!(listed([1, 2, 3].iter(), " → "), "1 → 2 → 3");
        let many = listed(0..MAX_LISTED + 7, ", ");
        assert!(many.starts_with("0, 1, 2"));
        assert!(many.ends_with(&format!(
            "{}, {} … and 7 more",
            MAX_LISTED - 2,
            MAX_LISTED - 1
        )));
        assert_eq!(listed_of(0..MAX_LISTED, MAX_LISTED + 7, ", "), many);
        assert_eq!(listed_of([1, 2].iter(), 5, ", "), "1, 2 … and 3 more");
    }

    #[test]
    fn tour_positions_keep_the_first_and_count_them_all() {
        let text = "robotLocationDescription 1 Hall\ntourSpecification 5 1 2 1 1 1\n";
        let source = crate::SourceFile::from_bytes("kb.dat", text.as_bytes().to_vec());
        let checked = crate::check(&source, &Default::default());
        let all = TourPositions::new(&checked.kb);
        assert_eq!((all.of(1), all.count(1)), (&[1, 3, 4, 5][..], 4));
        let first = TourPositions::first(&checked.kb, 2);
        assert_eq!((first.of(1), first.count(1)), (&[1, 3][..], 4));
        assert_eq!((first.of(2), first.count(2)), (&[2][..], 1));
        assert_eq!((first.of(7), first.count(7)), (&[][..], 0));
    }

    #[test]
    fn all_tour_positions_read_again_or_held_list_the_same() {
        let text = "robotLocationDescription 1 Hall\ntourSpecification 5 1 2 1 1 1\n";
        let source = crate::SourceFile::from_bytes("kb.dat", text.as_bytes().to_vec());
        let checked = crate::check(&source, &Default::default());
        let read_again = AllTourPositions::new(&checked.kb);
        assert!(matches!(read_again, AllTourPositions::ReadAgain { .. }));
        let held = AllTourPositions::Held(TourPositions::new(&checked.kb));
        for all in [read_again, held] {
            let listed = |id| serde_json::to_string(&all.of(id)).unwrap();
            assert_eq!(
                [listed(1), listed(2), listed(7)],
                ["[1,3,4,5]", "[2]", "[]"].map(String::from)
            );
        }
    }

    #[test]
    fn many_locations_on_a_long_tour_have_their_positions_held() {
        let stops = MOST_STOPS_READ_AGAIN.isqrt() + 1;
        let tour: String = (1..=stops).map(|id| format!(" {id}")).collect();
        let text = format!("tourSpecification {stops}{tour}\n");
        let source = crate::SourceFile::from_bytes("kb.dat", text.into_bytes());
        let checked = crate::check(&source, &Default::default());
        let all = AllTourPositions::new(&checked.kb);
        assert!(matches!(all, AllTourPositions::Held(_)));
        assert_eq!(serde_json::to_string(&all.of(3)).unwrap(), "[3]");
    }

    #[test]
    fn gestures() {
        let at = |x, y, z| Gesture::of(&Point { x, y, z });
        assert_eq!(at(0.0, 0.0, 0.0).short(), "no gesture");
        assert_eq!(at(3.2, 8.4, 0.82).short(), "3.2, 8.4, 0.82");
        assert!(matches!(at(1.0, -1.0, 0.0), Gesture::Skipped(_)));
        assert_eq!(
            at(3.2, 8.4, 0.82).sentence(Some(Arm::Left)),
            "points at 3.2, 8.4, 0.82 with the left arm"
        );
    }
}
