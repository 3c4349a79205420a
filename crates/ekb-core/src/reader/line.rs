//! How the robot's reader reads one line: one `fgets` call's worth of bytes.
//!
//! It reads a key and an integer with `sscanf("%s %d")`; a line without both is skipped. A
//! key it knows then finds its value by counting from the *start of the line*: `strlen(key)`,
//! then past everything that is not a letter or digit, past the id's letters and digits,
//! and past everything that is not a letter or digit again, on past a NUL and the line's
//! end into what earlier lines left in the buffer ([`super::buffer`]). Numbers are read
//! from there with `%f`; a text is the C string there less its last byte (taken to be the
//! newline).

use super::buffer::InBuffer;
use super::load::TOUR_BUFFER;
use crate::model::{Key, ValueKind};
use crate::robot::scan::{self, is_alnum};
use crate::robot::Reader;
use crate::syntax::Span;

/// What one line does to what the robot holds.
#[derive(Debug, Clone, PartialEq)]
pub enum LineRead {
    /// No key followed by an integer (a blank line, a comment, the rest of a split line
    /// that does not look like an entry): nothing happens.
    Skipped,
    /// A key that this version does not read, spelled as written.
    Ignored { key: Span },
    /// `key` of location `id` loads `value`, which is the C string at `value_at` in the
    /// buffer (`None`: undefined, or no culturalKnowledge word).
    Value {
        key: Key,
        key_span: Span,
        id: i32,
        value: LoadedValue,
        value_at: Option<ValueAt>,
    },
    /// A value the reader could not read (`unsuccessful attempt to assign …`): the line
    /// changes nothing.
    Failed { key: Key, id: i32 },
    /// The tour: its declared count, and the ids read into its first slots, in order;
    /// `None` where a slot is read from past the end of the line (undefined). Slots after
    /// the last one given keep what they held before.
    Tour { count: i32, stops: Vec<Option<i32>> },
    /// A tour whose count could not be read: nothing changes.
    TourFailed,
}

/// Where a value is in the buffer: at `at`, in bytes that the line starting at `piece` in
/// the file wrote (the line read, or an earlier, longer one).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ValueAt {
    pub piece: usize,
    pub at: usize,
}

/// A value as the reader loads it.
#[derive(Debug, Clone, PartialEq)]
pub enum LoadedValue {
    /// The bytes of the file it copies (less the last byte of the line).
    Text(Span),
    /// The three numbers of a pose or a gesture target, as C `float`s.
    Numbers([f32; 3]),
    /// The culturalKnowledge words, each as `%s` reads it.
    Words(Vec<Span>),
    /// Its scan ran off the end of the line into whatever the buffer held before.
    Undefined,
}

/// Reads `line` (one `fgets` call's bytes: at most a buffer less one, newline included if
/// it fitted), which starts at `offset` in the file, with nothing known of what the buffer
/// held before (a value found past the line is undefined).
pub fn read(line: &[u8], offset: usize, reader: Reader) -> LineRead {
    read_in(&InBuffer::alone(line, offset), reader)
}

/// Reads the line of `buffer`, over what earlier lines left in it.
pub fn read_in(buffer: &InBuffer<'_>, reader: Reader) -> LineRead {
    // `sscanf` reads the key and the id from the line as a C string, up to its first NUL.
    let line = buffer.c_line();
    let offset = buffer.offset();
    let at = |range: std::ops::Range<usize>| Span::new(offset + range.start, offset + range.end);
    let Some(key_range) = scan::word(line, 0) else {
        return LineRead::Skipped;
    };
    let Some((id, _)) = scan::int(line, key_range.end) else {
        return LineRead::Skipped;
    };
    let key_span = at(key_range.clone());
    // Compared as bytes: a key is ASCII, and making a `str` of every line's first word first
    // cost as much as finding the key.
    let written = &line[key_range.clone()];
    let known = Key::ALL
        .into_iter()
        .find(|key| key.name().as_bytes() == written);
    let Some(key) = known.filter(|&key| reader.reads(key)) else {
        return LineRead::Ignored { key: key_span };
    };
    // The reader counts the key's length from the start of the line, not from the key.
    let key_length = key_range.len();
    if key == Key::TourSpecification {
        return tour(buffer, key_length);
    }
    let value_string = value_start(buffer, key_length)
        // The culturalKnowledge words are read only within the line (`i < strlen(line)`).
        .filter(|&start| key.value_kind() != ValueKind::Words || start < line.len())
        .and_then(|start| buffer.c_string(start));
    let Some(string) = value_string else {
        return LineRead::Value {
            key,
            key_span,
            id,
            value: past_the_line(key),
            value_at: None,
        };
    };
    let Some(value) = value(key, string.bytes, 0, string.file_offset()) else {
        return LineRead::Failed { key, id };
    };
    LineRead::Value {
        key,
        key_span,
        id,
        value,
        value_at: Some(ValueAt {
            piece: string.piece,
            at: string.at,
        }),
    }
}

