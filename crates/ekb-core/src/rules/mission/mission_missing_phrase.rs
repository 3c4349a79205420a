use crate::diagnostic::Diagnostic;
use crate::diagnostic::Diagnostics;
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

/// What the robot does when it says a phrase it declares but holds no text for.
const NULL_TEXT: &str = "make the phrase from a null pointer and stop with an error \
                         (logic_error) when the node runs";

pub fn check(
    mission: &Mission,
    culture: &CultureKnowledgeBase<'_>,
    types: &ValueTypes<'_>,
    language: Language,
    out: &mut Diagnostics,
) {
    for SaidPhrase { node, key, span } in said_phrases(mission, language) {
        let held = culture.held(types, &key);
        let (why, outcome) = match held {
            Held::Text(..) => continue,
            Held::NotDeclared => (
                "the types file does not declare it",
                "say whatever phrase it looked up last instead",
            ),
            Held::Undefined => ("the types file types it UNDEFINED", NULL_TEXT),
            Held::Missing => ("the culture knowledge base gives it no value", NULL_TEXT),
            Held::Unreadable(_) => (
                "its lines give no value that can be read",
                "hold no text it can say: it stops with an error or says garbage",
            ),
            Held::Number(..) => (
                "the types file types it NUMBER",
                "take the number for the address of a text, and crash",
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
                    "`{}` says `{key}`, but {why}: the robot would {outcome}",
                    node.name
                ),
            )
            .with_help(help),
        );
    }
}
