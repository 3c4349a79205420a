//! The rules about single lines, as the model is built: [`crate::model::build`] reports
//! what it finds on each line (facts: spans, keys, ids, tokens) and hands over each line,
//! and this module makes each fact its rule's finding, through the rule's own module, and
//! runs the rules that read a line's text (trailing whitespace, control characters, CRLF
//! endings, leading symbols). So the model layer names no rule, and the file is still read
//! once.

use std::ops::Range;

use crate::check::Diagnostics;
use crate::model::build::{Findings, LineFindings};
use crate::model::Key;
use crate::rules::{compat, content, structure, tour};
use crate::syntax::{Line, Span};

/// The line rules' findings on the lines of one part of a file.
#[derive(Debug)]
pub struct LineRules {
    /// The findings, at most [`crate::check::kept_at_most`] of each rule.
    found: Diagnostics,
    /// The CRLF endings so far: one finding for all of them, when the file is read.
    crlf_endings: Vec<Span>,
    /// Whether the part's lines have a byte that may start a control character: nearly no
    /// file has one, and one pass over all the bytes costs less than a check per value.
    controls_possible: bool,
}

impl Findings for Diagnostics {
    type Part = LineRules;

    fn part(text: &str, range: Range<usize>) -> LineRules {
        LineRules {
            found: Diagnostics::default(),
            crlf_endings: Vec::new(),
            controls_possible: structure::control_character::possible_in(&text[range]),
        }
    }

    fn add_part(&mut self, part: LineRules) {
        self.append(part.found);
    }
}

impl LineFindings for LineRules {
    #[inline]
    fn line(&mut self, line: &Line, text: &str) {
        let crlf_ending = compat::compat_crlf::ending(line, text);
        content::trailing_whitespace::check(line, crlf_ending, text, &mut self.found);
        self.crlf_endings.extend(crlf_ending);
    }

    #[inline]
    fn entry(&mut self, args: Span, text: &str) {
        if self.controls_possible {
            structure::control_character::check(args, text, &mut self.found);
        }
    }

    #[inline]
    fn value(&mut self, key: Key, id: u32, span: Span, value: &str) {
        compat::compat_leading_symbol::check(key, id, span, value, &mut self.found);
    }

    fn key_case(&mut self, span: Span, written: &str, key: Key, id: Option<u32>) {
        self.found.push_with(&structure::key_case::KEY_CASE, || {
            structure::key_case::diagnostic(span, written, key, id)
        });
    }

    fn unknown_key(&mut self, span: Span, written: &str, id: Option<u32>) {
        // Suggesting the nearest key is slow (an edit distance to every key), and a binary
        // file has millions of unknown keys: made only if kept.
        self.found
            .push_with(&structure::unknown_key::UNKNOWN_KEY, || {
                structure::unknown_key::diagnostic(span, written, id)
            });
    }

    fn missing_id(&mut self, key_span: Span, key: Key) {
        self.found
            .push(structure::missing_id::diagnostic(key_span, key));
    }

    fn invalid_id(&mut self, span: Span, token: &str, key: Key) {
        self.found
            .push(structure::invalid_id::diagnostic(span, token, key));
    }

    fn duplicate_key(&mut self, key: Key, id: u32, later: Span, earlier: Span) {
        self.found.push(structure::duplicate_key::diagnostic(
            key, id, later, earlier,
        ));
    }

    fn wrong_arity(&mut self, key: Key, id: u32, span: Span, expected: usize, found: usize) {
        self.found.push(structure::wrong_arity::diagnostic(
            key, id, span, expected, found,
        ));
    }

    fn empty_value(&mut self, key_span: Span, key: Key, id: u32) {
        self.found
            .push(structure::empty_value::diagnostic(key_span, key, id));
    }

    fn invalid_value(&mut self, key: Key, id: u32, span: Span, text: &str) {
        self.found
            .push(structure::invalid_value::diagnostic(key, id, span, text));
    }

    fn invalid_number(&mut self, key: Key, id: Option<u32>, span: Span, token: &str) {
        self.found
            .push(structure::invalid_number::diagnostic(key, id, span, token));
    }

    fn duplicate_tour(&mut self, later: Span, earlier: Span) {
        self.found
            .push(tour::tour_duplicate_spec::diagnostic(later, earlier));
    }

    fn mixed_dialect(&mut self, seed: (Span, usize), current: (Span, usize)) {
        self.found
            .push(structure::mixed_dialect::diagnostic(seed, current));
    }

    fn append(&mut self, later: LineRules) {
        self.found.append(later.found);
        self.crlf_endings.extend(later.crlf_endings);
    }

    fn finish(&mut self) {
        compat::compat_crlf::check(&self.crlf_endings, &mut self.found);
    }
}
