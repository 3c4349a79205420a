//! The JSON of `ekb export` as a [`Document`], for `ekb import`.
//!
//! Everything is checked before anything is written: a value that the file format cannot
//! hold (a text on two lines, an id out of range, …) is an error naming its JSON path, never
//! a silently different file.

use std::borrow::Cow;
use std::collections::HashMap;
use std::fmt;

use super::{BlockOrder, Document};
use crate::model::export::{ExportedKnowledgeBase, ExportedLocation, ExportedMessages};
use crate::model::{Dialect, Key, Language, Phase};
use crate::syntax::is_blank;

/// Numbers whose plain decimal form is longer than this are written with an exponent.
const LONGEST_PLAIN_NUMBER: usize = 24;

/// A value of the JSON that the file format cannot hold.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ImportError {
    /// Where, as `locations[2].preGestureMessage.english`.
    pub path: String,
    pub message: String,
}

impl fmt::Display for ImportError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: {}", self.path, self.message)
    }
}

impl std::error::Error for ImportError {}

impl Document<'static> {
    /// The canonical file of an export. A pose is written with the key of the export's
    /// dialect (`robotLocationPose` when it has none, as the current robot reads).
    ///
    /// The export's lines are written plainly, in canonical order, and laid out as `ekb fmt`
    /// lays out a file: one layout for both.
    pub fn from_export(kb: &ExportedKnowledgeBase) -> Result<Document<'static>, ImportError> {
        let pose_key = kb.dialect.unwrap_or(Dialect::Current).pose_key();
        let mut seen: HashMap<u32, usize> = HashMap::new();
        let mut text = String::new();
        // Without a pose line, the file would not tell its dialect: declare it.
        if let Some(dialect) = kb
            .dialect
            .filter(|_| kb.locations.iter().all(|l| l.pose.is_none()))
        {
            text.push_str(&dialect.declaration());
            text.push_str("\n\n");
        }
        for (index, location) in kb.locations.iter().enumerate() {
            let path = format!("locations[{index}]");
            check_id(location.id, &format!("{path}.id"))?;
            if let Some(first) = seen.insert(location.id, index) {
                return Err(error(
                    format!("{path}.id"),
                    format!(
                        "location {} is also at locations[{first}]; each id may appear once",
                        location.id
                    ),
                ));
            }
            for (key, value) in values(location, pose_key, &path)? {
                text.push_str(&format!("{} {} {value}\n", key.name(), location.id));
            }
        }
        if let Some(stops) = &kb.tour {
            for (index, &id) in stops.iter().enumerate() {
                check_id(id, &format!("tour[{index}]"))?;
            }
            let items: Vec<String> = std::iter::once(stops.len() as u32)
                .chain(stops.iter().copied())
                .map(|n| n.to_string())
                .collect();
            let key = Key::TourSpecification.name();
            text.push_str(&format!("{key} {}\n", items.join(" ")));
        }
        // Every value was checked to fit on its line, so each line reads as written.
        Ok(
            Document::parse_text(Cow::Owned(text), BlockOrder::FirstSeen)
                .expect("no stray carriage return"),
        )
    }
}

/// A location's values, in canonical order.
fn values<'a>(
    location: &'a ExportedLocation,
    pose_key: Key,
    path: &str,
) -> Result<Vec<(Key, Cow<'a, str>)>, ImportError> {
    let mut values: Vec<(Key, Cow<'a, str>)> = Vec::new();
    if let Some(description) = &location.description {
        let at = format!("{path}.description");
        values.push((Key::RobotLocationDescription, text(description, &at)?));
    }
    if let Some(pose) = &location.pose {
        let value = [metres(pose.x), metres(pose.y), number(pose.theta)].join(" ");
        values.push((pose_key, value.into()));
    }
    if let Some(target) = &location.gesture_target {
        let value = [metres(target.x), metres(target.y), metres(target.z)].join(" ");
        values.push((Key::GestureTarget, value.into()));
    }
    if let Some(arm) = location.gesture_arm {
        values.push((Key::GestureArm, arm.name().into()));
    }
    for phase in Phase::ALL {
        let (messages, field) = match phase {
            Phase::Pre => (&location.pre_gesture_message, "preGestureMessage"),
            Phase::Post => (&location.post_gesture_message, "postGestureMessage"),
        };
        for language in Language::ALL {
            if let Some(message) = message(messages, language) {
                let at = format!("{path}.{field}.{}", language_field(language));
                values.push((Key::for_message(phase, language), text(message, &at)?));
            }
        }
    }
    if !location.cultural_knowledge.is_empty() {
        for (index, word) in location.cultural_knowledge.iter().enumerate() {
            check_word(word, &format!("{path}.culturalKnowledge[{index}]"))?;
        }
        values.push((
            Key::CulturalKnowledge,
            location.cultural_knowledge.join(" ").into(),
        ));
    }
    if values.is_empty() {
        return Err(error(
            path.to_string(),
            format!(
                "location {} has no field at all; a file cannot hold an empty location, so give \
                 it a description or leave it out",
                location.id
            ),
        ));
    }
    Ok(values)
}

fn message(messages: &ExportedMessages, language: Language) -> Option<&String> {
    match language {
        Language::English => messages.english.as_ref(),
        Language::IsiZulu => messages.isi_zulu.as_ref(),
        Language::Kinyarwanda => messages.kinyarwanda.as_ref(),
    }
}

/// The JSON field of a language (as in `ExportedMessages`).
fn language_field(language: Language) -> &'static str {
    match language {
        Language::English => "english",
        Language::IsiZulu => "isiZulu",
        Language::Kinyarwanda => "kinyarwanda",
    }
}

