//! Small facts about text values shared by rules and renderers.

/// The words of a value, split on spaces and tabs.
pub fn words(text: &str) -> impl Iterator<Item = &str> {
    text.split([' ', '\t']).filter(|word| !word.is_empty())
}

/// Whether a message is a placeholder such as `No message in isiZulu` rather than a message.
pub fn is_placeholder(text: &str) -> bool {
    // Run on every message: compare in place rather than lowercase a copy.
    let text = text.trim().as_bytes();
    // Nearly every message is a message: most start with a letter no placeholder starts with.
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
    }
}