/// The value of location key `key` that starts at `start` in `line` (which starts at
/// `offset` in the file), or `None` if its numbers cannot be read.
pub fn value(key: Key, line: &[u8], start: usize, offset: usize) -> Option<LoadedValue> {
    let at = |range: std::ops::Range<usize>| Span::new(offset + range.start, offset + range.end);
    Some(match key.value_kind() {
        ValueKind::Pose | ValueKind::Point => LoadedValue::Numbers(three_floats(line, start)?),
        ValueKind::Words => LoadedValue::Words(words(line, start).into_iter().map(at).collect()),
        // A text (and on 2026-03 the arm) is the rest of the line less its last byte.
        ValueKind::Text | ValueKind::Arm => {
            LoadedValue::Text(at(start..(line.len() - 1).max(start)))
        }
        ValueKind::Tour => unreachable!("the tour is not a location's value"),
    })
}

/// What a value of `key` that starts past the end of its line loads: no culturalKnowledge
/// word (the reader's loop runs while it is within the line, so not once), and for any
/// other key whatever its buffer held before, undefined.
pub fn past_the_line(key: Key) -> LoadedValue {
    match key.value_kind() {
        ValueKind::Words => LoadedValue::Words(Vec::new()),
        _ => LoadedValue::Undefined,
    }
}

/// Whether `a`, read from `a_line`, and `b`, read from `b_line` (each read at offset 0),
/// change what the robot holds in the same way: the same value of the same key of the same
/// location, or nothing at all (a skipped line and an ignored one alike).
pub fn same_load(a: &LineRead, a_line: &[u8], b: &LineRead, b_line: &[u8]) -> bool {
    use LineRead::{Failed, Ignored, Skipped, Tour, TourFailed, Value};
    let bytes_of = |span: &Span, line: &[u8]| line.get(span.range()).map(<[u8]>::to_vec);
    let same_value = |x: &LoadedValue, y: &LoadedValue| match (x, y) {
        (LoadedValue::Text(x), LoadedValue::Text(y)) => bytes_of(x, a_line) == bytes_of(y, b_line),
        (LoadedValue::Numbers(x), LoadedValue::Numbers(y)) => {
            x.map(f32::to_bits) == y.map(f32::to_bits)
        }
        (LoadedValue::Words(x), LoadedValue::Words(y)) => {
            x.len() == y.len()
                && x.iter()
                    .zip(y)
                    .all(|(x, y)| bytes_of(x, a_line) == bytes_of(y, b_line))
        }
        (LoadedValue::Undefined, LoadedValue::Undefined) => true,
        _ => false,
    };
    match (a, b) {
        (Skipped | Ignored { .. }, Skipped | Ignored { .. }) | (TourFailed, TourFailed) => true,
        (
            Value {
                key: a_key,
                id: a_id,
                value: a_value,
                ..
            },
            Value {
                key: b_key,
                id: b_id,
                value: b_value,
                ..
            },
        ) => a_key == b_key && a_id == b_id && same_value(a_value, b_value),
        (Failed { .. }, Failed { .. }) | (Tour { .. }, Tour { .. }) => a == b,
        _ => false,
    }
}

/// Whether what `read` does changes nothing the robot holds (a blank line, a comment, a key
/// the version ignores).
pub fn loads_nothing(read: &LineRead) -> bool {
    matches!(read, LineRead::Skipped | LineRead::Ignored { .. })
}

/// Where a location key's value starts in the buffer: past `strlen(key)` bytes, then past
/// non-alphanumerics, alphanumerics (the id) and non-alphanumerics again, on past the line's
/// end if need be.
fn value_start(buffer: &InBuffer<'_>, key_length: usize) -> Option<usize> {
    let after_key = buffer.skip(key_length, |b| !is_alnum(b))?;
    let after_id = buffer.skip(after_key, is_alnum)?;
    buffer.skip(after_id, |b| !is_alnum(b))
}

