use crate::diagnostic::Diagnostics;
use crate::diagnostic::{Diagnostic, Edit};
use crate::rules::declare_rule;
use crate::syntax::{Span, BOM};

declare_rule! {
    /// ## What it does
    /// Flags a UTF-8 byte-order mark at the start of the file, and removes it.
    ///
    /// ## Why it matters
    /// The robot's reader takes the three bytes of the mark as part of the first key, does
    /// not recognise it, and ignores the first line without a word. Some Windows editors
    /// add the mark when saving as UTF-8.
    ///
    /// ## Example
    /// `\xEF\xBB\xBFrobotLocationDescription 1 Pepper's starting location`
    pub static COMPAT_BOM = {
        name: "compat-bom",
        category: Compat,
        severity: Error,
        fixable: true,
        summary: "a UTF-8 byte-order mark",
    };
}

pub fn check(text: &str, out: &mut Diagnostics) {
    if !text.starts_with(BOM) {
        return;
    }
    let span = Span::new(0, BOM.len());
    out.push_with(&COMPAT_BOM, || Diagnostic::new(&COMPAT_BOM,
            span,
            "the file starts with a byte-order mark: the robot's reader takes it as part of the first key and ignores line 1",
        )
        .with_help("save the file as UTF-8 without BOM")
        .with_fix("remove the byte-order mark", vec![Edit::delete(span)]),
    );
}
