//! Finding where blanks start and end: eight bytes at a time ([`super::swar`]), or the
//! first gap of a line's body from one mask of 32 bytes ([`super::masks`]).
//!
//! Lexing is most of the work of a check, and a line is long runs: a key, the padding that
//! aligns the values (a dozen blanks), words.

use super::swar::{blank_bytes, non_blank_bytes};
use super::{is_blank, masks};

/// The first index in `from..to` whose byte is (`blank`) or is not (`!blank`) a blank, or
/// `to`.
#[inline]
fn find(bytes: &[u8], mut from: usize, to: usize, blank: bool) -> usize {
    while let Some(chunk) = bytes[from..to].first_chunk::<8>() {
        let word = u64::from_le_bytes(*chunk);
        let wanted = if blank {
            blank_bytes(word)
        } else {
            non_blank_bytes(word)
        };
        if wanted != 0 {
            return from + (wanted.trailing_zeros() / 8) as usize;
        }
        from += 8;
    }
    while from < to && is_blank(bytes[from]) != blank {
        from += 1;
    }
    from
}

/// Where the first run of blanks in `bytes[from..to]` starts and ends (both `to` if it has
/// none): for a line's body, where its key ends and its arguments start. Nearly always
/// from one mask of the 32 bytes from `from` ([`masks`]), read past `to`.
#[inline(always)]
pub fn first_gap(bytes: &[u8], from: usize, to: usize) -> (usize, usize) {
    if let Some(chunk) = bytes[from..].first_chunk::<32>() {
        let (low, high) = chunk.split_at(16);
        let half = |half: &[u8]| masks::blanks(half.try_into().expect("sixteen bytes"));
        // Bit `i` for byte `from + i`; the gap is bits `start..end`.
        let blanks = half(low) | half(high) << 16;
        let start = blanks.trailing_zeros();
        let end = start + (!blanks.checked_shr(start).unwrap_or(0)).trailing_zeros();
        // Unless the gap goes past `to`, or may go on past the 32 bytes (or there is none).
        if end < 32 && from + end as usize <= to {
            return (from + start as usize, from + end as usize);
        }
    }
    let start = next_blank(bytes, from, to);
    (start, next_non_blank(bytes, start, to))
}

/// The index of the first blank in `bytes[from..to]`, or `to`.
pub fn next_blank(bytes: &[u8], from: usize, to: usize) -> usize {
    find(bytes, from, to, true)
}

/// The index of the first byte that is not a blank in `bytes[from..to]`, or `to`.
pub fn next_non_blank(bytes: &[u8], from: usize, to: usize) -> usize {
    find(bytes, from, to, false)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_first_gap_is_where_the_two_searches_find_it() {
        let texts = [
            "robotLocationDescription      1 a b\n".to_string(),
            "gestureTarget\t\t 1 0 0 0\ngestureArm 1 left\n".to_string(),
            format!("{}  x", "k".repeat(31)),
            format!("{}  x", "k".repeat(29)),
            format!("k{}x", " ".repeat(30)),
            format!("k{}x", " ".repeat(31)),
            "é \té\u{0} \u{a0} x".repeat(4),
            " ".repeat(40),
            "key".to_string(),
        ];
        for text in &texts {
            let bytes = text.as_bytes();
            for from in 0..=bytes.len() {
                for to in from..=bytes.len() {
                    let key_end = next_blank(bytes, from, to);
                    let expected = (key_end, next_non_blank(bytes, key_end, to));
                    assert_eq!(
                        first_gap(bytes, from, to),
                        expected,
                        "{from}..{to} of {text:?}"
                    );
                }
            }
        }
    }

    #[test]
    fn agrees_with_a_byte_loop_everywhere() {
        let text = b"key\t  \t value  with\tblanks \xc3\xa9\x00\x80\xff  \t\t end".repeat(3);
        for from in 0..text.len() {
            for to in from..=text.len() {
                let slow = |blank: bool| {
                    (from..to)
                        .find(|&i| is_blank(text[i]) == blank)
                        .unwrap_or(to)
                };
                assert_eq!(next_blank(&text, from, to), slow(true), "{from}..{to}");
                assert_eq!(next_non_blank(&text, from, to), slow(false), "{from}..{to}");
            }
        }
    }
}
