//! Text from a knowledge base in SVG and HTML: escaped for the terminal's sake first (no
//! control character is even valid in XML 1.0), then for markup.

use std::borrow::Cow;

use super::escape::escape;

/// `text` safe inside an element or a quoted attribute of SVG or HTML.
pub fn markup(text: &str) -> Cow<'_, str> {
    let text = escape(text);
    if !text.contains(['&', '<', '>', '"', '\'']) {
        return text;
    }
    let mut out = String::with_capacity(text.len() + 16);
    for ch in text.chars() {
        match ch {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&#39;"),
            ch => out.push(ch),
        }
    }
    Cow::Owned(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn markup_and_controls_are_escaped() {
        assert_eq!(markup("Pepper's <b>"), "Pepper&#39;s &lt;b&gt;");
        assert_eq!(markup("a\u{1b}[31m"), "a\\u{001B}[31m");
        assert!(matches!(markup("plain"), Cow::Borrowed("plain")));
    }
}
