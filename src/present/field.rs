//! The fields of a location, in the canonical order of SPEC §1, each with its value: what
//! `show` lists and what `diff` compares.

use serde::ser::{Serialize, SerializeSeq, Serializer};

use super::{point, pose};
use crate::model::{words, Arm, Dialect, Key, Language, Location, Phase, Point, Pose};
use crate::syntax::Span;

/// One field of a location. The pose is one field whichever dialect's key holds it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Field {
    Description,
    Pose,
    GestureTarget,
    GestureArm,
    Message(Phase, Language),
    CulturalKnowledge,
}

impl Field {
    /// Every field, in the order `ekb fmt` writes them.
    pub const ALL: [Field; 11] = [
        Field::Description,
        Field::Pose,
        Field::GestureTarget,
        Field::GestureArm,
        Field::Message(Phase::Pre, Language::English),
        Field::Message(Phase::Pre, Language::IsiZulu),
        Field::Message(Phase::Pre, Language::Kinyarwanda),
        Field::Message(Phase::Post, Language::English),
        Field::Message(Phase::Post, Language::IsiZulu),
        Field::Message(Phase::Post, Language::Kinyarwanda),
        Field::CulturalKnowledge,
    ];

    /// The key that holds this field in a file of `dialect`.
    pub fn key(self, dialect: Dialect) -> Key {
        match self {
            Field::Description => Key::RobotLocationDescription,
            Field::Pose => dialect.pose_key(),
            Field::GestureTarget => Key::GestureTarget,
            Field::GestureArm => Key::GestureArm,
            Field::Message(phase, language) => Key::for_message(phase, language),
            Field::CulturalKnowledge => Key::CulturalKnowledge,
        }
    }

    /// The field's name, the same in both dialects: the key, except `pose`.
    pub fn name(self) -> &'static str {
        match self {
            Field::Pose => "pose",
            other => other.key(Dialect::Current).name(),
        }
    }

    /// Only the current dialect has this field.
    pub fn is_current_only(self) -> bool {
        matches!(self, Field::GestureArm | Field::CulturalKnowledge)
    }

    /// The field's value at `location` and the span it was read from, if it has a valid one.
    pub fn get<'a>(self, location: &Location<'a>) -> Option<(FieldValue<'a>, Span)> {
        match self {
            Field::Description => location
                .description()
                .map(|v| (FieldValue::Text(v.value), v.span)),
            Field::Pose => location.pose.map(|v| (FieldValue::Pose(v.value), v.span)),
            Field::GestureTarget => location
                .gesture_target
                .map(|v| (FieldValue::Point(v.value), v.span)),
            Field::GestureArm => location
                .gesture_arm
                .map(|v| (FieldValue::Arm(v.value), v.span)),
            Field::Message(phase, language) => location
                .message(phase, language)
                .map(|v| (FieldValue::Text(v.value), v.span)),
            Field::CulturalKnowledge => location
                .cultural_knowledge()
                .map(|v| (FieldValue::Words(words(v.value).collect()), v.span)),
        }
    }

    /// The key that holds this field at `location` in a file of `dialect` (the pose: the
    /// key it was written with).
    pub fn key_at(self, location: &Location<'_>, dialect: Dialect) -> Key {
        match self {
            Field::Pose => location.pose_key.unwrap_or(dialect.pose_key()),
            other => other.key(dialect),
        }
    }

    /// Whether the file has a line for this field at `location`, valid or not.
    pub fn has_line(self, location: &Location<'_>) -> bool {
        location.has_line(self.key(Dialect::Current))
    }
}

/// A field's value, compared by meaning: `2.60` equals `2.6`, and the words of
/// `culturalKnowledge` are compared, not the blanks between them.
#[derive(Debug, Clone, PartialEq)]
pub enum FieldValue<'a> {
    Text(&'a str),
    Pose(Pose),
    Point(Point),
    Arm(Arm),
    Words(Vec<&'a str>),
}

impl FieldValue<'_> {
    /// The value for a person, escaped and cut after a few hundred characters; text in
    /// double quotes when `quote` is set.
    pub fn human(&self, quote: bool) -> String {
        match self {
            FieldValue::Text(text) if quote => super::quoted(text),
            FieldValue::Text(text) => super::text(text).into_owned(),
            FieldValue::Pose(value) => pose(value),
            FieldValue::Point(value) => point(value),
            FieldValue::Arm(arm) => arm.name().to_string(),
            FieldValue::Words(list) => super::text(&list.join(" ")).into_owned(),
        }
    }
}

/// As in `ekb export`: text as a string, a pose or point as an object, words as a list.
impl Serialize for FieldValue<'_> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        match self {
            FieldValue::Text(text) => serializer.serialize_str(text),
            FieldValue::Pose(value) => value.serialize(serializer),
            FieldValue::Point(value) => value.serialize(serializer),
            FieldValue::Arm(arm) => arm.serialize(serializer),
            FieldValue::Words(list) => {
                let mut seq = serializer.serialize_seq(Some(list.len()))?;
                for word in list {
                    seq.serialize_element(word)?;
                }
                seq.end()
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_are_dialect_neutral() {
        let names: Vec<&str> = Field::ALL.iter().map(|f| f.name()).collect();
        assert_eq!(
            names[..4],
            [
                "robotLocationDescription",
                "pose",
                "gestureTarget",
                "gestureArm"
            ]
        );
        assert_eq!(names[10], "culturalKnowledge");
        assert_eq!(Field::Pose.key(Dialect::Seed), Key::RobotLocation);
    }
}
