//! Arbitrary bytes through `ekb check`, `ekb fmt`, `ekb fix` and `ekb export | ekb import`,
//! asserting the invariants of `tests/invariants/` (shared with `tests/robustness.rs`): no
//! panic, valid spans, every format renders, fmt and fix idempotent, fmt keeps the model,
//! and a valid file's export imports to the same model.
#![no_main]

#[path = "../../tests/invariants/mod.rs"]
mod invariants;

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| invariants::survives(data));
