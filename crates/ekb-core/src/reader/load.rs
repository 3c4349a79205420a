//! A whole file, loaded as one version of the robot's reader loads it.

use super::buffer::{InBuffer, LineBuffer};
use super::line::{self, LineRead, LoadedValue, ValueAt};
use super::tree::{ShapeBuilder, TreeShape};
use crate::model::Key;
use crate::robot::scan::is_space;
use crate::robot::Reader;
use crate::syntax::Span;

/// What the robot holds after reading a file.
#[derive(Debug, Clone, PartialEq)]
pub struct Loaded<'a> {
    pub reader: Reader,
    /// By id, as `%d` read it (so possibly 0 or negative).
    pub locations: Locations,
    /// `None` when no line set the tour.
    pub tour: Option<LoadedTour>,
    pub tree: TreeShape,
    text: &'a [u8],
    /// The keys whose lines were read ([`load_fields`]), or `None`: every key's.
    only: Option<Vec<Key>>,
    /// Each line that set a field to what an earlier, longer line left in the buffer, as
    /// where it starts and where that earlier line starts, in file order.
    leftovers: Vec<(u32, u32)>,
}

/// One location as the robot holds it: each field set by a line, or never set (the
/// robot's empty text or 0). [`Loaded::field`] gives a field's value.
#[derive(Debug, Clone, PartialEq)]
pub struct LoadedLocation {
    pub id: i32,
    fields: SetFields,
}

/// The fields that lines set, each as where its line starts and where the value starts in
/// it, so that a view reads the value alone: reading each field's whole line again cost
/// `export --as-loaded` nearly as much as the load itself, and holding each value as a
/// [`LoadedValue`] would take 400 bytes a location.
#[derive(Debug, Clone, PartialEq)]
struct SetFields {
    /// Where the `fgets` call that last set each field starts, plus one (0: none), by
    /// [`Key::order`].
    lines: [u32; Key::ALL.len()],
    /// Where the value starts in the buffer ([`UNDEFINED`]: undefined), in bytes that line
    /// wrote or, for a line in [`Loaded::leftovers`], an earlier one.
    values: [u16; Key::ALL.len()],
}

/// A value that starts past the end of its line (no line is this long: see
/// [`Reader::line_buffer`]).
const UNDEFINED: u16 = u16::MAX;

impl SetFields {
    const NONE: SetFields = SetFields {
        lines: [0; Key::ALL.len()],
        values: [0; Key::ALL.len()],
    };

    /// Records that the line at `line` set `key` to the value at `value_at`.
    fn set(&mut self, key: Key, line: usize, value_at: Option<ValueAt>) {
        let slot = key.order();
        self.lines[slot] = u32::try_from(line + 1).expect("a file is less than 4 GiB");
        self.values[slot] = value_at.map_or(UNDEFINED, |value| {
            u16::try_from(value.at).expect("a value is within a reader's buffer")
        });
    }

    /// Each field that `later` sets, set as it does.
    fn overwrite_with(&mut self, later: &SetFields) {
        for slot in 0..Key::ALL.len() {
            if later.lines[slot] != 0 {
                self.lines[slot] = later.lines[slot];
                self.values[slot] = later.values[slot];
            }
        }
    }
}

/// The locations the robot holds, in ascending id order: a sorted list, which holds 100,000
/// of them in half the memory of a `BTreeMap`.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Locations(Vec<LoadedLocation>);

impl Locations {
    pub fn get(&self, id: &i32) -> Option<&LoadedLocation> {
        let index = self.0.binary_search_by_key(id, |location| location.id);
        index.ok().map(|index| &self.0[index])
    }

    /// In ascending id order.
    pub fn values(&self) -> std::slice::Iter<'_, LoadedLocation> {
        self.0.iter()
    }

    pub fn len(&self) -> usize {
        self.0.len()
    }

    pub fn is_empty(&self) -> bool {
        self.0.is_empty()
    }
}

impl std::ops::Index<&i32> for Locations {
    type Output = LoadedLocation;

    fn index(&self, id: &i32) -> &LoadedLocation {
        self.get(id).expect("no location with this id")
    }
}

/// A field's value and the line (`fgets` call) it came from.
#[derive(Debug, Clone, PartialEq)]
pub struct Field {
    pub line: Span,
    pub value: LoadedValue,
}

