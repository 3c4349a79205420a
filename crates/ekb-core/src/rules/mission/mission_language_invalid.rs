use crate::diagnostic::Diagnostic;
use crate::diagnostic::Diagnostics;
use crate::mission::culture::{CultureKnowledgeBase, Held, ValueTypes};
use crate::mission::{robot_language, LANGUAGE_KEY, ROBOT_LANGUAGES};
use crate::model::Language;
use crate::rules::declare_rule;
use crate::syntax::Span;

declare_rule! {
    /// ## What it does
    /// Flags a culture knowledge base whose `phraseLanguage`, the mission's language, is
    /// not exactly `English`, `Kinyarwanda` or `IsiZulu`, or that gives none.
    ///
    /// ## Why it matters
    /// The robot compares the word exactly: with `isiZulu` or `english` it logs "Unknown
    /// language set" and skips every exhibit of the tour, and asks for phrases such as
    /// `utilityPhraseisiZulu4`, which no culture knowledge base has.
    ///
    /// ## Example
    /// ```text
    /// phraseLanguage                            isiZulu
    /// ```
    /// Write `IsiZulu`.
    pub static MISSION_LANGUAGE_INVALID = {
        name: "mission-language-invalid",
        category: Mission,
        severity: Error,
        fixable: false,
        summary: "`phraseLanguage` not exactly `English`, `Kinyarwanda` or `IsiZulu`",
    };
}

/// The mission's language, or the finding (in the culture knowledge base) that it has none
/// the robot accepts.
pub fn check(
    culture: &CultureKnowledgeBase<'_>,
    types: &ValueTypes<'_>,
    out: &mut Diagnostics,
) -> Option<Language> {
    let held = culture.held(types, LANGUAGE_KEY);
    let (span, problem) = match &held {
        Held::Text(word, entry) => match robot_language(word) {
            Some(language) => return Some(language),
            None => (
                entry.first_word().map_or(entry.key_span, |(_, span)| span),
                format!("`{LANGUAGE_KEY}` is `{word}`"),
            ),
        },
        Held::Unreadable(entry) => (entry.key_span, format!("`{LANGUAGE_KEY}` has no value")),
        Held::Missing => (
            Span::empty_at(0),
            format!("the culture knowledge base has no `{LANGUAGE_KEY}` line"),
        ),
        Held::NotDeclared | Held::Undefined | Held::Number(..) => (
            culture
                .last(LANGUAGE_KEY)
                .map_or(Span::empty_at(0), |e| e.key_span),
            format!("the types file does not declare `{LANGUAGE_KEY}` as a WORD"),
        ),
    };
    let near = held.text().and_then(|word| {
        ROBOT_LANGUAGES
            .into_iter()
            .find(|l| l.eq_ignore_ascii_case(word))
    });
    let help = match near {
        Some(near) => format!("write `{near}`: the robot compares the word exactly"),
        None => format!("the robot accepts exactly {}", ROBOT_LANGUAGES.join(", ")),
    };
    out.push(
        Diagnostic::new(
            &MISSION_LANGUAGE_INVALID,
            span,
            match held {
                Held::Text(..) => format!(
                    "{problem}: the robot accepts only English, Kinyarwanda or IsiZulu; with \
                     any other language it logs \"Unknown language set\" and skips every \
                     exhibit"
                ),
                _ => format!(
                    "{problem}: the robot holds no language, makes its language from a null \
                     pointer and stops with an error (logic_error) as it starts"
                ),
            },
        )
        .with_help(help),
    );
    None
}
