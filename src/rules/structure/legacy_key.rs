use crate::check::Diagnostics;
use crate::diagnostic::{Diagnostic, Edit};
use crate::model::build::leading_id;
use crate::model::{Dialect, Key, ValueKind};
use crate::rules::{consequence, declare_rule};
use crate::syntax::Span;

declare_rule! {
    /// ## What it does
    /// When the configuration pins a dialect (`dialect = current` or `dialect = seed`),
    /// flags a key of the other dialect, and fixes the pose key.
    ///
    /// ## Why it matters
    /// The current robot's reader silently ignores `robotLocation`, so a file written in the
    /// document's dialect puts every pose at (0, 0). The document's reader, in turn, knows
    /// neither `robotLocationPose`, `culturalKnowledge` nor `gestureArm`.
    ///
    /// ## Example
    /// With `dialect = current` in the configuration:
    /// ```text
    /// robotLocation                 1 2.6 8.1 -90
    /// ```
    /// `ekb fix` rewrites it as `robotLocationPose`.
    pub static LEGACY_KEY = {
        name: "legacy-key",
        category: Structure,
        severity: Error,
        fixable: true,
        summary: "a key of the other dialect when the configuration pins one",
    };
}

/// `args` is the rest of the line, whose first word should be the location's id.
pub fn check(key: Key, span: Span, args: &str, pinned: Dialect, out: &mut Diagnostics) {
    if key.dialect() != Some(pinned.other()) {
        return;
    }
    let id = leading_id(args);
    let diagnostic = Diagnostic::new(
        &LEGACY_KEY,
        span,
        format!(
            "`{}` belongs to the {} dialect, but the configuration pins the {} dialect: that robot's reader ignores this line, so {}",
            key.name(),
            pinned.other().name(),
            pinned.name(),
            consequence::lost(key, id)
        ),
    )
    .at_location(id);
    out.push(if key.value_kind() == ValueKind::Pose {
        let replacement = pinned.pose_key().name();
        diagnostic
            .with_help(format!("write `{replacement}`"))
            .with_fix(
                format!("rename to `{replacement}`"),
                vec![Edit::replace(span, replacement)],
            )
    } else {
        diagnostic.with_help(format!(
            "the {} dialect cannot express `{}`: remove the line or pin the {} dialect",
            pinned.name(),
            key.name(),
            pinned.other().name()
        ))
    });
}