/// `sscanf("%f %f %f") == 3`, or nothing.
fn three_floats(line: &[u8], start: usize) -> Option<[f32; 3]> {
    let (x, at) = scan::float(line, start)?;
    let (y, at) = scan::float(line, at)?;
    let (z, _) = scan::float(line, at)?;
    Some([x, y, z])
}

/// The culturalKnowledge words: a `%s` word at each run of letters and digits, so that a
/// word with any other character in it counts twice or more (`Bow's`, then `s`).
fn words(line: &[u8], mut at: usize) -> Vec<std::ops::Range<usize>> {
    let mut words = Vec::new();
    while at < line.len() {
        let Some(word) = scan::word(line, at) else {
            break;
        };
        words.push(word);
        let Some(after_word) = scan::skip_while(line, at, is_alnum) else {
            break;
        };
        match scan::skip_while(line, after_word, |b| !is_alnum(b)) {
            Some(next) => at = next,
            None => break,
        }
    }
    words
}

/// What the reader loads from one culturalKnowledge word as written (`Deictic_Shape`): a
/// word at each run of letters and digits (`Deictic_Shape`, `Shape`).
pub fn word_pieces(word: &str) -> Vec<&str> {
    let Some(start) = word.bytes().position(is_alnum) else {
        return Vec::new();
    };
    words(word.as_bytes(), start)
        .into_iter()
        .map(|range| &word[range])
        .collect()
}

