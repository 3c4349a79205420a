//! Small facts about text values shared by rules and renderers.

/// The words of a value, split on spaces and tabs.
pub fn words(text: &str) -> impl Iterator<Item = &str> {
    text.split([' ', '\t']).filter(|word| !word.is_empty())
}

/// Whether a message is a placeholder such as `No message in isiZulu` rather than a message.
pub fn is_placeholder(text: &str) -> bool {
    let lower = text.trim().to_ascii_lowercase();
    let starts_with_phrase = |phrase: &str| {
        lower
            .strip_prefix(phrase)
            .is_some_and(|rest| rest.is_empty() || rest.starts_with(' '))
    };
    starts_with_phrase("no message")
        || starts_with_phrase("no translation")
        || matches!(
            lower.as_str(),
            "todo" | "tbd" | "-" | "n/a" | "none" | "..."
        )
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
