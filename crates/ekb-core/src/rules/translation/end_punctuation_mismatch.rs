use super::Message;
use crate::diagnostic::Diagnostics;
use crate::rules::declare_rule;

declare_rule! {
    /// ## What it does
    /// Flags a translation whose final punctuation differs from its English: the English
    /// ends in `.`, `?`, `!`, `:` or `…` (three dots count as `…`) and the translation does
    /// not, or ends in another of them, or the other way round. `…` and `.` both end a
    /// sentence, as Weblate's checks take them: one against the other is no finding.
    /// Closing quotes and brackets after the mark are looked through. English messages of 4 characters or fewer are
    /// not compared (`OK`, `Hi!`). Weblate's checks of the same kind: *Mismatched full
    /// stop* (`end_stop`), *question mark* (`end_question`), *exclamation mark*
    /// (`end_exclamation`), *colon* (`end_colon`) and *ellipsis* (`end_ellipsis`).
    ///
    /// ## Why it matters
    /// The robot's text-to-speech raises its voice at a question mark and pauses at a full
    /// stop: a question that ends without one is spoken as a statement. A missing mark can
    /// also be the sign of a sentence cut short.
    ///
    /// ## Example
    /// ```text
    /// preGestureMessageEnglish      3 Would you like a tour of the lab?
    /// preGestureMessageKinyarwanda  3 Wakwifuza gutemberezwa muri laboratwari
    /// ```
    pub static END_PUNCTUATION_MISMATCH = {
        name: "end-punctuation-mismatch",
        category: Translation,
        severity: Warning,
        fixable: false,
        summary: "`.` `?` `!` `:` `…` at the end of the English and not of the translation, or the other way round",
    };
}

/// English messages this short are not compared (as Weblate does not).
const SHORTEST_COMPARED: usize = 5;

pub fn check(message: &Message<'_>, out: &mut Diagnostics) {
    let Some(english) = message.english else {
        return;
    };
    // A text of this many bytes has this many characters (at most 4 bytes each): most
    // English messages, answered without reading them.
    let surely_long = english.value.len() >= 4 * SHORTEST_COMPARED;
    if !surely_long && english.value.chars().nth(SHORTEST_COMPARED - 1).is_none() {
        return;
    }
    let (expected, found) = (end_mark(english.value), end_mark(message.text.value));
    if ends_alike(expected, found) {
        return;
    }
    let text = message.text.value;
    let last = text.char_indices().next_back().map_or(0, |(at, _)| at);
    let span = message.span_of(last..text.len());
    let name = |mark: Option<&str>| mark.map_or("no mark".to_string(), |m| format!("`{m}`"));
    out.push_with(&END_PUNCTUATION_MISMATCH, || {
        message
            .finding(
                &END_PUNCTUATION_MISMATCH,
                span,
                format!(
                    "{} ends with {} where the English ends with {}: the robot's speech will \
                     {}",
                    message.describe(),
                    name(found),
                    name(expected),
                    if expected == Some("?") || found == Some("?") {
                        "ask where the English states, or state where it asks"
                    } else {
                        "pause and pitch the sentence differently in each language"
                    }
                ),
            )
            .with_label(english.span, "the English message")
            .with_help(match expected {
                Some(mark) => format!("end the translation with `{mark}` too, as the English does"),
                None => "end the translation without a mark, as the English does".to_string(),
            })
    });
}

/// Whether two end marks end a sentence alike: the same mark, or `…` and `.` (a sentence
/// trailing off ends all the same; translators often write one for the other).
fn ends_alike(english: Option<&str>, translation: Option<&str>) -> bool {
    let full_stop = |mark| matches!(mark, Some("." | "…"));
    english == translation || (full_stop(english) && full_stop(translation))
}

/// The punctuation mark a text ends with, closing quotes and brackets looked through:
/// `.`, `?`, `!`, `:` or `…` (for `…` and `...`).
fn end_mark(text: &str) -> Option<&'static str> {
    // Most messages end with a letter: no mark, and nothing to look through.
    if text
        .as_bytes()
        .last()
        .is_some_and(u8::is_ascii_alphanumeric)
    {
        return None;
    }
    let text = text.trim_end_matches(['"', '\'', '”', '’', '»', ')', ']']);
    if text.ends_with("...") || text.ends_with('…') {
        return Some("…");
    }
    match text.chars().next_back()? {
        '.' => Some("."),
        '?' => Some("?"),
        '!' => Some("!"),
        ':' => Some(":"),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn marks() {
        assert_eq!(end_mark("Would you like a tour of the lab?"), Some("?"));
        assert_eq!(end_mark("Murabeho"), None);
        assert_eq!(end_mark("He said \"Hello.\""), Some("."));
        assert_eq!(end_mark("Wait..."), Some("…"));
        assert_eq!(end_mark("Wait…"), Some("…"));
        assert_eq!(end_mark(""), None);
    }
}
