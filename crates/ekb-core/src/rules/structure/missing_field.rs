use crate::diagnostic::Diagnostic;
use crate::diagnostic::Diagnostics;
use crate::model::{Key, Language, Location, Phase};
use crate::rules::structure::key_case::KEY_CASE;
use crate::rules::structure::unknown_key::UNKNOWN_KEY;
use crate::rules::{consequence, declare_rule, LocationContext};

declare_rule! {
    /// ## What it does
    /// Flags a location that lacks its description, its pose, its gesture target or one of
    /// its six messages (before and after the gesture, in English, isiZulu and Kinyarwanda).
    ///
    /// ## Why it matters
    /// The robot's reader fills a missing field with nothing: a missing pose sends the
    /// robot to (0, 0), a missing message is silence at that point of the tour. A field
    /// whose line has a misspelled key counts as missing, because that is what the robot
    /// loads; when its key is in the wrong case or misspelled, the help points at that
    /// line's `key-case` or `unknown-key` finding, where the fix is, rather than ask for
    /// a line that would be a duplicate.
    ///
    /// ## Example
    /// ```text
    /// robotLocationDescription      4 Roomba
    /// robotLocation                 4 5.0 3.9 110
    /// gestureTarget                 4 6.8 4.8 0.82
    /// preGestureMessageEnglish      4 This is the Roomba
    /// ...                           (no postGestureMessageEnglish for 4)
    /// ```
    pub static MISSING_FIELD = {
        name: "missing-field",
        category: Structure,
        severity: Error,
        fixable: false,
        summary: "a location lacks its description, pose, gesture target or a message",
    };
}

/// One finding per incomplete location, naming every field it lacks.
pub fn check(location: &Location<'_>, context: &LocationContext<'_>, out: &mut Diagnostics) {
    let mut missing = missing_keys(location, context.pose_key).peekable();
    if missing.peek().is_none() {
        return;
    }
    out.push_with(&MISSING_FIELD, || {
        let missing: Vec<Key> = missing.collect();
        let first = missing[0];
        let id = location.id;
        let names: Vec<String> = missing
            .iter()
            .map(|key| format!("`{}`", key.name()))
            .collect();
        let message = match missing.len() {
            1 => format!(
                "location {id} has no {}: {}",
                names[0],
                consequence::lost(first, Some(id))
            ),
            count => format!(
                "location {id} lacks {count} fields ({}): the robot's reader leaves them empty; for one, {}",
                names.join(", "),
                consequence::lost(first, Some(id))
            ),
        };
        let (miscased, rest): (Vec<Key>, Vec<Key>) = missing
            .iter()
            .partition(|&&key| location.has_miscased_line(key));
        let (misspelled, absent): (Vec<Key>, Vec<Key>) = rest
            .into_iter()
            .partition(|&key| location.has_misspelled_line(key));
        let mut help = Vec::new();
        if !absent.is_empty() {
            let lines: Vec<String> = absent
                .iter()
                .map(|key| format!("`{} {id} …`", key.name()))
                .collect();
            help.push(match lines.len() {
                1 => format!("add a line {}", lines[0]),
                _ => format!("add the lines {}", lines.join(", ")),
            });
        }
        if !miscased.is_empty() {
            let keys: Vec<String> = miscased.iter().map(|key| format!("`{}`", key.name())).collect();
            help.push(format!(
                "the line of {} is there, its key in the wrong case: `ekb fix` corrects it (key-case)",
                keys.join(", ")
            ));
        }
        if !misspelled.is_empty() {
            let keys: Vec<String> = misspelled.iter().map(|key| format!("`{}`", key.name())).collect();
            help.push(format!(
                "the file has a line meant as {} with the key misspelled: correct the key there (see its unknown-key finding; `ekb fix --unsafe-fixes` renames it)",
                keys.join(", ")
            ));
        }
        let diagnostic = Diagnostic::new(&MISSING_FIELD, location.first_line, message)
            .at_location(Some(id))
            .with_help(help.join("; "));
        // Read with its cause: the line that is there, its key mistyped.
        match (miscased.is_empty(), misspelled.is_empty()) {
            (false, _) => diagnostic.following(&KEY_CASE),
            (true, false) => diagnostic.following(&UNKNOWN_KEY),
            (true, true) => diagnostic,
        }
    });
}

/// The required keys a location has no line for that the robot reads (a line with a bad
/// value still counts; one with the key in the wrong case does not).
fn missing_keys<'l>(location: &'l Location<'_>, pose_key: Key) -> impl Iterator<Item = Key> + 'l {
    let messages = Phase::ALL
        .into_iter()
        .flat_map(|phase| Language::ALL.map(|language| Key::for_message(phase, language)));
    [Key::RobotLocationDescription, pose_key, Key::GestureTarget]
        .into_iter()
        .chain(messages)
        .filter(|&key| !location.has_line(key))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::syntax::Span;

    fn complete_but_post_english(text: &str) -> Location<'_> {
        let mut location = Location::new(text, 4, Span::new(0, 1));
        // Every key but postGestureMessageEnglish has a line.
        location.given = !(1 << Key::PostGestureMessageEnglish.order());
        location
    }

    fn missing(location: &Location<'_>) -> Vec<Key> {
        missing_keys(location, Key::RobotLocation).collect()
    }

    #[test]
    fn a_field_whose_line_is_miscased_is_missing_and_points_at_the_fix() {
        let text = "postGestureMessageenglish 4 We use it for teaching";
        let mut location = complete_but_post_english(text);
        location.miscased = 1 << Key::PostGestureMessageEnglish.order();
        assert_eq!(missing(&location), [Key::PostGestureMessageEnglish]);
        let context = LocationContext {
            source: text,
            pose_key: Key::RobotLocation,
            visited: None,
            reader: crate::robot::Reader::D542,
        };
        let mut out = Diagnostics::default();
        check(&location, &context, &mut out);
        let help = out[0].help.as_deref().unwrap();
        assert!(!help.contains("add a line"), "{help}");
        assert!(help.contains("wrong case"), "{help}");
        // A miscased line of another key excuses nothing.
        location.miscased = 1 << Key::PostGestureMessageIsiZulu.order();
        let mut out = Diagnostics::default();
        check(&location, &context, &mut out);
        assert!(out[0].help.as_deref().unwrap().starts_with("add a line"));
    }
}
