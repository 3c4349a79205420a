//! The mission (SPEC §11): the behaviour tree that enacts the tour, and the culture
//! knowledge base it draws its words from, checked with the environment knowledge base.
//!
//! - [`xml`]: the mission's XML, with the place of every element and attribute;
//! - [`tree`]: its behaviour trees, which one runs, what each node element is;
//! - [`include`]: the files it `<include>`s, whose trees it may call;
//! - [`catalogue`]: the nodes BehaviorTree.CPP and the robot know;
//! - [`ports`]: the built-in nodes' typed ports, as BehaviorTree.CPP converts them;
//! - [`culture`]: the culture knowledge base and its types file, as the robot reads them;
//! - [`setup`]: where the robot's configuration folder says the files are;
//! - [`mod@check`]: the files checked together (and each alone, for `ekb check`);
//! - [`outline`] and [`walk`]: `ekb mission tree` and `ekb mission walk`.

pub mod catalogue;
pub mod check;
pub mod culture;
pub mod include;
pub mod outline;
pub mod ports;
pub mod setup;
pub mod tree;
pub mod walk;
pub mod xml;

use crate::model::Language;
use crate::syntax::Span;
use tree::Mission;
use xml::Element;

/// The culture key that holds the mission's language.
pub const LANGUAGE_KEY: &str = "phraseLanguage";

/// The languages the robot accepts, spelt as it compares them.
pub const ROBOT_LANGUAGES: [&str; 3] = ["English", "Kinyarwanda", "IsiZulu"];

/// The language a `phraseLanguage` word means to the robot: exactly one of
/// [`ROBOT_LANGUAGES`].
pub fn robot_language(word: &str) -> Option<Language> {
    match word {
        "English" => Some(Language::English),
        "Kinyarwanda" => Some(Language::Kinyarwanda),
        "IsiZulu" => Some(Language::IsiZulu),
        _ => None,
    }
}

/// The language as the robot spells it in keys: `utilityPhraseIsiZulu4`.
pub fn robot_word(language: Language) -> &'static str {
    match language {
        Language::English => "English",
        Language::Kinyarwanda => "Kinyarwanda",
        Language::IsiZulu => "IsiZulu",
    }
}

/// The culture key of the phrase `SayText name="number"` says in `language`.
pub fn phrase_key(number: &str, language: Language) -> String {
    format!("utilityPhrase{}{number}", robot_word(language))
}

/// A phrase the mission says: a `SayText` the main tree runs, and the key it looks up.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct SaidPhrase<'m> {
    pub node: &'m Element,
    pub key: String,
    /// Where its number is written.
    pub span: Span,
}

/// The phrases of the `SayText` nodes that the main tree runs (those with a number).
pub fn said_phrases(mission: &Mission, language: Language) -> Vec<SaidPhrase<'_>> {
    mission
        .reachable_nodes()
        .filter(|node| tree::node_id(node).map(catalogue::synchronous) == Some("SayText"))
        .filter_map(|node| {
            let name = node.attribute("name")?;
            catalogue::Names::Number
                .allows(&name.value)
                .then(|| SaidPhrase {
                    node,
                    key: phrase_key(&name.value, language),
                    span: name.value_span,
                })
        })
        .collect()
}
