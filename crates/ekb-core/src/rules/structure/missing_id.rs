use crate::diagnostic::Diagnostic;
use crate::model::Key;
use crate::rules::declare_rule;
use crate::syntax::Span;

declare_rule! {
    /// ## What it does
    /// Flags a location key that is not followed by a location id.
    ///
    /// ## Why it matters
    /// The id ties the lines of one location together. Without it the robot's reader
    /// takes the first word of the value as the id (usually reading 0, "not found"), so the
    /// line is lost.
    ///
    /// ## Example
    /// ```text
    /// robotLocationDescription      Roomba
    /// ```
    /// Write the id first: `robotLocationDescription 4 Roomba`.
    pub static MISSING_ID = {
        name: "missing-id",
        category: Structure,
        severity: Error,
        fixable: false,
        summary: "a location key with no id",
    };
}

pub fn diagnostic(key_span: Span, key: Key) -> Diagnostic {
    Diagnostic::new(
        &MISSING_ID,
        key_span,
        format!(
            "`{}` has no location id: the robot cannot tell which location this line belongs to and loses it",
            key.name()
        ),
    )
    .with_help(format!("write `{} ID VALUE`, where ID is the location's number", key.name()))
}
