use crate::check::Diagnostics;
use crate::diagnostic::Diagnostic;
use crate::model::Tour;
use crate::rules::declare_rule;

declare_rule! {
    /// ## What it does
    /// Flags the same location twice in a row in the tour.
    ///
    /// ## Why it matters
    /// The robot would give the same explanation twice without moving, which is almost
    /// always a typo for another id. (Visiting a location again later, such as returning
    /// to the start, is fine.)
    ///
    /// ## Example
    /// ```text
    /// tourSpecification 5 1 4 4 2 5
    /// ```
    pub static TOUR_REPEATED_STOP = {
        name: "tour-repeated-stop",
        category: Tour,
        severity: Warning,
        fixable: false,
        summary: "the same id twice in a row",
    };
}

pub fn check(tour: &Tour, out: &mut Diagnostics) {
    for pair in tour.stops.windows(2) {
        if pair[0].value == pair[1].value {
            out.push_with(&TOUR_REPEATED_STOP, || Diagnostic::new(&TOUR_REPEATED_STOP,
                    pair[1].span,
                    format!(
                        "location {} is visited twice in a row: the robot would repeat itself without moving",
                        pair[1].value
                    ),
                )
                .at_location(Some(pair[1].value))
                .with_label(pair[0].span, "first visit")
                .with_help("remove one of the two, or correct the id"),
            );
        }
    }
}
