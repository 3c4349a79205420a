use crate::check::Diagnostics;
use crate::diagnostic::Diagnostic;
use crate::mission::culture::{CultureKnowledgeBase, Held, ValueTypes};
use crate::mission::tree::Mission;
use crate::mission::{said_phrases, SaidPhrase};
use crate::model::Language;
use crate::rules::declare_rule;

declare_rule! {
    /// ## What it does
    /// Flags a `SayText` whose phrase, `utilityPhrase<Language><N>` of the culture
    /// knowledge base in the mission's language, is missing: not declared in the types
    /// file, typed `UNDEFINED` there, or given no value.
    ///
    /// ## Why it matters
    /// The robot finds no phrase and says whatever it looked up last (or garbage, for an
    /// `UNDEFINED` key), in front of the visitor. The upstream types file declares every
    /// `utilityPhraseIsiZulu1..7` `UNDEFINED`, so an isiZulu mission says none of its
    /// phrases.
    ///
    /// ## Example
    /// ```text
    /// utilityPhraseIsiZulu4                   UNDEFINED
    /// ```
    /// in the types file, with `phraseLanguage IsiZulu` and `<SayText name="4"/>`.
    pub static MISSION_MISSING_PHRASE = {
        name: "mission-missing-phrase",
        category: Mission,
        severity: Error,
        fixable: false,
        summary: "a `SayText` whose phrase is missing, or typed `UNDEFINED`, in the mission language",
    };
}

pub fn check(
    mission: &Mission,
    culture: &CultureKnowledgeBase<'_>,
    types: &ValueTypes<'_>,
    language: Language,
    out: &mut Diagnostics,
) {
    for SaidPhrase { node, key, span } in said_phrases(mission, language) {
        let held = culture.held(types, &key);
        let (why, says) = match held {
            Held::Text(..) | Held::Number(..) => continue,
            Held::NotDeclared => (
                "the types file does not declare it",
                "whatever phrase it looked up last",
            ),
            Held::Undefined => ("the types file types it UNDEFINED", "an undefined value"),
            Held::Missing => (
                "the culture knowledge base gives it no value",
                "an undefined value",
            ),
            Held::Unreadable(_) => (
                "its line gives no value that can be read",
                "an undefined value",
            ),
        };
        let help = match held {
            Held::Undefined | Held::NotDeclared => format!(
                "declare `{key}` as PHRASE in the types file and give it a value in the \
                 culture knowledge base"
            ),
            _ => format!("add a line `{key} …` to the culture knowledge base"),
        };
        out.push(
            Diagnostic::new(
                &MISSION_MISSING_PHRASE,
                span,
                format!(
                    "`{}` says `{key}`, but {why}: the robot would say {says} instead",
                    node.name
                ),
            )
            .with_help(help),
        );
    }
}
