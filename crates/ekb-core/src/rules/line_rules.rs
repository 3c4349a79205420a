//! The rules about single lines, as the model is built: [`crate::model::build`] reports
//! what it finds on each line (facts: spans, keys, ids, tokens) and hands over each line,
//! and this module makes each fact its rule's finding, through the rule's own module, and
//! runs the rules that read a line's text (trailing whitespace, control characters, CRLF
//! endings, leading symbols). So the model layer names no rule, and the file is still read
//! once.

use crate::diagnostic::Diagnostics;
use crate::model::build::{Findings, LineFindings};
use crate::model::Key;
use crate::rules::{compat, content, structure, tour};
use crate::syntax::{Line, Span};

/// The line rules' findings on the lines of one part of a file.
#[derive(Debug)]
pub struct LineRules {
    /// The findings, at most [`crate::diagnostic::kept_at_most`] of each rule.
    found: Diagnostics,
    /// The CRLF endings so far: one finding for all of them, when the file is read.
    crlf_endings: compat::compat_crlf::CrlfEndings,
    /// What the bytes read next may hold, up to where they were scanned.
    ahead: Ahead,
}

/// Whether the bytes up to `end`, from the line being read on, have a byte that may start a
/// control character, or a Unicode space: nearly no file has one, and a pass over the bytes
/// costs less than a look at every value. Scanned a window at a time just ahead of the
/// lines, so that the lines are read from the cache the scan brought them into, not from
/// memory again (measured: three passes over the file were the check's slowest part).
#[derive(Debug, Default)]
struct Ahead {
    end: usize,
    controls_possible: bool,
    unicode_spaces_possible: bool,
}

impl Ahead {
    /// How many bytes a window is, unless a line is longer: well within a core's cache.
    const WINDOW: usize = 64 << 10;

    /// Scans the next window if `line` goes past the last one.
    #[inline]
    fn cover(&mut self, line: &Line, text: &str) {
        if line.span.end as usize > self.end {
            self.scan(line, text);
        }
    }

    fn scan(&mut self, line: &Line, text: &str) {
        let start = line.span.start as usize;
        let end = (start + Self::WINDOW)
            .min(text.len())
            .max(line.span.end as usize);
        let window = &text.as_bytes()[start..end];
        self.controls_possible = structure::control_character::possible_in(window);
        self.unicode_spaces_possible = structure::unicode_space::possible_in(window);
        self.end = end;
    }
}

impl Findings for Diagnostics {
    type Part = LineRules;

    fn part(&self) -> LineRules {
        LineRules {
            found: self.part(),
            crlf_endings: Default::default(),
            ahead: Ahead::default(),
        }
    }

    fn add_part(&mut self, part: LineRules) {
        self.append(part.found);
    }
}

impl LineFindings for LineRules {
    #[inline]
    fn line(&mut self, line: &Line, text: &str) {
        self.ahead.cover(line, text);
        content::trailing_whitespace::check(line, text, &mut self.found);
        self.crlf_endings.add(line, text);
        if self.ahead.unicode_spaces_possible {
            structure::unicode_space::check(line, text, &mut self.found);
        }
    }

    #[inline]
    fn entry(&mut self, args: Span, text: &str) {
        if self.ahead.controls_possible {
            structure::control_character::check(args, text, &mut self.found);
        }
    }

    #[inline]
    fn value(&mut self, key: Key, id: u32, span: Span, value: &str) {
        compat::compat_leading_symbol::check(key, id, span, value, &mut self.found);
    }

    fn key_case(&mut self, span: Span, written: &str, key: Key, id: Option<u32>) {
        use structure::key_case;
        self.found.push_fixable_with(
            &key_case::KEY_CASE,
            span,
            || key_case::diagnostic(span, written, key, id),
            || key_case::edits(span, key),
        );
    }

    fn unknown_key(&mut self, span: Span, written: &str, id: Option<u32>) {
        // Suggesting the nearest key is slow (an edit distance to every key), and a binary
        // file has millions of unknown keys: made only if kept.
        self.found
            .push_with(&structure::unknown_key::UNKNOWN_KEY, || {
                structure::unknown_key::diagnostic(span, written, id)
            });
    }

    // Each of these can be found on every line of a file: made only if kept.

    fn missing_id(&mut self, key_span: Span, key: Key) {
        use structure::missing_id::{diagnostic, MISSING_ID};
        self.found
            .push_with(&MISSING_ID, || diagnostic(key_span, key));
    }

