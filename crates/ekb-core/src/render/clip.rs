//! Long file text, shown short: a value of the file may be megabytes long (a pasted book in
//! one message), and every place that shows one — a table cell, a quote in a finding, a line
//! of the tour — shows at most [`SHOWN_CHARS`] characters of it, then how many more there
//! are. Output stays proportional to what a person can read, and drawing it (wrapping,
//! measuring a table) stays fast, whatever the file.

use std::borrow::Cow;

use super::escape::escape;

/// The most characters of one value that are shown.
pub const SHOWN_CHARS: usize = 300;

/// The first [`SHOWN_CHARS`] characters of `text`, and how many characters follow them.
pub fn cut(text: &str) -> (&str, usize) {
    // A character is at most 4 bytes: text this short is shown whole, uncounted.
    if text.len() <= SHOWN_CHARS {
        return (text, 0);
    }
    match text.char_indices().nth(SHOWN_CHARS) {
        Some((end, _)) => (&text[..end], text[end..].chars().count()),
        None => (text, 0),
    }
}

/// `text`, escaped, cut after [`SHOWN_CHARS`] characters: `the robot greets… (49999700 more
/// characters)`.
pub fn shown(text: &str) -> Cow<'_, str> {
    match cut(text) {
        (_, 0) => escape(text),
        (head, more) => Cow::Owned(format!("{}{}", escape(head), more_note(more))),
    }
}

/// `text` in double quotes, escaped and cut as [`shown`] cuts it, the note after the quote.
pub fn quoted(text: &str) -> String {
    match cut(text) {
        (_, 0) => format!("\"{}\"", escape(text)),
        (head, more) => format!(
            "\"{}…\"{}",
            escape(head),
            more_note(more).trim_start_matches('…')
        ),
    }
}

/// `… (N more characters)`, after a cut.
fn more_note(more: usize) -> String {
    let s = if more == 1 { "" } else { "s" };
    format!("… ({more} more character{s})")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn short_text_is_shown_whole() {
        assert_eq!(shown("Roomba"), "Roomba");
        assert_eq!(quoted("Roomba"), "\"Roomba\"");
        let exactly = "é".repeat(SHOWN_CHARS);
        assert_eq!(shown(&exactly), exactly);
    }

    #[test]
    fn long_text_is_cut_and_counted_in_characters() {
        let long = "é".repeat(SHOWN_CHARS + 5);
        let head = "é".repeat(SHOWN_CHARS);
        assert_eq!(shown(&long), format!("{head}… (5 more characters)"));
        assert_eq!(quoted(&long), format!("\"{head}…\" (5 more characters)"));
        let one_more = "a".repeat(SHOWN_CHARS + 1);
        assert!(shown(&one_more).ends_with("a… (1 more character)"));
    }

    #[test]
    fn what_is_shown_is_escaped() {
        let long = format!("\u{1b}[31m{}", "a".repeat(SHOWN_CHARS));
        assert!(shown(&long).starts_with("\\u{001B}[31m"));
        assert!(!quoted(&long).contains('\u{1b}'));
    }
}
