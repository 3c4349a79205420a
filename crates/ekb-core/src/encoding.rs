//! Recognises text in UTF-16 or UTF-32, which ekb refuses to read.
//!
//! Such a file is not UTF-8, yet text of ASCII letters in it is valid UTF-8 byte by byte
//! (`r\0o\0b\0…`): read as UTF-8 it would be a file of NULs, and `ekb fix` would "fix" it
//! into a broken file. A byte-order mark names the encoding; without one, ASCII text has a
//! NUL in the same places of nearly every code unit, which a UTF-8 file has not.

use std::fmt;

/// How many bytes at the start of a file are looked at for the pattern of NULs.
const SAMPLE: usize = 4096;

/// A wide Unicode encoding, with its byte order.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum WideEncoding {
    Utf16Le,
    Utf16Be,
    Utf32Le,
    Utf32Be,
}

impl WideEncoding {
    /// The name `iconv` knows it by.
    pub fn name(self) -> &'static str {
        match self {
            WideEncoding::Utf16Le => "UTF-16LE",
            WideEncoding::Utf16Be => "UTF-16BE",
            WideEncoding::Utf32Le => "UTF-32LE",
            WideEncoding::Utf32Be => "UTF-32BE",
        }
    }

    /// Its byte-order mark. The UTF-32LE mark begins with the UTF-16LE one, so marks are
    /// tried in the order of [`WideEncoding::ALL`], the longer first.
    fn mark(self) -> &'static [u8] {
        match self {
            WideEncoding::Utf16Le => &[0xFF, 0xFE],
            WideEncoding::Utf16Be => &[0xFE, 0xFF],
            WideEncoding::Utf32Le => &[0xFF, 0xFE, 0, 0],
            WideEncoding::Utf32Be => &[0, 0, 0xFE, 0xFF],
        }
    }

    /// The bytes of a code unit that are NUL when it holds an ASCII character.
    fn nul_bytes_of_ascii(self) -> &'static [usize] {
        match self {
            WideEncoding::Utf16Le => &[1],
            WideEncoding::Utf16Be => &[0],
            WideEncoding::Utf32Le => &[1, 2, 3],
            WideEncoding::Utf32Be => &[0, 1, 2],
        }
    }

    fn unit(self) -> usize {
        match self {
            WideEncoding::Utf16Le | WideEncoding::Utf16Be => 2,
            WideEncoding::Utf32Le | WideEncoding::Utf32Be => 4,
        }
    }

    /// UTF-32 first: its units of ASCII look like UTF-16 units half of the time.
    const ALL: [WideEncoding; 4] = [
        WideEncoding::Utf32Le,
        WideEncoding::Utf32Be,
        WideEncoding::Utf16Le,
        WideEncoding::Utf16Be,
    ];
}

/// A wide encoding found at the start of a file, and how.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Detected {
    pub encoding: WideEncoding,
    /// Whether a byte-order mark said so (otherwise, the pattern of NULs).
    pub marked: bool,
}

impl fmt::Display for Detected {
    /// `it is UTF-16LE text (it starts with that encoding's byte-order mark), and ekb reads
    /// UTF-8 only: convert it first, e.g. `iconv -f UTF-16LE -t UTF-8 FILE > NEW``
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let name = self.encoding.name();
        let how = if self.marked {
            "it starts with that encoding's byte-order mark"
        } else {
            "no byte-order mark, but NUL bytes between its letters from line 1, column 1"
        };
        write!(
            f,
            "it is {name} text ({how}), and ekb reads UTF-8 only (as the robot does): convert \
             it first, e.g. `iconv -f {name} -t UTF-8 FILE > NEW`"
        )
    }
}

/// The wide encoding `bytes` (the start of a file, or all of it) are in, if any.
pub fn detect(bytes: &[u8]) -> Option<Detected> {
    if let Some(encoding) = WideEncoding::ALL
        .into_iter()
        .find(|encoding| bytes.starts_with(encoding.mark()))
    {
        return Some(Detected {
            encoding,
            marked: true,
        });
    }
    let sample = &bytes[..bytes.len().min(SAMPLE)];
    WideEncoding::ALL
        .into_iter()
        .find(|&encoding| mostly_ascii_in(sample, encoding))
        .map(|encoding| Detected {
            encoding,
            marked: false,
        })
}

/// Whether the first code unit of `sample` and at least half of all of them are ASCII
/// characters in `encoding`: NUL where the encoding puts its high bytes, and not NUL in the
/// other place.
fn mostly_ascii_in(sample: &[u8], encoding: WideEncoding) -> bool {
    let nul = encoding.nul_bytes_of_ascii();
    let is_ascii_unit =
        |unit: &[u8]| (0..unit.len()).all(|at| (unit[at] == 0) == nul.contains(&at));
    let units = sample.chunks_exact(encoding.unit());
    let total = units.len();
    let ascii = units.clone().filter(|unit| is_ascii_unit(unit)).count();
    total > 0 && sample.get(..encoding.unit()).is_some_and(is_ascii_unit) && ascii * 2 >= total
}

#[cfg(test)]
mod tests {
    use super::*;

    fn encode_utf16(text: &str, big_endian: bool) -> Vec<u8> {
        text.encode_utf16()
            .flat_map(|unit| {
                if big_endian {
                    unit.to_be_bytes()
                } else {
                    unit.to_le_bytes()
                }
            })
            .collect()
    }

    fn encode_utf32(text: &str, big_endian: bool) -> Vec<u8> {
        text.chars()
            .flat_map(|ch| {
                if big_endian {
                    (ch as u32).to_be_bytes()
                } else {
                    (ch as u32).to_le_bytes()
                }
            })
            .collect()
    }

    const LINE: &str = "robotLocationDescription 1 Ùmuntu\n";

    #[test]
    fn every_wide_encoding_is_found_with_or_without_a_mark() {
        let cases = [
            (WideEncoding::Utf16Le, encode_utf16(LINE, false)),
            (WideEncoding::Utf16Be, encode_utf16(LINE, true)),
            (WideEncoding::Utf32Le, encode_utf32(LINE, false)),
            (WideEncoding::Utf32Be, encode_utf32(LINE, true)),
        ];
        for (encoding, bytes) in cases {
            let found = detect(&bytes);
            assert_eq!(
                found,
                Some(Detected {
                    encoding,
                    marked: false
                })
            );
            let marked = [encoding.mark(), &bytes].concat();
            assert_eq!(
                detect(&marked),
                Some(Detected {
                    encoding,
                    marked: true
                })
            );
        }
    }

    #[test]
    fn utf8_with_a_few_nuls_is_not_wide() {
        assert_eq!(detect(LINE.as_bytes()), None);
        assert_eq!(detect(b"robotLocationDescription 1 a\0b\n"), None);
        assert_eq!(detect(&[0; 64]), None);
        assert_eq!(detect(b""), None);
        // A UTF-8 byte-order mark is UTF-8 (compat-bom reports it).
        assert_eq!(detect("\u{feff}robotLocation".as_bytes()), None);
    }

    #[test]
    fn the_message_says_how_to_convert() {
        let found = detect(&[0xFF, 0xFE, b'r', 0]).unwrap();
        assert_eq!(
            found.to_string(),
            "it is UTF-16LE text (it starts with that encoding's byte-order mark), and ekb reads \
             UTF-8 only (as the robot does): convert it first, e.g. `iconv -f UTF-16LE -t UTF-8 \
             FILE > NEW`"
        );
    }
}
