//! Rules for what the robot's own reader would silently load differently (SPEC §2), and the
//! pass that runs those that depend on the version of the reader.

pub mod compat_bom;
pub mod compat_crlf;
pub mod compat_cultural_word_split;
pub mod compat_ignored_key;
pub mod compat_indented_line;
pub mod compat_key_too_long;
pub mod compat_leading_symbol;
pub mod compat_line_too_long;
pub mod compat_no_final_newline;
pub mod compat_reader_crash;
pub mod compat_slow_load;
pub mod compat_too_many_cultural_keys;

use crate::check::Diagnostics;
use crate::diagnostic::Severity;
use crate::model::{Key, KnowledgeBase};
use crate::reader::{tree, Reader};
use crate::rules::content::trailing_whitespace::TRAILING_WHITESPACE;
use crate::rules::structure::legacy_key;
use crate::syntax::{self, Body, Span};

/// Runs the rules about the whole file that depend on the version of the reader, but those
/// about the tree of locations it builds ([`check_tree`]).
pub fn check_file(kb: &KnowledgeBase<'_>, text: &str, reader: Reader, out: &mut Diagnostics) {
    compat_line_too_long::check(kb, text, reader, out);
    compat_no_final_newline::check(text, reader, out);
    compat_indented_line::check(kb, text, reader, out);
    compat_key_too_long::check(kb, text, reader, out);
    legacy_key::check(kb, text, reader, out);
    compat_ignored_key::check(kb, text, reader, out);
    compat_slow_load::check_tours(kb, text, reader, out);
    compat_too_many_cultural_keys::check_overwritten(kb, text, reader, out);
    arm_blanks_are_errors(kb, text, reader, out);
}

/// The shape of the tree of locations that loading `kb` builds: a pass over every location,
/// in file order.
pub fn tree_shape(kb: &KnowledgeBase<'_>) -> tree::TreeShape {
    tree::shape_of_locations(kb.locations().iter().map(|location| {
        let lines = location.given.count_ones();
        (location.first_line.start, location.id as i32, lines)
    }))
}

/// Runs the rules about the tree of locations, of `shape`, that `reader` builds from `kb`.
pub fn check_tree(
    kb: &KnowledgeBase<'_>,
    shape: &tree::TreeShape,
    reader: Reader,
    out: &mut Diagnostics,
) {
    compat_reader_crash::check(kb, shape, reader, out);
    compat_slow_load::check(shape, reader, out);
}

/// The key and arguments of every line of `key`, in file order.
pub(crate) fn lines_of_key(text: &str, key: Key) -> impl Iterator<Item = (Span, Span)> + '_ {
    syntax::lines(text).filter_map(move |line| match line.body {
        Body::Entry {
            key: key_span,
            args,
        } if key_span.text(text) == key.name() => Some((key_span, args)),
        _ => None,
    })
}

/// On `2026-03`, which passes `gestureArm` verbatim to the arm controller, trailing blanks
/// on its line (`right␠`) make an arm no controller knows: `trailing-whitespace` there is an
/// error (SPEC §2.13).
fn arm_blanks_are_errors(
    kb: &KnowledgeBase<'_>,
    text: &str,
    reader: Reader,
    out: &mut Diagnostics,
) {
    if !reader.reads(Key::GestureArm) || !kb.lines.has(Key::GestureArm) {
        return;
    }
    // In file order, so sorted: each finding is looked up, not compared with every line.
    let arm_lines: Vec<Span> = lines_of_key(text, Key::GestureArm)
        .map(|(key, args)| key.cover(args))
        .collect();
    let on_arm_line = |at: u32| {
        let before = arm_lines.partition_point(|line| line.start <= at);
        before > 0 && at <= arm_lines[before - 1].end + 1
    };
    for diagnostic in out.iter_mut() {
        if std::ptr::eq(diagnostic.rule, &TRAILING_WHITESPACE) && on_arm_line(diagnostic.span.start)
        {
            diagnostic.message.push_str(&format!(
                ": reader {reader} passes the arm to the arm controller with them, which knows no such arm"
            ));
            diagnostic.set_severity(Severity::Error);
        }
    }
}
