use crate::diagnostic::Diagnostic;
use crate::model::Key;
use crate::rules::{declare_rule, excerpt};
use crate::syntax::Span;

declare_rule! {
    /// ## What it does
    /// Flags a number that does not parse: `8,1`, `abc`, `nan`, `inf`, or digits too large
    /// for a number.
    ///
    /// ## Why it matters
    /// The robot's reader stops at the first character it cannot read and keeps whatever
    /// it had, so `8,1` becomes 8 and `abc` becomes 0: the robot stands or points somewhere
    /// else without a warning.
    ///
    /// ## Example
    /// ```text
    /// robotLocationPose             1 2.6 8,1 -90
    /// ```
    /// Use a decimal point: `8.1`.
    pub static INVALID_NUMBER = {
        name: "invalid-number",
        category: Structure,
        severity: Error,
        fixable: false,
        summary: "a number that does not parse",
    };
}

pub fn diagnostic(key: Key, id: Option<u32>, span: Span, token: &str) -> Diagnostic {
    let token = excerpt(token);
    let (message, help) = if key == Key::TourSpecification {
        (
            format!("the number of tour stops `{token}` is not a whole number: the robot would read some other number of stops"),
            "write how many ids follow, e.g. `tourSpecification 5 1 4 3 2 5`",
        )
    } else {
        (
            format!(
                "`{token}` in `{}` is not a finite decimal number: the robot would read some other value here",
                key.name()
            ),
            if token.contains(',') {
                "write decimals with a point, e.g. `8.1`"
            } else {
                "numbers are decimal, e.g. `2.6`, `-90` or `0.82`"
            },
        )
    };
    Diagnostic::new(&INVALID_NUMBER, span, message)
        .at_location(id)
        .with_help(help)
}
