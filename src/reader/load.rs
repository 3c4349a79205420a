//! A whole file, loaded as one version of the robot's reader loads it.

use std::collections::BTreeMap;

use super::line::{self, LineRead, LoadedValue};
use super::tree::{ShapeBuilder, TreeShape};
use super::Reader;
use crate::model::Key;
use crate::syntax::Span;

/// What the robot holds after reading a file.
#[derive(Debug, Clone, PartialEq)]
pub struct Loaded<'a> {
    pub reader: Reader,
    /// By id, as `%d` read it (so possibly 0 or negative).
    pub locations: BTreeMap<i32, LoadedLocation<'a>>,
    /// `None` when no line set the tour.
    pub tour: Option<LoadedTour>,
    pub tree: TreeShape,
    text: &'a [u8],
}

/// One location as the robot holds it: each field set by a line, or never set (the
/// robot's empty text or 0).
///
/// It keeps only where each field's line starts, and reads the line again when asked: a
/// file of 100,000 locations would otherwise hold every value a second time.
#[derive(Debug, Clone, PartialEq)]
pub struct LoadedLocation<'a> {
    pub id: i32,
    /// Where the `fgets` call that last set each field starts, plus one (0: none), by
    /// [`Key::order`].
    lines: [u32; Key::ALL.len()],
    text: &'a [u8],
    reader: Reader,
}

/// A field's value and the line (`fgets` call) it came from.
#[derive(Debug, Clone, PartialEq)]
pub struct Field {
    pub line: Span,
    pub value: LoadedValue,
}

impl LoadedLocation<'_> {
    /// The value of `key` (for the pose, either pose key), if a line set it.
    pub fn field(&self, key: Key) -> Option<Field> {
        let start = self.lines[key.order()].checked_sub(1)? as usize;
        let (_, chunk) = chunks(&self.text[start..], self.reader.line_buffer()).next()?;
        let line = Span::new(start, start + chunk.len());
        match line::read(chunk, start, self.reader) {
            LineRead::Value { value, .. } => Some(Field { line, value }),
            _ => unreachable!("the line set this field when it was read"),
        }
    }
}

impl<'a> Loaded<'a> {
    /// The file the values are spans of.
    pub fn text(&self) -> &'a [u8] {
        self.text
    }
}

/// The tour as the robot holds it.
#[derive(Debug, Clone, PartialEq)]
pub struct LoadedTour {
    /// The line that last set it.
    pub line: Span,
    /// `numberOfLocations`.
    pub count: i32,
    /// The first `count` slots (at most those ever written, or the 20 of its buffer); `None`
    /// where a slot holds whatever was in memory.
    pub stops: Vec<Option<i32>>,
}

/// The stops of the robot's tour buffer.
const TOUR_BUFFER: usize = 20;

/// Loads `text` as `reader` does.
pub fn load(text: &[u8], reader: Reader) -> Loaded<'_> {
    let mut locations: BTreeMap<i32, LoadedLocation> = BTreeMap::new();
    let mut tour_line = None;
    let mut count = 0;
    let mut slots: Vec<Option<i32>> = Vec::new();
    let mut tree = ShapeBuilder::default();
    // Most lines follow one of the same location: they are gathered here, and the map is
    // updated once per run of them.
    let mut run: Option<(i32, [u32; Key::ALL.len()], u32)> = None;
    let mut end_run = |run: Option<(i32, [u32; Key::ALL.len()], u32)>| {
        let Some((id, lines, count)) = run else {
            return;
        };
        tree.add(id, count);
        let location = locations.entry(id).or_insert_with(|| LoadedLocation {
            id,
            lines: [0; Key::ALL.len()],
            text,
            reader,
        });
        for (held, later) in location.lines.iter_mut().zip(lines) {
            if later != 0 {
                *held = later;
            }
        }
    };
    for (offset, chunk) in chunks(text, reader.line_buffer()) {
        let line = Span::new(offset, offset + chunk.len());
        match line::read(chunk, offset, reader) {
            LineRead::Value { key, id, .. } => {
                if run.as_ref().is_none_or(|(run_id, ..)| *run_id != id) {
                    end_run(run.take());
                    run = Some((id, [0; Key::ALL.len()], 0));
                }
                if let Some((_, lines, count)) = &mut run {
                    lines[key.order()] = line.start + 1;
                    *count += 1;
                }
            }
            LineRead::Tour { count: n, stops } => {
                tour_line = Some(line);
                count = n;
                if slots.len() < stops.len() {
                    slots.resize(stops.len(), None);
                }
                for (slot, stop) in slots.iter_mut().zip(stops) {
                    *slot = stop;
                }
            }
            LineRead::Skipped
            | LineRead::Ignored { .. }
            | LineRead::Failed { .. }
            | LineRead::TourFailed => {}
        }
    }
    end_run(run);
    let tree = tree.shape();
    let tour = tour_line.map(|line| {
        let shown = (count.max(0) as usize).min(slots.len().max(TOUR_BUFFER));
        LoadedTour {
            line,
            count,
            stops: (0..shown)
                .map(|k| slots.get(k).copied().flatten())
                .collect(),
        }
    });
    Loaded {
        reader,
        locations,
        tour,
        tree,
        text,
    }
}

