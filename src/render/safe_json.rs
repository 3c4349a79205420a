//! JSON for the terminal and CI logs: pretty, with every character that could change what
//! a terminal shows or hide (what [`is_hidden`] flags) written as a `\uXXXX` escape, and the
//! `[` of `##[` too (a GitHub Actions runner obeys `##[` anywhere in a line). The JSON means
//! exactly the same; only its spelling is safe to print.

use std::io::{self, BufWriter, Write};

use serde::ser::{Error as _, SerializeSeq, Serializer};
use serde::Serialize;
use serde_json::ser::{Formatter, PrettyFormatter};
use serde_json::value::RawValue;

use crate::parallel;
use crate::render::escape::{ends_with_ci_marker, is_hidden};

/// Writes `value` as pretty JSON and a newline.
pub fn write<T: Serialize + ?Sized>(value: &T, out: &mut dyn Write) -> io::Result<()> {
    // The serializer writes a few bytes at a time: through a buffer, not a call (and, to a
    // line-buffered standard output, a system call per line) each.
    let mut out = BufWriter::with_capacity(1 << 16, out);
    let mut serializer =
        serde_json::Serializer::with_formatter(&mut out, SafeFormatter(PrettyFormatter::new()));
    value.serialize(&mut serializer).map_err(io::Error::from)?;
    writeln!(out)?;
    out.flush()
}

/// The items of a large array, each made by `make` and written as JSON on every core, then
/// written in order: writing 100,000 locations on one core took longer than checking them.
/// They are made a batch at a time, so that only a batch is ever held.
///
/// Each item is written as [`write`] writes the items of an array that is the value of a
/// field of the top-level object (two levels deep): that is where to put it.
pub struct InParts<'a, I, F, W = fn(&I) -> usize> {
    items: &'a [I],
    make: F,
    /// How much each item's JSON weighs: 1 for an item of an ordinary size (up to a few
    /// kilobytes), more for a larger one. One that weighs more than a batch is written as
    /// it is made, on one core.
    weight: W,
}

/// At most how much the items made before they are written weigh (see [`InParts`]).
const BATCH: usize = 4096;

/// Below this many items of a batch, a part is not worth a thread.
const MIN_ITEMS_PER_PART: usize = 512;

impl<'a, I, F> InParts<'a, I, F> {
    /// Items of an ordinary size each.
    pub fn new(items: &'a [I], make: F) -> InParts<'a, I, F> {
        InParts {
            items,
            make,
            weight: |_| 1,
        }
    }

    /// Items that weigh as `weight` says: fewer of the heavy ones are made at a time.
    pub fn weighed<W: Fn(&I) -> usize>(self, weight: W) -> InParts<'a, I, F, W> {
        InParts {
            items: self.items,
            make: self.make,
            weight,
        }
    }
}

impl<'a, I, F, W: Fn(&I) -> usize> InParts<'a, I, F, W> {
    /// The items in batches that weigh about the same (none too small to share between the
    /// cores), each at most [`BATCH`] or a single item.
    fn batches(&self) -> Vec<&'a [I]> {
        let weight = &self.weight;
        let total: usize = self.items.iter().map(weight).sum();
        let batches = total.div_ceil(BATCH).max(1);
        let most = total.div_ceil(batches).max(1);
        let (mut cut, mut start, mut so_far) = (Vec::with_capacity(batches), 0, 0);
        for (at, item) in self.items.iter().enumerate() {
            let item_weight = weight(item);
            if so_far > 0 && so_far + item_weight > most {
                cut.push(&self.items[start..at]);
                (start, so_far) = (at, 0);
            }
            so_far += item_weight;
        }
        if start < self.items.len() {
            cut.push(&self.items[start..]);
        }
        cut
    }
}

