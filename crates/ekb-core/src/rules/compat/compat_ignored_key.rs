use crate::diagnostic::Diagnostic;
use crate::diagnostic::Diagnostics;
use crate::model::build::leading_id;
use crate::model::{Key, KnowledgeBase};
use crate::robot::Reader;
use crate::rules::compat::lines_of_key;
use crate::rules::{consequence, declare_rule};

declare_rule! {
    /// ## What it does
    /// Flags a line of a key that the chosen version of the robot's reader does not read:
    /// `gestureArm` on every version but `2026-03`, `culturalKnowledge` on `d5.4.2`. (A pose
    /// key of the other dialect is a `legacy-key` error.)
    ///
    /// ## Why it matters
    /// The robot ignores the line without a word: on `2025-06` the robot gestures with its
    /// default arm whatever `gestureArm` says, and on `2026-04` the arm comes from the culture
    /// knowledge base instead.
    ///
    /// ## Example
    /// With `--reader 2025-06`:
    /// ```text
    /// gestureArm                    1 left
    /// ```
    pub static COMPAT_IGNORED_KEY = {
        name: "compat-ignored-key",
        category: Compat,
        severity: Warning,
        fixable: false,
        summary: "a key the chosen reader does not read (gestureArm except on 2026-03; culturalKnowledge on d5.4.2)",
    };
}

/// Checks the lines of the keys that `reader` does not read.
pub fn check(kb: &KnowledgeBase<'_>, text: &str, reader: Reader, out: &mut Diagnostics) {
    for key in [Key::GestureArm, Key::CulturalKnowledge] {
        if reader.reads(key) || !kb.lines.has(key) {
            continue;
        }
        for (key_span, args) in lines_of_key(text, key) {
            out.push_with(&COMPAT_IGNORED_KEY, || {
                let id = leading_id(args.text(text));
                let instead = match (key, reader) {
                    (Key::GestureArm, Reader::V2026_04) => {
                        " (it takes the arm from the culture knowledge base)"
                    }
                    _ => "",
                };
                Diagnostic::new(
                    &COMPAT_IGNORED_KEY,
                    key_span,
                    format!(
                        "reader {reader} does not read `{}`{instead}: it ignores this line, so {}",
                        key.name(),
                        consequence::lost(key, id)
                    ),
                )
                .at_location(id)
                .with_help(match key {
                    Key::GestureArm => "only reader 2026-03 reads `gestureArm`: check against it with `--reader 2026-03`, or remove the line",
                    _ => "the document's reader has no cultural knowledge: check against an upstream reader (`--reader 2025-06`), or remove the line",
                })
            });
        }
    }
}
