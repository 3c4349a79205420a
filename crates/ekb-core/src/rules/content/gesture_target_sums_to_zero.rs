use crate::diagnostic::Diagnostic;
use crate::diagnostic::Diagnostics;
use crate::model::Location;
use crate::rules::declare_rule;

declare_rule! {
    /// ## What it does
    /// Flags a gesture target other than `0 0 0` whose coordinates add up to 0.
    ///
    /// ## Why it matters
    /// The robot decides "no gesture here" by testing `x + y + z == 0`, not by comparing
    /// each coordinate with 0, so a real target such as `1.0 -1.0 0.0` is never pointed at.
    ///
    /// ## Example
    /// ```text
    /// gestureTarget                 3 1.0 -1.0 0.0
    /// ```
    pub static GESTURE_TARGET_SUMS_TO_ZERO = {
        name: "gesture-target-sums-to-zero",
        category: Content,
        severity: Warning,
        fixable: false,
        summary: "a target other than `0 0 0` whose coordinates sum to 0",
    };
}

pub fn check(location: &Location<'_>, out: &mut Diagnostics) {
    let Some(target) = location.gesture_target else {
        return;
    };
    let point = target.value;
    if point.is_no_gesture() || !point.robot_sees_no_gesture() {
        return;
    }
    out.push_with(&GESTURE_TARGET_SUMS_TO_ZERO, || Diagnostic::new(&GESTURE_TARGET_SUMS_TO_ZERO,
            target.span,
            format!(
                "the gesture target of location {} adds up to 0: the robot takes that for \"no gesture\" and will not point",
                location.id
            ),
        )
        .at_location(Some(location.id))
        .with_help("move the target slightly (e.g. change z by 0.01) so its coordinates do not sum to 0"),
    );
}
