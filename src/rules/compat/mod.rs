//! Rules for what the robot's own reader would silently load differently (SPEC §2).

pub mod compat_bom;
pub mod compat_crlf;
pub mod compat_leading_symbol;
pub mod compat_line_too_long;
pub mod compat_no_final_newline;
pub mod compat_too_many_cultural_keys;
