//! Terminal safety: text from a knowledge base is untrusted, so control characters and
//! bidirectional overrides are shown as escapes, never written raw.

use std::borrow::Cow;

/// Whether `ch` could change what a terminal shows, or hide: controls, bidi overrides and
/// isolates, and zero-width characters (including the byte-order mark).
pub fn is_unsafe(ch: char) -> bool {
    (ch.is_control() && ch != '\n')
        || matches!(
            ch,
            '\u{202A}'..='\u{202E}'
                | '\u{2066}'..='\u{2069}'
                | '\u{200B}'..='\u{200F}'
                | '\u{061C}'
                | '\u{FEFF}'
        )
}

/// `text` with every unsafe character written as `\u{…}` (tab as `\t`).
pub fn escape(text: &str) -> Cow<'_, str> {
    // Nearly all text is printable ASCII: checking bytes first (without stopping early, so
    // that the check is vectorised) spares decoding characters.
    let printable = |ok, &b: &u8| ok & matches!(b, b' '..=b'~' | b'\n');
    if text.as_bytes().iter().fold(true, printable) || !text.chars().any(is_unsafe) {
        return Cow::Borrowed(text);
    }
    let mut out = String::with_capacity(text.len() + 8);
    for ch in text.chars() {
        match ch {
            '\t' => out.push_str("\\t"),
            ch if is_unsafe(ch) => out.push_str(&format!("\\u{{{:04X}}}", ch as u32)),
            ch => out.push(ch),
        }
    }
    Cow::Owned(out)
}

/// `text` as [`escape`] writes it, with every space other than the plain one (U+0020) escaped
/// too: for a key or an id, where such a space looks like a separator and is none.
pub fn escape_odd_spaces(text: &str) -> Cow<'_, str> {
    if !text.chars().any(is_odd_space) {
        return escape(text);
    }
    let mut out = String::with_capacity(text.len() + 8);
    for ch in text.chars() {
        match ch {
            '\t' => out.push_str("\\t"),
            ch if is_unsafe(ch) || is_odd_space(ch) => {
                out.push_str(&format!("\\u{{{:04X}}}", ch as u32))
            }
            ch => out.push(ch),
        }
    }
    Cow::Owned(out)
}

/// Whitespace that is not a plain space: a tab, a no-break space, an em space, …
pub fn is_odd_space(ch: char) -> bool {
    ch.is_whitespace() && ch != ' '
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn odd_spaces_are_escaped_where_they_would_pass_for_plain_ones() {
        assert_eq!(escape_odd_spaces("key 1"), "key 1");
        assert_eq!(escape_odd_spaces("key\u{A0}1"), "key\\u{00A0}1");
        assert_eq!(
            escape_odd_spaces("a\u{2003}b\tc\u{202E}"),
            "a\\u{2003}b\\tc\\u{202E}"
        );
    }

    #[test]
    fn escapes_controls_and_bidi() {
        assert_eq!(escape("plain isiZulu"), "plain isiZulu");
        assert_eq!(escape("a\x1b[31mb"), "a\\u{001B}[31mb");
        assert_eq!(escape("x\u{202E}y\tz"), "x\\u{202E}y\\tz");
        assert_eq!(escape("a\rb\0"), "a\\u{000D}b\\u{0000}");
        assert_eq!(escape("\u{FEFF}key"), "\\u{FEFF}key");
    }
}
