use crate::diagnostic::Diagnostic;
use crate::diagnostic::Diagnostics;
use crate::model::Key;
use crate::rules::declare_rule;
use crate::syntax::Span;

declare_rule! {
    /// ## What it does
    /// Flags a number of a pose or a gesture target that is a finite decimal too large for
    /// a C `float` (beyond about ±3.4e38): `1e39`, `-1e39`, `3.4028236e38`.
    ///
    /// ## Why it matters
    /// The robot's reader parses numbers with `%f` into a `float`, and every version loads
    /// such a number as an infinity, without a word (SPEC §2.15): the robot would drive
    /// or point to infinity.
    ///
    /// ## Example
    /// ```text
    /// gestureTarget                 1 3.0 1e39 0.82
    /// ```
    /// loads y = inf. Write the coordinate in metres.
    pub static COMPAT_FLOAT_OVERFLOW = {
        name: "compat-float-overflow",
        category: Compat,
        severity: Error,
        fixable: false,
        summary: "a number too large for the reader's float: it loads as inf",
    };
}

/// Reports `token` of `key` at location `id`, whose value overflows a `float`; `first`: it
/// is the line's first number, whose sign the reader skips (`compat-leading-symbol`).
pub fn check(key: Key, id: u32, span: Span, token: &str, first: bool, out: &mut Diagnostics) {
    out.push_with(&COMPAT_FLOAT_OVERFLOW, || {
        let loaded = match token.starts_with('-') && !first {
            true => "-inf",
            false => "inf",
        };
        Diagnostic::new(
            &COMPAT_FLOAT_OVERFLOW,
            span,
            format!(
                "`{token}` in `{}` is too large for the robot's `float` (at most about 3.4e38): every version of its reader loads {loaded}",
                key.name()
            ),
        )
        .at_location(Some(id))
        .with_help("write the number in metres, within the map")
    });
}
