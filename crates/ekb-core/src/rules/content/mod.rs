//! Rules about what the robot says and where it points.

pub mod gesture_behind_robot;
pub mod gesture_target_sums_to_zero;
pub mod repeated_word;
pub mod theta_out_of_range;
pub mod trailing_whitespace;
pub mod untranslated_message;
