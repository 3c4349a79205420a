use crate::diagnostic::Diagnostic;
use crate::model::KnowledgeBase;
use crate::rules::content::messages;
use crate::rules::declare_rule;
use crate::syntax::{self, Span};

declare_rule! {
    /// ## What it does
    /// Flags the same word twice in a row, ignoring case, in a description or a message.
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

pub fn check(kb: &KnowledgeBase<'_>, out: &mut Vec<Diagnostic>) {
    // `word word word …` makes a finding every five bytes: past what check keeps, stop
    // (50 MB of it made ten million findings, 3.8 GB).
    let limit = out.len() + crate::check::MAX_KEPT_PER_RULE;
    for location in kb.locations() {
        if out.len() >= limit {
            return;
        }
        let texts = location
            .description
            .into_iter()
            .chain(messages(location).map(|(_, _, message)| message));
        for text in texts {
            let room = limit - out.len();
            for (first, second, word) in repeats(text.value, text.span.start as usize, room) {
                out.push(
                    Diagnostic::new(
                        &REPEATED_WORD,
                        first.cover(second),
                        format!("\"{word}\" is repeated: the robot would say it twice"),
                    )
                    .at_location(Some(location.id))
                    .with_help(format!(
                        "delete one \"{word}\", or write the word that was meant"
                    )),
                );
            }
        }
    }
}

/// Pairs of adjacent equal words (ignoring case) containing a letter.
/// The repeated words of `text`, at most `limit` of them.
fn repeats(text: &str, offset: usize, limit: usize) -> Vec<(Span, Span, &str)> {
    let mut found = Vec::new();
    if limit == 0 {
        return found;
    }
    let mut previous: Option<(Span, &str)> = None;
    for (span, word) in syntax::tokens(text, offset) {
        if let Some((previous_span, previous_word)) = previous {
            if word.eq_ignore_ascii_case(previous_word)
                && (word.is_ascii() || word.to_lowercase() == previous_word.to_lowercase())
                && word.chars().any(char::is_alphabetic)
            {
                found.push((previous_span, span, word));
                if found.len() == limit {
                    break;
                }
            }
        }
        previous = Some((span, word));
    }
    found
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn finds_adjacent_repeats_only() {
        let found = repeats("Welcome the The robotics lab", 10, usize::MAX);
        assert_eq!(found.len(), 1);
        assert_eq!(found[0].0, Span::new(18, 21));
        assert_eq!(found[0].1, Span::new(22, 25));
        assert!(repeats("the robot and the lab", 0, 9).is_empty());
        assert!(repeats("1 1", 0, 9).is_empty());
        assert!(repeats("that, that", 0, 9).is_empty());
        assert_eq!(repeats("a a a a a", 0, 2).len(), 2);
        assert!(repeats("a a", 0, 0).is_empty());
    }
}
