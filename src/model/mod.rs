//! The typed view of a knowledge base: locations and the tour, each value with its span.
//!
//! The model holds what the robot's reader would load from the file, read faithfully:
//! a key in the wrong case is not a key (the robot ignores it, and so a message goes
//! missing), later lines for the same id and key win, the last tour wins. It borrows its
//! text from the [`SourceFile`](crate::SourceFile), so building it copies no strings.

pub mod build;
pub mod export;
mod ids;
mod keys;
mod text;

pub use ids::{IdMap, IdSet};
pub use keys::{Dialect, Key, Language, Phase, ValueKind};
pub use text::{is_placeholder, words};

use serde::{Deserialize, Serialize};

use crate::source::LineStart;
use crate::syntax::Span;

/// A value read from the file, with the span of its text.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Value<T> {
    pub value: T,
    pub span: Span,
}

/// Where the robot stands: metres, metres, degrees. (An unknown field in the JSON of
/// `ekb import` is refused, as everywhere in an export: it is a typo or another tool's.)
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Pose {
    pub x: f64,
    pub y: f64,
    pub theta: f64,
}

/// A point the robot gestures at, in metres. `0 0 0` means no gesture.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(deny_unknown_fields)]
pub struct Point {
    pub x: f64,
    pub y: f64,
    pub z: f64,
}

impl Point {
    /// `0 0 0`: the location has no gesture.
    pub fn is_no_gesture(&self) -> bool {
        self.x == 0.0 && self.y == 0.0 && self.z == 0.0
    }

    /// The robot's own test for "no gesture", in its own arithmetic: it stores coordinates
    /// as C `float`s and compares `x + y + z == 0`, so `1.0 -1.0 0.0` counts as no gesture,
    /// and so does `1 1e-8 -1`.
    pub fn robot_sees_no_gesture(&self) -> bool {
        let (x, y, z) = (self.x as f32, self.y as f32, self.z as f32);
        x + y + z == 0.0
    }
}

/// The arm the robot gestures with.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(rename_all = "lowercase")]
pub enum Arm {
    Left,
    Right,
}

impl Arm {
    pub fn name(self) -> &'static str {
        match self {
            Arm::Left => "left",
            Arm::Right => "right",
        }
    }

    pub fn parse(text: &str) -> Option<Arm> {
        match text {
            "left" => Some(Arm::Left),
            "right" => Some(Arm::Right),
            _ => None,
        }
    }
}

/// One place on the tour.
///
/// Its text values are kept as spans into the file's text (8 bytes each, instead of 24 for
/// a string slice and its span): a 60 MB file has 100,000 locations, and their size is
/// most of what ekb holds besides the text itself. Read them with the accessors.
#[derive(Debug, Clone, PartialEq)]
pub struct Location<'a> {
    pub id: u32,
    /// The first line that mentions this location.
    pub first_line: Span,
    text: SourceText<'a>,
    /// The text values, by [`text_index`].
    texts: [TextSlot; 8],
    pub pose: Option<Value<Pose>>,
    /// The key the pose was written with (`robotLocation` or `robotLocationPose`).
    pub pose_key: Option<Key>,
    pub gesture_target: Option<Value<Point>>,
    pub gesture_arm: Option<Value<Arm>>,
    /// Which keys have a line for this location, valid or not: bit `1 << Key::order()`.
    pub given: u16,
    /// Which keys have a line for this location written in the wrong case (which the robot
    /// ignores, and `key-case` reports): bit `1 << Key::order()`.
    pub miscased: u16,
    /// Which keys have a line for this location whose key is misspelled (an unknown key
    /// close to this one, which `unknown-key` reports): bit `1 << Key::order()`.
    pub misspelled: u16,
}

impl<'a> Location<'a> {
    /// A location with no values yet; `text` is the file's text, which values are spans of.
    pub fn new(text: &'a str, id: u32, first_line: Span) -> Location<'a> {
        Location {
            id,
            first_line,
            text: SourceText(text),
            texts: [TextSlot::EMPTY; 8],
            pose: None,
            pose_key: None,
            gesture_target: None,
            gesture_arm: None,
            given: 0,
            miscased: 0,
            misspelled: 0,
        }
    }

    /// The file's text, which this location's values are spans of.
    pub fn file_text(&self) -> &'a str {
        self.text.0
    }

    /// Whether the file has a line with this key for this location (even a malformed one).
    pub fn has_line(&self, key: Key) -> bool {
        self.given & (1 << key.order()) != 0
    }

    /// Whether the file has a line for this location with this key in the wrong case.
    pub fn has_miscased_line(&self, key: Key) -> bool {
        self.miscased & (1 << key.order()) != 0
    }

