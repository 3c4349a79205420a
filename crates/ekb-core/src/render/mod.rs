//! What every face shows of a file the same way: its text escaped for a terminal or a log
//! ([`escape`]), a quoted value clipped ([`clip`]), JSON escaped alike ([`safe_json`]), and
//! findings located by line and column ([`located`]). The output formats of `ekb check`
//! are the command line's (`ekb::render`).

pub mod clip;
pub mod escape;
pub mod located;
pub mod safe_json;

pub use located::{FileReport, LocatedDiagnostic};
