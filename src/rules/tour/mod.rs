//! Rules about `tourSpecification`: the order in which the robot visits locations.

pub mod tour_count_mismatch;
pub mod tour_duplicate_spec;
pub mod tour_empty;
pub mod tour_missing;
pub mod tour_repeated_stop;
pub mod tour_too_long;
pub mod tour_unknown_location;
pub mod unused_location;

use crate::model::build::tour_items;
use crate::model::Tour;

/// How many ids follow `n` in the tour, valid or not: the robot counts them all, so an
/// invalid id is an `invalid-id`, not also a count mismatch.
pub(crate) fn listed_stops(tour: &Tour, source: &str) -> u64 {
    let items = tour_items(tour.span.text(source), tour.span.start as usize).count();
    items.saturating_sub(1) as u64
}
