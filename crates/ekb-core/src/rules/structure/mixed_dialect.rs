use crate::diagnostic::Diagnostic;
use crate::rules::declare_rule;
use crate::syntax::Span;

declare_rule! {
    /// ## What it does
    /// Flags a file that writes poses with both `robotLocation` (the document's dialect)
    /// and `robotLocationPose` (the robot's current dialect).
    ///
    /// ## Why it matters
    /// Each version of the robot's reader knows only one of the two keys and silently
    /// ignores the other, so whichever robot loads this file, some locations have no pose
    /// and the robot drives to (0, 0). `ekb fix --dialect current` makes the file consistent.
    ///
    /// ## Example
    /// ```text
    /// robotLocation                 1 2.6 8.1 -90
    /// robotLocationPose             2 2.6 8.1 -45
    /// ```
    pub static MIXED_DIALECT = {
        name: "mixed-dialect",
        category: Structure,
        severity: Warning,
        fixable: false,
        summary: "`robotLocation` and `robotLocationPose` in one file",
    };
}

/// `seed` and `current`: the first line of each pose key and how many lines use it.
pub fn diagnostic(seed: (Span, usize), current: (Span, usize)) -> Diagnostic {
    // Point at the first line of the rarer spelling: that is the odd one out.
    let (span, other, rare, common) = if seed.1 <= current.1 {
        (seed.0, current.0, "robotLocation", "robotLocationPose")
    } else {
        (current.0, seed.0, "robotLocationPose", "robotLocation")
    };
    Diagnostic::new(
        &MIXED_DIALECT,
        span,
        format!(
            "this file uses both `{rare}` and `{common}`: a robot knows only one of them and leaves the other locations at (0, 0)"
        ),
    )
    .with_label(other, format!("`{common}` used here"))
    .with_help("use one dialect throughout: `ekb fix --dialect current` (or `--dialect seed`)")
}
