use crate::diagnostic::Diagnostic;
use crate::model::Key;
use crate::rules::declare_rule;
use crate::syntax::Span;

declare_rule! {
    /// ## What it does
    /// Flags a value with fewer or more parts than its key needs: a pose (`x y theta`) and a
    /// gesture target (`x y z`) take three numbers (an empty one has 0), `gestureArm` one
    /// word. (A tour whose count is wrong is `tour-count-mismatch`.)
    ///
    /// ## Why it matters
    /// With too few numbers the robot's reader leaves the rest as whatever was in memory;
    /// with too many it silently drops the extra ones, which usually means a typo moved a
    /// number.
    ///
    /// ## Example
    /// ```text
    /// gestureTarget                 2 3.2 8.4
    /// ```
    pub static WRONG_ARITY = {
        name: "wrong-arity",
        category: Structure,
        severity: Error,
        fixable: false,
        summary: "fewer or more values than the key needs (pose, target: 3; `gestureArm`: 1)",
    };
}

pub fn diagnostic(key: Key, id: u32, span: Span, expected: usize, found: usize) -> Diagnostic {
    let consequence = if key == Key::GestureArm {
        // The robot compares the whole value with `left` and `right`.
        "the robot would not recognise it and gesture with its default arm"
    } else if found < expected {
        "the robot would fill the missing ones with undefined values"
    } else {
        "the robot would ignore the extra ones"
    };
    Diagnostic::new(
        &WRONG_ARITY,
        span,
        format!(
            "`{}` takes {expected} value{}, found {found}: {consequence}",
            key.name(),
            if expected == 1 { "" } else { "s" }
        ),
    )
    .at_location(Some(id))
    .with_help(match expected {
        1 => "write one word: `left` or `right`",
        _ if key == Key::GestureTarget => "write three numbers: `x y z` in metres",
        _ => "write three numbers: `x y theta` in metres and degrees",
    })
}
