//! Small facts about text values shared by rules and renderers.

/// The words of a value, split on spaces and tabs.
pub fn words(text: &str) -> impl Iterator<Item = &str> {
    text.split([' ', '\t']).filter(|word| !word.is_empty())
}

/// Whether a message is a placeholder such as `No message in isiZulu` rather than a message.
pub fn is_placeholder(text: &str) -> bool {
    // Run on every message: compare in place rather than lowercase a copy.
    let text = text.trim().as_bytes();
    let starts_with = |prefix: &str| {
        text.len() >= prefix.len() && text[..prefix.len()].eq_ignore_ascii_case(prefix.as_bytes())
    };
    starts_with("no message")
        || starts_with("no translation")
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
        assert!(!is_placeholder("Murakaza neza"));
    }
}
