//! What a message's text holds that the translation rules look for, found in one pass over
//! its bytes: the rules run on every message of every location, and most need nothing
//! more.

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

/// Whether `byte` belongs to a word: an ASCII letter, or a byte of a non-ASCII character.
fn in_word(byte: u8) -> bool {
    byte.is_ascii_alphabetic() || !byte.is_ascii()
}

impl Scan {
    /// Scans `text`, counting the words of `lengths` bytes (at most 8; an empty range counts
    /// none) for which `is_word` holds, given each word with its ASCII letters lowercased.
    pub fn of(
        text: &str,
        lengths: std::ops::RangeInclusive<usize>,
        is_word: impl Fn(&[u8]) -> bool,
    ) -> Scan {
        assert!(*lengths.end() <= 8, "words of up to 8 bytes are looked up");
        let bytes = text.as_bytes();
        let mut scan = Scan {
            ascii: text.is_ascii(),
            delimiters: !text.is_ascii(),
            ..Scan::default()
        };
        let mut after_blank = false;
        let mut at = 0;
        while at < bytes.len() {
            let byte = bytes[at];
            if in_word(byte) {
                let length = bytes[at..].iter().take_while(|&&b| in_word(b)).count();
                scan.words += 1;
                if lengths.contains(&length) {
                    let mut lower = [0; 8];
                    lower[..length].copy_from_slice(&bytes[at..at + length]);
                    lower.make_ascii_lowercase();
                    scan.words_found += usize::from(is_word(&lower[..length]));
                }
                at += length;
                after_blank = false;
                continue;
            }
            let blank = byte == b' ' || byte == b'\t';
            scan.blanks_in_a_row |= blank && after_blank;
            scan.punctuation |= PUNCTUATION.contains(&byte);
            scan.delimiters |= DELIMITERS.contains(&byte);
            after_blank = blank;
            at += 1;
        }
        scan
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scan(text: &str) -> Scan {
        Scan::of(text, 2..=3, |word| word == b"the")
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
        // Long words, blanks in a row, words of every length, non-ASCII words.
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
