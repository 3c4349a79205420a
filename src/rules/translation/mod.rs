//! The checks translators expect (SPEC §8), each named after the Weblate check it matches:
//! rules about one message in one language, and about a translation against its English.
//!
//! A placeholder (`No message in isiZulu`) is no text to check: `untranslated-message`
//! reports it. The rules about spacing and punctuation read every language's messages,
//! English included; the others compare an isiZulu or Kinyarwanda message with the English
//! message of the same location and phase.

pub mod double_space;
pub mod end_punctuation_mismatch;
pub mod length_mismatch;
pub mod repeated_punctuation;
pub mod same_as_source;
pub mod space_before_punctuation;
pub mod unbalanced_delimiters;
pub mod wrong_language;

use crate::check::Diagnostics;
use crate::diagnostic::Diagnostic;
use crate::model::{is_placeholder, Language, Location, Phase, Value};
use crate::rules::Rule;
use crate::syntax::Span;

/// One message in one language, written (not a placeholder), with its English.
#[derive(Debug, Clone, Copy)]
pub struct Message<'a> {
    pub location: u32,
    pub phase: Phase,
    pub language: Language,
    pub text: Value<&'a str>,
    /// The English message of the same location and phase, if it is written; `None` for
    /// an English message.
    pub english: Option<Value<&'a str>>,
}

impl<'a> Message<'a> {
    /// The messages of `location` that hold text, English first.
    pub fn all_of<'l>(location: &'l Location<'a>) -> impl Iterator<Item = Message<'a>> + 'l {
        Phase::ALL.into_iter().flat_map(move |phase| {
            let english = written(location, phase, Language::English);
            Language::ALL.into_iter().filter_map(move |language| {
                Some(Message {
                    location: location.id,
                    phase,
                    language,
                    text: written(location, phase, language)?,
                    english: english.filter(|_| language != Language::English),
                })
            })
        })
    }

    /// `the isiZulu message before the gesture at location 2`.
    pub fn describe(&self) -> String {
        format!(
            "the {} message {} the gesture at location {}",
            self.language.name(),
            self.phase.name(),
            self.location
        )
    }

    /// The span of `range`, byte offsets into the message's text.
    fn span_of(&self, range: std::ops::Range<usize>) -> Span {
        let start = self.text.span.start as usize;
        Span::new(start + range.start, start + range.end)
    }

    /// A finding of `rule` about this message, at `span`.
    fn finding(&self, rule: &'static Rule, span: Span, message: String) -> Diagnostic {
        Diagnostic::new(rule, span, message).at_location(Some(self.location))
    }
}

/// What a text holds that the rules about spacing and punctuation look for.
#[derive(Debug, Default, PartialEq)]
struct Shape {
    blanks_in_a_row: bool,
    /// `,` `.` `;` `:` `!` `?`
    punctuation: bool,
    /// A bracket, a straight double quote, or a byte of a non-ASCII character (which may be
    /// a curly quote or a guillemet).
    delimiters: bool,
}

impl Shape {
    fn of(text: &str) -> Shape {
        const BLANK: u8 = 1;
        const PUNCTUATION: u8 = 2;
        const DELIMITER: u8 = 4;
        const CLASSES: [u8; 256] = {
            let mut classes = [0; 256];
            classes[b' ' as usize] = BLANK;
            classes[b'\t' as usize] = BLANK;
            let punctuation = b",.;:!?";
            let mut i = 0;
            while i < punctuation.len() {
                classes[punctuation[i] as usize] = PUNCTUATION;
                i += 1;
            }
            let delimiters = b"()[]{}\"";
            let mut i = 0;
            while i < delimiters.len() {
                classes[delimiters[i] as usize] = DELIMITER;
                i += 1;
            }
            let mut byte = 0x80;
            while byte < 256 {
                classes[byte] = DELIMITER;
                byte += 1;
            }
            classes
        };
        let (mut seen, mut previous, mut in_a_row) = (0, 0, false);
        for &byte in text.as_bytes() {
            let class = CLASSES[byte as usize];
            in_a_row |= class & previous & BLANK != 0;
            seen |= class;
            previous = class;
        }
        Shape {
            blanks_in_a_row: in_a_row,
            punctuation: seen & PUNCTUATION != 0,
            delimiters: seen & DELIMITER != 0,
        }
    }
}

/// A message that holds text: present and not a placeholder.
fn written<'a>(
    location: &Location<'a>,
    phase: Phase,
    language: Language,
) -> Option<Value<&'a str>> {
    location
        .message(phase, language)
        .filter(|message| !is_placeholder(message.value))
}

/// Runs every translation rule on the messages of `location`.
pub fn check(location: &Location<'_>, out: &mut Diagnostics) {
    for message in Message::all_of(location) {
        check_message(&message, out);
    }
}

/// Runs every translation rule on one message.
pub fn check_message(message: &Message<'_>, out: &mut Diagnostics) {
    // Run on every message of every location: one pass over the bytes, a table lookup each,
    // tells which of the rules about spacing and punctuation can find anything (nearly
    // always none), instead of a pass of each (measured: the four passes were half the time
    // of a whole check; vectorised comparisons, twice this one's).
    let shape = Shape::of(message.text.value);
    if shape.blanks_in_a_row {
        double_space::check(message, out);
    }
    if shape.punctuation {
        space_before_punctuation::check(message, out);
        repeated_punctuation::check(message, out);
    }
    if shape.delimiters {
        unbalanced_delimiters::check(message, out);
    }
    if same_as_source::check(message, out) {
        // The English text itself: nothing else to compare, and it reads as English.
        return;
    }
    end_punctuation_mismatch::check(message, out);
    length_mismatch::check(message, out);
    wrong_language::check(message, out);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_pass_sees_what_each_rule_looks_for() {
        assert_eq!(
            Shape::of("Murakaza neza muri laboratwari"),
            Shape::default()
        );
        assert!(Shape::of("a \t b").blanks_in_a_row);
        assert!(!Shape::of("a b c").blanks_in_a_row);
        assert!(Shape::of("gato , nizereko").punctuation);
        assert!(Shape::of("n'urugendo (robo)").delimiters);
        assert!(Shape::of("“Pepper").delimiters);
    }
}
