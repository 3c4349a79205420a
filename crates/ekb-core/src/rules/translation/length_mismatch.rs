use super::scan::Scan;
use super::Message;
use crate::diagnostic::Diagnostics;
use crate::rules::declare_rule;

declare_rule! {
    /// ## What it does
    /// Flags a translation under a third, or over three times, the length of its English
    /// message (in characters). Weblate's nearest check is *Maximum length of translation*
    /// (`max-length`), which needs a limit set per string; this is the Translate Toolkit's
    /// `short` and `long` checks (run by Pootle and `pofilter`), with a wider margin,
    /// since isiZulu and Kinyarwanda words run long.
    ///
    /// ## Why it matters
    /// A translation much shorter than its English was likely cut (a line pasted in part, a
    /// sentence left unfinished); one much longer was likely pasted twice, or holds a
    /// second message. Either way the robot says something else than the English.
    ///
    /// ## Example
    /// ```text
    /// postGestureMessageEnglish     2 Please follow me as I move around.
    /// postGestureMessageKinyarwanda 2 Munkurikire
    /// ```
    /// (`Munkurikire`, "follow me", leaves out "as I move around".)
    pub static LENGTH_MISMATCH = {
        name: "length-mismatch",
        category: Translation,
        severity: Warning,
        fixable: false,
        summary: "a translation under a third or over three times the length of its English",
    };
}

/// How many characters `text` has (its length, for the ASCII text most messages are).
fn characters(text: &str, ascii: bool) -> usize {
    match ascii {
        true => text.len(),
        false => text.chars().count(),
    }
}

/// How many times shorter or longer than its English a translation may be.
const RATIO: usize = 3;

pub fn check(message: &Message<'_>, scan: &Scan, out: &mut Diagnostics) {
    let Some(english) = message.english else {
        return;
    };
    let english_length = characters(english.value, english.value.is_ascii());
    let length = characters(message.text.value, scan.ascii);
    let too_short = length * RATIO < english_length;
    let too_long = length > english_length * RATIO;
    if !(too_short || too_long) {
        return;
    }
    out.push_with(&LENGTH_MISMATCH, || {
        let (what, likely) = match too_short {
            true => ("under a third", "cut"),
            false => (
                "over three times",
                "pasted twice, or joined to another message",
            ),
        };
        message
            .finding(
                &LENGTH_MISMATCH,
                message.text.span,
                format!(
                    "{} is {length} characters, {what} the length of its English \
                     ({english_length}): it was likely {likely}, and the robot would say \
                     something else than the English",
                    message.describe()
                ),
            )
            .with_label(english.span, "the English message")
            .with_help("compare it with the English message and complete or shorten it")
    });
}
