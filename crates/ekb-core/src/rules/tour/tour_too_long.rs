use crate::diagnostic::Diagnostic;
use crate::diagnostic::Diagnostics;
use crate::model::Tour;
use crate::rules::declare_rule;

/// The robot's tour buffer holds this many stops.
pub const MAX_STOPS: u64 = 20;

declare_rule! {
    /// ## What it does
    /// Flags a tour of more than 20 stops.
    ///
    /// ## Why it matters
    /// The robot's reader stores the tour in a fixed array of 20 ids. A longer tour
    /// overflows it and corrupts the memory next to it.
    ///
    /// ## Example
    /// ```text
    /// tourSpecification 21 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16 17 18 19 20 21
    /// ```
    pub static TOUR_TOO_LONG = {
        name: "tour-too-long",
        category: Tour,
        severity: Error,
        fixable: false,
        summary: "more than 20 stops",
    };
}

/// `listed` is the number of ids listed after `n` (see [`Tour::listed`]).
pub fn check(tour: &Tour, listed: u64, out: &mut Diagnostics) {
    let stops = listed.max(tour.declared.map_or(0, |d| d.value));
    if stops > MAX_STOPS {
        out.push_with(&TOUR_TOO_LONG, || Diagnostic::new(&TOUR_TOO_LONG,
                tour.span,
                format!(
                    "the tour has {stops} stops, but the robot holds at most {MAX_STOPS}: its reader would write past the end of its tour buffer and corrupt its memory"
                ),
            )
            .with_help("split the tour, or drop stops to keep at most 20"),
        );
    }
}
