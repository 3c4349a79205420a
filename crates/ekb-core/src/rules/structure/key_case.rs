use crate::diagnostic::{Diagnostic, Edit};
use crate::model::Key;
use crate::rules::{consequence, declare_rule};
use crate::syntax::Span;

declare_rule! {
    /// ## What it does
    /// Flags a known key written in the wrong case, and fixes it.
    ///
    /// ## Why it matters
    /// The robot's reader matches keys case-sensitively and ignores any line it does not
    /// recognise. A single wrong letter therefore leaves a message, a pose or a target
    /// empty, and the robot says nothing or stands in the wrong place. The document's own
    /// ontology table spells keys this way (`RobotLocation`, `PreGestureMessageIsizulu`).
    ///
    /// ## Example
    /// ```text
    /// postGestureMessageenglish     4 We use it for teaching mobile robotics
    /// ```
    /// `ekb fix` rewrites the key as `postGestureMessageEnglish`.
    pub static KEY_CASE = {
        name: "key-case",
        category: Structure,
        severity: Error,
        fixable: true,
        summary: "a known key in the wrong case",
    };
}

pub fn diagnostic(span: Span, written: &str, key: Key, id: Option<u32>) -> Diagnostic {
    let id = if key == Key::TourSpecification {
        None
    } else {
        id
    };
    Diagnostic::new(
        &KEY_CASE,
        span,
        format!(
            "`{written}` is `{}` in the wrong case: the robot's reader ignores this line, so {}",
            key.name(),
            consequence::lost(key, id)
        ),
    )
    .at_location(id)
    .with_help(format!("write the key as `{}`", key.name()))
    .with_fix(format!("rename to `{}`", key.name()), edits(span, key))
}

/// The edits of the fix of [`diagnostic`], alone: for `ekb fix`, which makes a million
/// of them and reads no message.
pub fn edits(span: Span, key: Key) -> Vec<Edit> {
    vec![Edit::replace(span, key.name())]
}
