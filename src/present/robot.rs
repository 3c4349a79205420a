//! What the robot holds, shown beside what the file says: each view that shows a value
//! (`show`, `tour`, `locations`) shows the chosen reader's, marked where the file differs.

use super::field::{Field, FieldValue};
use crate::model::{Point, Pose};
use crate::reader::view::{self, Held};
use crate::reader::Reader;

/// What the robot holds of a field the file gives as `written`, and, where that is not
/// what the file says, what the file says.
pub fn as_loaded(field: Field, written: &FieldValue<'_>, held: &Held, reader: Reader) -> String {
    let file_says = describe(field, written);
    match held {
        Held::NotRead => format!("{file_says} (reader {reader} does not read this line)"),
        Held::Undefined => format!("undefined (the file says {file_says})"),
        _ if agrees(field, written, held) => file_says,
        _ => format!("{} (the file says {file_says})", shown(field, held)),
    }
}

/// Whether the robot holds what the file says.
pub fn agrees(field: Field, written: &FieldValue<'_>, held: &Held) -> bool {
    match (held, written) {
        (Held::Text(held), FieldValue::Text(text)) => held == text,
        (Held::Text(held), FieldValue::Arm(arm)) => held == arm.name(),
        (Held::Words(held), FieldValue::Words(words)) => held == words,
        (Held::Numbers(held), FieldValue::Pose(pose)) => {
            *held == [pose.x, pose.y, pose.theta].map(|n| n as f32)
        }
        (Held::Numbers(held), FieldValue::Point(point)) => {
            *held == [point.x, point.y, point.z].map(|n| n as f32)
        }
        (Held::Nothing, _) => shown(field, held) == written.human(false),
        _ => false,
    }
}

/// What the robot holds, for a person: a text quoted, numbers as the views write them, a
/// field no line set as the robot's empty text or 0.
pub fn shown(field: Field, held: &Held) -> String {
    let numbers = |[a, b, c]: [f64; 3]| match field {
        Field::Pose => FieldValue::Pose(Pose {
            x: a,
            y: b,
            theta: c,
        })
        .human(false),
        _ => FieldValue::Point(Point { x: a, y: b, z: c }).human(false),
    };
    match held {
        Held::Nothing if matches!(field, Field::Pose | Field::GestureTarget) => numbers([0.0; 3]),
        Held::Nothing => "nothing".to_string(),
        Held::Text(text) => super::quoted(text),
        Held::Words(words) => super::text(&words.join(" ")).into_owned(),
        Held::Numbers(loaded) => numbers(loaded.map(view::shortest)),
        Held::Undefined => "undefined".to_string(),
        Held::NotRead => "not read".to_string(),
    }
}

/// A field's value, with what it means where that is not plain.
fn describe(field: Field, value: &FieldValue<'_>) -> String {
    match (field, value) {
        (Field::GestureTarget, FieldValue::Point(target)) => super::Gesture::of(target).short(),
        (Field::Message(..), FieldValue::Text(text)) if crate::model::is_placeholder(text) => {
            format!("{} (placeholder, untranslated)", value.human(false))
        }
        _ => value.human(false),
    }
}
