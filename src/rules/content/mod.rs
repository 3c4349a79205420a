//! Rules about what the robot says and where it points.

pub mod gesture_behind_robot;
pub mod gesture_target_sums_to_zero;
pub mod repeated_word;
pub mod theta_out_of_range;
pub mod trailing_whitespace;
pub mod untranslated_message;

use crate::model::{Language, Location, Phase, Value};

/// Every message of a location with its phase and language, skipping absent ones.
pub(crate) fn messages<'l, 'a>(
    location: &'l Location<'a>,
) -> impl Iterator<Item = (Phase, Language, Value<&'a str>)> + 'l {
    Phase::ALL.into_iter().flat_map(move |phase| {
        Language::ALL.into_iter().filter_map(move |language| {
            location
                .message(phase, language)
                .map(|value| (phase, language, value))
        })
    })
}
