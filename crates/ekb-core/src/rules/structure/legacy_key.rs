use crate::diagnostic::Diagnostics;
use crate::diagnostic::{Diagnostic, Edit};
use crate::model::build::leading_id;
use crate::model::{Key, KnowledgeBase};
use crate::robot::Reader;
use crate::rules::compat::lines_of_key;
use crate::rules::{consequence, declare_rule};

declare_rule! {
    /// ## What it does
    /// Flags a pose key that the chosen version of the robot's reader does not read, and
    /// renames it: `robotLocation` on every upstream version (`2025-06` on),
    /// `robotLocationPose` on the document's reader (`d5.4.2`).
    ///
    /// ## Why it matters
    /// The robot's reader silently ignores the other dialect's pose key, so a file written
    /// in the document's dialect puts every pose at (0, 0, 0) on today's robot: it drives
    /// to the map's origin before every exhibit.
    ///
    /// ## Example
    /// With `--reader 2025-06`:
    /// ```text
    /// robotLocation                 1 2.6 8.1 -90
    /// ```
    /// `ekb fix` rewrites it as `robotLocationPose`.
    pub static LEGACY_KEY = {
        name: "legacy-key",
        category: Structure,
        severity: Error,
        fixable: true,
        summary: "a pose key that the chosen reader does not read (robotLocation upstream, robotLocationPose on d5.4.2)",
    };
}

/// Checks the pose lines that `reader` does not read.
pub fn check(kb: &KnowledgeBase<'_>, text: &str, reader: Reader, out: &mut Diagnostics) {
    let wanted = reader.pose_key();
    for key in [Key::RobotLocation, Key::RobotLocationPose] {
        if key == wanted || !kb.lines.has(key) {
            continue;
        }
        for (key_span, args) in lines_of_key(text, key) {
            out.push_with(&LEGACY_KEY, || {
                let id = leading_id(args.text(text));
                Diagnostic::new(
                    &LEGACY_KEY,
                    key_span,
                    format!(
                        "reader {reader} reads poses from `{}`, not `{}`: it ignores this line, so {}",
                        wanted.name(),
                        key.name(),
                        consequence::lost(key, id)
                    ),
                )
                .at_location(id)
                .with_help(format!("write `{}`", wanted.name()))
                .with_fix(
                    format!("rename to `{}`", wanted.name()),
                    vec![Edit::replace(key_span, wanted.name())],
                )
            });
        }
    }
}
