//! Word-wrapping a line of prose (a finding in `ekb show`'s list) to the output's width,
//! its continuation lines indented under its text:
//!
//! ```text
//!   line 5: warning[repeated-word] "the" is repeated: the robot would say it
//!       twice
//! ```
//!
//! Lines break at plain spaces only; a word longer than the width stays whole.

/// `text` broken at spaces into lines of at most `width` characters (where the words
/// allow), every line after the first starting with `indent`.
pub fn wrap(text: &str, width: usize, indent: &str) -> String {
    let mut out = String::with_capacity(text.len() + 16);
    let mut column = 0;
    for (i, word) in text.split(' ').enumerate() {
        let length = word.chars().count();
        if i > 0 {
            if column + 1 + length > width {
                out.push('\n');
                out.push_str(indent);
                column = indent.chars().count();
            } else {
                out.push(' ');
                column += 1;
            }
        }
        out.push_str(word);
        column += length;
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn breaks_at_spaces_and_indents_what_follows() {
        assert_eq!(
            wrap("  line 5: the robot would say it twice", 20, "      "),
            "  line 5: the robot\n      would say it\n      twice"
        );
        assert_eq!(wrap("short", 20, "  "), "short");
        assert_eq!(
            wrap("a verylongwordindeed b", 8, "  "),
            "a\n  verylongwordindeed\n  b"
        );
    }
}
