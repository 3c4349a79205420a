use super::scan::Scan;
use super::Message;
use crate::diagnostic::Diagnostics;
use crate::model::Language;
use crate::rules::declare_rule;

declare_rule! {
    /// ## What it does
    /// Flags an isiZulu or Kinyarwanda message that reads as English: at least two of its
    /// words, and at least two in five, are common English words (`the`, `is`, `this`,
    /// `you`, `welcome`, …) that are no words of isiZulu or Kinyarwanda. English names and
    /// loanwords in a translation (`Pepper`, `mobile`, `lab`) do not count. A one-word
    /// message is never flagged. Weblate has no language detection; its nearest check is
    /// *Unchanged translation* (`same`), which `same-as-source` matches; this rule also
    /// finds English that was edited after it was copied.
    ///
    /// ## Why it matters
    /// The robot speaks the message with the voice of the language the visitor chose: an
    /// English sentence in the isiZulu line is spoken to an isiZulu listener, in English,
    /// with isiZulu pronunciation.
    ///
    /// ## Example
    /// ```text
    /// preGestureMessageEnglish      2 This is the Pepper humanoid robot
    /// preGestureMessageIsiZulu      2 This is Pepper, our humanoid robot
    /// ```
    pub static WRONG_LANGUAGE = {
        name: "wrong-language",
        category: Translation,
        severity: Warning,
        fixable: false,
        summary: "an isiZulu or Kinyarwanda message that reads as English",
    };
}

/// The lengths of the common English words: most words of a translation are longer.
const ENGLISH_LENGTHS: std::ops::RangeInclusive<usize> = 2..=7;

/// Scans `message` for every translation rule, counting its common English words if it is
/// a translation.
pub(super) fn scan(message: &Message<'_>) -> Scan {
    let lengths = match message.language {
        // English is what is looked for: nothing to look up.
        #[allow(clippy::reversed_empty_ranges)]
        Language::English => 1..=0,
        _ => ENGLISH_LENGTHS,
    };
    Scan::of(message.text.value, lengths, is_common_english)
}

/// Whether `word` (lowercased) is a common English word that is no word of isiZulu or
/// Kinyarwanda. Left out on purpose: `a`, `i`, `me`, `no`, `we` (words, or parts written
/// apart, of those languages). Asked of every word of every translation: a binary search
/// of numbers (a search of byte strings, a call of `memcmp` each, was a fifth of a check).
fn is_common_english(word: &[u8]) -> bool {
    word.len() <= 8 && COMMON_ENGLISH.binary_search(&as_number(word)).is_ok()
}

/// A word of at most 8 bytes as one number whose order is the words' byte order: its
/// bytes, then zeros, big-endian.
const fn as_number(word: &[u8]) -> u64 {
    let mut bytes = [0; 8];
    let mut i = 0;
    while i < word.len() {
        bytes[i] = word[i];
        i += 1;
    }
    u64::from_be_bytes(bytes)
}

/// [`COMMON_ENGLISH_WORDS`] as numbers ([`as_number`]), in the same order.
const COMMON_ENGLISH: [u64; COMMON_ENGLISH_WORDS.len()] = {
    let mut numbers = [0; COMMON_ENGLISH_WORDS.len()];
    let mut i = 0;
    while i < numbers.len() {
        numbers[i] = as_number(COMMON_ENGLISH_WORDS[i]);
        i += 1;
    }
    numbers
};

/// In byte order (then so are their numbers), for [`is_common_english`]'s binary search.
const COMMON_ENGLISH_WORDS: [&[u8]; 61] = [
    b"about", b"again", b"all", b"an", b"and", b"are", b"as", b"at", b"be", b"by", b"can", b"do",
    b"enjoy", b"enjoyed", b"for", b"from", b"goodbye", b"has", b"have", b"hello", b"here", b"hope",
    b"how", b"in", b"is", b"it", b"its", b"like", b"my", b"of", b"on", b"or", b"our", b"please",
    b"see", b"soon", b"thank", b"thanks", b"that", b"the", b"their", b"there", b"these", b"they",
    b"this", b"those", b"to", b"tour", b"us", b"use", b"was", b"welcome", b"were", b"what",
    b"which", b"who", b"will", b"with", b"would", b"you", b"your",
];

/// At least this many English words, and at least two in five of all words.
const MIN_ENGLISH_WORDS: usize = 2;

pub fn check(message: &Message<'_>, scan: &Scan, out: &mut Diagnostics) {
    if message.language == Language::English {
        return;
    }
    let (english, words) = (scan.words_found, scan.words);
    if english < MIN_ENGLISH_WORDS || english * 5 < words * 2 {
        return;
    }
    out.push_with(&WRONG_LANGUAGE, || {
        message
            .finding(
                &WRONG_LANGUAGE,
                message.text.span,
                format!(
                    "{} reads as English ({english} of its {words} words are common English \
                     words): the robot will say it with its {} voice to a visitor who chose {}",
                    message.describe(),
                    message.language.name(),
                    message.language.name()
                ),
            )
            .with_help(format!(
                "write the message in {}, or move this text to the English line",
                message.language.name()
            ))
    });
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_common_words_are_in_byte_order_and_found() {
        assert!(COMMON_ENGLISH_WORDS.is_sorted() && COMMON_ENGLISH.is_sorted());
        for word in COMMON_ENGLISH_WORDS {
            assert!(is_common_english(word));
        }
        assert!(!is_common_english(b"muri"));
        assert!(!is_common_english(b""));
        assert!(!is_common_english(b"enjoyedly"));
    }

    fn english_words(text: &str) -> (usize, usize) {
        let scan = Scan::of(text, ENGLISH_LENGTHS, is_common_english);
        (scan.words_found, scan.words)
    }

    #[test]
    fn counts_english_words() {
        assert_eq!(english_words("This is the Pepper humanoid robot"), (3, 6));
        assert_eq!(
            english_words("Nizere ko muri buryoherwe n'urugendo"),
            (0, 6)
        );
        assert_eq!(
            english_words("Tuyikoresha mukwigisha mobile robotikisi"),
            (0, 4)
        );
    }
}
