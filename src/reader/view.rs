//! One field of one location as the robot holds it, for views that show it beside what the
//! file says (`ekb show`, `ekb tour`).

use std::borrow::Cow;

use super::line::LoadedValue;
use super::Loaded;
use crate::model::Key;

/// What the robot holds in one field; its texts are the file's.
#[derive(Debug, Clone, PartialEq)]
pub enum Held<'a> {
    /// A text (the description, a message, the arm of `2026-03`), lossy where a cut split a
    /// character.
    Text(Cow<'a, str>),
    Numbers([f32; 3]),
    Words(Vec<Cow<'a, str>>),
    /// No line set it: the robot's empty text, or 0.
    Nothing,
    /// The reader took it from past the end of its line.
    Undefined,
    /// This version does not read the key at all.
    NotRead,
}

/// What `loaded` holds for `key` (for the pose, either pose key) at location `id`; `text` is
/// the file the values are spans of.
pub fn held<'a>(loaded: &Loaded<'_>, text: &'a [u8], id: u32, key: Key) -> Held<'a> {
    let key = match key {
        Key::RobotLocation | Key::RobotLocationPose => loaded.reader.pose_key(),
        other => other,
    };
    if !loaded.reader.reads(key) {
        return Held::NotRead;
    }
    let field = i32::try_from(id)
        .ok()
        .and_then(|id| loaded.locations.get(&id))
        .and_then(|location| location.field(key));
    let lossy = |span: &crate::syntax::Span| String::from_utf8_lossy(&text[span.range()]);
    match field.map(|field| field.value) {
        None => Held::Nothing,
        Some(LoadedValue::Text(span)) => Held::Text(lossy(&span)),
        Some(LoadedValue::Numbers(numbers)) => Held::Numbers(numbers),
        Some(LoadedValue::Words(words)) => Held::Words(words.iter().map(lossy).collect()),
        Some(LoadedValue::Undefined) => Held::Undefined,
    }
}

/// A C `float` as the shortest decimal that reads back as the same `float`, as an `f64`
/// (so `2.6`, not `2.5999999`).
pub fn shortest(value: f32) -> f64 {
    value.to_string().parse().unwrap_or(f64::NAN)
}

/// Three numbers of location `id` as `loaded` holds them for `key` (for the pose, the key
/// its version reads), each as [`shortest`] writes it, with the line that set them; `None`
/// when no line set them (the robot holds 0, 0, 0) or the reader took them from past the
/// end of their line.
pub fn numbers(loaded: &Loaded<'_>, id: u32, key: Key) -> Option<([f64; 3], crate::syntax::Span)> {
    let key = match key {
        Key::RobotLocation | Key::RobotLocationPose => loaded.reader.pose_key(),
        other => other,
    };
    let field = loaded.locations.get(&i32::try_from(id).ok()?)?.field(key)?;
    match field.value {
        LoadedValue::Numbers(numbers) => Some((numbers.map(shortest), field.line)),
        _ => None,
    }
}
