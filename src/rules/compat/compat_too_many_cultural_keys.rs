use crate::check::Diagnostics;
use crate::diagnostic::Diagnostic;
use crate::model::Location;
use crate::render::clip;
use crate::rules::declare_rule;
use crate::syntax::{self, Span};

/// The robot keeps this many culturalKnowledge words per location.
pub const MAX_CULTURAL_KEYS: usize = 2;

declare_rule! {
    /// ## What it does
    /// Flags a `culturalKnowledge` line with more than 2 words.
    ///
    /// ## Why it matters
    /// The robot's reader keeps at most 2 culture-knowledge keys per location and drops
    /// the rest without a word, so the robot's behaviour there ignores them.
    ///
    /// ## Example
    /// ```text
    /// culturalKnowledge             1 SymbolicShapeRespect BowExtentRespect DeicticShape
    /// ```
    pub static COMPAT_TOO_MANY_CULTURAL_KEYS = {
        name: "compat-too-many-cultural-keys",
        category: Compat,
        severity: Error,
        fixable: false,
        summary: "more than 2 `culturalKnowledge` words",
    };
}

pub fn check(location: &Location<'_>, out: &mut Diagnostics) {
    let Some(value) = location.cultural_knowledge() else {
        return;
    };
    let words: Vec<(Span, &str)> = syntax::tokens(value.value, value.span.start as usize).collect();
    if words.len() <= MAX_CULTURAL_KEYS {
        return;
    }
    let dropped = &words[MAX_CULTURAL_KEYS..];
    let span = dropped[0].0.cover(dropped[dropped.len() - 1].0);
    let names: Vec<&str> = dropped.iter().map(|(_, word)| *word).collect();
    out.push_with(&COMPAT_TOO_MANY_CULTURAL_KEYS, || Diagnostic::new(&COMPAT_TOO_MANY_CULTURAL_KEYS,
            span,
            format!(
                "location {} has {} culturalKnowledge words, but the robot keeps only {MAX_CULTURAL_KEYS}: it ignores {}",
                location.id,
                words.len(),
                clip::shown(&names.join(", "))
            ),
        )
        .at_location(Some(location.id))
        .with_help("keep the two that matter most"),
    );
}
