//! JSON for the terminal and CI logs: pretty, with every character that could change what
//! a terminal shows or hide (what [`is_hidden`] flags) written as a `\uXXXX` escape, and the
//! `[` of `##[` too (a GitHub Actions runner obeys `##[` anywhere in a line). The JSON means
//! exactly the same; only its spelling is safe to print.

use std::io::{self, BufWriter, Write};

use serde::ser::{SerializeSeq, Serializer};
use serde::Serialize;
use serde_json::ser::{Formatter, PrettyFormatter};

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

/// The items of a large array, each made by `make` as it is written: a file of 100,000
/// locations is never held as JSON values all at once.
pub struct MadeAsWritten<'a, I, F> {
    items: &'a [I],
    make: F,
}

impl<'a, I, F> MadeAsWritten<'a, I, F> {
    pub fn new(items: &'a [I], make: F) -> MadeAsWritten<'a, I, F> {
        MadeAsWritten { items, make }
    }
}

impl<I, F: Fn(&I) -> T, T: Serialize> Serialize for MadeAsWritten<'_, I, F> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let mut seq = serializer.serialize_seq(Some(self.items.len()))?;
        for item in self.items {
            seq.serialize_element(&(self.make)(item))?;
        }
        seq.end()
    }
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
    fn items_made_as_written_are_written_as_items_made_first() {
        #[derive(Serialize)]
        struct Top<L> {
            name: &'static str,
            items: L,
            after: [u8; 2],
        }
        let numbers: Vec<u32> = (0..100).collect();
        let item =
            |&n: &u32| serde_json::json!({ "n": n, "text": "a\u{202E}##[b", "list": [n, [n]] });
        for count in [0, 1, 2, numbers.len()] {
            let numbers = &numbers[..count];
            let whole: Vec<_> = numbers.iter().map(item).collect();
            let made = MadeAsWritten::new(numbers, item);
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
                    items: made,
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
