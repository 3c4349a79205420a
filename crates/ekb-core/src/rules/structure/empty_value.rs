use crate::diagnostic::Diagnostic;
use crate::model::Key;
use crate::rules::{consequence, declare_rule};
use crate::syntax::Span;

declare_rule! {
    /// ## What it does
    /// Flags a key and id with nothing after them: a description, a message,
    /// `gestureArm` or `culturalKnowledge`. (An empty pose or gesture target has too few
    /// numbers: that is `wrong-arity`.)
    ///
    /// ## Why it matters
    /// An empty message is silence; an empty description leaves the location unnamed in
    /// every log. It is usually a line whose text was lost in an edit.
    ///
    /// ## Example
    /// ```text
    /// preGestureMessageEnglish      3
    /// ```
    pub static EMPTY_VALUE = {
        name: "empty-value",
        category: Structure,
        severity: Error,
        fixable: false,
        summary: "a key with no value (an empty pose or target is `wrong-arity`)",
    };
}

pub fn diagnostic(key_span: Span, key: Key, id: u32) -> Diagnostic {
    Diagnostic::new(
        &EMPTY_VALUE,
        key_span,
        format!(
            "`{}` for location {id} has no value: {}",
            key.name(),
            consequence::lost(key, Some(id))
        ),
    )
    .at_location(Some(id))
    .with_help("write the value after the id, or delete the line")
}
