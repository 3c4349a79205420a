use super::Message;
use crate::diagnostic::Diagnostics;
use crate::diagnostic::Edit;
use crate::rules::declare_rule;

declare_rule! {
    /// ## What it does
    /// Flags a space before a comma, full stop, semicolon, colon, exclamation or question
    /// mark that ends a word (` ,` ` .` ` ?`), in any language. An ellipsis (` ...`, ` …`)
    /// and a mark that starts a word (` .5`) are not flagged. English, isiZulu and
    /// Kinyarwanda all write these marks right after the word. Weblate's nearest check is
    /// *Punctuation spacing* (`punctuation_spacing`), which asks for the space in French;
    /// this rule asks for its absence. The fix removes the space.
    ///
    /// ## Why it matters
    /// The robot's text-to-speech pauses at punctuation that follows a word; a mark standing
    /// alone can be read out, or the pause lost. It is also the most common slip when a
    /// sentence is edited in a hurry.
    ///
    /// ## Example
    /// ```text
    /// postGestureMessageKinyarwanda 1 Ngiye kubatemberezaho gato , nizereko muribuze kuryoherwa
    /// ```
    pub static SPACE_BEFORE_PUNCTUATION = {
        name: "space-before-punctuation",
        category: Translation,
        severity: Warning,
        fixable: true,
        summary: "a space before `,` `.` `;` `:` `!` or `?` in any language",
    };
}

/// The marks written right after a word.
const MARKS: &[u8] = b",.;:!?";

pub fn check(message: &Message<'_>, out: &mut Diagnostics) {
    let bytes = message.text.value.as_bytes();
    for at in 1..bytes.len().saturating_sub(1) {
        let (before, blank, mark) = (bytes[at - 1], bytes[at], bytes[at + 1]);
        let after = bytes.get(at + 2).copied();
        let is_blank = |b: u8| b == b' ' || b == b'\t';
        // One blank only: two are `double-space`'s, whose fix must not overlap this one's.
        let lone_blank = is_blank(blank) && !is_blank(before);
        let ends_a_word =
            after.is_none_or(|b| is_blank(b) || matches!(b, b'"' | b'\'' | b')' | b']'));
        if !(lone_blank && MARKS.contains(&mark) && ends_a_word) {
            continue;
        }
        let span = message.span_of(at..at + 1);
        let mark = mark as char;
        out.push_with(&SPACE_BEFORE_PUNCTUATION, || {
            message
                .finding(
                    &SPACE_BEFORE_PUNCTUATION,
                    span,
                    format!(
                        "{} has a space before `{mark}`: the robot's speech may read the mark \
                         apart from the word it ends",
                        message.describe()
                    ),
                )
                .with_help(format!("write `{mark}` right after the word"))
                .with_fix("remove the space", vec![Edit::delete(span)])
        });
    }
}
