//! The JSON shape of `ekb export` and `ekb import` (SPEC §5), shared by both commands.
//!
//! Its JSON Schema is derived from these types (`ekb export --schema`), never written by hand.

use schemars::JsonSchema;
use serde::{Deserialize, Serialize, Serializer};

use crate::model::{
    Arm, Dialect, KnowledgeBase, Language, Location, Locations, Phase, Point, Pose,
};
use crate::render::safe_json::MadeAsWritten;

/// A whole knowledge base as JSON.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(rename_all = "camelCase", deny_unknown_fields)]
pub struct ExportedKnowledgeBase {
    /// `seed` or `current`; null when the file has no dialect-specific key.
    pub dialect: Option<Dialect>,
    /// In the order of the file (ascending ids, for a file written in that order).
    pub locations: Vec<ExportedLocation>,
    /// Location ids in the order visited; null when the file has no tour.
    pub tour: Option<Vec<u32>>,
}

/// One location as JSON. A field absent from the file is null.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize, JsonSchema)]
#[serde(rename_all = "camelCase", deny_unknown_fields)]
pub struct ExportedLocation {
    /// 1..=2147483647
    #[schemars(range(min = 1, max = 2147483647))]
    pub id: u32,
    pub description: Option<String>,
    pub pose: Option<Pose>,
    pub gesture_target: Option<Point>,
    pub gesture_arm: Option<Arm>,
    pub pre_gesture_message: ExportedMessages,
    pub post_gesture_message: ExportedMessages,
    pub cultural_knowledge: Vec<String>,
}

/// The three languages of one message.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize, JsonSchema, Default)]
#[serde(deny_unknown_fields)]
pub struct ExportedMessages {
    pub english: Option<String>,
    #[serde(rename = "isiZulu")]
    pub isi_zulu: Option<String>,
    pub kinyarwanda: Option<String>,
}

impl From<&KnowledgeBase<'_>> for ExportedKnowledgeBase {
    /// The model as JSON: the values the robot would load, nothing of the layout.
    fn from(kb: &KnowledgeBase<'_>) -> ExportedKnowledgeBase {
        ExportedKnowledgeBase {
            dialect: kb.dialect,
            locations: kb
                .locations()
                .in_file_order()
                .into_iter()
                .map(ExportedLocation::from)
                .collect(),
            tour: kb
                .tour
                .as_ref()
                .map(|tour| tour.stops().map(|stop| stop.value).collect()),
        }
    }
}

impl From<&Location<'_>> for ExportedLocation {
    fn from(location: &Location<'_>) -> ExportedLocation {
        let messages = |phase: Phase| {
            let text = |language: Language| {
                location
                    .message(phase, language)
                    .map(|value| value.value.to_string())
            };
            ExportedMessages {
                english: text(Language::English),
                isi_zulu: text(Language::IsiZulu),
                kinyarwanda: text(Language::Kinyarwanda),
            }
        };
        ExportedLocation {
            id: location.id,
            description: location.description().map(|value| value.value.to_string()),
            pose: location.pose.map(|value| value.value),
            gesture_target: location.gesture_target.map(|value| value.value),
            gesture_arm: location.gesture_arm.map(|value| value.value),
            pre_gesture_message: messages(Phase::Pre),
            post_gesture_message: messages(Phase::Post),
            cultural_knowledge: location.cultural_words().map(str::to_string).collect(),
        }
    }
}

/// The JSON of [`ExportedKnowledgeBase`], serialized straight from the model: one location
/// at a time, its texts borrowed from the file. Building the owned export first copied every
/// text of the file (60 MB for 100,000 locations) before writing any of it.
#[derive(Serialize)]
#[serde(rename = "ExportedKnowledgeBase")]
pub struct ExportView<'k, 'a> {
    dialect: Option<Dialect>,
    #[serde(serialize_with = "locations_view")]
    locations: &'k Locations<'a>,
    tour: Option<Vec<u32>>,
}

impl<'k, 'a> ExportView<'k, 'a> {
    pub fn new(kb: &'k KnowledgeBase<'a>) -> ExportView<'k, 'a> {
        ExportView {
            dialect: kb.dialect,
            locations: kb.locations(),
            tour: kb.tour.as_ref().map(|_| kb.tour_stops().collect()),
        }
    }
}

fn locations_view<'a, S: Serializer>(locations: &Locations<'a>, out: S) -> Result<S::Ok, S::Error> {
    let locations = locations.in_file_order();
    MadeAsWritten::new(&locations, |location: &&Location<'a>| {
        LocationView::new(location)
    })
    .serialize(out)
}

/// [`ExportedLocation`], borrowed from the model: the same fields, in the same order.
#[derive(Serialize)]
#[serde(rename = "ExportedLocation", rename_all = "camelCase")]
pub struct LocationView<'a> {
    id: u32,
    description: Option<&'a str>,
    pose: Option<Pose>,
    gesture_target: Option<Point>,
    gesture_arm: Option<Arm>,
    pre_gesture_message: MessagesView<'a>,
    post_gesture_message: MessagesView<'a>,
    cultural_knowledge: Vec<&'a str>,
}

/// [`ExportedMessages`], borrowed from the model.
#[derive(Serialize)]
#[serde(rename = "ExportedMessages")]
struct MessagesView<'a> {
    english: Option<&'a str>,
    #[serde(rename = "isiZulu")]
    isi_zulu: Option<&'a str>,
    kinyarwanda: Option<&'a str>,
}

impl<'a> LocationView<'a> {
    pub fn new(location: &Location<'a>) -> LocationView<'a> {
        let messages = |phase: Phase| {
            let text = |language: Language| location.message(phase, language).map(|m| m.value);
            MessagesView {
                english: text(Language::English),
                isi_zulu: text(Language::IsiZulu),
                kinyarwanda: text(Language::Kinyarwanda),
            }
        };
        LocationView {
            id: location.id,
            description: location.description().map(|value| value.value),
            pose: location.pose.map(|value| value.value),
            gesture_target: location.gesture_target.map(|value| value.value),
            gesture_arm: location.gesture_arm.map(|value| value.value),
            pre_gesture_message: messages(Phase::Pre),
            post_gesture_message: messages(Phase::Post),
            cultural_knowledge: location.cultural_words().collect(),
        }
    }
}
