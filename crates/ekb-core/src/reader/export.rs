//! `ekb export --as-loaded`: what a version of the reader loads, in the JSON shape of SPEC
//! §5. Each field holds what the robot holds: a field no line set is the robot's empty text
//! or 0; `gestureArm` and `culturalKnowledge` are `null` where the version does not read
//! them; a value the reader took from bytes of its buffer that no line wrote (undefined) is
//! `null`. A number JSON cannot hold, which the robot does hold (`1e39` loads as an
//! infinity), is the string `"inf"`, `"-inf"` or `"nan"`.

use std::borrow::Cow;

use serde::{Serialize, Serializer};

use super::line::LoadedValue;
use super::load::{Loaded, LoadedLocation};
use super::view::shortest;
use crate::model::{Dialect, Key, Language, Phase};
use crate::render::safe_json::MadeAsWritten;

/// The whole of what the robot holds.
#[derive(Debug, Serialize)]
#[serde(rename_all = "camelCase")]
pub struct LoadedExport<'a> {
    /// The version of the reader.
    pub reader: &'static str,
    pub dialect: Dialect,
    /// In ascending id order.
    pub locations: LoadedLocations<'a>,
    /// `null` when no line set the tour; a `null` stop holds whatever was in memory.
    pub tour: Option<Vec<Option<i32>>>,
}

/// Every location, made as it is written ([`MadeAsWritten`]): a file of 100,000 locations would
/// otherwise hold all of them at once, as large as the file, and read every field's line
/// again on one core.
#[derive(Debug)]
pub struct LoadedLocations<'a> {
    loaded: &'a Loaded<'a>,
}

impl Serialize for LoadedLocations<'_> {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let loaded = self.loaded;
        let locations = loaded.locations.values().as_slice();
        let make =
            |location: &LoadedLocation| LoadedLocationExport::new(location, loaded, loaded.text());
        MadeAsWritten::new(locations, make).serialize(serializer)
    }
}

#[derive(Debug, Serialize)]
#[serde(rename_all = "camelCase")]
pub struct LoadedLocationExport<'a> {
    pub id: i32,
    pub description: Option<Cow<'a, str>>,
    pub pose: Option<LoadedPose>,
    pub gesture_target: Option<LoadedPoint>,
    pub gesture_arm: Option<Cow<'a, str>>,
    pub pre_gesture_message: LoadedMessages<'a>,
    pub post_gesture_message: LoadedMessages<'a>,
    pub cultural_knowledge: Option<Vec<Cow<'a, str>>>,
}

#[derive(Debug, Serialize)]
pub struct LoadedPose {
    pub x: LoadedNumber,
    pub y: LoadedNumber,
    pub theta: LoadedNumber,
}

#[derive(Debug, Serialize)]
pub struct LoadedPoint {
    pub x: LoadedNumber,
    pub y: LoadedNumber,
    pub z: LoadedNumber,
}

/// A C `float` as the robot holds it: a JSON number where JSON has one (see [`shortest`]),
/// else the name C's `printf` gives it, `"inf"`, `"-inf"` or `"nan"`.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(untagged)]
pub enum LoadedNumber {
    Finite(f64),
    NotFinite(&'static str),
}

impl LoadedNumber {
    pub fn of(value: f32) -> LoadedNumber {
        match value {
            _ if value.is_nan() => LoadedNumber::NotFinite("nan"),
            f32::INFINITY => LoadedNumber::NotFinite("inf"),
            f32::NEG_INFINITY => LoadedNumber::NotFinite("-inf"),
            _ => LoadedNumber::Finite(shortest(value)),
        }
    }
}

#[derive(Debug, Serialize)]
pub struct LoadedMessages<'a> {
    pub english: Option<Cow<'a, str>>,
    #[serde(rename = "isiZulu")]
    pub isi_zulu: Option<Cow<'a, str>>,
    pub kinyarwanda: Option<Cow<'a, str>>,
}

impl<'a> LoadedExport<'a> {
    pub fn new(loaded: &'a Loaded<'a>) -> LoadedExport<'a> {
        LoadedExport {
            reader: loaded.reader.name(),
            dialect: match loaded.reader.pose_key() {
                Key::RobotLocation => Dialect::Seed,
                _ => Dialect::Current,
            },
            locations: LoadedLocations { loaded },
            tour: loaded.tour.as_ref().map(|tour| tour.stops.clone()),
        }
    }
}

impl<'a> LoadedLocationExport<'a> {
    fn new(
        location: &LoadedLocation,
        loaded: &Loaded<'_>,
        text: &'a [u8],
    ) -> LoadedLocationExport<'a> {
        let value = |key: Key| loaded.field(location, key).map(|field| field.value);
        let text_of = |key: Key| match value(key) {
            None => Some(Cow::Borrowed("")),
            Some(value) => loaded_text(&value, text),
        };
        let numbers = |key: Key| match value(key) {
            None => Some([LoadedNumber::Finite(0.0); 3]),
            Some(LoadedValue::Numbers(numbers)) => Some(numbers.map(LoadedNumber::of)),
            Some(_) => None,
        };
        let messages = |phase: Phase| {
            let message = |language| text_of(Key::for_message(phase, language));
            LoadedMessages {
                english: message(Language::English),
                isi_zulu: message(Language::IsiZulu),
                kinyarwanda: message(Language::Kinyarwanda),
            }
        };
        let reader = loaded.reader;
        LoadedLocationExport {
            id: location.id,
            description: text_of(Key::RobotLocationDescription),
            pose: numbers(reader.pose_key()).map(|[x, y, theta]| LoadedPose { x, y, theta }),
            gesture_target: numbers(Key::GestureTarget).map(|[x, y, z]| LoadedPoint { x, y, z }),
            gesture_arm: if reader.reads(Key::GestureArm) {
                text_of(Key::GestureArm)
            } else {
                None
            },
            pre_gesture_message: messages(Phase::Pre),
            post_gesture_message: messages(Phase::Post),
            cultural_knowledge: match value(Key::CulturalKnowledge) {
                _ if !reader.reads(Key::CulturalKnowledge) => None,
                None => Some(Vec::new()),
                Some(LoadedValue::Words(words)) => Some(
                    words
                        .iter()
                        .map(|span| String::from_utf8_lossy(&text[span.range()]))
                        .collect(),
                ),
                Some(_) => None,
            },
        }
    }
}

/// A loaded text (lossy where a cut split a character), or `None` when undefined.
fn loaded_text<'a>(value: &LoadedValue, text: &'a [u8]) -> Option<Cow<'a, str>> {
    match value {
        LoadedValue::Text(span) => Some(String::from_utf8_lossy(&text[span.range()])),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn floats_print_as_their_shortest_decimal_or_their_c_name() {
        let json = |value: f32| serde_json::to_string(&LoadedNumber::of(value)).unwrap();
        assert_eq!(json(2.6), "2.6");
        assert_eq!(json(-90.0), "-90.0");
        assert_eq!(json(f32::INFINITY), r#""inf""#);
        assert_eq!(json(f32::NEG_INFINITY), r#""-inf""#);
        assert_eq!(json(f32::NAN), r#""nan""#);
    }
}