    fn invalid_id(&mut self, span: Span, token: &str, key: Key) {
        use structure::invalid_id::{diagnostic, INVALID_ID};
        self.found
            .push_with(&INVALID_ID, || diagnostic(span, token, key));
    }

    fn duplicate_key(&mut self, key: Key, id: u32, later: Span, earlier: Span) {
        use structure::duplicate_key::{diagnostic, DUPLICATE_KEY};
        self.found
            .push_with(&DUPLICATE_KEY, || diagnostic(key, id, later, earlier));
    }

    fn wrong_arity(&mut self, key: Key, id: u32, span: Span, expected: usize, found: usize) {
        use structure::wrong_arity::{diagnostic, WRONG_ARITY};
        self.found
            .push_with(&WRONG_ARITY, || diagnostic(key, id, span, expected, found));
    }

    fn empty_value(&mut self, key_span: Span, key: Key, id: u32) {
        use structure::empty_value::{diagnostic, EMPTY_VALUE};
        self.found
            .push_with(&EMPTY_VALUE, || diagnostic(key_span, key, id));
    }

    fn invalid_value(&mut self, key: Key, id: u32, span: Span, text: &str) {
        use structure::invalid_value::{diagnostic, INVALID_VALUE};
        self.found
            .push_with(&INVALID_VALUE, || diagnostic(key, id, span, text));
    }

    fn float_overflow(&mut self, key: Key, id: u32, span: Span, token: &str, first: bool) {
        compat::compat_float_overflow::check(key, id, span, token, first, &mut self.found);
    }

    fn invalid_number(&mut self, key: Key, id: Option<u32>, span: Span, token: &str) {
        use structure::invalid_number::{diagnostic, INVALID_NUMBER};
        self.found
            .push_with(&INVALID_NUMBER, || diagnostic(key, id, span, token));
    }

    fn duplicate_tour(&mut self, later: Span, earlier: Span) {
        self.found
            .push(tour::tour_duplicate_spec::diagnostic(later, earlier));
    }

    fn mixed_dialect(&mut self, seed: (Span, usize), current: (Span, usize)) {
        self.found
            .push(structure::mixed_dialect::diagnostic(seed, current));
    }

    fn finish(&mut self) {
        compat::compat_crlf::check(&self.crlf_endings, &mut self.found);
    }
}

#[cfg(test)]
mod tests {
    use crate::diagnostic::Diagnostics;
    use crate::model::build::{build, Options};
    use crate::syntax::BOM;

    #[test]
    fn every_line_rule_finds_something_on_its_lines() {
        let mut text = String::from(BOM);
        for (id, line) in (1..).zip(LINES) {
            text.push_str(&line.replace('#', &(id % 3 + 1).to_string()));
            text.push_str(if id % 2 == 0 { "\r\n" } else { "\n" });
        }
        let mut found = Diagnostics::default();
        build(&text, &Options::default(), &mut found);
        let mut rules: Vec<&str> = found.iter().map(|d| d.rule.name).collect();
        rules.sort_unstable();
        rules.dedup();
        assert_eq!(
            rules,
            [
                "compat-crlf",
                "compat-leading-symbol",
                "control-character",
                "duplicate-key",
                "empty-value",
                "invalid-id",
                "invalid-number",
                "invalid-value",
                "key-case",
                "missing-id",
                "mixed-dialect",
                "tour-duplicate-spec",
                "trailing-whitespace",
                "unknown-key",
                "wrong-arity"
            ]
        );
    }

    /// Lines that make every line rule find something; `#` stands for an id.
    const LINES: &[&str] = &[
        "robotLocationDescription # Hall",
        "robotLocation # 1 2 90",
        "robotLocationPose # 1 2 -90",
        "robotLocation # -1 2 90 ",
        "gestureTarget # 1 1 1",
        "gestureTarget # x 1",
        "gestureTarget #",
        "gestureArm # left",
        "gestureArm # up",
        "gestureArm # left right",
        "culturalKnowledge # a b c\t",
        "preGestureMessageEnglish # Hello the the lab",
        "postGestureMessageIsiZulu #",
        "preGestureMessageenglish # miscased",
        "robotLocationDescription # \u{202e}reversed",
        "robotLocationDescription # -dash",
        "robotLocationDescription",
        "bogus # 1",
        "tourSpecification 2 # 1",
        "tourSpecification x y",
        "# a comment",
        "  ",
        "robotLocationDescription 0 no id",
        "robotLocationDescription # be\u{7}ll",
        // `\r\r\n` where a CRLF ending follows.
        "robotLocationDescription # Hall\r",
    ];
}
