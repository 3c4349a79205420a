use crate::check::Diagnostics;
use crate::diagnostic::Diagnostic;
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
    for text in texts.filter(|text| may_repeat(text.value)) {
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

/// Whether `text` holds a repeat, as [`repeats`] would find it; for a text of more than 64
/// bytes, `true` (then it is left to [`repeats`]).
///
/// Splitting every description and English message into tokens was the most costly rule of
/// a large file, and hardly any text holds a repeat. This finds the tokens of a text from
/// one mask of its blanks, made sixteen bytes at a time, with no span for each.
fn may_repeat(text: &str) -> bool {
    let bytes = text.as_bytes();
    let len = bytes.len();
    if len > 64 {
        return true;
    }
    // Bit `i` is set if byte `i` is a blank.
    let (blanks, ascii) = syntax::masks::blanks_and_ascii(bytes);
    let mut tokens = !blanks & bits(0..len as u32);
    if !may_hold_alike(bytes, tokens) {
        return false;
    }
    let mut words = Words::new(ascii);
    while tokens != 0 {
        let start = tokens.trailing_zeros();
        let end = start + (!(tokens >> start)).trailing_zeros();
        tokens &= !bits(start..end);
        // Blanks are ASCII, so a token starts and ends on characters' boundaries.
        if words
            .next((), &text[start as usize..end as usize])
            .is_some()
        {
            return true;
        }
    }
    false
}

/// Whether two tokens in a row (the runs of bits set in `tokens`, bit `i` for byte `i` of
/// `bytes`) may hold the same word. Most texts have no such pair, and this tells so from
/// one byte of each token.
///
/// A token that starts with an ASCII letter or digit holds a word that starts there, and
/// two such words are the same only if they start with the same character, ignoring case
/// (its lowercase is ASCII too). Any other token may hold any word.
fn may_hold_alike(bytes: &[u8], tokens: u64) -> bool {
    let mut starts = tokens & !(tokens << 1);
    let mut previous = None;
    while starts != 0 {
        let first = bytes[starts.trailing_zeros() as usize];
        if !first.is_ascii_alphanumeric() {
            return true;
        }
        let first = first.to_ascii_lowercase();
        if previous == Some(first) {
            return true;
        }
        previous = Some(first);
        starts &= starts - 1;
    }
    false
}

/// The bits `range` of a word, set.
fn bits(range: std::ops::Range<u32>) -> u64 {
    let below = |end: u32| u64::MAX.checked_shl(end).map_or(u64::MAX, |above| !above);
    below(range.end) & !below(range.start)
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

    /// What [`may_repeat`] must answer: exactly what [`repeats`] finds, up to 64 bytes.
    fn assert_may_repeat_agrees(text: &str) {
        let found = repeats(text, 0).next().is_some();
        let expected = found || text.len() > 64;
        assert_eq!(may_repeat(text), expected, "{text:?}");
    }

    #[test]
    fn may_repeat_answers_as_repeats_does() {
        for text in [
            "",
            " \t ",
            "the",
            "the the",
            "\tthe\t\tThe ",
            "the, the",
            "(the the)",
            "1 1",
            "café CAFÉ",
            "café that",
            "«the» the",
            "the «the»",
            "\u{212A}elvin kelvin",
            "kelvin \u{212A}elvin",
            "the then",
            "then the",
            "Tea tea",
            "tea, Tea",
            "9 9a 9A",
            "a b a",
            "ab\u{e9} AB\u{c9}",
            "k \u{212A}",
            "İ i̇",
            "a\u{0}a a",
            // 64 bytes, the last a repeat; then 65.
            "aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa b b",
            "aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa b b",
            "aaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaaa bc",
        ] {
            assert_may_repeat_agrees(text);
        }
    }

    #[test]
    fn bits_cover_their_range() {
        assert_eq!(bits(0..0), 0);
        assert_eq!(bits(0..64), u64::MAX);
        assert_eq!(bits(3..5), 0b11000);
        assert_eq!(bits(63..64), 1 << 63);
        assert_eq!(bits(64..64), 0);
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
        fn may_repeat_agrees_with_repeats(
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
            assert_may_repeat_agrees(&text);
            assert_may_repeat_agrees(text.trim_end());
        }
    }
}
