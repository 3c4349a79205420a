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
mod scan;
pub mod space_before_punctuation;
pub mod unbalanced_delimiters;
pub mod wrong_language;

use crate::diagnostic::Diagnostic;
use crate::diagnostic::Diagnostics;
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
    /// Calls `each` with every message of `location` that holds text, English first.
    /// (A loop, not an iterator: run on every location, the iterator's states cost a tenth
    /// of all the translation rules, measured.)
    pub fn each_of(location: &Location<'a>, mut each: impl FnMut(Message<'a>)) {
        for phase in Phase::ALL {
            let english = written(location, phase, Language::English);
            for language in Language::ALL {
                if let Some(text) = written(location, phase, language) {
                    each(Message {
                        location: location.id,
                        phase,
                        language,
                        text,
                        english: english.filter(|_| language != Language::English),
                    });
                }
            }
        }
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
    Message::each_of(location, |message| check_message(&message, out));
}

/// Runs every translation rule on one message.
pub fn check_message(message: &Message<'_>, out: &mut Diagnostics) {
    // Run on every message of every location: one pass over the bytes tells which of the
    // rules about spacing and punctuation can find anything (nearly always none), and counts
    // what the others need.
    let scan = wrong_language::scan(message);
    if scan.blanks_in_a_row {
        double_space::check(message, out);
    }
    if scan.punctuation {
        space_before_punctuation::check(message, out);
        repeated_punctuation::check(message, out);
    }
    if scan.delimiters {
        unbalanced_delimiters::check(message, out);
    }
    if same_as_source::check(message, out) {
        // The English text itself: nothing else to compare, and it reads as English.
        return;
    }
    end_punctuation_mismatch::check(message, out);
    length_mismatch::check(message, &scan, out);
    wrong_language::check(message, &scan, out);
}
