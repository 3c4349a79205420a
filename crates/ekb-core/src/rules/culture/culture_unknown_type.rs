use crate::diagnostic::Diagnostic;
use crate::diagnostic::Diagnostics;
use crate::mission::catalogue::nearest_of;
use crate::mission::culture::{ValueType, ValueTypes};
use crate::rules::declare_rule;

declare_rule! {
    /// ## What it does
    /// Flags a line of the types file whose type is not `UNDEFINED`, `NUMBER`, `WORD` or
    /// `PHRASE` (types are upper case), or that has no type; and a types file whose first
    /// line declares no key (a blank line, a comment, a header), or that declares none.
    ///
    /// ## Why it matters
    /// The robot matches no type, declares nothing for the key, and stores the line
    /// before's key again: every value of the key in the culture knowledge base is lost.
    /// A line with no type is worse: the robot reuses the type word of the line before,
    /// so the key's type depends on its neighbour. And while nothing is declared yet, the
    /// robot stores a node without a key, on which its next lookup crashes (segmentation
    /// fault): a types file that starts with a comment or a blank line stops the robot
    /// before the tour begins.
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

/// What the robot does on a line of the types file that names no known type.
const CRASHES: &str = "nothing is declared before it, so the robot stores a node without a \
                       key here and crashes (segmentation fault) on its next lookup, before \
                       the tour begins";

pub fn check(types: &ValueTypes<'_>, out: &mut Diagnostics) {
    let mut crash_reported = false;
    for entry in types.entries.iter().filter(|e| !e.continuation) {
        let (span, shown) = match entry.first_word() {
            Some((word, _)) if ValueType::parse(word).is_some() => continue,
            Some((word, span)) => (span, format!("`{word}`")),
            None => (entry.key_span, "no type".to_string()),
        };
        let crashes = types
            .crash
            .is_some_and(|crash| crash.start == entry.span.start);
        crash_reported |= crashes;
        let consequence = match types.declared(entry.key) {
            _ if crashes => CRASHES.to_string(),
            Some(declared) if declared.borrowed && types.entries[declared.entry] == *entry => {
                format!(
                    "the robot reuses the type word of a line before and declares it {}, \
                     by accident",
                    declared.value_type.name()
                )
            }
            _ => "the robot declares nothing for it, and loses its value".to_string(),
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
                format!("`{}` has {shown} for a type: {consequence}", entry.key),
            )
            .with_help(help),
        );
    }
    if let Some(crash) = types.crash.filter(|_| !crash_reported) {
        let message = match crash.is_empty() {
            true => "the types file declares no key: the robot crashes when it loads the \
                     culture knowledge base, before the tour begins"
                .to_string(),
            false => format!(
                "the types file's first line declares no key (a blank line or a comment): \
                 {CRASHES}"
            ),
        };
        out.push(
            Diagnostic::new(&CULTURE_UNKNOWN_TYPE, crash, message)
                .with_help("start the types file with a `key TYPE` line; put comments after it"),
        );
    }
}
