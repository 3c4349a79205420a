//! Rules about the shape of lines: keys, ids, values, and whole locations.

pub mod control_character;
pub mod duplicate_key;
pub mod empty_value;
pub mod invalid_id;
pub mod invalid_number;
pub mod invalid_utf8;
pub mod invalid_value;
pub mod key_case;
pub mod legacy_key;
pub mod missing_field;
pub mod missing_id;
pub mod mixed_dialect;
pub mod not_a_knowledge_base;
pub mod unicode_space;
pub mod unknown_key;
pub mod unused_suppression;
pub mod wrong_arity;
