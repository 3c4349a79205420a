//! Rules for what the robot's own reader would silently load differently (SPEC §2), and the
//! pass that runs those that depend on the version of the reader.

pub mod compat_bom;
pub mod compat_crlf;
pub mod compat_cultural_word_split;
pub mod compat_float_overflow;
pub mod compat_ignored_key;
pub mod compat_indented_line;
pub mod compat_key_too_long;
pub mod compat_leading_symbol;
pub mod compat_line_too_long;
pub mod compat_no_final_newline;
pub mod compat_reader_crash;
pub mod compat_slow_load;
pub mod compat_too_many_cultural_keys;

use crate::diagnostic::Diagnostics;
use crate::diagnostic::Severity;
use crate::model::{Key, KnowledgeBase};
use crate::reader::tree;
use crate::robot::Reader;
use crate::rules::content::trailing_whitespace::TRAILING_WHITESPACE;
use crate::rules::structure::{self, legacy_key};
use crate::rules::Rule;
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
    compat_crlf::grade(text, reader, out);
    structure::control_character::check_at_cuts(text, reader, out);
}

/// The shape of the tree of locations that `reader` builds from the file: the reader's own
/// (SPEC §2.16: only the lines it inserts add nodes) where the written model could
/// differ from it ([`model_tree_is_the_readers`]), else made from the model, which costs
/// a pass over its locations instead of loading the file again.
pub fn tree_shape(
    kb: &KnowledgeBase<'_>,
    text: &str,
    reader: Reader,
    from_model: bool,
) -> tree::TreeShape {
    match from_model {
        true => model_tree_shape(kb),
        false => crate::reader::load(text.as_bytes(), reader).tree,
    }
}

/// The findings that say a line loads into another location than the file says, or into
/// none although the model holds it (a value the reader cannot read), or that a line is
/// cut and its rest read as a line of its own: after one of these, the order in which the
/// reader first inserts each id may not be the model's.
const INSERTED_OTHERWISE: [&Rule; 7] = [
    &structure::invalid_id::INVALID_ID,
    &structure::missing_id::MISSING_ID,
    &structure::invalid_number::INVALID_NUMBER,
    &structure::wrong_arity::WRONG_ARITY,
    &structure::control_character::CONTROL_CHARACTER,
    &compat_line_too_long::COMPAT_LINE_TOO_LONG,
    &compat_key_too_long::COMPAT_KEY_TOO_LONG,
];

/// Whether the tree that the written model's order of first lines builds is the one that
/// `reader` builds: no finding so far says a line is inserted otherwise, no lone `\r` ends
/// a line where the reader's buffer cuts it, and no location's
/// first line is of a key the reader ignores (`gestureArm` first, say, on a version that
/// does not read it: the reader first inserts that location at its next line).
pub fn model_tree_is_the_readers(
    kb: &KnowledgeBase<'_>,
    text: &str,
    reader: Reader,
    found: &Diagnostics,
) -> bool {
    if INSERTED_OTHERWISE
        .iter()
        .any(|&rule| found.reported(rule) > 0)
    {
        return false;
    }
    // A lone `\r` that ends what the reader's buffer holds of a line ends that line: what
    // follows is a line of its own to the reader, which the model does not see.
    let buffer = reader.line_buffer();
    if crate::reader::carriage_returns_at_cuts(text.as_bytes(), buffer)
        .next()
        .is_some()
    {
        return false;
    }
    let ignored: Vec<&[u8]> = Key::ALL
        .into_iter()
        .filter(|&key| !reader.reads(key) && kb.lines.has(key))
        .map(|key| key.name().as_bytes())
        .collect();
    if ignored.is_empty() {
        return true;
    }
    let bytes = text.as_bytes();
    kb.locations().iter().all(|location| {
        let line = &bytes[location.first_line.range()];
        let key_end = line.iter().position(|&byte| syntax::is_c_space(byte));
        !ignored.contains(&&line[..key_end.unwrap_or(line.len())])
    })
}

/// The shape of the tree of locations that loading `kb` builds: a pass over every location,
/// in file order.
fn model_tree_shape(kb: &KnowledgeBase<'_>) -> tree::TreeShape {
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
