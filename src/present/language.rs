//! `--lang`: a language by name (`english`, `isizulu`, `kinyarwanda`, any case) or by code
//! (`en`, `zu`, `rw`).

use clap::builder::{PossibleValuesParser, TypedValueParser};

use crate::model::Language;

/// Every accepted spelling, lower case; clap lists them when given something else.
const NAMES: [&str; 6] = ["english", "isizulu", "kinyarwanda", "en", "zu", "rw"];

/// The language a name or code means, ignoring case.
pub fn parse(text: &str) -> Option<Language> {
    match text.to_ascii_lowercase().as_str() {
        "english" | "en" => Some(Language::English),
        "isizulu" | "zu" => Some(Language::IsiZulu),
        "kinyarwanda" | "rw" => Some(Language::Kinyarwanda),
        _ => None,
    }
}

/// The clap parser of `--lang` (give the argument `ignore_case = true`).
pub fn parser() -> impl TypedValueParser<Value = Language> {
    PossibleValuesParser::new(NAMES).try_map(|text| parse(&text).ok_or("unknown language"))
}

/// The two-letter code: `EN`, `ZU`, `RW`.
pub fn code(language: Language) -> &'static str {
    match language {
        Language::English => "EN",
        Language::IsiZulu => "ZU",
        Language::Kinyarwanda => "RW",
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_and_codes() {
        assert_eq!(parse("isiZulu"), Some(Language::IsiZulu));
        assert_eq!(parse("ISIZULU"), Some(Language::IsiZulu));
        assert_eq!(parse("Rw"), Some(Language::Kinyarwanda));
        assert_eq!(parse("en"), Some(Language::English));
        assert_eq!(parse("french"), None);
        assert!(NAMES.iter().all(|name| parse(name).is_some()));
    }
}
