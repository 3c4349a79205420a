//! The robot's reader as fixed facts, before any file is read: its versions and their
//! buffers ([`Reader`]), the keys, dialects and languages of the format it reads
//! ([`keys`]), and how the C library it calls reads one word or number of a line
//! ([`scan`]); what its text-to-speech speaks, and how fast ([`speech`]). The model is
//! built by these facts; what a version loads from a whole file is [`crate::reader`]'s.

pub mod key_buffer;
pub mod keys;
pub mod scan;
pub mod speech;
mod version;

pub use keys::{Dialect, Key, Language, Phase, ValueKind};
pub use version::Reader;