impl<I: Sync, F: Fn(&I) -> T + Sync, T: Serialize, W: Fn(&I) -> usize> Serialize
    for InParts<'_, I, F, W>
{
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let mut seq = serializer.serialize_seq(Some(self.items.len()))?;
        let make = &self.make;
        for batch in self.batches() {
            // An item heavier than a batch is written as it is made, not held.
            if let [item] = batch {
                if (self.weight)(item) > BATCH {
                    seq.serialize_element(&make(item))?;
                    continue;
                }
            }
            let ranges = parallel::item_ranges(batch.len(), MIN_ITEMS_PER_PART);
            let parts = parallel::map_ranges(ranges, |range| {
                let items = batch[range].iter();
                items
                    .map(|item| item_json(&make(item)))
                    .collect::<serde_json::Result<Vec<_>>>()
            });
            for part in parts {
                for json in part.map_err(S::Error::custom)? {
                    seq.serialize_element(&json)?;
                }
            }
        }
        seq.end()
    }
}

/// `value` written as [`write`] writes an item two levels deep (see [`InParts`]).
fn item_json(value: &impl Serialize) -> serde_json::Result<Box<RawValue>> {
    let mut formatter = PrettyFormatter::new();
    let mut nowhere = io::sink();
    formatter
        .begin_object(&mut nowhere)
        .and_then(|()| formatter.begin_array(&mut nowhere))
        .map_err(serde_json::Error::io)?;
    let mut json = Vec::with_capacity(1024);
    let mut serializer =
        serde_json::Serializer::with_formatter(&mut json, SafeFormatter(formatter));
    value.serialize(&mut serializer)?;
    let json = String::from_utf8(json).expect("serde_json writes UTF-8");
    // SAFETY: serde_json wrote one value, which starts and ends with no blank.
    Ok(unsafe { RawValue::from_string_unchecked(json) })
}

/// [`PrettyFormatter`] that also escapes what [`is_hidden`] flags (serde_json escapes only
/// C0 controls: DEL, C1 controls, bidirectional overrides and Unicode spaces would pass
/// through raw), and a `[` that would make a CI command. serde_json cuts a string into
/// fragments only at what it escapes itself, so `##[` is never cut.
struct SafeFormatter<'a>(PrettyFormatter<'a>);

