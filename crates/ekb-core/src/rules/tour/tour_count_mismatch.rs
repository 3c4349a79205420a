use crate::diagnostic::Diagnostic;
use crate::diagnostic::Diagnostics;
use crate::model::Tour;
use crate::rules::declare_rule;

declare_rule! {
    /// ## What it does
    /// Flags a tour whose declared number of stops `n` differs from the number of ids after it.
    ///
    /// ## Why it matters
    /// With fewer ids than `n` the robot visits undefined locations at the end of the tour;
    /// with more, it silently drops the extra stops.
    ///
    /// ## Example
    /// ```text
    /// tourSpecification 5 1 4 3 2
    /// ```
    pub static TOUR_COUNT_MISMATCH = {
        name: "tour-count-mismatch",
        category: Tour,
        severity: Error,
        fixable: false,
        summary: "`n` differs from the number of ids that follow",
    };
}

/// `found` is the number of ids listed after `n` (see [`Tour::listed`]).
pub fn check(tour: &Tour, found: u64, out: &mut Diagnostics) {
    let Some(declared) = tour.declared else {
        return;
    };
    if declared.value == found || declared.value == 0 {
        return;
    }
    let consequence = if found < declared.value {
        "the robot would visit undefined locations after the last one"
    } else {
        "the robot would drop the stops after the first n"
    };
    out.push_with(&TOUR_COUNT_MISMATCH, || {
        Diagnostic::new(
            &TOUR_COUNT_MISMATCH,
            declared.span,
            format!(
                "the tour declares {} stops but lists {found}: {consequence}",
                declared.value
            ),
        )
        .with_help(format!(
            "make the first number {found}, or list {} ids",
            declared.value
        ))
    });
}
