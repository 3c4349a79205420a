//! What a message's text holds that the translation rules look for, found in one pass over
//! its bytes, sixteen at a time.
//!
//! The rules run on every message of every location: a pass of each over the bytes (or a
//! loop over them, a byte at a time) was a third of a whole check (measured). One pass
//! makes masks of the bytes' classes (letters, blanks, non-ASCII, the rest); most rules then
//! need nothing more, and the rest run only where the masks say they can find something.

use crate::syntax::{masks, swar};

/// `,` `.` `;` `:` `!` `?`
const PUNCTUATION: &[u8] = b",.;:!?";
/// Brackets and the straight double quote (non-ASCII bytes count too: see [`Scan`]).
const DELIMITERS: &[u8] = b"()[]{}\"";

/// What a message's text holds.
#[derive(Debug, Default, PartialEq)]
pub struct Scan {
    /// Two blanks (spaces or tabs) in a row.
    pub blanks_in_a_row: bool,
    /// One of `,` `.` `;` `:` `!` `?`.
    pub punctuation: bool,
    /// A bracket, a straight double quote, or a byte of a non-ASCII character (which may be
    /// a curly quote or a guillemet).
    pub delimiters: bool,
    /// Every byte is ASCII.
    pub ascii: bool,
    /// How many words: runs of ASCII letters and non-ASCII characters (split at ASCII
    /// bytes only, as every word `is_word` looks for is ASCII).
    pub words: usize,
    /// How many of the words `is_word` holds for.
    pub words_found: usize,
}

/// The classes of up to 64 bytes: bit `i` for byte `i`.
struct Masks {
    blanks: u64,
    non_ascii: u64,
    /// ASCII letters and non-ASCII bytes.
    in_words: u64,
    /// The bytes of none of the classes above: punctuation, digits, symbols.
    others: u64,
}

impl Masks {
    /// The masks of `block`, at most 64 bytes.
    fn of(block: &[u8]) -> Masks {
        let (mut blanks, mut non_ascii, mut letters) = (0, 0, 0);
        let mut add = |chunk: &[u8; 16], shift: usize, seen: usize| {
            blanks |= u64::from(masks::blanks(chunk) >> seen) << shift;
            non_ascii |= u64::from(masks::non_ascii(chunk) >> seen) << shift;
            letters |= u64::from(masks::letters(chunk) >> seen) << shift;
        };
        let mut at = 0;
        while let Some(chunk) = block[at..].first_chunk::<16>() {
            add(chunk, at, 0);
            at += 16;
        }
        if at < block.len() {
            match block.last_chunk::<16>() {
                // The last sixteen bytes, of which the first were in the chunks above.
                Some(last) => add(last, at, 16 - (block.len() - at)),
                None => {
                    let mut padded = [0; 16];
                    padded[..block.len()].copy_from_slice(block);
                    add(&padded, 0, 0);
                }
            }
        }
        let all = u64::MAX >> (64 - block.len());
        let in_words = letters | non_ascii;
        Masks {
            blanks,
            non_ascii,
            in_words,
            // A padding byte (0) is no letter, blank or non-ASCII byte: cut it off.
            others: !(in_words | blanks) & all,
        }
    }
}

/// Whether `byte` belongs to a word: an ASCII letter, or a byte of a non-ASCII character.
fn in_word(byte: u8) -> bool {
    byte.is_ascii_alphabetic() || !byte.is_ascii()
}

impl Scan {
    /// Scans `text`, counting the words of `lengths` bytes (at most 8; an empty range counts
    /// none) for which `is_word` holds. `is_word` is given each word lowercased, as one
    /// number: its first eight bytes, little-endian, each with bit `0x20` set (which
    /// lowercases a letter and leaves a non-ASCII byte non-ASCII), then zeros. It is asked of
    /// words of other lengths too (its answer then unused), so it must be cheap and never
    /// panic.
    pub fn of(
        text: &str,
        lengths: std::ops::RangeInclusive<usize>,
        is_word: impl Fn(u64) -> bool,
    ) -> Scan {
        assert!(*lengths.end() <= 8, "a word of up to 8 bytes is one number");
        let bytes = text.as_bytes();
        let mut scan = Scan {
            ascii: true,
            ..Scan::default()
        };
        // Whether the byte before the block is a blank, and in a word.
        let (mut after_blank, mut after_word) = (0, 0);
        for (number, block) in bytes.chunks(64).enumerate() {
            let masks = Masks::of(block);
            scan.blanks_in_a_row |= masks.blanks & (masks.blanks << 1 | after_blank) != 0;
            scan.ascii &= masks.non_ascii == 0;
            scan.delimiters |= masks.non_ascii != 0;
            let mut others = masks.others;
            while others != 0 {
                let byte = block[others.trailing_zeros() as usize];
                others &= others - 1;
                scan.punctuation |= PUNCTUATION.contains(&byte);
                scan.delimiters |= DELIMITERS.contains(&byte);
            }
            let in_words = masks.in_words;
            let starts = in_words & !(in_words << 1 | after_word);
            scan.words += starts.count_ones() as usize;
            if !lengths.is_empty() {
                // The last byte of each word (bit 63: the word may go on past the block),
                // but for the word that went on from the block before: it was counted there.
                let mut ends = in_words & !(in_words >> 1);
                if after_word & in_words != 0 {
                    ends &= ends - 1;
                }
                let words = Words {
                    bytes,
                    block_start: 64 * number,
                    starts,
                    ends,
                };
                scan.words_found += words.count(&lengths, &is_word);
            }
            after_blank = masks.blanks >> 63;
            after_word = in_words >> 63;
        }
        scan
    }
}

