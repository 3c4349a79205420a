use crate::diagnostic::Diagnostic;
use crate::diagnostic::Diagnostics;
use crate::model::{Tour, Value};
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
    let mut previous: Option<Value<u32>> = None;
    for stop in tour.stops() {
        if let Some(first) = previous.filter(|first| first.value == stop.value) {
            out.push_with(&TOUR_REPEATED_STOP, || Diagnostic::new(&TOUR_REPEATED_STOP,
                    stop.span,
                    format!(
                        "location {} is visited twice in a row: the robot would repeat itself without moving",
                        stop.value
                    ),
                )
                .at_location(Some(stop.value))
                .with_label(first.span, "first visit")
                .with_help("remove one of the two, or correct the id"),
            );
        }
        previous = Some(stop);
    }
}