fn error(path: String, message: impl Into<String>) -> ImportError {
    ImportError {
        path,
        message: message.into(),
    }
}

fn check_id(id: u32, path: &str) -> Result<(), ImportError> {
    if id == 0 || id > i32::MAX as u32 {
        return Err(error(
            path.to_string(),
            format!("{id} is no location id: ids are 1 to 2147483647"),
        ));
    }
    Ok(())
}

/// A text value the file can hold: one line, no control character but tab, and no blanks at
/// either end (the file format trims them).
fn text<'a>(value: &'a str, path: &str) -> Result<Cow<'a, str>, ImportError> {
    let fail = |message: String| Err(error(path.to_string(), message));
    if value.is_empty() {
        return fail("is empty; write null for a value the location does not have".into());
    }
    if let Some(ch) = value.chars().find(|&ch| ch.is_control() && ch != '\t') {
        return if matches!(ch, '\n' | '\r') {
            fail("contains a line break; a value must fit on one line".into())
        } else {
            fail(format!(
                "contains the control character U+{:04X}; remove it",
                ch as u32
            ))
        };
    }
    let bytes = value.as_bytes();
    if is_blank(bytes[0]) || is_blank(bytes[bytes.len() - 1]) {
        return fail(
            "starts or ends with a space or tab, which the file format cannot keep; trim it".into(),
        );
    }
    Ok(value.into())
}

/// A culturalKnowledge word: no blanks inside (they separate words), no control characters.
fn check_word(word: &str, path: &str) -> Result<(), ImportError> {
    if word.is_empty() || word.chars().any(|ch| ch.is_control() || ch == ' ') {
        return Err(error(
            path.to_string(),
            format!(
                "`{}` is not one word; each entry must be a single word without spaces or control characters",
                crate::render::escape::escape(word)
            ),
        ));
    }
    Ok(())
}

/// A number as the robot's files write it, parsing back to exactly the same `f64`: the
/// shortest decimal form (`2.6`, `-90`), or with an exponent when that would be very long.
fn number(n: f64) -> String {
    let plain = n.to_string();
    if plain.len() > LONGEST_PLAIN_NUMBER {
        format!("{n:e}")
    } else {
        plain
    }
}

/// A distance in metres, as the robot's files write them: always with a decimal point
/// (`2.0`, `0.82`), while angles are whole when they can be (`-90`).
fn metres(n: f64) -> String {
    let mut written = number(n);
    if !written.contains(['.', 'e']) {
        written.push_str(".0");
    }
    written
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::build::parse_number;

    #[test]
    fn numbers_are_written_as_the_robot_files_write_them() {
        assert_eq!(number(2.6), "2.6");
        assert_eq!(number(-90.0), "-90");
        assert_eq!(metres(0.0), "0.0");
        assert_eq!(metres(2.0), "2.0");
        assert_eq!(metres(0.82), "0.82");
        assert_eq!(metres(-0.0), "-0.0");
        assert_eq!(number(1e300), "1e300");
        assert_eq!(metres(1e-300), "1e-300");
    }

    #[test]
    fn numbers_parse_back_to_the_same_value() {
        for n in [
            0.1 + 0.2,
            1.0 / 3.0,
            -123456.789,
            f64::MAX,
            f64::MIN_POSITIVE,
            5e-324,
        ] {
            assert_eq!(parse_number(&number(n)), Some(n));
            assert_eq!(parse_number(&metres(n)), Some(n));
        }
    }

    #[test]
    fn texts_the_file_cannot_hold_are_refused() {
        assert!(text("Sawubona", "p").is_ok());
        assert!(text("tab\tinside", "p").is_ok());
        for bad in ["", "two\nlines", "bell\u{7}", " leading", "trailing\t"] {
            let error = text(bad, "locations[0].description").unwrap_err();
            assert_eq!(error.path, "locations[0].description");
        }
    }
}
