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
    double_space::check(message, out);
    space_before_punctuation::check(message, out);
    repeated_punctuation::check(message, out);
    unbalanced_delimiters::check(message, out);
    if same_as_source::check(message, out) {
        // The English text itself: nothing else to compare, and it reads as English.
        return;
    }
    end_punctuation_mismatch::check(message, out);
    length_mismatch::check(message, out);
    wrong_language::check(message, out);
}
