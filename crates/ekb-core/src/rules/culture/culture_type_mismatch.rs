use crate::diagnostic::Diagnostic;
use crate::diagnostic::Diagnostics;
use crate::mission::culture::{c_integer, is_integer, CultureKnowledgeBase, ValueType, ValueTypes};
use crate::rules::declare_rule;

declare_rule! {
    /// ## What it does
    /// Flags a value that does not read as its key's type: a `NUMBER` that is not an
    /// integer or does not fit in a C `int`, a `WORD` of several words (or none), a
    /// `PHRASE` with no letter or digit, or on an indented line, and a value for a key
    /// typed `UNDEFINED`.
    ///
    /// ## Why it matters
    /// The robot reads a `NUMBER` with `%d` (`2.5` loads as 2, `two` not at all and the
    /// value before stays, `4294967297` as 1) and a `WORD` with `%s` (`FACE AND OBJECT`
    /// loads as `FACE`; a line with no value reads the value word of a line before). It
    /// copies a `PHRASE` from the first letter or digit at the key's length from the
    /// start of the line: an indented line loses or gains letters, and a line with no
    /// letter or digit after its key is copied from what earlier lines left in the line
    /// buffer. It ignores the value of an `UNDEFINED` key: the robot behaves on something
    /// other than what the file says.
    ///
    /// ## Example
    /// ```text
    /// pauseDuration                             2.5
    /// focusofAttentionTargetExplanationTo       FACE AND OBJECT
    /// ```
    pub static CULTURE_TYPE_MISMATCH = {
        name: "culture-type-mismatch",
        category: Culture,
        severity: Error,
        fixable: false,
        summary: "a `NUMBER` that is not an integer, a `WORD` of several words, a value for an `UNDEFINED` key",
    };
}

pub fn check(culture: &CultureKnowledgeBase<'_>, types: &ValueTypes<'_>, out: &mut Diagnostics) {
    for entry in culture.entries.iter().filter(|e| !e.continuation) {
        let Some(value_type) = culture.value_type(types, entry.key) else {
            continue;
        };
        let key = entry.key;
        let (span, message, help) = match (value_type, entry.first_word()) {
            (ValueType::Number, Some((word, span))) if !is_integer(word) => (
                span,
                format!("`{key}` is a NUMBER, and `{word}` is not an integer: the robot reads only its leading digits, if any"),
                "write a whole number, such as `2`".to_string(),
            ),
            (ValueType::Number, Some((word, span))) if word.parse::<i32>().is_err() => (
                span,
                format!("`{key}` is a NUMBER, and `{word}` does not fit in a C int: the robot holds {}", c_integer(word).unwrap_or_default()),
                "write a whole number between -2147483648 and 2147483647".to_string(),
            ),
            (ValueType::Number | ValueType::Word, None) => (
                entry.key_span,
                format!("`{key}` has no value: the robot reads the value word of a line before in its place"),
                format!("give `{key}` a value"),
            ),
            (ValueType::Phrase, _) if culture.phrase_start(entry).is_none() => (
                entry.key_span,
                format!("`{key}` is a PHRASE with no letter or digit after its key: the robot copies what earlier lines left in its line buffer instead"),
                format!("give `{key}` its phrase"),
            ),
            (ValueType::Phrase, _) if entry.key_span.start != entry.span.start => (
                entry.key_span,
                format!("the line of `{key}` is indented: the robot counts the key's length from the start of the line and holds \"{}\"", culture.phrase(entry)),
                "start the line with its key".to_string(),
            ),
            (ValueType::Word, Some((word, _))) if entry.words.len() > 1 => (
                entry.rest_span,
                format!("`{key}` is a WORD, and this is {} words: the robot reads only `{word}`", entry.words.len()),
                "join the words (`FACE_AND_OBJECT`), or declare the key PHRASE in the types file".to_string(),
            ),
            (ValueType::Undefined, Some(_)) => (
                entry.rest_span,
                format!("`{key}` is typed UNDEFINED: the robot ignores this value"),
                format!("declare `{key}` with its type (NUMBER, WORD or PHRASE) in the types file"),
            ),
            _ => continue,
        };
        out.push(Diagnostic::new(&CULTURE_TYPE_MISMATCH, span, message).with_help(help));
    }
}
