use crate::diagnostic::Diagnostic;
use crate::diagnostic::Diagnostics;
use crate::model::KnowledgeBase;
use crate::rules::declare_rule;

declare_rule! {
    /// ## What it does
    /// Flags a tour stop whose id no location has.
    ///
    /// ## Why it matters
    /// The robot's lookup of that id fails; the tour either stops there or the robot drives
    /// to an undefined pose.
    ///
    /// ## Example
    /// ```text
    /// tourSpecification 3 1 7 5      <- there is no location 7
    /// ```
    pub static TOUR_UNKNOWN_LOCATION = {
        name: "tour-unknown-location",
        category: Tour,
        severity: Error,
        fixable: false,
        summary: "a tour id with no location",
    };
}

pub fn check(kb: &KnowledgeBase<'_>, out: &mut Diagnostics) {
    let Some(tour) = &kb.tour else {
        return;
    };
    for stop in tour.stops() {
        if kb.location(stop.value).is_none() {
            out.push_with(&TOUR_UNKNOWN_LOCATION, || Diagnostic::new(&TOUR_UNKNOWN_LOCATION,
                    stop.span,
                    format!(
                        "the tour visits location {}, which does not exist: the robot cannot find it",
                        stop.value
                    ),
                )
                .at_location(Some(stop.value))
                .with_help("add the location, or correct the id"),
            );
        }
    }
}
