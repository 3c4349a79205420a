use crate::diagnostic::Diagnostic;
use crate::diagnostic::Diagnostics;
use crate::model::Location;
use crate::reader::line::word_pieces;
use crate::render::clip;
use crate::robot::Reader;
use crate::rules::compat::compat_too_many_cultural_keys::{
    crashes, loaded_words, MAX_CULTURAL_KEYS,
};
use crate::rules::declare_rule;
use crate::syntax;

declare_rule! {
    /// ## What it does
    /// Flags a `culturalKnowledge` word with a character other than an ASCII letter or
    /// digit, and says what the robot's reader loads from it.
    ///
    /// ## Why it matters
    /// The reader splits the words at every such character and counts each piece as a word:
    /// `Deictic_Shape` loads two words, `Deictic_Shape` and `Shape`; `Bow's` loads `Bow's`
    /// and `s`. Its buffer holds two words, so two such words overflow it and crash the
    /// reader (a segmentation fault while the robot starts).
    ///
    /// ## Example
    /// ```text
    /// culturalKnowledge             1 Deictic_Shape Bow's
    /// ```
    /// Write the culture knowledge base's keys in letters and digits only: `DeicticShape`.
    pub static COMPAT_CULTURAL_WORD_SPLIT = {
        name: "compat-cultural-word-split",
        category: Compat,
        severity: Error,
        fixable: false,
        summary: "a culturalKnowledge word with a character other than an ASCII letter or digit",
    };
}

/// The reader's buffer of culturalKnowledge words.
const WORD_BUFFER: usize = MAX_CULTURAL_KEYS;

/// Two words that the reader splits overflow its buffer and crash it (SPEC §2.12).
const CRASHING_SPLIT_WORDS: usize = 2;

/// How many of the words the reader splits in two or more.
fn split_words(words: &str) -> usize {
    syntax::tokens(words, 0)
        .filter(|(_, word)| word_pieces(word).len() > 1)
        .count()
}

/// Checks the culturalKnowledge words of `location`, if `reader` reads them.
pub fn check(location: &Location<'_>, reader: Reader, out: &mut Diagnostics) {
    let Some(words) = location
        .cultural_knowledge()
        .filter(|_| reader.reads(crate::model::Key::CulturalKnowledge))
    else {
        return;
    };
    if words
        .value
        .bytes()
        .all(|b| b.is_ascii_alphanumeric() || syntax::is_blank(b))
    {
        return;
    }
    let tokens: Vec<_> = syntax::tokens(words.value, words.span.start as usize).collect();
    let loaded = loaded_words(words.value);
    let split = split_words(words.value);
    let crashing = crashes(location, reader);
    for (index, (span, word)) in tokens.iter().enumerate() {
        let pieces = word_pieces(word);
        // A first word that only loses leading symbols is `compat-leading-symbol`'s.
        if pieces == [*word] || (index == 0 && pieces.len() == 1) {
            continue;
        }
        let consequence = if crashing && split >= CRASHING_SPLIT_WORDS {
            " Two such words overflow its buffer of two words: the reader crashes while the robot starts.".to_string()
        } else if crashing {
            format!(
                " With the others that makes {loaded} words, more than its buffer holds ({WORD_BUFFER}): the reader crashes while the robot starts."
            )
        } else if loaded > WORD_BUFFER {
            format!(
                " With the others that makes {loaded} words, more than its buffer holds ({WORD_BUFFER})."
            )
        } else {
            String::new()
        };
        let listed: Vec<String> = pieces.iter().map(|piece| format!("`{piece}`")).collect();
        out.push_with(&COMPAT_CULTURAL_WORD_SPLIT, || {
            Diagnostic::new(
                &COMPAT_CULTURAL_WORD_SPLIT,
                *span,
                format!(
                    "the robot's reader splits `{}` at each character that is not a letter or digit and loads {}: {}.{consequence}",
                    clip::shown(word),
                    match pieces.len() {
                        1 => "1 word".to_string(),
                        n => format!("{n} words"),
                    },
                    if listed.is_empty() { "nothing".to_string() } else { clip::shown(&listed.join(", ")).into_owned() }
                ),
            )
            .at_location(Some(location.id))
            .with_help("write the word in ASCII letters and digits only")
        });
    }
}
