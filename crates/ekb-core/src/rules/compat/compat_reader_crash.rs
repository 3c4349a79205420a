use crate::diagnostic::Diagnostics;
use crate::diagnostic::{Diagnostic, Severity};
use crate::model::KnowledgeBase;
use crate::reader::tree::TreeShape;
use crate::robot::Reader;
use crate::rules::declare_rule;
use crate::syntax::Span;

declare_rule! {
    /// ## What it does
    /// Flags a file whose order of ids builds a tree of locations deep enough to crash the
    /// chosen version of the robot's reader: from the lowest depth at which it was measured
    /// to crash, over the robot's own build and an optimised one (5,455 for `2025-06` and
    /// `d5.4.2`, 3,740 for `2026-02`, 1,695 for `2026-03`, whose records also hold the
    /// arm, and 1,932 for `2026-04`). From 90% of that depth it is a warning: the exact
    /// point depends on the build. `ekb fix` writes the locations in an order that builds
    /// a balanced tree.
    ///
    /// ## Why it matters
    /// The reader keeps locations in an unbalanced binary search tree and recurses on it.
    /// With ids in ascending order, the natural way to write a file, the tree is a chain as
    /// deep as there are locations, and past that depth the reader overflows its 8 MB stack:
    /// the robot crashes while it starts. The same locations in another order load fine.
    ///
    /// ## Example
    /// A file of 6,000 locations, ids 1 to 6,000 in order, crashes `2025-06`.
    pub static COMPAT_READER_CRASH = {
        name: "compat-reader-crash",
        category: Compat,
        severity: Error,
        fixable: true,
        summary: "the order of ids builds a tree deep enough to crash the reader",
    };
}

/// Checks the depth of the tree that `kb` builds in `reader`.
pub fn check(kb: &KnowledgeBase<'_>, shape: &TreeShape, reader: Reader, out: &mut Diagnostics) {
    if shape.height < reader.crash_margin_depth() {
        return;
    }
    let crashes = shape.height >= reader.crash_depth();
    let at = shape
        .deepest
        .and_then(|id| u32::try_from(id).ok())
        .and_then(|id| kb.location(id))
        .map_or(Span::empty_at(0), |location| location.first_line);
    let message = match crashes {
        true => format!(
            "the order of this file's ids builds the robot's tree of locations {} deep: reader {reader} overflows its stack from a depth of {} and crashes while the robot starts",
            shape.height,
            reader.crash_depth()
        ),
        false => format!(
            "the order of this file's ids builds the robot's tree of locations {} deep, near the depth of {} from which reader {reader} was measured to overflow its stack: the exact point depends on the build, and on what else is on the stack",
            shape.height,
            reader.crash_depth()
        ),
    };
    let severity = match crashes {
        true => Severity::Error,
        false => Severity::Warning,
    };
    out.push(
        Diagnostic::new(&COMPAT_READER_CRASH, at, message)
            .with_severity(severity)
        .at_location(shape.deepest.and_then(|id| u32::try_from(id).ok()))
        .with_help("run `ekb fix` to write the locations in an order that builds a balanced tree (the middle id first)"),
    );
}
