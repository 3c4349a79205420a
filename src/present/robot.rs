//! What the robot holds, shown beside what the file says: each view that shows a value
//! (`show`, `tour`, `locations`) shows the chosen reader's, marked where the file differs.

use super::field::{Field, FieldValue};
use crate::model::{Dialect, Key, KnowledgeBase, Location, Point, Pose};
use crate::reader::view::{self, Held};
use crate::reader::Loaded;
use crate::robot::Reader;
use crate::syntax::Span;

/// One field of a location as `show` lists it.
#[derive(Debug, Clone, PartialEq)]
pub struct Row {
    pub field: Field,
    /// The key that holds it in this file.
    pub key: Key,
    /// Where its value is, if it has a valid one.
    pub span: Option<Span>,
    /// Its value as the reader loads it (see [`as_loaded`]), or why it has none.
    pub value: String,
}

/// Every field of `location` in a file of `dialect` (the current dialect's own fields only
/// where given, in a seed file), each as `loaded` holds it; `text` is the file.
pub fn rows(
    location: &Location<'_>,
    dialect: Dialect,
    loaded: &Loaded<'_>,
    text: &[u8],
) -> Vec<Row> {
    let mut rows = Vec::with_capacity(Field::ALL.len());
    for field in Field::ALL {
        let given = field.has_line(location);
        if field.is_current_only() && !given && dialect == Dialect::Seed {
            continue;
        }
        let key = field.key_at(location, dialect);
        let held = view::held(loaded, text, location.id, key);
        let (span, value) = match field.get(location) {
            Some((value, span)) => (Some(span), as_loaded(field, &value, &held, loaded.reader)),
            // What the robot holds then, as `check` and `tour` say it.
            None if given => (None, invalid(field, &held, loaded.reader)),
            None if field.is_current_only() => (None, "(not given)".into()),
            None => (None, "MISSING".into()),
        };
        rows.push(Row {
            field,
            key,
            span,
            value,
        });
    }
    rows
}

/// What the robot holds of a field whose line the model could not read (a number that is
/// none, such as `−45` with a Unicode minus): what the reader leaves there.
fn invalid(field: Field, held: &Held, reader: Reader) -> String {
    match held {
        Held::NotRead => format!("invalid (and reader {reader} does not read this line)"),
        held => format!(
            "{} (the line's value is invalid, so the robot's reader holds this; see the \
             finding on the line)",
            shown(field, held)
        ),
    }
}

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

/// The tour the robot loads, where it is not the file's: each stop (`None`: whatever was in
/// memory), empty when it loads no tour at all.
pub fn other_tour(kb: &KnowledgeBase<'_>, loaded: &Loaded<'_>) -> Option<Vec<Option<i32>>> {
    // Compared stop by stop, not collected: a tour may have a million stops.
    let written = kb.tour_stops().map(|id| i32::try_from(id).ok());
    let held = loaded
        .tour
        .as_ref()
        .map_or_else(Vec::new, |tour| tour.stops.clone());
    (!held.iter().copied().eq(written)).then_some(held)
}

/// `1 → 4 → ?` (`?`: undefined; at most [`super::MAX_LISTED`] stops), or `no tour at all`.
pub fn tour_text(stops: &[Option<i32>]) -> String {
    if stops.is_empty() {
        return "no tour at all".to_string();
    }
    let stops = stops
        .iter()
        .map(|stop| stop.map_or("?".to_string(), |id| id.to_string()));
    super::listed(stops, " → ")
}
