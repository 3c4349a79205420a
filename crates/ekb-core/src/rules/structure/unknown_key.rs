use crate::diagnostic::{Diagnostic, Edit};
use crate::model::build::parse_id;
use crate::model::Key;
use crate::render::escape::{escape, is_odd_space};
use crate::rules::{consequence, declare_rule, excerpt};
use crate::syntax::{self, Span};

declare_rule! {
    /// ## What it does
    /// Flags a line whose key is no known key, even ignoring case, and suggests the nearest.
    ///
    /// ## Why it matters
    /// The robot's reader ignores a line with an unknown key without a word, so whatever
    /// the line was meant to set (a message, a pose) silently goes missing.
    ///
    /// ## Example
    /// ```text
    /// preGestureMesageEnglish       2 This is the Pepper humanoid robot
    /// ```
    /// Use `preGestureMessageEnglish`.
    ///
    /// ## Fix (unsafe)
    /// `ekb fix --unsafe-fixes` renames the key to the nearest one: a guess at what was
    /// meant.
    ///
    /// A key run into its id by a space that is not a plain one, such as a no-break space (U+00A0) that a word processor put there, is no key
    /// either: the message shows the space as `\u{00A0 NO-BREAK SPACE}`.
    pub static UNKNOWN_KEY = {
        name: "unknown-key",
        category: Structure,
        severity: Error,
        fixable: false,
        summary: "a key that is no known key even ignoring case",
    };
}

pub fn diagnostic(span: Span, key: &str, id: Option<u32>) -> Diagnostic {
    if let Some(diagnostic) = key_before_odd_space(span, key) {
        return diagnostic;
    }
    let ignored = format!(
        "`{}` is not a key of the knowledge base: the robot's reader ignores this line",
        escape(&excerpt(key))
    );
    match Key::nearest_to(key) {
        Some(near) => Diagnostic::new(
            &UNKNOWN_KEY,
            span,
            format!(
                "{ignored}; if it is meant as `{}`, {}",
                near.name(),
                consequence::lost(near, id.filter(|_| near != Key::TourSpecification))
            ),
        )
        .with_help(format!("did you mean `{}`?", near.name()))
        .with_unsafe_fix(
            format!("rename to `{}`", near.name()),
            vec![Edit::replace(span, near.name())],
        ),
        None => Diagnostic::new(&UNKNOWN_KEY, span, ignored).with_help(format!(
            "the keys are: {}",
            Key::ALL.map(Key::name).join(", ")
        )),
    }
    .at_location(id)
}

/// The finding for a known key followed by a space that is not a plain one
/// (`preGestureMessageEnglish\u{A0}3`). To the robot's reader a no-break space or another
/// Unicode space is no space: the key and the id are one word, and the line is ignored. A
/// vertical tab or a form feed is a space to it (C's `isspace`): it reads the line as if a
/// plain space were there, where ekb and other tools see one unknown word.
fn key_before_odd_space(span: Span, written: &str) -> Option<Diagnostic> {
    let (at, space) = written.char_indices().find(|&(_, ch)| is_odd_space(ch))?;
    let key = Key::from_name(&written[..at])?;
    let id = parse_id(&written[at + space.len_utf8()..]).filter(|_| key != Key::TourSpecification);
    let read_by_robot = space.is_ascii() && syntax::is_c_space(space as u8);
    let space = super::unicode_space::name(space);
    let message = if read_by_robot {
        format!(
            "`{}` is not a key of the knowledge base: {space}, not a plain space, follows \
             `{}`; the robot's reader takes it for a space and reads this line, but ekb and \
             other tools do not",
            escape(&excerpt(written)),
            key.name(),
        )
    } else {
        format!(
            "`{}` is not a key of the knowledge base: {space}, not a plain space, follows \
             `{}`, so the robot's reader ignores this line; {}",
            escape(&excerpt(written)),
            key.name(),
            consequence::lost(key, id)
        )
    };
    Some(
        Diagnostic::new(&UNKNOWN_KEY, span, message)
            .at_location(id)
            .with_help(format!(
                "a plain space or a tab must separate the key from what follows: replace \
                 {space} after `{}` with a plain space",
                key.name()
            )),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn suggests_the_nearest_key() {
        assert_eq!(
            Key::nearest_to("preGestureMesageEnglish"),
            Some(Key::PreGestureMessageEnglish)
        );
        assert_eq!(
            Key::nearest_to("robotLocationPos"),
            Some(Key::RobotLocationPose)
        );
        assert_eq!(Key::nearest_to("colour"), None);
    }

    #[test]
    fn a_key_run_into_its_id_by_a_no_break_space_is_shown_escaped() {
        let key = "preGestureMessageEnglish\u{A0}3";
        let found = diagnostic(Span::new(0, key.len()), key, None);
        assert_eq!(
            found.message,
            "`preGestureMessageEnglish\\u{00A0 NO-BREAK SPACE}3` is not a key of the knowledge base: a no-break \
             space (U+00A0), not a plain space, follows `preGestureMessageEnglish`, so the \
             robot's reader ignores this line; location 3 will say nothing before the gesture \
             in English"
        );
        assert_eq!(found.location_id, Some(3));
        assert!(found
            .help
            .unwrap()
            .contains("replace a no-break space (U+00A0) after `preGestureMessageEnglish`"));
        // A vertical tab is a space to the robot's reader: it reads the line.
        let key = "robotLocationDescription\u{B}2";
        let found = diagnostic(Span::new(0, key.len()), key, None);
        assert!(
            found
                .message
                .contains("takes it for a space and reads this line"),
            "{}",
            found.message
        );
        assert_eq!(found.location_id, Some(2));
        // Any other key with an odd space in it is shown escaped too.
        let found = diagnostic(Span::new(0, 10), "colour\u{2003}1", None);
        assert!(found
            .message
            .starts_with("`colour\\u{2003 EM SPACE}1` is not a key"));
    }
}
