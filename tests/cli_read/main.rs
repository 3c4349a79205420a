//! The reading commands end to end: `locations`, `show`, `tour`, `diff` and `export`, on the
//! seed file and on fixtures of both dialects (`tests/fixtures/read/`).

mod common;
mod diff;
mod export;
mod locations;
mod show;
mod tour;
