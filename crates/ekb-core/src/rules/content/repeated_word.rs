use crate::diagnostic::Diagnostic;
use crate::diagnostic::Diagnostics;
use crate::model::{Language, Location, Phase};
use crate::render::clip;
use crate::rules::declare_rule;
use crate::syntax::{self, Span};

declare_rule! {
    /// ## What it does
    /// Flags the same word twice in a row, ignoring case and surrounding punctuation, in a
    /// description or an English message. Words separated by punctuation (`that, that`)
    /// are meant. isiZulu and Kinyarwanda messages are not checked: both languages repeat
    /// words as grammar (`kancane kancane`, `buhoro buhoro`: "slowly").
    ///
    /// ## Why it matters
    /// The robot reads the text aloud exactly as written, so a slip that the eye skips over
    /// is plainly heard by every visitor.
    ///
    /// ## Example
    /// ```text
    /// preGestureMessageEnglish      1 Welcome the the robotics lab at Carnegie Mellon University Africa
    /// ```
    /// Probably meant: `Welcome to the robotics lab`.
    pub static REPEATED_WORD = {
        name: "repeated-word",
        category: Content,
        severity: Warning,
        fixable: false,
        summary: "the same word twice in a row, case-insensitively",
    };
}

pub fn check(location: &Location<'_>, out: &mut Diagnostics) {
    let english = Phase::ALL.map(|phase| location.message(phase, Language::English));
    let texts = location
        .description()
        .into_iter()
        .chain(english.into_iter().flatten());
    for text in texts {
        for (first, second, word) in repeats(text.value, text.span.start as usize) {
            out.push_with(&REPEATED_WORD, || {
                Diagnostic::new(
                    &REPEATED_WORD,
                    first.cover(second),
                    format!(
                        "{} is repeated: the robot would say it twice",
                        clip::quoted(word)
                    ),
                )
                .at_location(Some(location.id))
                .with_help(format!(
                    "delete one {}, or write the word that was meant",
                    clip::quoted(word)
                ))
            });
        }
    }
}

/// Pairs of adjacent equal words (ignoring case and the punctuation around them) that
/// contain a letter, with no punctuation between them.
fn repeats(text: &str, offset: usize) -> impl Iterator<Item = (Span, Span, &str)> {
    let mut words = Words::new(text.is_ascii());
    syntax::tokens(text, offset).filter_map(move |(span, token)| {
        let (previous, word) = words.next(span, token)?;
        Some((previous, span, word))
    })
}

/// The words of a text, each compared with the one before: fed the text's tokens in order.
struct Words<'t, P> {
    /// The word of the token before, and where it was, unless it ended in punctuation.
    previous: Option<(P, &'t str)>,
    /// Whether the whole text is ASCII: then no word needs to be looked at beyond its bytes.
    ascii: bool,
}

impl<'t, P: Copy> Words<'t, P> {
    fn new(ascii: bool) -> Self {
        Words {
            previous: None,
            ascii,
        }
    }

    /// Takes the next token, found at `place`; if its word repeats the word before, returns
    /// where that one was, and the word.
    #[inline]
    fn next(&mut self, place: P, token: &'t str) -> Option<(P, &'t str)> {
        let word = trim_to_word(token);
        let repeat = self
            .previous
            .filter(|&(_, previous)| {
                same_word(word, previous, self.ascii) && word.chars().any(char::is_alphabetic)
            })
            .map(|(previous_place, _)| (previous_place, word));
        // `that, that` is meant: a word followed by punctuation starts afresh.
        self.previous = ends_in_word(token).then_some((place, word));
        repeat
    }
}

// Every word of every text passes through the three functions below: each answers from
// the ASCII bytes at hand, which is nearly always enough, and is inlined; the rare rest is
// out of line.

/// `token` without the punctuation around it.
#[inline]
fn trim_to_word(token: &str) -> &str {
    let bytes = token.as_bytes();
    match (bytes.first(), bytes.last()) {
        (Some(first), Some(last))
            if first.is_ascii_alphanumeric() && last.is_ascii_alphanumeric() =>
        {
            token
        }
        _ => trim_punctuation(token),
    }
}

#[cold]
fn trim_punctuation(token: &str) -> &str {
    token.trim_matches(|c: char| !c.is_alphanumeric())
}

#[inline]
fn ends_in_word(token: &str) -> bool {
    match token.as_bytes().last() {
        Some(last) if last.is_ascii() => last.is_ascii_alphanumeric(),
        _ => token.ends_with(char::is_alphanumeric),
    }
}

/// Whether `a` and `b` are the same word; `ascii` if both are known to be ASCII.
// Always inlined: left to the compiler, it was a call for every word (measured).
#[inline(always)]
fn same_word(a: &str, b: &str, ascii: bool) -> bool {
    a.eq_ignore_ascii_case(b) || (!ascii && !a.is_ascii() && same_lowercase(a, b))
}

/// Lowercasing may change the length of a non-ASCII word: compares the lowercase
/// characters, without making lowercase copies.
#[cold]
fn same_lowercase(a: &str, b: &str) -> bool {
    a.chars()
        .flat_map(char::to_lowercase)
        .eq(b.chars().flat_map(char::to_lowercase))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn finds_adjacent_repeats_only() {
        let found: Vec<_> = repeats("Welcome the The robotics lab", 10).collect();
        assert_eq!(found.len(), 1);
        assert_eq!(found[0].0, Span::new(18, 21));
        assert_eq!(found[0].1, Span::new(22, 25));
        assert!(repeats("the robot and the lab", 0).next().is_none());
        assert!(repeats("1 1", 0).next().is_none());
        assert!(repeats("that, that", 0).next().is_none());
        assert_eq!(repeats("see the the.", 0).count(), 1);
        assert_eq!(repeats("(the the)", 0).count(), 1);
        assert!(repeats("the. The robot", 0).next().is_none());
        assert_eq!(repeats("Ùmuntu ùmuntu", 0).count(), 1);
        assert_eq!(repeats("a a a a a", 0).count(), 4);
    }

    /// Words and punctuation that are the same or not in tricky ways: case, accents, the
    /// Kelvin sign (a `K` that lowercases to ASCII), a letter that lowercases to two.
    const TOKENS: &[&str] = &[
        "the", "The", "THE", "the,", "(the", "the)", "«the»", "a", "A", "1", "café", "CAFÉ",
        "Café,", "\u{212A}", "k", "K", "İ", "i̇", "—", "don't", "x\u{0}y",
    ];

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig::with_cases(2000))]
        /// Texts around 64 bytes long, of words that repeat or nearly do, blanks of every
        /// kind between them.
        #[test]
        fn repeats_are_the_neighbouring_words_that_match(
            words in proptest::collection::vec(
                (0..TOKENS.len(), proptest::sample::select(vec![" ", "\t", "  ", " \t"])),
                0..20),
            lead in proptest::sample::select(vec!["", " ", "\t"]),
        ) {
            let mut text = String::from(lead);
            for (token, blank) in words {
                text.push_str(TOKENS[token]);
                text.push_str(blank);
            }
            // As many repeats as pairs of neighbouring words that a plain split finds.
            let tokens: Vec<&str> = text.split_ascii_whitespace().collect();
            let pairs = tokens.windows(2).filter(|pair| {
                let (a, b) = (trim_to_word(pair[0]), trim_to_word(pair[1]));
                ends_in_word(pair[0])
                    && same_word(b, a, text.is_ascii())
                    && b.chars().any(char::is_alphabetic)
            });
            assert_eq!(repeats(&text, 0).count(), pairs.count(), "{text:?}");
        }
    }
}
