use crate::check::Diagnostics;
use crate::diagnostic::Diagnostic;
use crate::model::{Language, Location, Phase};
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
                    format!("\"{word}\" is repeated: the robot would say it twice"),
                )
                .at_location(Some(location.id))
                .with_help(format!(
                    "delete one \"{word}\", or write the word that was meant"
                ))
            });
        }
    }
}

/// Pairs of adjacent equal words (ignoring case and the punctuation around them) that
/// contain a letter, with no punctuation between them.
fn repeats(text: &str, offset: usize) -> impl Iterator<Item = (Span, Span, &str)> {
    let mut previous: Option<(Span, &str)> = None;
    // Known once for the whole text: then no word needs to be looked at beyond its bytes.
    let ascii = text.is_ascii();
    syntax::tokens(text, offset).filter_map(move |(span, token)| {
        let word = trim_to_word(token);
        let repeat = previous
            .filter(|&(_, previous_word)| {
                same_word(word, previous_word, ascii) && word.chars().any(char::is_alphabetic)
            })
            .map(|(previous_span, _)| (previous_span, span, word));
        // `that, that` is meant: a word followed by punctuation starts afresh.
        previous = ends_in_word(token).then_some((span, word));
        repeat
    })
}

// Every word of every description and English message passes through the three functions
// below: each answers from the ASCII bytes at hand, which is nearly always enough, and is
// inlined; the rare rest is out of line.

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
#[inline]
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
}
