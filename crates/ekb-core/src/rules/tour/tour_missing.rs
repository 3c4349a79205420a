use crate::diagnostic::Diagnostic;
use crate::diagnostic::Diagnostics;
use crate::model::KnowledgeBase;
use crate::rules::declare_rule;
use crate::syntax::Span;

declare_rule! {
    /// ## What it does
    /// Flags a knowledge base with no `tourSpecification` line.
    ///
    /// ## Why it matters
    /// Without a tour the robot has nowhere to go, and it takes its start and home pose
    /// from the tour's first stop.
    ///
    /// ## Example
    /// Add, as the last line:
    /// ```text
    /// tourSpecification 5 1 4 3 2 5
    /// ```
    pub static TOUR_MISSING = {
        name: "tour-missing",
        category: Tour,
        severity: Error,
        fixable: false,
        summary: "no `tourSpecification` line",
    };
}

pub fn check(kb: &KnowledgeBase<'_>, out: &mut Diagnostics) {
    if kb.tour.is_none() {
        out.push_with(&TOUR_MISSING, || Diagnostic::new(&TOUR_MISSING,
                Span::empty_at(0),
                "there is no `tourSpecification` line: the robot has no tour to follow and no start pose",
            )
            .with_help("add `tourSpecification N ID1 ID2 … IDN` listing the locations in the order to visit"),
        );
    }
}