    /// Whether a line of this location has `key` misspelled.
    pub fn has_misspelled_line(&self, key: Key) -> bool {
        self.misspelled & (1 << key.order()) != 0
    }

    pub fn description(&self) -> Option<Value<&'a str>> {
        self.text_value(Key::RobotLocationDescription)
    }

    pub fn message(&self, phase: Phase, language: Language) -> Option<Value<&'a str>> {
        self.value_at(message_index(phase, language))
    }

    /// The words, as one value (split with [`words`]).
    pub fn cultural_knowledge(&self) -> Option<Value<&'a str>> {
        self.text_value(Key::CulturalKnowledge)
    }

    /// The culturalKnowledge words, empty when there are none.
    pub fn cultural_words(&self) -> impl Iterator<Item = &'a str> {
        self.cultural_knowledge()
            .map(|value| value.value)
            .into_iter()
            .flat_map(words)
    }

    /// Adds the values of `later`, the same location as read from later lines, if the two
    /// have no key in common (so that neither overrides the other); returns whether it did.
    pub(crate) fn join(&mut self, later: Location<'a>) -> bool {
        let both_posed = self.pose_key.is_some() && later.pose_key.is_some();
        if self.given & later.given != 0 || both_posed {
            return false;
        }
        for (slot, value) in self.texts.iter_mut().zip(later.texts) {
            if value != TextSlot::EMPTY {
                *slot = value;
            }
        }
        self.pose = self.pose.or(later.pose);
        self.pose_key = self.pose_key.or(later.pose_key);
        self.gesture_target = self.gesture_target.or(later.gesture_target);
        self.gesture_arm = self.gesture_arm.or(later.gesture_arm);
        self.given |= later.given;
        self.miscased |= later.miscased;
        self.misspelled |= later.misspelled;
        true
    }

    /// Sets the value of a text key (a description, a message or the culturalKnowledge
    /// words) to the text at `span`.
    pub fn set_text(&mut self, key: Key, span: Span) {
        self.texts[text_index(key)] = TextSlot(span);
    }

    /// The value of a text key, if it has one.
    pub fn text_value(&self, key: Key) -> Option<Value<&'a str>> {
        self.value_at(text_index(key))
    }

    fn value_at(&self, index: usize) -> Option<Value<&'a str>> {
        let TextSlot(span) = self.texts[index];
        (TextSlot(span) != TextSlot::EMPTY).then(|| Value {
            value: span.text(self.text.0),
            span,
        })
    }
}

/// Where the value of a text key is in [`Location::texts`]: the description, the six
/// messages, the culturalKnowledge words.
fn text_index(key: Key) -> usize {
    match key.message() {
        Some((phase, language)) => message_index(phase, language),
        None if key.value_kind() == ValueKind::Words => 7,
        None => 0,
    }
}

fn message_index(phase: Phase, language: Language) -> usize {
    1 + phase.index() * Language::ALL.len() + language.index()
}

/// The span of a text value, or [`TextSlot::EMPTY`] (no value).
#[derive(Debug, Clone, Copy, PartialEq)]
struct TextSlot(Span);

impl TextSlot {
    /// No value: no file is 4 GiB long (ekb reads at most 512 MiB).
    const EMPTY: TextSlot = TextSlot(Span {
        start: u32::MAX,
        end: u32::MAX,
    });
}

/// The file's text, shared by every location. Two locations are equal when they are the same
/// spans of the same text (not merely equal text), and `Debug` does not print it.
#[derive(Clone, Copy)]
struct SourceText<'a>(&'a str);

impl PartialEq for SourceText<'_> {
    fn eq(&self, other: &Self) -> bool {
        std::ptr::eq(self.0, other.0)
    }
}

impl std::fmt::Debug for SourceText<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "<{} bytes of text>", self.0.len())
    }
}

/// The order in which the tour visits locations.
///
/// The stops are read again from the line's text whenever they are asked for, not held: a
/// tour of a million stops is 2 MB of text, and was 12 MB as a list of values with spans.
#[derive(Debug, Clone, PartialEq)]
pub struct Tour<'a> {
    /// The whole `tourSpecification` line's arguments.
    pub span: Span,
    /// The declared number of stops, `n`, if it is a number.
    pub declared: Option<Value<u64>>,
    /// The text of `span`.
    text: &'a str,
}

