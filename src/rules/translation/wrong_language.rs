use super::scan::Scan;
use super::Message;
use crate::check::Diagnostics;
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

/// Whether `word` (as [`Scan::of`] packs it, lowercased) is a common English word that is
/// no word of isiZulu or Kinyarwanda. Left out on purpose: `a`, `i`, `me`, `no`, `we` (words,
/// or parts written apart, of those languages). Asked of every word of every translation: one
/// look in a table, with no branch.
fn is_common_english(word: u64) -> bool {
    COMMON_ENGLISH[slot_of(word)] == word
}

/// The one place of `word` in [`COMMON_ENGLISH`]: a multiplicative hash whose multiplier
/// was chosen (by trying random odd numbers, a few hundred tries) so that no two words of
/// the list share a place.
const fn slot_of(word: u64) -> usize {
    (word.wrapping_mul(0x6d98_14d5_dac5_04e5) >> (64 - COMMON_ENGLISH_SLOTS.trailing_zeros()))
        as usize
}

const COMMON_ENGLISH_SLOTS: usize = 256;

/// The common English words, each as one number ([`packed`]) in its own place
/// ([`slot_of`]; an empty place is 0, which no packed word is). A word that shares a place
/// with another fails the build: then choose another multiplier for [`slot_of`].
const COMMON_ENGLISH: [u64; COMMON_ENGLISH_SLOTS] = {
    let mut table = [0; COMMON_ENGLISH_SLOTS];
    let mut i = 0;
    while i < COMMON_ENGLISH_WORDS.len() {
        let word = packed(COMMON_ENGLISH_WORDS[i]);
        let slot = slot_of(word);
        assert!(table[slot] == 0, "two common English words share a place");
        table[slot] = word;
        i += 1;
    }
    table
};

const COMMON_ENGLISH_WORDS: [&[u8]; 61] = [
    b"about", b"again", b"all", b"an", b"and", b"are", b"as", b"at", b"be", b"by", b"can", b"do",
    b"enjoy", b"enjoyed", b"for", b"from", b"goodbye", b"has", b"have", b"hello", b"here", b"hope",
    b"how", b"in", b"is", b"it", b"its", b"like", b"my", b"of", b"on", b"or", b"our", b"please",
    b"see", b"soon", b"thank", b"thanks", b"that", b"the", b"their", b"there", b"these", b"they",
    b"this", b"those", b"to", b"tour", b"us", b"use", b"was", b"welcome", b"were", b"what",
    b"which", b"who", b"will", b"with", b"would", b"you", b"your",
];

/// A word of at most 8 bytes as one number.
const fn packed(word: &[u8]) -> u64 {
    let mut bytes = [0; 8];
    let mut i = 0;
    while i < word.len() {
        bytes[i] = word[i];
        i += 1;
    }
    u64::from_le_bytes(bytes)
}

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
