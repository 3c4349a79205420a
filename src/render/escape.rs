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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn escapes_controls_and_bidi() {
        assert_eq!(escape("plain isiZulu"), "plain isiZulu");
        assert_eq!(escape("a\x1b[31mb"), "a\\u{001B}[31mb");
        assert_eq!(escape("x\u{202E}y\tz"), "x\\u{202E}y\\tz");
        assert_eq!(escape("a\rb\0"), "a\\u{000D}b\\u{0000}");
        assert_eq!(escape("\u{FEFF}key"), "\\u{FEFF}key");
    }
}
