//! The reading commands end to end: `locations`, `show`, `tour`, `diff`, `export` and
//! `mission`, on the seed file, on fixtures of both dialects (`tests/fixtures/read/`) and
//! on the robot's mission set-up (`tests/fixtures/mission/`).

mod common;
mod diff;
mod export;
#[path = "../support/lab_map.rs"]
mod lab_map;
mod locations;
mod mission;
mod show;
mod tour;
