//! The typed view of a knowledge base: locations and the tour, each value with its span.
//!
//! The model holds what the robot's reader would load from the file, read faithfully:
//! a key in the wrong case is not a key (the robot ignores it, and so a message goes
//! missing), later lines for the same id and key win, the last tour wins. It borrows its
//! text from the [`SourceFile`](crate::SourceFile), so building it copies no strings.

pub mod build;
pub mod export;
mod ids;
mod text;

pub use crate::robot::{Dialect, Key, Language, Phase, ValueKind};
pub use ids::{IdMap, IdSet};
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
    /// in file order: where locating a finding
    /// can start counting lines, instead of at the start of the file (on a 100,000-location
    /// file, a finding on the last line was a count of 900,000 newlines, on one core).
    pub line_starts: Vec<LineStart>,
}

/// How many bytes apart [`LineFacts::line_starts`] are, at least.
pub const LINE_STARTS_EVERY: usize = 1 << 20;

impl LineFacts {
    /// Notes `line`'s length, and the length of its first word where it can matter.
    pub fn note_length(&mut self, line: &crate::syntax::Line, text: &str) {
        use crate::robot::{key_buffer, Reader};
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
}

impl<'a> KnowledgeBase<'a> {
    pub fn new(
        dialect: Option<Dialect>,
        locations: Vec<Location<'a>>,
        tour: Option<Tour<'a>>,
    ) -> KnowledgeBase<'a> {
        KnowledgeBase {
            dialect,
            locations: Locations::new(locations),
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
#[derive(Debug, Clone, Default, PartialEq)]
pub struct Locations<'a>(Vec<Location<'a>>);

impl<'a> Locations<'a> {
    fn new(mut locations: Vec<Location<'a>>) -> Locations<'a> {
        // Files are usually written in id order: then there is nothing to sort.
        if !locations.is_sorted_by_key(|location| location.id) {
            locations.sort_unstable_by_key(|location| location.id);
        }
        Locations(locations)
    }

    pub fn iter(&self) -> std::slice::Iter<'_, Location<'a>> {
        self.0.iter()
    }

    pub fn len(&self) -> usize {
        self.0.len()
    }

    /// The locations in the order of the file: each where its first line is. (`ekb import`
    /// writes them back in this order: a file's order is what keeps the robot's tree of ids
    /// shallow, and sorted ids would make it a list.)
    pub fn in_file_order(&self) -> Vec<&Location<'a>> {
        let mut locations: Vec<&Location<'a>> = self.0.iter().collect();
        if !locations.is_sorted_by_key(|location| location.first_line.start) {
            locations.sort_by_key(|location| location.first_line.start);
        }
        locations
    }

    pub fn is_empty(&self) -> bool {
        self.0.is_empty()
    }

    fn get(&self, id: u32) -> Option<&Location<'a>> {
        let index = self
            .0
            .binary_search_by_key(&id, |location| location.id)
            .ok()?;
        Some(&self.0[index])
    }
}

impl<'k, 'a> IntoIterator for &'k Locations<'a> {
    type Item = &'k Location<'a>;
    type IntoIter = std::slice::Iter<'k, Location<'a>>;

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
