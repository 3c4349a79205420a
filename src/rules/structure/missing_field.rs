use crate::check::Diagnostics;
use crate::diagnostic::Diagnostic;
use crate::model::{Key, Language, Location, Phase};
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
    /// loads; one whose line has its key in the wrong case is reported once, as `key-case`,
    /// where the fix is.
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
        let lines: Vec<String> = missing
            .iter()
            .map(|key| format!("`{} {id} …`", key.name()))
            .collect();
        Diagnostic::new(&MISSING_FIELD, location.first_line, message)
            .at_location(Some(id))
            .with_help(match lines.len() {
                1 => format!("add a line {}", lines[0]),
                _ => format!("add the lines {}", lines.join(", ")),
            })
    });
}

/// The required keys a location has no line for (a line with a bad value still counts, and
/// so does one with the key in the wrong case: `key-case` reports it).
fn missing_keys<'l>(location: &'l Location<'_>, pose_key: Key) -> impl Iterator<Item = Key> + 'l {
    let messages = Phase::ALL
        .into_iter()
        .flat_map(|phase| Language::ALL.map(|language| Key::for_message(phase, language)));
    [Key::RobotLocationDescription, pose_key, Key::GestureTarget]
        .into_iter()
        .chain(messages)
        .filter(|&key| !location.has_line(key) && !location.has_miscased_line(key))
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
    fn a_field_whose_line_is_miscased_is_not_also_missing() {
        let text = "postGestureMessageenglish 4 We use it for teaching";
        let mut location = complete_but_post_english(text);
        assert_eq!(missing(&location), [Key::PostGestureMessageEnglish]);
        location.miscased = 1 << Key::PostGestureMessageEnglish.order();
        assert_eq!(missing(&location), []);
        // A miscased line of another key excuses nothing.
        location.miscased = 1 << Key::PostGestureMessageIsiZulu.order();
        assert_eq!(missing(&location), [Key::PostGestureMessageEnglish]);
    }
}
