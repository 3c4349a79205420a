//! Finding where blanks start and end, eight bytes at a time ([`super::swar`]).
//!
//! Lexing is most of the work of a check, and a line is long runs: a key, the padding that
//! aligns the values (a dozen blanks), words.

use super::is_blank;
use super::swar::{blank_bytes, non_blank_bytes};

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
