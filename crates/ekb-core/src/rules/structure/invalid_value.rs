use crate::diagnostic::Diagnostic;
use crate::model::Key;
use crate::rules::{declare_rule, excerpt};
use crate::syntax::Span;

declare_rule! {
    /// ## What it does
    /// Flags a value outside its set of allowed words, such as `gestureArm up`.
    ///
    /// ## Why it matters
    /// The robot compares the word exactly; anything else falls back to a default arm, so
    /// the gesture may cross the robot's body or hit a visitor.
    ///
    /// ## Example
    /// ```text
    /// gestureArm                    2 up
    /// ```
    /// Use `left` or `right`.
    pub static INVALID_VALUE = {
        name: "invalid-value",
        category: Structure,
        severity: Error,
        fixable: false,
        summary: "a value outside its set, e.g. `gestureArm up`",
    };
}

pub fn diagnostic(key: Key, id: u32, span: Span, text: &str) -> Diagnostic {
    Diagnostic::new(
        &INVALID_VALUE,
        span,
        format!(
            "`{}` is not a valid `{}`: the robot would gesture with its default arm",
            excerpt(text),
            key.name()
        ),
    )
    .at_location(Some(id))
    .with_help(match text.to_ascii_lowercase().as_str() {
        lower @ ("left" | "right") => format!("write it in lower case: `{lower}`"),
        _ => "write `left` or `right`".to_string(),
    })
}