impl<'a> Loaded<'a> {
    /// The file the values are spans of.
    pub fn text(&self) -> &'a [u8] {
        self.text
    }

    /// The value of `key` at `location` (for the pose, either pose key), if a line set it.
    pub fn field(&self, location: &LoadedLocation, key: Key) -> Option<Field> {
        debug_assert!(
            self.only.as_ref().is_none_or(|keys| keys.contains(&key)),
            "the lines of {key:?} were not read"
        );
        let slot = key.order();
        let start = location.fields.lines[slot].checked_sub(1)? as usize;
        let (_, chunk) = chunks(&self.text[start..], self.reader.line_buffer()).next()?;
        let line = Span::new(start, start + chunk.len());
        let value = match location.fields.values[slot] {
            UNDEFINED => line::past_the_line(key),
            // Read again from where it starts, in the line that wrote it: a C string ends
            // at its first NUL.
            at => {
                let at = usize::from(at);
                let piece = self.leftover_of(start).unwrap_or(start);
                let (_, bytes) = chunks(&self.text[piece..], self.reader.line_buffer()).next()?;
                let rest = &bytes[at..];
                let string = &rest[..memchr::memchr(0, rest).unwrap_or(rest.len())];
                line::value(key, string, 0, piece + at)
                    .expect("the line set this field when it was read")
            }
        };
        Some(Field { line, value })
    }
}

impl Loaded<'_> {
    /// Where the earlier line starts whose leftovers the line at `line` loaded, if it did.
    fn leftover_of(&self, line: usize) -> Option<usize> {
        let line = u32::try_from(line).ok()?;
        let index = self
            .leftovers
            .binary_search_by_key(&line, |&(at, _)| at)
            .ok()?;
        Some(self.leftovers[index].1 as usize)
    }
}

/// The tour as the robot holds it.
#[derive(Debug, Clone, PartialEq)]
pub struct LoadedTour {
    /// The line that last set it.
    pub line: Span,
    /// `numberOfLocations`.
    pub count: i32,
    /// The first `count` slots (at most those ever written, or the 20 of its buffer): 0
    /// where no line read one; `None` where a slot holds whatever was in memory.
    pub stops: Vec<Option<i32>>,
}

/// The stops of the robot's tour buffer.
pub(super) const TOUR_BUFFER: usize = 20;

/// Loads `text` as `reader` does.
pub fn load(text: &[u8], reader: Reader) -> Loaded<'_> {
    load_only(text, reader, None)
}

/// [`load`] of the fields of `keys` alone (for the pose, whichever key `reader` reads),
/// for a view that shows no others: a line of another key is passed over once its first
/// word is seen not to be one of them, which made loading 100,000 locations for
/// `ekb locations` take half as long. What else it holds (the locations, the tour unless
/// `keys` has its key, the tree) is what the lines of `keys` alone load.
pub fn load_fields<'a>(text: &'a [u8], reader: Reader, keys: &[Key]) -> Loaded<'a> {
    let keys = keys
        .iter()
        .map(|&key| match key {
            Key::RobotLocation | Key::RobotLocationPose => reader.pose_key(),
            other => other,
        })
        .collect();
    load_only(text, reader, Some(keys))
}

/// [`load`] of the lines of `only` (`None`: all).
fn load_only(text: &[u8], reader: Reader, only: Option<Vec<Key>>) -> Loaded<'_> {
    let names: Option<Vec<&[u8]>> = only
        .as_ref()
        .map(|keys| keys.iter().map(|key| key.name().as_bytes()).collect());
    // The whole load is made without a test of each line's key (a closure that always says
    // yes costs nothing).
    let whole = 0..text.len();
    let part = match &names {
        None => read_part(text, whole, reader, |_| true),
        Some(names) => read_part(text, whole, reader, |line| starts_with_one_of(line, names)),
    };
    let mut tree = ShapeBuilder::default();
    for (run, &lines) in part.runs.iter().zip(&part.lines) {
        tree.add(run.id, lines);
    }
    let mut locations = part.runs;
    let mut tour_line = None;
    let mut count = 0;
    let mut slots: Vec<Option<i32>> = Vec::new();
    let leftovers = part.leftovers;
    for (line, declared, stops) in part.tours {
        tour_line = Some(line);
        count = declared;
        if slots.len() < stops.len() {
            slots.resize(stops.len(), None);
        }
        for (slot, stop) in slots.iter_mut().zip(stops) {
            *slot = stop;
        }
    }
    // By id, and in file order within an id (the sort is stable), so that a later line
    // overwrites an earlier one's field.
    locations.sort_by_key(|location| location.id);
    locations.dedup_by(|later, earlier| {
        let same = later.id == earlier.id;
        if same {
            earlier.fields.overwrite_with(&later.fields);
        }
        same
    });
    let tour = tour_line.map(|line| {
        let shown = (count.max(0) as usize).min(slots.len().max(TOUR_BUFFER));
        LoadedTour {
            line,
            count,
            // The tour is zero-filled when loading starts (SPEC §2.17): a slot that no
            // line read is 0.
            stops: (0..shown)
                .map(|k| slots.get(k).copied().unwrap_or(Some(0)))
                .collect(),
        }
    });
    Loaded {
        reader,
        locations: Locations(locations),
        tour,
        tree: tree.shape(),
        text,
        only,
        leftovers,
    }
}