impl Formatter for SafeFormatter<'_> {
    fn write_string_fragment<W: ?Sized + Write>(
        &mut self,
        writer: &mut W,
        fragment: &str,
    ) -> io::Result<()> {
        // Nearly all text is printable ASCII without a `#`: checking bytes (without stopping
        // early, so that the check is vectorised) spares decoding characters, and looking for
        // `##[` (a searcher made for each of a million strings cost more than the writing).
        let bytes = fragment.as_bytes();
        let plain = |ok, &b: &u8| ok & matches!(b, b' '..=b'~') & (b != b'#');
        if bytes.iter().fold(true, plain) {
            return writer.write_all(bytes);
        }
        let mut written = 0;
        for (at, ch) in fragment.char_indices() {
            let escaped = is_hidden(ch) || (ch == '[' && ends_with_ci_marker(&fragment[..at]));
            if !escaped {
                continue;
            }
            writer.write_all(&bytes[written..at])?;
            let mut units = [0u16; 2];
            for unit in ch.encode_utf16(&mut units) {
                write!(writer, "\\u{unit:04x}")?;
            }
            written = at + ch.len_utf8();
        }
        writer.write_all(&bytes[written..])
    }

    fn begin_array<W: ?Sized + Write>(&mut self, writer: &mut W) -> io::Result<()> {
        self.0.begin_array(writer)
    }

    fn end_array<W: ?Sized + Write>(&mut self, writer: &mut W) -> io::Result<()> {
        self.0.end_array(writer)
    }

    fn begin_array_value<W: ?Sized + Write>(
        &mut self,
        writer: &mut W,
        first: bool,
    ) -> io::Result<()> {
        self.0.begin_array_value(writer, first)
    }

    fn end_array_value<W: ?Sized + Write>(&mut self, writer: &mut W) -> io::Result<()> {
        self.0.end_array_value(writer)
    }

    fn begin_object<W: ?Sized + Write>(&mut self, writer: &mut W) -> io::Result<()> {
        self.0.begin_object(writer)
    }

    fn end_object<W: ?Sized + Write>(&mut self, writer: &mut W) -> io::Result<()> {
        self.0.end_object(writer)
    }

    fn begin_object_key<W: ?Sized + Write>(
        &mut self,
        writer: &mut W,
        first: bool,
    ) -> io::Result<()> {
        self.0.begin_object_key(writer, first)
    }

    fn begin_object_value<W: ?Sized + Write>(&mut self, writer: &mut W) -> io::Result<()> {
        self.0.begin_object_value(writer)
    }

    fn end_object_value<W: ?Sized + Write>(&mut self, writer: &mut W) -> io::Result<()> {
        self.0.end_object_value(writer)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn unsafe_characters_are_escaped_and_the_json_is_unchanged() {
        let value = serde_json::json!({ "text": "a\u{1b}[31m\u{202E}b\u{85}é\u{a0}##[x]" });
        let mut out = Vec::new();
        write(&value, &mut out).unwrap();
        let printed = String::from_utf8(out).unwrap();
        assert_eq!(
            printed,
            "{\n  \"text\": \"a\\u001b[31m\\u202eb\\u0085é\\u00a0##\\u005bx]\"\n}\n"
        );
        let back: serde_json::Value = serde_json::from_str(&printed).unwrap();
        assert_eq!(back, value);
    }

    #[test]
    fn items_in_parts_are_written_as_items_made_whole() {
        #[derive(Serialize)]
        struct Top<L> {
            name: &'static str,
            items: L,
            after: [u8; 2],
        }
        fn written(items: impl Serialize) -> Vec<u8> {
            let top = Top {
                name: "x",
                items,
                after: [1, 2],
            };
            let mut written = Vec::new();
            write(&top, &mut written).unwrap();
            written
        }
        let numbers: Vec<u32> = (0..3 * BATCH as u32 + 7).collect();
        let item =
            |&n: &u32| serde_json::json!({ "n": n, "text": "a\u{202E}##[b", "list": [n, [n]] });
        for count in [0, 1, 2, MIN_ITEMS_PER_PART * 2 + 1, numbers.len()] {
            let numbers = &numbers[..count];
            let whole: Vec<_> = numbers.iter().map(item).collect();
            let expected = written(whole);
            let in_parts = InParts::new(numbers, item);
            assert!(written(in_parts) == expected, "{count} items");
            let heavy = |&n: &u32| if n % 100 == 0 { 2 * BATCH } else { 1 };
            let weighed = InParts::new(numbers, item).weighed(heavy);
            assert!(written(weighed) == expected, "{count} items, weighed");
        }
    }

    #[test]
    fn batches_weigh_about_the_same_and_a_heavy_item_is_made_alone() {
        let items: Vec<usize> = (0..=BATCH).collect();
        let lengths = |batches: Vec<&[usize]>| batches.iter().map(|b| b.len()).collect::<Vec<_>>();
        // Items of an ordinary size: batches of the same size, none too small to share.
        let ordinary = InParts::new(&items, |_: &usize| ());
        assert_eq!(lengths(ordinary.batches()), [BATCH / 2 + 1, BATCH / 2]);
        let heavy = |&item: &usize| if item % 1000 == 0 { 10 * BATCH } else { 1 };
        let batches = InParts::new(&items, |_: &usize| ())
            .weighed(heavy)
            .batches();
        assert_eq!(batches.concat(), items);
        for batch in batches {
            let weight: usize = batch.iter().map(heavy).sum();
            assert!(batch.len() == 1 || weight <= BATCH, "{batch:?}");
        }
    }

    #[test]
    fn a_ci_marker_in_plain_ascii_is_escaped_too() {
        let mut out = Vec::new();
        write(&serde_json::json!(["#1 ok", "see ##[warning]"]), &mut out).unwrap();
        let printed = String::from_utf8(out).unwrap();
        assert_eq!(printed, "[\n  \"#1 ok\",\n  \"see ##\\u005bwarning]\"\n]\n");
    }
}
