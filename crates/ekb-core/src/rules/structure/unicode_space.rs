use crate::diagnostic::Diagnostics;
use crate::diagnostic::{Diagnostic, Edit};
use crate::model::{Key, ValueKind};
use crate::rules::declare_rule;
use crate::syntax::{Body, Line, Span};

declare_rule! {
    /// ## What it does
    /// Flags a space other than a plain space or a tab — a no-break space (U+00A0), a narrow
    /// no-break space (U+202F), an em space (U+2003), … — where the fields of a line are
    /// separated: before or after the key, after the id, between the numbers of a pose or a
    /// gesture target, between the words of `culturalKnowledge` or the ids of the tour. The
    /// fix makes each a plain space. Inside a message such a space is text, and is left alone.
    ///
    /// ## Why it matters
    /// Word processors and web pages put these spaces in, and they look exactly like plain
    /// ones. The robot's reader does not take them for spaces: the key and the id become one
    /// unknown word and the line is ignored, or a number stops short and the pose is not read.
    ///
    /// ## Example
    /// ```text
    /// robotLocationDescription␣1 Entrance      <- ␣ is U+00A0, a no-break space
    /// robotLocationPose        1 2.0␣7.8 90
    /// ```
    pub static UNICODE_SPACE = {
        name: "unicode-space",
        category: Structure,
        severity: Error,
        fixable: true,
        summary: "a no-break or other Unicode space between the fields of a line",
    };
}

/// Whether `ch` looks like a space to a person but is none to the robot's reader.
pub fn is_unicode_space(ch: char) -> bool {
    ch.is_whitespace() && !ch.is_ascii()
}

/// Whether `text` has a byte that may start a Unicode space in UTF-8 (U+0085 and U+00A0
/// start with 0xC2, U+1680 with 0xE1, U+2000 to U+205F with 0xE2, U+3000 with 0xE3): most
/// files have none, and one pass over the bytes costs less than a look at every line.
pub fn possible_in(bytes: &[u8]) -> bool {
    memchr::memchr3(0xC2, 0xE2, 0xE3, bytes).is_some() || memchr::memchr(0xE1, bytes).is_some()
}

/// How a finding names `space`: `a no-break space (U+00A0)`.
pub fn name(space: char) -> String {
    match space {
        '\u{A0}' => "a no-break space (U+00A0)".to_string(),
        '\u{202F}' => "a narrow no-break space (U+202F)".to_string(),
        '\u{B}' => "a vertical tab (U+000B)".to_string(),
        '\u{C}' => "a form feed (U+000C)".to_string(),
        other => format!("a Unicode space (U+{:04X})", other as u32),
    }
}

pub fn check(line: &Line, text: &str, out: &mut Diagnostics) {
    if !matches!(line.body, Body::Entry { .. }) {
        return;
    }
    let content = line.content();
    let written = content.text(text);
    if written.is_ascii() || text_past_ascii_fields(written) {
        return;
    }
    let spaces = structural_spaces(written);
    let Some(&(first, space)) = spaces.first() else {
        return;
    };
    let at = |offset: usize, ch: char| {
        let start = content.start as usize + offset;
        Span::new(start, start + ch.len_utf8())
    };
    let edits = spaces
        .iter()
        .map(|&(offset, ch)| Edit::replace(at(offset, ch), " "))
        .collect();
    let more = match spaces.len() {
        1 => String::new(),
        n => format!(" (and {} more on this line)", n - 1),
    };
    out.push(
        Diagnostic::new(
            &UNICODE_SPACE,
            at(first, space),
            format!(
                "{} separates the fields of this line{more}: the robot's reader does not take \
                 it for a space, and misreads the line",
                name(space)
            ),
        )
        .with_help("type a plain space instead (`ekb fix` does)")
        .with_fix("replace with a plain space", edits),
    );
}

/// Whether `content` is a text line whose key, id and the blanks around them come before its
/// first non-ASCII byte: then its Unicode spaces, if any, are text. (Most lines with a
/// non-ASCII letter are messages; this spares them [`structural_spaces`].)
fn text_past_ascii_fields(content: &str) -> bool {
    let first_wide = content.bytes().position(|b| !b.is_ascii());
    let ascii = &content[..first_wide.unwrap_or(content.len())];
    let blanks = [' ', '\t'];
    let fields = ascii.trim_start_matches(blanks);
    let Some((key, rest)) = fields.split_once(blanks) else {
        return false;
    };
    let is_text = Key::from_name(key).is_some_and(|key| key.value_kind() == ValueKind::Text);
    let value = rest
        .trim_start_matches(blanks)
        .split_once(blanks)
        .map(|(_, value)| value.trim_start_matches(blanks));
    is_text && value.is_some_and(|value| !value.is_empty())
}

/// The Unicode spaces of an entry line's `content` that stand between its fields, by byte
/// offset. The fields are split at every space, plain or not: the key, the id (the tour has
/// none), then the value; a text value's own spaces are its text.
fn structural_spaces(content: &str) -> Vec<(usize, char)> {
    let is_space = |ch: char| ch == ' ' || ch == '\t' || is_unicode_space(ch);
    let key_start = content.find(|ch| !is_space(ch)).unwrap_or(content.len());
    let key_end = content[key_start..]
        .find(is_space)
        .map_or(content.len(), |end| key_start + end);
    let key = Key::from_name_ignoring_case(&content[key_start..key_end]);
    let text_value = key.is_none_or(|key| matches!(key.value_kind(), ValueKind::Text));
    let value_start = if text_value {
        // Past the gap, the id, and the gap after it.
        let after_gap = |from: usize| {
            content[from..]
                .find(|ch| !is_space(ch))
                .map_or(content.len(), |at| from + at)
        };
        let id_start = after_gap(key_end);
        let id_end = content[id_start..]
            .find(is_space)
            .map_or(content.len(), |end| id_start + end);
        after_gap(id_end)
    } else {
        content.len()
    };
    content[..value_start]
        .char_indices()
        .filter(|&(_, ch)| is_unicode_space(ch))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spaces_between_fields_count_and_those_inside_a_message_do_not() {
        let spaces = |line: &str| -> Vec<usize> {
            structural_spaces(line)
                .into_iter()
                .map(|(at, _)| at)
                .collect()
        };
        assert_eq!(spaces("robotLocationDescription\u{A0}1 Entrance"), [24]);
        assert_eq!(
            spaces("preGestureMessageEnglish 1\u{2003}Hi\u{A0}there"),
            [26]
        );
        assert_eq!(
            spaces("robotLocationPose 1 2.0\u{A0}7.8\u{202F}90"),
            [23, 28]
        );
        assert_eq!(spaces("tourSpecification 2\u{A0}1 2"), [19]);
        assert!(spaces("preGestureMessageEnglish 1 Hi\u{A0}there").is_empty());
        let fast = text_past_ascii_fields;
        assert!(fast("preGestureMessageEnglish 1 Hi\u{A0}there"));
        assert!(!fast("preGestureMessageEnglish 1\u{A0}Hi there"));
        assert!(!fast("robotLocationPose 1 2.0\u{A0}7.8 90"));
        assert!(!fast("robotLocationDescription\u{A0}1 Entrance"));
        for space in [
            '\u{85}', '\u{A0}', '\u{1680}', '\u{2003}', '\u{202F}', '\u{3000}',
        ] {
            assert!(possible_in(format!("a{space}b").as_bytes()), "{space:?}");
        }
        assert!(!possible_in("Caf\u{E9} \u{1F600}".as_bytes()));
    }
}
