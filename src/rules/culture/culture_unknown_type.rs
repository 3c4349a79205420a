use crate::check::Diagnostics;
use crate::diagnostic::Diagnostic;
use crate::mission::catalogue::nearest_of;
use crate::mission::culture::{ValueType, ValueTypes};
use crate::rules::declare_rule;

declare_rule! {
    /// ## What it does
    /// Flags a line of the types file whose type is not `UNDEFINED`, `NUMBER`, `WORD` or
    /// `PHRASE` (types are upper case), or that has no type.
    ///
    /// ## Why it matters
    /// The robot matches no type, declares nothing for the key, and stores the line
    /// before's key again: every value of the key in the culture knowledge base is lost.
    ///
    /// ## Example
    /// ```text
    /// utilityPhraseEnglish4                   Phrase
    /// ```
    pub static CULTURE_UNKNOWN_TYPE = {
        name: "culture-unknown-type",
        category: Culture,
        severity: Error,
        fixable: false,
        summary: "a type other than `UNDEFINED`, `NUMBER`, `WORD` or `PHRASE` in the types file",
    };
}

pub fn check(types: &ValueTypes<'_>, out: &mut Diagnostics) {
    for entry in types.entries.iter().filter(|e| !e.continuation) {
        let (span, shown) = match entry.first_word() {
            Some((word, _)) if ValueType::parse(word).is_some() => continue,
            Some((word, span)) => (span, format!("`{word}`")),
            None => (entry.key_span, "no type".to_string()),
        };
        let help = match entry
            .first_word()
            .and_then(|(w, _)| nearest_of(w, ValueType::NAMES.into_iter()))
        {
            Some(near) => format!("did you mean `{near}`? Types are upper case"),
            None => "the types are UNDEFINED, NUMBER, WORD and PHRASE".to_string(),
        };
        out.push(
            Diagnostic::new(
                &CULTURE_UNKNOWN_TYPE,
                span,
                format!(
                    "`{}` has {shown} for a type: the robot declares nothing for it, and \
                     loses its value",
                    entry.key
                ),
            )
            .with_help(help),
        );
    }
}
