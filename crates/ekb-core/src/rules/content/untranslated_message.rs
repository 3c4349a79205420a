use crate::diagnostic::Diagnostic;
use crate::diagnostic::Diagnostics;
use crate::model::{is_placeholder, Language, Location, Phase, Value};
use crate::render::clip;
use crate::rules::declare_rule;

declare_rule! {
    /// ## What it does
    /// Flags a message that is a placeholder, such as `No message in isiZulu`, instead of a
    /// message.
    ///
    /// ## Why it matters
    /// The robot speaks the placeholder aloud to a visitor who chose that language. A
    /// translator can find every missing translation with
    /// `ekb check --format concise | grep untranslated-message`, or read them in context
    /// with `ekb tour --lang isizulu`.
    ///
    /// ## Example
    /// ```text
    /// preGestureMessageIsiZulu      1 No message in isiZulu
    /// ```
    pub static UNTRANSLATED_MESSAGE = {
        name: "untranslated-message",
        category: Content,
        severity: Warning,
        fixable: false,
        summary: "a placeholder such as `No message in isiZulu` instead of a message",
    };
}

pub fn check(location: &Location<'_>, out: &mut Diagnostics) {
    // Run on every location: plain loops, not a chain of iterators (measured).
    for phase in Phase::ALL {
        for language in Language::ALL {
            match location.message(phase, language) {
                Some(message) if is_placeholder(message.value) => {
                    report(location, phase, language, message, out)
                }
                _ => {}
            }
        }
    }
}

fn report(
    location: &Location<'_>,
    phase: Phase,
    language: Language,
    message: Value<&str>,
    out: &mut Diagnostics,
) {
    out.push_with(&UNTRANSLATED_MESSAGE, || {
        let english = location
            .message(phase, Language::English)
            .filter(|english| !is_placeholder(english.value));
        let help = match english {
            Some(english) if language != Language::English => format!(
                "translate the English message into {}: {}",
                language.name(),
                clip::quoted(english.value)
            ),
            _ => format!("write the message in {}", language.name()),
        };
        let message_text = format!(
            "the {} message {} the gesture at location {} is a placeholder: the robot would say {}",
            language.name(),
            phase.name(),
            location.id,
            clip::quoted(message.value)
        );
        Diagnostic::new(&UNTRANSLATED_MESSAGE, message.span, message_text)
            .at_location(Some(location.id))
            .with_help(help)
    });
}
