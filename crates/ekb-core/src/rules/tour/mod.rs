//! Rules about `tourSpecification`: the order in which the robot visits locations.

pub mod tour_count_mismatch;
pub mod tour_duplicate_spec;
pub mod tour_empty;
pub mod tour_missing;
pub mod tour_repeated_stop;
pub mod tour_too_long;
pub mod tour_unknown_location;
pub mod unused_location;
