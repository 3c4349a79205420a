use crate::diagnostic::Diagnostic;
use crate::diagnostic::Diagnostics;
use crate::mission::catalogue::nearest_of;
use crate::mission::culture::{CultureKnowledgeBase, ValueTypes};
use crate::rules::declare_rule;

declare_rule! {
    /// ## What it does
    /// Flags a key of the culture knowledge base that its types file does not declare,
    /// with the nearest declared key.
    ///
    /// ## Why it matters
    /// The robot builds its dictionary from the types file and skips a line whose key it
    /// does not find there: the value is lost, without a word. Keys are case-sensitive.
    ///
    /// ## Example
    /// ```text
    /// utilityPhraseEnglsh4     Hello! Welcome to the Robotics Lab!
    /// ```
    pub static CULTURE_UNKNOWN_KEY = {
        name: "culture-unknown-key",
        category: Culture,
        severity: Error,
        fixable: false,
        summary: "a culture key that the types file does not declare (did-you-mean)",
    };
}

pub fn check(culture: &CultureKnowledgeBase<'_>, types: &ValueTypes<'_>, out: &mut Diagnostics) {
    for entry in culture.entries.iter().filter(|e| !e.continuation) {
        if types.declaration(entry.key).is_some() {
            continue;
        }
        let help = match nearest_of(entry.key, types.keys()) {
            Some(near) => format!("did you mean `{near}`? Keys are case-sensitive"),
            None => format!("declare `{}` in the types file, with its type", entry.key),
        };
        out.push(
            Diagnostic::new(
                &CULTURE_UNKNOWN_KEY,
                entry.key_span,
                format!(
                    "`{}` is not declared in the types file: the robot skips this line and \
                     its value is lost",
                    entry.key
                ),
            )
            .with_help(help),
        );
    }
}
