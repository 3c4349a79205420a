//! The culture knowledge base's rules (SPEC §11): its keys and values against the types
//! file, and the hazards of the robot's line reader that it shares with the environment
//! knowledge base's (SPEC §2: the line buffer, a last letter lost, CRLF).

pub mod culture_crlf;
pub mod culture_duplicate_key;
pub mod culture_line_too_long;
pub mod culture_no_final_newline;
pub mod culture_type_mismatch;
pub mod culture_unknown_key;
pub mod culture_unknown_type;
pub mod culture_word_too_long;
