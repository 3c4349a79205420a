//! `--lang`: the languages' names and codes of the core ([`ekb_core::present::language`]),
//! and the command line's parser of them.

use clap::builder::{PossibleValuesParser, TypedValueParser};

pub use ekb_core::present::language::*;

use crate::model::Language;

/// The clap parser of `--lang` (give the argument `ignore_case = true`).
pub fn parser() -> impl TypedValueParser<Value = Language> {
    PossibleValuesParser::new(SPELLINGS.map(|(spelling, _)| spelling))
        .try_map(|text| parse(&text).ok_or("unknown language"))
}