impl<'a> Tour<'a> {
    /// The tour of the arguments `text` at `span`, whose first item declared `declared`.
    pub fn new(span: Span, text: &'a str, declared: Option<Value<u64>>) -> Tour<'a> {
        Tour {
            span,
            declared,
            text,
        }
    }

    /// The items after `n`, valid ids or not, with their spans: the robot counts them all.
    pub fn listed(&self) -> impl Iterator<Item = (Span, &'a str)> + 'a {
        build::tour_items(self.text, self.span.start as usize).skip(1)
    }

    /// The location ids, in the order visited (the items that are not ids left out).
    pub fn stops(&self) -> impl Iterator<Item = Value<u32>> + 'a {
        self.listed()
            .filter_map(|(span, token)| build::parse_id(token).map(|value| Value { value, span }))
    }

    /// Whether the tour has no stop.
    pub fn has_no_stops(&self) -> bool {
        self.stops().next().is_none()
    }
}

/// A whole knowledge base.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct KnowledgeBase<'a> {
    /// `None` when the file has no key of either dialect.
    pub dialect: Option<Dialect>,
    locations: Locations<'a>,
    pub tour: Option<Tour<'a>>,
    /// What the rules about the robot's reader need to know of the lines.
    pub lines: LineFacts,
}

/// Facts about a file's lines that are not part of its values, but decide what a version of
/// the robot's reader loads from it (see [`crate::reader`]).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct LineFacts {
    /// How many lines of each key (by `Key as usize`) the file has.
    pub key_lines: [u32; Key::ALL.len()],
    /// Lines as long as the smallest reader's line buffer or longer, in file order.
    pub long_lines: Vec<Span>,
    /// Lines of a key that start with a blank, in file order.
    pub indented_lines: Vec<Span>,
    /// Lines shorter than every reader's line buffer whose first word is as long as the
    /// reader's key buffer or longer, in file order (the longer lines are in `long_lines`).
    pub long_first_words: Vec<Span>,
    /// How many comment lines mention `ekb:`, the lines a suppression can be on; `None` if
    /// the knowledge base was not read from its lines (then any line may hold one).
    pub suppression_lines: Option<u32>,
    /// How many lines were read.
    pub lines: u32,
    /// The first line to start at or after each multiple of [`LINE_STARTS_EVERY`] bytes,
    /// in file order (the same however many parts read the file): where locating a finding
    /// can start counting lines, instead of at the start of the file (on a 100,000-location
    /// file, a finding on the last line was a count of 900,000 newlines, on one core).
    pub line_starts: Vec<LineStart>,
}

/// How many bytes apart [`LineFacts::line_starts`] are, at least.
pub const LINE_STARTS_EVERY: usize = 1 << 20;

/// Where [`LineFacts::line_starts`] has its next line, for lines read from `start` on (a
/// line's start): at the first multiple of [`LINE_STARTS_EVERY`] after the line before.
pub fn next_noted_line_start(bytes: &[u8], start: usize) -> usize {
    let line_before = match start.checked_sub(1) {
        Some(newline) => memchr::memrchr(b'\n', &bytes[..newline]).map_or(0, |end| end + 1),
        None => 0,
    };
    (line_before / LINE_STARTS_EVERY + 1) * LINE_STARTS_EVERY
}

impl LineFacts {
    /// Notes `line`'s length, and the length of its first word where it can matter.
    pub fn note_length(&mut self, line: &crate::syntax::Line, text: &str) {
        use crate::reader::{key_buffer, Reader};
        let length = line.span.len();
        if length >= Reader::SMALLEST_LINE_BUFFER {
            self.long_lines.push(line.span);
        } else if length >= key_buffer::KEY_BUFFER
            && key_buffer::overflows(&text.as_bytes()[line.span.range()])
        {
            self.long_first_words.push(line.span);
        }
    }

    /// Whether the file has a line of `key`.
    pub fn has(&self, key: Key) -> bool {
        self.key_lines[key as usize] > 0
    }

    /// How many lines of `key` the file has.
    pub fn count(&self, key: Key) -> usize {
        self.key_lines[key as usize] as usize
    }

    /// Adds the facts of the lines after these.
    pub fn append(&mut self, later: LineFacts) {
        for (count, more) in self.key_lines.iter_mut().zip(later.key_lines) {
            *count += more;
        }
        self.long_lines.extend(later.long_lines);
        self.indented_lines.extend(later.indented_lines);
        self.long_first_words.extend(later.long_first_words);
        self.suppression_lines = match (self.suppression_lines, later.suppression_lines) {
            (Some(these), Some(those)) => Some(these + those),
            _ => None,
        };
        let before = self.lines;
        self.line_starts
            .extend(later.line_starts.into_iter().map(|start| LineStart {
                line: start.line + before,
                ..start
            }));
        self.lines += later.lines;
    }
}

