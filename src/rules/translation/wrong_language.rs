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

/// Whether `word` is a common English word that is no word of isiZulu or Kinyarwanda.
/// Left out on purpose: `a`, `i`, `me`, `no`, `we` (words, or parts written apart, of those
/// languages). Run on every word of every translation: a `match`, not a search of a list.
fn is_common_english(bytes: &[u8]) -> bool {
    // The longest is 7 letters: most words of a translation are longer.
    if !(2..=7).contains(&bytes.len()) {
        return false;
    }
    let mut lower = [0u8; 8];
    for (to, from) in lower.iter_mut().zip(bytes) {
        *to = from.to_ascii_lowercase();
    }
    matches!(
        &lower[..bytes.len()],
        b"about"
            | b"again"
            | b"all"
            | b"an"
            | b"and"
            | b"are"
            | b"as"
            | b"at"
            | b"be"
            | b"by"
            | b"can"
            | b"do"
            | b"enjoy"
            | b"enjoyed"
            | b"for"
            | b"from"
            | b"goodbye"
            | b"has"
            | b"have"
            | b"hello"
            | b"here"
            | b"hope"
            | b"how"
            | b"in"
            | b"is"
            | b"it"
            | b"its"
            | b"like"
            | b"my"
            | b"of"
            | b"on"
            | b"or"
            | b"our"
            | b"please"
            | b"see"
            | b"soon"
            | b"thank"
            | b"thanks"
            | b"that"
            | b"the"
            | b"their"
            | b"there"
            | b"these"
            | b"they"
            | b"this"
            | b"those"
            | b"to"
            | b"tour"
            | b"us"
            | b"use"
            | b"was"
            | b"welcome"
            | b"were"
            | b"what"
            | b"which"
            | b"who"
            | b"will"
            | b"with"
            | b"would"
            | b"you"
            | b"your"
    )
}

/// At least this many English words, and at least two in five of all words.
const MIN_ENGLISH_WORDS: usize = 2;

pub fn check(message: &Message<'_>, out: &mut Diagnostics) {
    if message.language == Language::English {
        return;
    }
    let (english, words) = english_words(message.text.value);
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

/// How many of the words of `text` are common English words, and how many words it has.
/// A word is a run of letters and of non-ASCII characters (split at ASCII bytes only, as
/// every common English word is ASCII: run on every translation, it reads bytes, not
/// characters).
fn english_words(text: &str) -> (usize, usize) {
    /// Letters, and the bytes of non-ASCII characters.
    const IN_WORD: [bool; 256] = {
        let mut in_word = [false; 256];
        let mut byte = 0;
        while byte < 256 {
            in_word[byte] = (byte as u8).is_ascii_alphabetic() || byte >= 0x80;
            byte += 1;
        }
        in_word
    };
    let bytes = text.as_bytes();
    let (mut english, mut words, mut at) = (0, 0, 0);
    while at < bytes.len() {
        while at < bytes.len() && !IN_WORD[bytes[at] as usize] {
            at += 1;
        }
        let start = at;
        while at < bytes.len() && IN_WORD[bytes[at] as usize] {
            at += 1;
        }
        if at > start {
            words += 1;
            english += usize::from(is_common_english(&bytes[start..at]));
        }
    }
    (english, words)
}

#[cfg(test)]
mod tests {
    use super::*;

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