/// What the lines of a file load, in file order.
#[derive(Default)]
struct Part {
    /// Each run of consecutive lines of one location that load values, as a location of
    /// the fields they set.
    runs: Vec<LoadedLocation>,
    /// How many lines each run has.
    lines: Vec<u32>,
    /// Each tour line read: where, its count, and its stops.
    tours: Vec<(Span, i32, Vec<Option<i32>>)>,
    /// Each line that set a field to what an earlier line left ([`Loaded::leftovers`]).
    leftovers: Vec<(u32, u32)>,
}

/// Reads the whole lines of `text` in `range` that `wanted` says may set a field.
fn read_part(
    text: &[u8],
    range: std::ops::Range<usize>,
    reader: Reader,
    wanted: impl Fn(&[u8]) -> bool,
) -> Part {
    let mut part = Part::default();
    let start = range.start;
    let part_text = &text[range];
    // A text without a NUL byte need not be searched for one line by line.
    let has_nul = memchr::memchr(0, part_text).is_some();
    let mut history = LineBuffer::new(reader.line_buffer());
    for (offset, chunk) in chunks(part_text, reader.line_buffer()) {
        let offset = start + offset;
        if !wanted(chunk) {
            history.push(offset, chunk.len());
            continue;
        }
        let line = Span::new(offset, offset + chunk.len());
        let buffer = InBuffer::new(chunk, offset, text, &history);
        let buffer = match has_nul {
            true => buffer,
            false => buffer.without_nul(),
        };
        match line::read_in(&buffer, reader) {
            LineRead::Value {
                key, id, value_at, ..
            } => {
                if let Some(value) = value_at.filter(|value| value.piece != offset) {
                    let at =
                        |offset: usize| u32::try_from(offset).expect("a file is less than 4 GiB");
                    part.leftovers.push((at(offset), at(value.piece)));
                }
                if part.runs.last().is_none_or(|run| run.id != id) {
                    part.runs.push(LoadedLocation {
                        id,
                        fields: SetFields::NONE,
                    });
                    part.lines.push(0);
                }
                let run = part.runs.last_mut().expect("a run was just pushed");
                run.fields.set(key, offset, value_at);
                *part.lines.last_mut().expect("a run was just pushed") += 1;
            }
            LineRead::Tour { count, stops } => part.tours.push((line, count, stops)),
            LineRead::Skipped
            | LineRead::Ignored { .. }
            | LineRead::Failed { .. }
            | LineRead::TourFailed => {}
        }
        history.push(offset, chunk.len());
    }
    part
}

/// Whether the first word of `line`, as `%s` reads it, is one of `names`. A line whose
/// word is cut by a NUL byte is not: the reader finds no id after it, and skips the line.
fn starts_with_one_of(line: &[u8], names: &[&[u8]]) -> bool {
    let start = line.iter().position(|&byte| !is_space(byte));
    let word = &line[start.unwrap_or(line.len())..];
    // The first byte first: it tells most keys apart without a call to compare the rest.
    names.iter().any(|name| {
        word.first() == name.first()
            && word.starts_with(name)
            && word.get(name.len()).is_none_or(|&byte| is_space(byte))
    })
}

/// Whether the byte at `at` of `text` is a lone `\r` (no `\n` after it) that is the last
/// byte of a piece filling a line buffer of `buffer` bytes before its line ends: the reader
/// takes it for the line's end (it drops the last byte of a text, taking it for the
/// newline) and reads what follows as a line of its own, as if the `\r` were a `\n`.
pub fn is_carriage_return_at_a_cut(text: &[u8], at: usize, buffer: usize) -> bool {
    if text.get(at) != Some(&b'\r') || text.get(at + 1).is_none_or(|&next| next == b'\n') {
        return false;
    }
    let line_start = memchr::memrchr(b'\n', &text[..at]).map_or(0, |newline| newline + 1);
    (at + 1 - line_start) % (buffer - 1) == 0
}

