use crate::diagnostic::Diagnostic;
use crate::model::Key;
use crate::rules::declare_rule;
use crate::syntax::Span;

declare_rule! {
    /// ## What it does
    /// Flags a key given twice for the same location, pointing at both lines.
    ///
    /// ## Why it matters
    /// The robot's reader keeps the later line and drops the earlier one without a word.
    /// Usually one of the two was meant for another location (a copied block whose id was
    /// not changed).
    ///
    /// ## Example
    /// ```text
    /// robotLocationDescription      2 The (other) Pepper robot
    /// robotLocationDescription      2 Lynxmotion
    /// ```
    pub static DUPLICATE_KEY = {
        name: "duplicate-key",
        category: Structure,
        severity: Warning,
        fixable: false,
        summary: "the same key twice for one id; the later wins",
    };
}

pub fn diagnostic(key: Key, id: u32, later: Span, earlier: Span) -> Diagnostic {
    Diagnostic::new(
        &DUPLICATE_KEY,
        later,
        format!(
            "location {id} has `{}` twice: the robot keeps this line and ignores the earlier one",
            key.name()
        ),
    )
    .at_location(Some(id))
    .with_label(earlier, "first given here")
    .with_help("delete the line you do not want, or give it the id it was meant for")
}
