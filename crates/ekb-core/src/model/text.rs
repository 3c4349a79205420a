//! Small facts about text values shared by rules and renderers.

/// The words of a value, split on spaces and tabs.
pub fn words(text: &str) -> impl Iterator<Item = &str> {
    text.split([' ', '\t']).filter(|word| !word.is_empty())
}

/// Whether a message is a placeholder such as `No message in isiZulu` rather than a message.
#[inline]
pub fn is_placeholder(text: &str) -> bool {
    // Run on every message: inlined, and answered from the first byte for nearly all.
    // Nearly every message is a message, and starts with a letter no placeholder starts
    // with (a value starts after the blanks, so only a rare Unicode space needs the trim
    // to see that).
    let ruled_out = text.as_bytes().first().is_some_and(|&first| {
        first.is_ascii_graphic() && !matches!(first, b'n' | b'N' | b't' | b'T' | b'-' | b'.')
    });
    !ruled_out && looks_like_placeholder(text)
}

/// [`is_placeholder`] past its first byte: compares in place rather than lowercase a copy.
fn looks_like_placeholder(text: &str) -> bool {
    let text = text.trim().as_bytes();
    if !matches!(text.first(), Some(b'n' | b'N' | b't' | b'T' | b'-' | b'.')) {
        return false;
    }
    // The phrase as a whole: `No message in isiZulu`, but not `No messages are lost`.
    let starts_with_phrase = |phrase: &str| {
        text.len() >= phrase.len()
            && text[..phrase.len()].eq_ignore_ascii_case(phrase.as_bytes())
            && text.get(phrase.len()).is_none_or(|&next| next == b' ')
    };
    starts_with_phrase("no message")
        || starts_with_phrase("no translation")
        || ["todo", "tbd", "-", "n/a", "none", "..."]
            .iter()
            .any(|word| text.eq_ignore_ascii_case(word.as_bytes()))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn placeholders() {
        assert!(is_placeholder("No message in isiZulu"));
        assert!(is_placeholder("TODO"));
        assert!(!is_placeholder("Nomessage is fine as a word"));
        assert!(!is_placeholder("No messages are lost when you follow me"));
        assert!(!is_placeholder("Murakaza neza"));
        assert!(is_placeholder("\u{a0}TBD "));
        assert!(!is_placeholder(""));
    }
}
