use super::Message;
use crate::diagnostic::Diagnostics;
use crate::rules::declare_rule;

declare_rule! {
    /// ## What it does
    /// Flags the same punctuation mark twice or more in a row (`..`, `,,`, `!!`, `??`,
    /// `....`), in any language. An ellipsis written as three dots (`...`) is not flagged.
    /// Weblate has no check of this name; it is the punctuation counterpart of its
    /// *Consecutive duplicated words* (`duplicate`).
    ///
    /// ## Why it matters
    /// A doubled mark is nearly always a slip of editing (a sentence joined to another, a
    /// comma typed twice). The robot's speech turns each mark into a pause or an
    /// intonation, so the slip is heard.
    ///
    /// ## Example
    /// ```text
    /// postGestureMessageIsiZulu     5 Sizobonana futhi maduze!!
    /// ```
    pub static REPEATED_PUNCTUATION = {
        name: "repeated-punctuation",
        category: Translation,
        severity: Warning,
        fixable: false,
        summary: "the same punctuation mark twice in a row (`..`, `,,`, `!!`; not `...`)",
    };
}

/// The marks that are never doubled.
const MARKS: &[u8] = b".,;:!?";

pub fn check(message: &Message<'_>, out: &mut Diagnostics) {
    let bytes = message.text.value.as_bytes();
    let mut at = 0;
    while at < bytes.len() {
        let mark = bytes[at];
        let run = bytes[at..].iter().take_while(|&&b| b == mark).count();
        if run >= 2 && MARKS.contains(&mark) && !(mark == b'.' && run == 3) {
            let span = message.span_of(at..at + run);
            let written = &message.text.value[at..at + run];
            out.push_with(&REPEATED_PUNCTUATION, || {
                message
                    .finding(
                        &REPEATED_PUNCTUATION,
                        span,
                        format!(
                            "{} has `{written}`: the robot's speech will pause or rise as \
                             the marks say, which is rarely what was meant",
                            message.describe()
                        ),
                    )
                    .with_help(format!(
                        "write one `{}`{}",
                        mark as char,
                        if mark == b'.' {
                            ", or `...` for an ellipsis"
                        } else {
                            ""
                        }
                    ))
            });
        }
        at += run;
    }
}