/// Where `text` has a lone `\r` that a line buffer of `buffer` bytes cuts its line after
/// ([`is_carriage_return_at_a_cut`]).
pub fn carriage_returns_at_cuts(text: &[u8], buffer: usize) -> impl Iterator<Item = usize> + '_ {
    memchr::memchr_iter(b'\r', text)
        .filter(move |&at| is_carriage_return_at_a_cut(text, at, buffer))
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
            text_of(text, loaded.field(location, Key::RobotLocationDescription)),
            "Lab"
        );
        let pose = loaded
            .field(location, Key::RobotLocationPose)
            .map(|f| f.value);
        assert_eq!(pose, Some(LoadedValue::Numbers([1.0, 2.0, 3.0])));
        let seed = load(text.as_bytes(), Reader::D542);
        let pose = seed
            .field(&seed.locations[&2], Key::RobotLocation)
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
            cut.field(&cut.locations[&1], Key::PreGestureMessageEnglish),
        );
        assert_eq!(loaded.len(), 199 - 27 - 1);
        let whole = load(text.as_bytes(), Reader::V2026_02);
        let loaded = text_of(
            &text,
            whole.field(&whole.locations[&1], Key::PreGestureMessageEnglish),
        );
        assert_eq!(loaded, message);
    }

    #[test]
    fn the_last_tour_wins_and_keeps_the_slots_it_does_not_read() {
        // A letter stops the reading of ids: the later slots keep the earlier tour's.
        let text = "tourSpecification 3 1 2 3\ntourSpecification 3 7 x\n";
        let tour = load(text.as_bytes(), Reader::V2025_06).tour.unwrap();
        assert_eq!(
            (tour.count, tour.stops),
            (3, vec![Some(7), Some(2), Some(3)])
        );
        // The end of the line does not: the reader reads on into its buffer's old bytes,
        // the `3` the longer line before left at 24, then bytes no line wrote.
        let text = "tourSpecification 3 1 2 3\ntourSpecification 3 7\n";
        let tour = load(text.as_bytes(), Reader::V2025_06).tour.unwrap();
        assert_eq!(tour.stops, vec![Some(7), Some(3), None]);
        assert_eq!(load(b"", Reader::V2025_06).tour, None);
    }

    #[test]
    fn the_fields_of_some_keys_load_as_in_the_whole_load() {
        // Locations out of id order, each key in both dialects' pose, and other keys.
        let mut text: String = (1..=300)
            .map(|n| (n * 7) % 300 + 1)
            .map(|id| {
                format!(
                    "robotLocationDescription {id} Stop {id}\nrobotLocationPose {id} 1 2 3\n\
                     robotLocation {id} 4 5 6\ngestureTarget {id} 1 2 3\n\n"
                )
            })
            .collect();
        // Lines of the keys in odd places: indented, cut by a NUL, a key alone, only other
        // keys' lines for a location.
        text.push_str(
            "  robotLocationDescription 7 Indented\nrobotLocationDescription\x00 8 Cut\n\
             robotLocationDescription\ngestureTarget 9000 1 2 3\n\
             robotLocationDescriptionX 9 Longer key\nrobotLocation 5 1 2 3\n",
        );
        let keys = [Key::RobotLocationDescription, Key::RobotLocationPose];
        for reader in Reader::ALL {
            let whole = load(text.as_bytes(), reader);
            let some = load_fields(text.as_bytes(), reader, &keys);
            let pose = reader.pose_key();
            for location in whole.locations.values() {
                for key in [Key::RobotLocationDescription, pose] {
                    let field = |loaded: &Loaded<'_>| {
                        let location = loaded.locations.get(&location.id)?;
                        loaded.field(location, key)
                    };
                    assert_eq!(
                        field(&some),
                        field(&whole),
                        "{reader} {key:?} {}",
                        location.id
                    );
                }
            }
            assert!(some.locations.get(&9000).is_none());
        }
    }

    #[test]
    fn the_tree_follows_the_order_of_ids() {
        let text: String = (1..=5)
            .map(|id| format!("robotLocationDescription {id} x\n"))
            .collect();
        assert_eq!(load(text.as_bytes(), Reader::V2025_06).tree.height, 5);
    }
}