/// The tour's line: the count after the key, then one id after each run of letters and
/// digits, on past the line's end into what earlier lines left in the buffer; an id that
/// cannot be read leaves its slot, and every later one, as it was; where the reader runs
/// into bytes no line wrote, the slots it has room for are undefined.
fn tour(buffer: &InBuffer<'_>, key_length: usize) -> LineRead {
    // Within the line, read from it: a C string searched for its end at every id would
    // make a line of a million ids quadratic.
    let line = buffer.c_line();
    let number_at = |at: usize| match at < line.len() {
        true => scan::int(line, at).map(|(n, _)| n),
        false => scan::int(buffer.c_string(at)?.bytes, 0).map(|(n, _)| n),
    };
    let Some(at) = buffer.skip(key_length, |b| !is_alnum(b)) else {
        return LineRead::TourFailed;
    };
    let Some(count) = number_at(at) else {
        return LineRead::TourFailed;
    };
    let next = |at: usize| {
        buffer
            .skip(at, is_alnum)
            .and_then(|after| buffer.skip(after, |b| !is_alnum(b)))
    };
    let mut stops = Vec::new();
    let mut at = next(at);
    for _ in 0..count.max(0) {
        let Some(id) = at.map(|start| (start, number_at(start))) else {
            let room = usize::try_from(count).map_or(TOUR_BUFFER, |count| count.min(TOUR_BUFFER));
            stops.resize(stops.len().max(room), None);
            break;
        };
        let (start, Some(id)) = id else {
            break;
        };
        stops.push(Some(id));
        at = next(start);
    }
    LineRead::Tour { count, stops }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn read_str(line: &str, reader: Reader) -> LineRead {
        read(line.as_bytes(), 0, reader)
    }

    fn text(line: &str, reader: Reader) -> String {
        match read_str(line, reader) {
            LineRead::Value {
                value: LoadedValue::Text(span),
                ..
            } => line[span.range()].to_string(),
            other => panic!("{line:?}: {other:?}"),
        }
    }

    fn numbers(line: &str, reader: Reader) -> [f32; 3] {
        match read_str(line, reader) {
            LineRead::Value {
                value: LoadedValue::Numbers(numbers),
                ..
            } => numbers,
            other => panic!("{line:?}: {other:?}"),
        }
    }

    const NOW: Reader = Reader::V2025_06;

    #[test]
    fn leading_symbols_of_the_first_value_are_lost() {
        assert_eq!(
            numbers("robotLocationPose 1 -2.5 1.0 90\n", NOW),
            [2.5, 1.0, 90.0]
        );
        assert_eq!(
            numbers("robotLocationPose 1 2.5 -1.0 90\n", NOW),
            [2.5, -1.0, 90.0]
        );
        assert_eq!(
            numbers("robotLocationPose 1 +1.5 1 2\n", NOW),
            [1.5, 1.0, 2.0]
        );
        assert_eq!(
            text("preGestureMessageEnglish 1 \"Hello\"\n", NOW),
            "Hello\""
        );
        assert_eq!(text("robotLocationDescription 1 Ùmuntu\n", NOW), "muntu");
    }

    #[test]
    fn a_text_loses_its_last_byte_and_keeps_blanks_and_carriage_returns() {
        assert_eq!(text("postGestureMessageIsiZulu 5 Sawubona", NOW), "Sawubon");
        assert_eq!(
            text("postGestureMessageIsiZulu 5 Sawubona\r\n", NOW),
            "Sawubona\r"
        );
        assert_eq!(
            text("robotLocationDescription 1 Roomba  \n", NOW),
            "Roomba  "
        );
    }

    #[test]
    fn an_indented_line_is_read_from_the_wrong_place() {
        assert_eq!(
            numbers(" robotLocationPose 1 2.0 3.0 90\n", NOW),
            [1.0, 2.0, 3.0]
        );
        assert_eq!(text(" preGestureMessageEnglish 1 Hello\n", NOW), "1 Hello");
        assert_eq!(
            read_str(" tourSpecification 2 1 2\n", NOW),
            LineRead::TourFailed
        );
    }

    #[test]
    fn keys_that_a_version_does_not_read_are_ignored() {
        let line = "robotLocation 1 2.6 8.1 -90\n";
        assert!(matches!(read_str(line, NOW), LineRead::Ignored { .. }));
        assert_eq!(numbers(line, Reader::D542), [2.6, 8.1, -90.0]);
        let arm = "gestureArm 1 right \n";
        assert!(matches!(read_str(arm, NOW), LineRead::Ignored { .. }));
        assert_eq!(text(arm, Reader::V2026_03), "right ");
        assert!(matches!(
            read_str("culturalKnowledge 1 Bow\n", Reader::D542),
            LineRead::Ignored { .. }
        ));
        assert!(matches!(
            read_str("postGestureMessageenglish 1 Hi\n", NOW),
            LineRead::Ignored { .. }
        ));
    }

    #[test]
    fn lines_without_a_key_and_an_integer_are_skipped() {
        for line in [
            "\n",
            "  \x0c \n",
            "# a comment\n",
            "robotLocationDescription x\n",
        ] {
            assert_eq!(read_str(line, NOW), LineRead::Skipped, "{line:?}");
        }
    }

    #[test]
    fn cultural_words_split_at_other_characters() {
        let line = "culturalKnowledge 1 Deictic_Shape Bow's\n";
        let LineRead::Value {
            value: LoadedValue::Words(words),
            ..
        } = read_str(line, NOW)
        else {
            panic!()
        };
        let words: Vec<&str> = words.iter().map(|span| &line[span.range()]).collect();
        assert_eq!(words, ["Deictic_Shape", "Shape", "Bow's", "s"]);
        assert_eq!(word_pieces("Bow's"), ["Bow's", "s"]);
        assert_eq!(word_pieces("_x"), ["x"]);
        assert_eq!(word_pieces("Plain"), ["Plain"]);
    }

    #[test]
    fn the_tour_skips_commas_and_stops_at_what_it_cannot_read() {
        let stops = |line: &str| match read_str(line, NOW) {
            LineRead::Tour { count, stops } => (count, stops),
            other => panic!("{other:?}"),
        };
        assert_eq!(
            stops("tourSpecification 3 1, 4, 2\n"),
            (3, vec![Some(1), Some(4), Some(2)])
        );
        assert_eq!(
            stops("tourSpecification 3 1 4\n"),
            (3, vec![Some(1), Some(4), None])
        );
        assert_eq!(stops("tourSpecification 3 1 x 4\n"), (3, vec![Some(1)]));
        assert_eq!(stops("tourSpecification 2147483647\n").1, vec![None; 20]);
        assert_eq!(
            stops("tourSpecification 2 1 4 5\n"),
            (2, vec![Some(1), Some(4)])
        );
        assert_eq!(
            stops("tourSpecification 2 -1 4\n"),
            (2, vec![Some(1), Some(4)])
        );
    }

    #[test]
    fn a_value_that_runs_off_the_line_is_undefined_and_bad_numbers_fail() {
        assert!(matches!(
            read_str("robotLocationDescription 4\n", NOW),
            LineRead::Value {
                value: LoadedValue::Undefined,
                ..
            }
        ));
        // Measured with the real reader: culturalKnowledge alone loads no word.
        assert!(matches!(
            read_str("culturalKnowledge 4 \n", NOW),
            LineRead::Value {
                value: LoadedValue::Words(words),
                ..
            } if words.is_empty()
        ));
        assert_eq!(
            read_str("gestureTarget 4 8,1 2 3\n", NOW),
            LineRead::Failed {
                key: Key::GestureTarget,
                id: 4
            }
        );
    }
}
