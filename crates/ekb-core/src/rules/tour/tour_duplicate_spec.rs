use crate::diagnostic::Diagnostic;
use crate::rules::declare_rule;
use crate::syntax::Span;

declare_rule! {
    /// ## What it does
    /// Flags a second (third, …) `tourSpecification` line.
    ///
    /// ## Why it matters
    /// The robot's reader keeps only the last one, so an older tour left higher up in the
    /// file is dead text that a reader may take for the real tour.
    ///
    /// ## Example
    /// ```text
    /// tourSpecification 5 1 4 3 2 5
    /// tourSpecification 3 1 2 5
    /// ```
    pub static TOUR_DUPLICATE_SPEC = {
        name: "tour-duplicate-spec",
        category: Tour,
        severity: Warning,
        fixable: false,
        summary: "more than one `tourSpecification`; the last wins",
    };
}

pub fn diagnostic(later: Span, earlier: Span) -> Diagnostic {
    Diagnostic::new(
        &TOUR_DUPLICATE_SPEC,
        later,
        "a second `tourSpecification`: the robot follows this one and ignores the earlier tour",
    )
    .with_label(earlier, "earlier tour, ignored")
    .with_help("keep one `tourSpecification` line")
}