/// The words that start in one block of up to 64 bytes.
struct Words<'t> {
    bytes: &'t [u8],
    block_start: usize,
    /// Bit `i` for the first byte of a word.
    starts: u64,
    /// Bit `i` for the last byte of a word, in the same order.
    ends: u64,
}

impl Words<'_> {
    /// How many of the words of `lengths` bytes `is_word` holds for.
    ///
    /// Every word is packed and asked about, and the answer counted only if its length is
    /// in `lengths`: no branch on the length or the answer, which vary from word to word and
    /// were mispredicted (measured: this loop was the check's most costly in cycles).
    #[inline(always)]
    fn count(
        mut self,
        lengths: &std::ops::RangeInclusive<usize>,
        is_word: &impl Fn(u64) -> bool,
    ) -> usize {
        let mut found = 0;
        while self.starts != 0 {
            let start = self.starts.trailing_zeros() as usize;
            let end = self.ends.trailing_zeros() as usize + 1;
            self.starts &= self.starts - 1;
            self.ends &= self.ends - 1;
            let from = self.block_start + start;
            let mut to = self.block_start + end;
            if end == 64 {
                // The word reaches the end of the block: it may go on past it.
                to += self.bytes[to..]
                    .iter()
                    .take(lengths.end() + 1)
                    .take_while(|&&byte| in_word(byte))
                    .count();
            }
            let length = to - from;
            // Every byte of a word is a letter or non-ASCII: setting `0x20` lowercases it.
            let lower = swar::word_at(self.bytes, from) | u64::from_le_bytes([0x20; 8]);
            let packed = lower & u64::MAX >> (8 * (8 - length.min(8)));
            found += usize::from(lengths.contains(&length) & is_word(packed));
        }
        found
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scan(text: &str) -> Scan {
        Scan::of(text, 2..=3, |word| {
            word == u64::from_le_bytes(*b"the\0\0\0\0\0")
        })
    }

    #[test]
    fn one_pass_sees_what_each_rule_looks_for() {
        let plain = scan("Murakaza neza muri laboratwari");
        assert!(!plain.blanks_in_a_row && !plain.punctuation && !plain.delimiters);
        assert!(plain.ascii);
        assert!(scan("a \t b").blanks_in_a_row);
        assert!(!scan("a b c").blanks_in_a_row);
        assert!(scan("gato , nizereko").punctuation);
        assert!(scan("n'urugendo (robo)").delimiters);
        assert!(scan("“Pepper").delimiters);
        assert!(!scan("“Pepper").ascii);
    }

    #[test]
    fn counts_words_as_a_byte_loop_would() {
        // Words across the 64-byte blocks, blanks in a row across them, words of every
        // length around the block's end.
        let texts = [
            "This is the Pepper humanoid robot".to_string(),
            "The the, THE théâtre 3the the9 x".to_string(),
            format!("{}the the", "a".repeat(61)),
            format!("{} the", "b".repeat(62)),
            format!("{}  x", "c".repeat(63)),
            format!("{} the{}", "ab ".repeat(40), "é".repeat(40)),
        ];
        for text in &texts {
            for cut in 0..=text.len() {
                let Some(text) = text.get(..cut) else {
                    continue;
                };
                let words: Vec<&str> = text
                    .split(|c: char| c.is_ascii() && !c.is_ascii_alphabetic())
                    .filter(|word| !word.is_empty())
                    .collect();
                let found = words
                    .iter()
                    .filter(|w| w.eq_ignore_ascii_case("the"))
                    .count();
                let scan = scan(text);
                assert_eq!(
                    (scan.words, scan.words_found),
                    (words.len(), found),
                    "{text:?}"
                );
                assert_eq!(scan.blanks_in_a_row, text.contains("  "), "{text:?}");
                assert_eq!(scan.ascii, text.is_ascii(), "{text:?}");
            }
        }
    }
}
