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

/// One language, or all three side by side (`--lang all`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Languages {
    One(Language),
    All,
}

impl Languages {
    /// The languages chosen, in the knowledge base's order.
    pub fn each(self) -> Vec<Language> {
        match self {
            Languages::One(language) => vec![language],
            Languages::All => Language::ALL.to_vec(),
        }
    }
}

/// The clap parser of `--lang` that also takes `all`.
pub fn parser_or_all() -> impl TypedValueParser<Value = Languages> {
    let spellings = SPELLINGS.map(|(spelling, _)| spelling);
    PossibleValuesParser::new(spellings.into_iter().chain(["all"])).try_map(|text| match text {
        text if text.eq_ignore_ascii_case("all") => Ok(Languages::All),
        text => parse(&text).map(Languages::One).ok_or("unknown language"),
    })
}

/// Serializes a language as its name (`isiZulu`), as the JSON of `tour` writes it.
pub fn serialize_name<S: serde::Serializer>(language: &Language, s: S) -> Result<S::Ok, S::Error> {
    s.serialize_str(language.name())
}
