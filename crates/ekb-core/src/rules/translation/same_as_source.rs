use super::Message;
use crate::diagnostic::Diagnostics;
use crate::rules::declare_rule;

declare_rule! {
    /// ## What it does
    /// Flags an isiZulu or Kinyarwanda message that is the English message of the same
    /// location, word for word. Weblate's check of the same kind: *Unchanged translation*
    /// (`same`). `ekb translations` does not count such a message as translated, and
    /// `ekb export --format po` marks it fuzzy, for a translator to review.
    ///
    /// ## Why it matters
    /// It is how an untranslated message most often hides: the English was copied into
    /// the other language's line to be translated later. The robot then speaks English to
    /// a visitor who chose isiZulu or Kinyarwanda.
    ///
    /// ## Example
    /// ```text
    /// preGestureMessageEnglish      2 This is the Pepper humanoid robot
    /// preGestureMessageIsiZulu      2 This is the Pepper humanoid robot
    /// ```
    pub static SAME_AS_SOURCE = {
        name: "same-as-source",
        category: Translation,
        severity: Warning,
        fixable: false,
        summary: "a translation that is the English text",
    };
}

/// Reports `message` if it is its English text; returns whether it is.
pub fn check(message: &Message<'_>, out: &mut Diagnostics) -> bool {
    let Some(english) = message.english.filter(|e| e.value == message.text.value) else {
        return false;
    };
    out.push_with(&SAME_AS_SOURCE, || {
        message
            .finding(
                &SAME_AS_SOURCE,
                message.text.span,
                format!(
                    "{} is the English text: the robot will speak English to a visitor who \
                     chose {}",
                    message.describe(),
                    message.language.name()
                ),
            )
            .with_label(english.span, "the English message")
            .with_help(format!(
                "translate it into {} (`ekb translations --lang {}` lists what is left)",
                message.language.name(),
                crate::present::language::iso_code(message.language)
            ))
    });
    true
}
