use crate::diagnostic::Diagnostics;
use crate::diagnostic::{Diagnostic, Severity};
use crate::mission::culture::{CultureKnowledgeBase, ValueType, ValueTypes};
use crate::rules::declare_rule;
use crate::syntax::Span;

declare_rule! {
    /// ## What it does
    /// Flags a culture knowledge base whose last line has no newline and is a `PHRASE`
    /// (or of a type unknown, when the types file is not at hand). It is an error when the
    /// mission says that phrase in its language, a warning otherwise.
    ///
    /// ## Why it matters
    /// The robot drops the last character of a `PHRASE`'s line, taking it for the newline:
    /// without one, the phrase loses its last letter (SPEC §2). The upstream file ends with
    /// `utilityPhraseKinyarwanda7 Murabeho`, which a Kinyarwanda mission says as
    /// `Murabeh`.
    ///
    /// ## Example
    /// `utilityPhraseEnglish7 Goodbye` at the end of the file, with no newline.
    pub static CULTURE_NO_FINAL_NEWLINE = {
        name: "culture-no-final-newline",
        category: Culture,
        severity: Warning,
        fixable: false,
        summary: "no newline after a last `PHRASE`, which loses its last letter",
    };
}

/// `said` are the keys of the phrases the mission says.
pub fn check(
    culture: &CultureKnowledgeBase<'_>,
    types: Option<&ValueTypes<'_>>,
    said: &[String],
    out: &mut Diagnostics,
) {
    let Some(last) = culture.entries.last() else {
        return;
    };
    if culture.text.ends_with('\n') {
        return;
    }
    let value_type = types.and_then(|types| types.type_of(last.key));
    if !matches!(value_type, None | Some(ValueType::Phrase)) || last.rest.is_empty() {
        return;
    }
    let said_here = said.iter().any(|key| key == last.key);
    let kept = culture.phrase(last);
    let end = culture.text.len();
    let last_char = culture.text[..end]
        .chars()
        .next_back()
        .map_or(0, char::len_utf8);
    let finding = Diagnostic::new(
        &CULTURE_NO_FINAL_NEWLINE,
        Span::new(end - last_char, end),
        format!(
            "the file ends without a newline: the robot drops the last letter of `{}` and \
             holds \"{kept}\"{}",
            last.key,
            if said_here {
                ", which the mission says"
            } else {
                ""
            }
        ),
    )
    .with_help("end the file with a newline");
    out.push(if said_here {
        finding.with_severity(Severity::Error)
    } else {
        finding
    });
}
