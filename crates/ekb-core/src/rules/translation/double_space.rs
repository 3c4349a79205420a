use super::Message;
use crate::diagnostic::Diagnostics;
use crate::diagnostic::Edit;
use crate::rules::declare_rule;

declare_rule! {
    /// ## What it does
    /// Flags two or more spaces (or tabs) in a row inside a message, in any language.
    /// Weblate's check of the same name: *Double space* (`double_space`).
    ///
    /// ## Why it matters
    /// A double space is a typing slip, often where a word was deleted or pasted. The robot
    /// reads the words around it as written, so a missing word goes unheard until a visitor
    /// hears the sentence limp. The fix makes it one space.
    ///
    /// ## Example
    /// ```text
    /// preGestureMessageIsiZulu      2 Leli  yirobhothi elibizwa ngokuthi uPepper
    /// ```
    pub static DOUBLE_SPACE = {
        name: "double-space",
        category: Translation,
        severity: Warning,
        fixable: true,
        summary: "two or more spaces in a row inside a message, in any language",
    };
}

pub fn check(message: &Message<'_>, out: &mut Diagnostics) {
    let bytes = message.text.value.as_bytes();
    let is_blank = |b: &u8| *b == b' ' || *b == b'\t';
    let mut at = 0;
    while let Some(found) = bytes[at..]
        .windows(2)
        .position(|pair| pair.iter().all(is_blank))
    {
        let start = at + found;
        let end = start + bytes[start..].iter().take_while(|b| is_blank(b)).count();
        let span = message.span_of(start..end);
        out.push_with(&DOUBLE_SPACE, || {
            message
                .finding(
                    &DOUBLE_SPACE,
                    span,
                    format!(
                        "{} has {} blanks in a row: the robot reads the words around them as \
                         written, so check that no word is missing",
                        message.describe(),
                        end - start
                    ),
                )
                .with_help("make it one space")
                .with_fix(
                    "replace them with one space",
                    vec![Edit::replace(span, " ")],
                )
        });
        at = end;
    }
}
