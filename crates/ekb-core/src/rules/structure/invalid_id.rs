use crate::diagnostic::Diagnostic;
use crate::model::Key;
use crate::rules::{declare_rule, excerpt};
use crate::syntax::Span;

declare_rule! {
    /// ## What it does
    /// Flags a location id (or a tour stop) that is not a whole number from 1 to 2147483647.
    ///
    /// ## Why it matters
    /// The robot's reader uses id 0 for "not found", so a location 0 can never be
    /// retrieved; a negative id, `4a` or a number too large for a C `int` is read as some
    /// other number, and the line joins the wrong location.
    ///
    /// ## Example
    /// ```text
    /// robotLocationDescription      0 Pepper's starting location
    /// tourSpecification 3 1 4a 2
    /// ```
    pub static INVALID_ID = {
        name: "invalid-id",
        category: Structure,
        severity: Error,
        fixable: false,
        summary: "an id that is not an integer in 1..=2147483647",
    };
}

pub fn diagnostic(span: Span, token: &str, key: Key) -> Diagnostic {
    let why = if token.bytes().all(|b| b.is_ascii_digit()) && token.bytes().any(|b| b != b'0') {
        "is larger than 2147483647, the largest id the robot can hold"
    } else if token.bytes().all(|b| b == b'0') {
        "is 0, which the robot's reader uses for \"not found\""
    } else {
        "is not a positive whole number written in digits"
    };
    let subject = if key == Key::TourSpecification {
        "tour stop"
    } else {
        "location id"
    };
    Diagnostic::new(
        &INVALID_ID,
        span,
        format!(
            "{subject} `{}` {why}: the robot would read a different location or none",
            excerpt(token)
        ),
    )
    .with_help("ids are whole numbers from 1 to 2147483647")
}
