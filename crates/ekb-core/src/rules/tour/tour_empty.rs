use crate::diagnostic::Diagnostic;
use crate::diagnostic::Diagnostics;
use crate::model::Tour;
use crate::rules::declare_rule;

declare_rule! {
    /// ## What it does
    /// Flags a tour whose number of stops is 0, or that has no number at all.
    ///
    /// ## Why it matters
    /// A tour of no stops is no tour: the robot greets visitors and goes nowhere, and has
    /// no start pose.
    ///
    /// ## Example
    /// ```text
    /// tourSpecification 0
    /// ```
    pub static TOUR_EMPTY = {
        name: "tour-empty",
        category: Tour,
        severity: Error,
        fixable: false,
        summary: "`n` is 0",
    };
}

pub fn check(tour: &Tour, out: &mut Diagnostics) {
    let empty = match tour.declared {
        Some(declared) => declared.value == 0,
        None => tour.span.is_empty(),
    };
    if empty {
        let span = tour.declared.map_or(tour.span, |declared| declared.span);
        out.push_with(&TOUR_EMPTY, || {
            Diagnostic::new(
                &TOUR_EMPTY,
                span,
                "the tour has no stops: the robot would go nowhere and have no start pose",
            )
            .with_help("write `tourSpecification N ID1 … IDN` with at least one stop")
        });
    }
}
