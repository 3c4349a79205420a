//! The robot's reader, version by version (SPEC §2): the one place that knows how each
//! version loads a file — how it cuts lines, which keys it reads, where it finds each
//! value, what it drops and keeps, and the tree its order of ids builds.
//!
//! [`load`] runs a version over a file and gives what the robot holds ([`Loaded`]), for
//! `export --as-loaded` and the views; the compatibility rules ask the same questions of
//! single lines ([`line::read`]) and of the written model.

pub mod buffer;
pub mod export;
pub mod line;
mod load;
pub mod tree;
pub mod view;

pub use load::{
    carriage_returns_at_cuts, chunks, is_carriage_return_at_a_cut, load, load_fields, Field,
    Loaded, LoadedLocation, LoadedTour, Locations,
};
