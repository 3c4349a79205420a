//! Finding where blanks start and end, eight bytes at a time.
//!
//! Lexing is most of the work of a check, and a line is long runs: a key, the padding that
//! aligns the values (a dozen blanks), words. A byte loop spends a compare and a branch on
//! each byte; testing a word of eight bytes at once (SWAR) takes a few operations for all.

use super::is_blank;

const LOW_BITS: u64 = 0x7f7f_7f7f_7f7f_7f7f;
const HIGH_BITS: u64 = 0x8080_8080_8080_8080;
const SPACES: u64 = u64::from_ne_bytes([b' '; 8]);
const TABS: u64 = u64::from_ne_bytes([b'\t'; 8]);

/// The high bit of each byte of `x` that is zero (exactly: no carry crosses bytes).
fn zero_bytes(x: u64) -> u64 {
    !(((x & LOW_BITS) + LOW_BITS) | x) & HIGH_BITS
}

/// The high bit of each byte of `word` that is a blank.
fn blank_bytes(word: u64) -> u64 {
    zero_bytes(word ^ SPACES) | zero_bytes(word ^ TABS)
}

/// The first index in `from..to` whose byte is (`blank`) or is not (`!blank`) a blank, or
/// `to`.
fn find(bytes: &[u8], mut from: usize, to: usize, blank: bool) -> usize {
    while let Some(chunk) = bytes[from..to].first_chunk::<8>() {
        // Little-endian, so that the first byte in the text is the lowest in the word.
        let blanks = blank_bytes(u64::from_le_bytes(*chunk));
        let wanted = if blank { blanks } else { !blanks & HIGH_BITS };
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