impl<'a> KnowledgeBase<'a> {
    pub fn new(
        dialect: Option<Dialect>,
        locations: Vec<Location<'a>>,
        tour: Option<Tour<'a>>,
    ) -> KnowledgeBase<'a> {
        KnowledgeBase::from_runs(dialect, vec![locations], tour)
    }

    /// A knowledge base of the locations read from the parts of a file, a run per part in
    /// file order (see [`Locations`]).
    pub fn from_runs(
        dialect: Option<Dialect>,
        runs: Vec<Vec<Location<'a>>>,
        tour: Option<Tour<'a>>,
    ) -> KnowledgeBase<'a> {
        KnowledgeBase {
            dialect,
            locations: Locations::new(runs),
            tour,
            lines: LineFacts::default(),
        }
    }

    /// Every location, in ascending id order.
    pub fn locations(&self) -> &Locations<'a> {
        &self.locations
    }

    /// The location with this id.
    pub fn location(&self, id: u32) -> Option<&Location<'a>> {
        self.locations.get(id)
    }

    /// The tour's stops, in order (empty without a tour).
    pub fn tour_stops(&self) -> impl Iterator<Item = u32> + '_ {
        self.tour
            .iter()
            .flat_map(|tour| tour.stops().map(|stop| stop.value))
    }
}

/// The locations of a knowledge base, in ascending id order.
///
/// A large file is read in parts, each into its own list (see [`build`]). When the lists
/// are in id order one after the other, as in a file written in id order, they are kept as
/// they are, as runs: moving them into one list would copy every location and touch as
/// much new memory again. Otherwise they are made one list and sorted.
#[derive(Debug, Clone, Default)]
pub struct Locations<'a> {
    /// Not empty, each in ascending id order, each after the one before.
    runs: Vec<Vec<Location<'a>>>,
}

impl<'a> Locations<'a> {
    fn new(runs: Vec<Vec<Location<'a>>>) -> Locations<'a> {
        let mut runs: Vec<_> = runs.into_iter().filter(|run| !run.is_empty()).collect();
        let in_order = runs
            .iter()
            .all(|run| run.is_sorted_by_key(|location| location.id))
            && runs
                .windows(2)
                .all(|pair| pair[0][pair[0].len() - 1].id < pair[1][0].id);
        if !in_order {
            let mut all = match runs.len() {
                1 => runs.pop().expect("one run"),
                _ => runs.drain(..).flatten().collect(),
            };
            all.sort_unstable_by_key(|location| location.id);
            runs = vec![all];
        }
        Locations { runs }
    }

    pub fn iter(&self) -> std::iter::Flatten<std::slice::Iter<'_, Vec<Location<'a>>>> {
        self.runs.iter().flatten()
    }

    pub fn len(&self) -> usize {
        self.runs.iter().map(Vec::len).sum()
    }

    pub fn is_empty(&self) -> bool {
        self.runs.is_empty()
    }

    /// The runs, in order: a large file's work is split along them.
    pub fn runs(&self) -> &[Vec<Location<'a>>] {
        &self.runs
    }

    fn get(&self, id: u32) -> Option<&Location<'a>> {
        let run = &self.runs[self
            .runs
            .partition_point(|run| run[run.len() - 1].id < id)
            .min(self.runs.len().checked_sub(1)?)];
        run.binary_search_by_key(&id, |location| location.id)
            .ok()
            .map(|index| &run[index])
    }
}

/// The same locations in the same order, however they are held.
impl PartialEq for Locations<'_> {
    fn eq(&self, other: &Self) -> bool {
        self.len() == other.len() && self.iter().eq(other)
    }
}

impl<'k, 'a> IntoIterator for &'k Locations<'a> {
    type Item = &'k Location<'a>;
    type IntoIter = std::iter::Flatten<std::slice::Iter<'k, Vec<Location<'a>>>>;

    fn into_iter(self) -> Self::IntoIter {
        self.iter()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn locations_stay_small() {
        // 100,000 locations of a 60 MB file: their size counts against peak memory.
        assert!(std::mem::size_of::<Location>() <= 192);
        let text = "abc def";
        let mut location = Location::new(text, 1, Span::new(0, 7));
        assert_eq!(location.description(), None);
        location.set_text(Key::CulturalKnowledge, Span::new(4, 7));
        let words = location.cultural_knowledge().unwrap();
        assert_eq!((words.value, words.span), ("def", Span::new(4, 7)));
        assert_eq!(location.text_value(Key::RobotLocationDescription), None);
    }

    #[test]
    fn the_robot_sums_in_single_precision() {
        let sums_to_zero = |x, y, z| Point { x, y, z }.robot_sees_no_gesture();
        assert!(sums_to_zero(1.0, -1.0, 0.0));
        assert!(sums_to_zero(0.1, 0.2, -0.3));
        assert!(sums_to_zero(1.0, 1e-8, -1.0));
        assert!(!sums_to_zero(1.0, -1.0, 0.01));
    }
}