/// The file as `fgets` with a buffer of `buffer` bytes returns it: each line, newline
/// included, in pieces of at most `buffer - 1` bytes; with where each starts.
pub fn chunks(text: &[u8], buffer: usize) -> impl Iterator<Item = (usize, &[u8])> {
    let most = buffer - 1;
    let mut at = 0;
    std::iter::from_fn(move || {
        if at >= text.len() {
            return None;
        }
        let rest = &text[at..];
        // Only the bytes one call can take are searched: a line may be megabytes long.
        let window = &rest[..rest.len().min(most)];
        let length = memchr::memchr(b'\n', window).map_or(window.len(), |newline| newline + 1);
        let chunk = (at, &rest[..length]);
        at += length;
        Some(chunk)
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn text_of(text: &str, field: Option<Field>) -> &str {
        match field.map(|field| field.value) {
            Some(LoadedValue::Text(span)) => &text[span.range()],
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn lines_are_cut_where_fgets_cuts_them() {
        let line = format!("{}\n", "x".repeat(199));
        let pieces: Vec<usize> = chunks(line.as_bytes(), 200).map(|(_, c)| c.len()).collect();
        assert_eq!(pieces, [199, 1]);
        let pieces: Vec<usize> = chunks(line.as_bytes(), 300).map(|(_, c)| c.len()).collect();
        assert_eq!(pieces, [200]);
        let pieces: Vec<usize> = chunks(b"ab\ncd", 200).map(|(_, c)| c.len()).collect();
        assert_eq!(pieces, [3, 2]);
    }

    #[test]
    fn later_lines_overwrite_earlier_ones_field_by_field() {
        let text = "robotLocationDescription 2 Hall\nrobotLocationPose 2 1 2 3\n\
                    robotLocationDescription 2 Lab\nrobotLocation 2 9 9 9\n";
        let loaded = load(text.as_bytes(), Reader::V2025_06);
        let location = &loaded.locations[&2];
        assert_eq!(
            text_of(text, location.field(Key::RobotLocationDescription)),
            "Lab"
        );
        let pose = location.field(Key::RobotLocationPose).map(|f| f.value);
        assert_eq!(pose, Some(LoadedValue::Numbers([1.0, 2.0, 3.0])));
        let seed = load(text.as_bytes(), Reader::D542);
        let pose = seed.locations[&2]
            .field(Key::RobotLocation)
            .map(|f| f.value);
        assert_eq!(pose, Some(LoadedValue::Numbers([9.0, 9.0, 9.0])));
    }

    #[test]
    fn a_long_line_is_cut_and_its_rest_read_as_a_line() {
        let message = "a".repeat(250);
        let text = format!("preGestureMessageEnglish 1 {message}\n");
        let cut = load(text.as_bytes(), Reader::V2025_06);
        let loaded = text_of(
            &text,
            cut.locations[&1].field(Key::PreGestureMessageEnglish),
        );
        assert_eq!(loaded.len(), 199 - 27 - 1);
        let whole = load(text.as_bytes(), Reader::V2026_02);
        let loaded = text_of(
            &text,
            whole.locations[&1].field(Key::PreGestureMessageEnglish),
        );
        assert_eq!(loaded, message);
    }

    #[test]
    fn the_last_tour_wins_and_keeps_the_slots_it_does_not_write() {
        let text = "tourSpecification 3 1 2 3\ntourSpecification 3 7\n";
        let tour = load(text.as_bytes(), Reader::V2025_06).tour.unwrap();
        assert_eq!(
            (tour.count, tour.stops),
            (3, vec![Some(7), Some(2), Some(3)])
        );
        let fresh = load(b"tourSpecification 3 7\n", Reader::V2025_06)
            .tour
            .unwrap();
        assert_eq!(fresh.stops, vec![Some(7), None, None]);
        assert_eq!(load(b"", Reader::V2025_06).tour, None);
    }

    #[test]
    fn the_tree_follows_the_order_of_ids() {
        let text: String = (1..=5)
            .map(|id| format!("robotLocationDescription {id} x\n"))
            .collect();
        assert_eq!(load(text.as_bytes(), Reader::V2025_06).tree.height, 5);
    }
}
