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
pub struct InParts<'a, I, F> {
    items: &'a [I],
    make: F,
}

/// At most how many items are made before they are written.
const BATCH: usize = 4096;

/// Below this many items of a batch, a part is not worth a thread.
const MIN_ITEMS_PER_PART: usize = 512;

impl<'a, I, F> InParts<'a, I, F> {
    pub fn new(items: &'a [I], make: F) -> InParts<'a, I, F> {
        InParts { items, make }
    }
}

impl<I: Sync, F: Fn(&I) -> T + Sync, T: Serialize> Serialize for InParts<'_, I, F> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let mut seq = serializer.serialize_seq(Some(self.items.len()))?;
        // Batches of equal size, so that none is too small to share between the cores.
        let batches = self.items.len().div_ceil(BATCH);
        let size = self.items.len().div_ceil(batches.max(1)).max(1);
        for batch in self.items.chunks(size) {
            let ranges = parallel::item_ranges(batch.len(), MIN_ITEMS_PER_PART);
            let parts = parallel::map_ranges(ranges, |range| {
                let items = batch[range].iter();
                items
                    .map(|item| item_json(&(self.make)(item)))
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
        let numbers: Vec<u32> = (0..3 * BATCH as u32 + 7).collect();
        let item =
            |&n: &u32| serde_json::json!({ "n": n, "text": "a\u{202E}##[b", "list": [n, [n]] });
        for count in [0, 1, 2, MIN_ITEMS_PER_PART * 2 + 1, numbers.len()] {
            let numbers = &numbers[..count];
            let whole: Vec<_> = numbers.iter().map(item).collect();
            let in_parts = InParts::new(numbers, item);
            let (mut expected, mut written) = (Vec::new(), Vec::new());
            write(
                &Top {
                    name: "x",
                    items: whole,
                    after: [1, 2],
                },
                &mut expected,
            )
            .unwrap();
            write(
                &Top {
                    name: "x",
                    items: in_parts,
                    after: [1, 2],
                },
                &mut written,
            )
            .unwrap();
            assert!(written == expected, "{count} items");
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
