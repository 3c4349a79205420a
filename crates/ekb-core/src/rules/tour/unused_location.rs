use crate::diagnostic::Diagnostic;
use crate::diagnostic::Diagnostics;
use crate::model::Location;
use crate::rules::{declare_rule, LocationContext};

declare_rule! {
    /// ## What it does
    /// Notes a location that no tour stop visits.
    ///
    /// ## Why it matters
    /// It may be intended (a location kept for the receptionist scenario or a future
    /// tour), but it is often a stop that was dropped from the tour by mistake.
    ///
    /// ## Example
    /// ```text
    /// tourSpecification 1 2      <- locations 1, 3, 4 and 5 are never visited
    /// ```
    pub static UNUSED_LOCATION = {
        name: "unused-location",
        category: Tour,
        severity: Info,
        fixable: false,
        summary: "a location that no tour stop visits",
    };
}

pub fn check(location: &Location<'_>, context: &LocationContext<'_>, out: &mut Diagnostics) {
    let Some(visited) = &context.visited else {
        return; // tour-missing says it all
    };
    if !visited.contains(&location.id) {
        out.push_with(&UNUSED_LOCATION, || {
            Diagnostic::new(
                &UNUSED_LOCATION,
                location.first_line,
                format!(
                    "location {} is not on the tour: the robot will never go there",
                    location.id
                ),
            )
            .at_location(Some(location.id))
            .with_help(format!(
                "add {} to `tourSpecification` if visitors should see it",
                location.id
            ))
        });
    }
}
