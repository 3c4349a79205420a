//! A language by name or by ISO 639 code, ignoring case (`--lang`, `ekb.toml`):
//! `english`/`en`/`eng`, `isizulu`/`zulu`/`zu`/`zul`, `kinyarwanda`/`rw`/`kin`.

use crate::model::Language;

/// Every accepted spelling, lower case, with the language it means; the command line lists
/// them when given something else.
pub const SPELLINGS: [(&str, Language); 11] = [
    ("english", Language::English),
    ("isizulu", Language::IsiZulu),
    ("kinyarwanda", Language::Kinyarwanda),
    ("zulu", Language::IsiZulu),
    ("ikinyarwanda", Language::Kinyarwanda),
    // ISO 639-1, then 639-2 and 639-3 (the same three letters for these languages).
    ("en", Language::English),
    ("zu", Language::IsiZulu),
    ("rw", Language::Kinyarwanda),
    ("eng", Language::English),
    ("zul", Language::IsiZulu),
    ("kin", Language::Kinyarwanda),
];

/// The language a name or code means, ignoring case.
pub fn parse(text: &str) -> Option<Language> {
    SPELLINGS
        .iter()
        .find(|(spelling, _)| spelling.eq_ignore_ascii_case(text))
        .map(|&(_, language)| language)
}

/// The two-letter code: `EN`, `ZU`, `RW`.
pub fn code(language: Language) -> &'static str {
    match language {
        Language::English => "EN",
        Language::IsiZulu => "ZU",
        Language::Kinyarwanda => "RW",
    }
}

/// The ISO 639-1 code, as gettext's `Language:` header and XLIFF write it: `en`, `zu`, `rw`.
pub fn iso_code(language: Language) -> &'static str {
    match language {
        Language::English => "en",
        Language::IsiZulu => "zu",
        Language::Kinyarwanda => "rw",
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
        assert!(SPELLINGS.iter().all(|(name, _)| parse(name).is_some()));
    }

    #[test]
    fn iso_639_codes_of_every_part_and_the_names_people_use() {
        for (text, language) in [
            ("eng", Language::English),
            ("ENG", Language::English),
            ("zul", Language::IsiZulu),
            ("Zulu", Language::IsiZulu),
            ("isiZulu", Language::IsiZulu),
            ("kin", Language::Kinyarwanda),
            ("Kinyarwanda", Language::Kinyarwanda),
            ("Ikinyarwanda", Language::Kinyarwanda),
        ] {
            assert_eq!(parse(text), Some(language), "{text}");
        }
        for language in Language::ALL {
            assert_eq!(parse(iso_code(language)), Some(language));
            assert_eq!(parse(code(language)), Some(language));
        }
    }
}
