use crate::diagnostic::Diagnostics;
use crate::diagnostic::{Diagnostic, Edit};
use crate::model::build::leading_id;
use crate::model::{Key, ValueKind};
use crate::rules::declare_rule;
use crate::syntax::{Body, Line, Span, BOM};

declare_rule! {
    /// ## What it does
    /// Flags spaces or tabs at the end of a line (including a line of only whitespace), and
    /// removes them.
    ///
    /// ## Why it matters
    /// They are invisible, but the robot's reader keeps them as part of the value, and
    /// they make diffs noisy.
    ///
    /// ## Example
    /// ```text
    /// preGestureMessageEnglish      4 This is the Roomba.␠␠
    /// ```
    pub static TRAILING_WHITESPACE = {
        name: "trailing-whitespace",
        category: Content,
        severity: Warning,
        fixable: true,
        summary: "spaces or tabs at the end of a line",
    };
}

/// Reports the blanks at the end of `line`, before its ending (which `compat-crlf` fixes).
pub fn check(line: &Line, text: &str, out: &mut Diagnostics) {
    let span = match line.body {
        // A blank line's whitespace is all indentation (after a byte-order mark, if any).
        Body::Blank => {
            let indent = line.indent.text(text);
            let skip = if indent.starts_with(BOM) {
                BOM.len()
            } else {
                0
            };
            Span::new(line.indent.start as usize + skip, line.indent.end as usize)
        }
        _ => line.trailing,
    };
    if span.is_empty() {
        return;
    }
    let key = match line.body {
        Body::Entry { key, .. } => Key::from_name(key.text(text)),
        _ => None,
    };
    let keeps_it = key.is_some_and(|key| key.value_kind() == ValueKind::Text);
    let id = match line.body {
        Body::Entry { args, .. } if key != Some(Key::TourSpecification) => {
            leading_id(args.text(text))
        }
        _ => None,
    };
    let consequence = if keeps_it {
        "the robot's reader keeps it at the end of the text"
    } else {
        "the robot's reader skips it, but it is invisible and makes diffs noisy"
    };
    out.push_with(&TRAILING_WHITESPACE, || {
        Diagnostic::new(
            &TRAILING_WHITESPACE,
            span,
            format!("trailing whitespace: {consequence}"),
        )
        .at_location(id)
        .with_help("remove it")
        .with_fix("remove trailing whitespace", vec![Edit::delete(span)])
    });
}
