//! The keys of the knowledge-base format, their canonical spelling and what their values hold.

use serde::{Deserialize, Serialize};

/// One of the two spellings of the format (SPEC §1).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize, schemars::JsonSchema)]
#[serde(rename_all = "lowercase")]
pub enum Dialect {
    /// The document's dialect (v1.1): `robotLocation`.
    Seed,
    /// The robot's current dialect: `robotLocationPose`, `culturalKnowledge`, `gestureArm`.
    Current,
}

impl Dialect {
    pub const ALL: [Dialect; 2] = [Dialect::Seed, Dialect::Current];

    /// What this dialect is, in a line (`ekb fix --help` shows it beside the name).
    pub fn summary(self) -> &'static str {
        match self {
            Dialect::Seed => "The document's dialect (v1.1): `robotLocation`",
            Dialect::Current => {
                "The robot's current dialect: `robotLocationPose`, `culturalKnowledge`, `gestureArm`"
            }
        }
    }

    pub fn name(self) -> &'static str {
        match self {
            Dialect::Seed => "seed",
            Dialect::Current => "current",
        }
    }

    pub fn other(self) -> Dialect {
        match self {
            Dialect::Seed => Dialect::Current,
            Dialect::Current => Dialect::Seed,
        }
    }

    /// The key that holds a location's pose in this dialect.
    pub fn pose_key(self) -> Key {
        match self {
            Dialect::Seed => Key::RobotLocation,
            Dialect::Current => Key::RobotLocationPose,
        }
    }

    /// The comment that declares this dialect in a file whose lines do not tell it (no pose,
    /// no key of the current dialect): what `ekb import` writes for an export without poses,
    /// so that exporting the file again gives the same dialect.
    pub fn declaration(self) -> String {
        format!("{DECLARATION}{}", self.name())
    }

    /// The dialect that a comment line of `text` declares ([`Dialect::declaration`], blanks
    /// free around each part), the first if several do.
    pub fn declared_in(text: &str) -> Option<Dialect> {
        let declared = |line: &str| {
            let rest = line.trim().strip_prefix('#')?.trim_start();
            let rest = rest.strip_prefix("ekb:")?.trim_start();
            match rest.strip_prefix("dialect")?.trim() {
                "seed" => Some(Dialect::Seed),
                "current" => Some(Dialect::Current),
                _ => None,
            }
        };
        // Looked for only where the lines tell no dialect, by memchr, a line at most once.
        let bytes = text.as_bytes();
        let mut from = 0;
        while let Some(found) = memchr::memmem::find(&bytes[from..], b"ekb:") {
            let at = from + found;
            // `from` is always where a line starts.
            let start = memchr::memrchr(b'\n', &bytes[from..at]).map_or(from, |i| from + i + 1);
            let end = memchr::memchr(b'\n', &bytes[at..]).map_or(bytes.len(), |i| at + i);
            if let Some(dialect) = declared(&text[start..end]) {
                return Some(dialect);
            }
            from = end + 1;
            if from >= bytes.len() {
                break;
            }
        }
        None
    }
}

/// How a dialect's declaration begins ([`Dialect::declaration`]).
const DECLARATION: &str = "# ekb: dialect ";

/// The languages the robot speaks.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Language {
    English,
    IsiZulu,
    Kinyarwanda,
}

impl Language {
    pub const ALL: [Language; 3] = [Language::English, Language::IsiZulu, Language::Kinyarwanda];

    /// The name as the keys and the robot write it.
    pub fn name(self) -> &'static str {
        match self {
            Language::English => "English",
            Language::IsiZulu => "isiZulu",
            Language::Kinyarwanda => "Kinyarwanda",
        }
    }

    pub fn index(self) -> usize {
        self as usize
    }
}

/// Whether a message is said before or after the gesture.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Phase {
    Pre,
    Post,
}

impl Phase {
    pub const ALL: [Phase; 2] = [Phase::Pre, Phase::Post];

    pub fn name(self) -> &'static str {
        match self {
            Phase::Pre => "before",
            Phase::Post => "after",
        }
    }

    pub fn index(self) -> usize {
        self as usize
    }
}

/// What a key's value holds.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ValueKind {
    Text,
    /// `x y theta`
    Pose,
    /// `x y z`
    Point,
    /// `left` or `right`
    Arm,
    /// one or more words
    Words,
    /// `n id1 … idn`, with no location id before it
    Tour,
}

/// A known key, in the order of SPEC §1's table (the order `ekb fmt` writes them in).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Key {
    RobotLocationDescription,
    RobotLocation,
    RobotLocationPose,
    GestureTarget,
    GestureArm,
    PreGestureMessageEnglish,
    PreGestureMessageIsiZulu,
    PreGestureMessageKinyarwanda,
    PostGestureMessageEnglish,
    PostGestureMessageIsiZulu,
    PostGestureMessageKinyarwanda,
    CulturalKnowledge,
    TourSpecification,
}

impl Key {
    pub const ALL: [Key; 13] = [
        Key::RobotLocationDescription,
        Key::RobotLocation,
        Key::RobotLocationPose,
        Key::GestureTarget,
        Key::GestureArm,
        Key::PreGestureMessageEnglish,
        Key::PreGestureMessageIsiZulu,
        Key::PreGestureMessageKinyarwanda,
        Key::PostGestureMessageEnglish,
        Key::PostGestureMessageIsiZulu,
        Key::PostGestureMessageKinyarwanda,
        Key::CulturalKnowledge,
        Key::TourSpecification,
    ];

    /// The spelling the robot's reader matches.
    pub fn name(self) -> &'static str {
        match self {
            Key::RobotLocationDescription => "robotLocationDescription",
            Key::RobotLocation => "robotLocation",
            Key::RobotLocationPose => "robotLocationPose",
            Key::GestureTarget => "gestureTarget",
            Key::GestureArm => "gestureArm",
            Key::PreGestureMessageEnglish => "preGestureMessageEnglish",
            Key::PreGestureMessageIsiZulu => "preGestureMessageIsiZulu",
            Key::PreGestureMessageKinyarwanda => "preGestureMessageKinyarwanda",
            Key::PostGestureMessageEnglish => "postGestureMessageEnglish",
            Key::PostGestureMessageIsiZulu => "postGestureMessageIsiZulu",
            Key::PostGestureMessageKinyarwanda => "postGestureMessageKinyarwanda",
            Key::CulturalKnowledge => "culturalKnowledge",
            Key::TourSpecification => "tourSpecification",
        }
    }

    /// The key spelled exactly so. (Run on every line: a `match` on the string compiles to
    /// a dispatch on length and a few comparisons, not thirteen string comparisons.)
    pub fn from_name(name: &str) -> Option<Key> {
        Some(match name {
            "robotLocationDescription" => Key::RobotLocationDescription,
            "robotLocation" => Key::RobotLocation,
            "robotLocationPose" => Key::RobotLocationPose,
            "gestureTarget" => Key::GestureTarget,
            "gestureArm" => Key::GestureArm,
            "preGestureMessageEnglish" => Key::PreGestureMessageEnglish,
            "preGestureMessageIsiZulu" => Key::PreGestureMessageIsiZulu,
            "preGestureMessageKinyarwanda" => Key::PreGestureMessageKinyarwanda,
            "postGestureMessageEnglish" => Key::PostGestureMessageEnglish,
            "postGestureMessageIsiZulu" => Key::PostGestureMessageIsiZulu,
            "postGestureMessageKinyarwanda" => Key::PostGestureMessageKinyarwanda,
            "culturalKnowledge" => Key::CulturalKnowledge,
            "tourSpecification" => Key::TourSpecification,
            _ => return None,
        })
    }

    /// The key spelled so, ignoring ASCII case.
    pub fn from_name_ignoring_case(name: &str) -> Option<Key> {
        Key::ALL
            .into_iter()
            .find(|key| key.name().eq_ignore_ascii_case(name))
    }

    /// The key `written` is likely a typo of (`preGestureMesageEnglish`): the closest by
    /// edit distance, ignoring case, if close enough.
    pub fn nearest_to(written: &str) -> Option<Key> {
        // Long garbage (a pasted paragraph) is no typo, and comparing it would be slow.
        if written.len() > 64 {
            return None;
        }
        let lower = written.to_ascii_lowercase();
        Key::ALL
            .into_iter()
            .map(|candidate| {
                let name = candidate.name().to_ascii_lowercase();
                (strsim::damerau_levenshtein(&lower, &name), candidate)
            })
            .filter(|&(distance, candidate)| distance <= 3.max(candidate.name().len() / 5))
            .min_by_key(|&(distance, _)| distance)
            .map(|(_, candidate)| candidate)
    }

    pub fn value_kind(self) -> ValueKind {
        match self {
            Key::RobotLocation | Key::RobotLocationPose => ValueKind::Pose,
            Key::GestureTarget => ValueKind::Point,
            Key::GestureArm => ValueKind::Arm,
            Key::CulturalKnowledge => ValueKind::Words,
            Key::TourSpecification => ValueKind::Tour,
            _ => ValueKind::Text,
        }
    }

    /// What the key's value means, for people (SPEC §1's table).
    pub fn meaning(self) -> &'static str {
        match self {
            Key::RobotLocationDescription => "the short name of the location, e.g. `Roomba`",
            Key::RobotLocation | Key::RobotLocationPose => {
                "where the robot stands on the map: x and y in metres, theta (its heading) in degrees"
            }
            Key::GestureTarget => {
                "the point the robot gestures at, in metres; `0 0 0` means no gesture here"
            }
            Key::GestureArm => "the arm the robot gestures with",
            Key::PreGestureMessageEnglish
            | Key::PreGestureMessageIsiZulu
            | Key::PreGestureMessageKinyarwanda => "what the robot says before the gesture",
            Key::PostGestureMessageEnglish
            | Key::PostGestureMessageIsiZulu
            | Key::PostGestureMessageKinyarwanda => "what the robot says after the gesture",
            Key::CulturalKnowledge => {
                "keys into the culture knowledge base, e.g. `DeicticShape` (at most 2)"
            }
            Key::TourSpecification => {
                "the tour: the number of stops, then each location's id in the order visited (no location id before it)"
            }
        }
    }

    /// How the key's value is written.
    pub fn value_syntax(self) -> &'static str {
        match self.value_kind() {
            ValueKind::Text => "text",
            ValueKind::Pose => "x y theta",
            ValueKind::Point => "x y z",
            ValueKind::Arm => "left | right",
            ValueKind::Words => "word [word]",
            ValueKind::Tour => "n id1 … idn",
        }
    }

    /// The dialect a key belongs to, or `None` for keys both dialects share.
    pub fn dialect(self) -> Option<Dialect> {
        match self {
            Key::RobotLocation => Some(Dialect::Seed),
            Key::RobotLocationPose | Key::CulturalKnowledge | Key::GestureArm => {
                Some(Dialect::Current)
            }
            _ => None,
        }
    }

    /// The message a key holds, if it is one of the six message keys.
    pub fn message(self) -> Option<(Phase, Language)> {
        use Language::*;
        use Phase::*;
        match self {
            Key::PreGestureMessageEnglish => Some((Pre, English)),
            Key::PreGestureMessageIsiZulu => Some((Pre, IsiZulu)),
            Key::PreGestureMessageKinyarwanda => Some((Pre, Kinyarwanda)),
            Key::PostGestureMessageEnglish => Some((Post, English)),
            Key::PostGestureMessageIsiZulu => Some((Post, IsiZulu)),
            Key::PostGestureMessageKinyarwanda => Some((Post, Kinyarwanda)),
            _ => None,
        }
    }

    /// The key of a message.
    pub fn for_message(phase: Phase, language: Language) -> Key {
        Key::ALL
            .into_iter()
            .find(|key| key.message() == Some((phase, language)))
            .expect("every message has a key")
    }

    /// The slot a key fills in a location block (the two pose keys share one).
    pub fn order(self) -> usize {
        match self {
            Key::RobotLocationDescription => 0,
            Key::RobotLocation | Key::RobotLocationPose => 1,
            other => other as usize,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_comment_declares_a_dialect() {
        for dialect in [Dialect::Seed, Dialect::Current] {
            let text = format!(
                "# header\n{}\nrobotLocationDescription 1 A\n",
                dialect.declaration()
            );
            assert_eq!(Dialect::declared_in(&text), Some(dialect));
        }
        assert_eq!(
            Dialect::declared_in("#ekb:dialect   seed  \n"),
            Some(Dialect::Seed)
        );
        for text in [
            "",
            "# ekb: dialect\n",
            "# ekb: dialect old\n",
            "robotLocationDescription 1 ekb: dialect seed\n",
            "# ekb: ignore[key-case] ekb: dialect seed\n",
        ] {
            assert_eq!(Dialect::declared_in(text), None, "{text:?}");
        }
        let many = "# ekb: x ".repeat(100_000) + "\n# ekb: dialect current";
        assert_eq!(Dialect::declared_in(&many), Some(Dialect::Current));
    }

    #[test]
    fn names_round_trip() {
        for key in Key::ALL {
            assert_eq!(Key::from_name(key.name()), Some(key));
        }
        assert_eq!(Key::from_name("postGestureMessageenglish"), None);
        assert_eq!(
            Key::from_name_ignoring_case("PreGestureMessageIsizulu"),
            Some(Key::PreGestureMessageIsiZulu)
        );
    }

    #[test]
    fn message_keys() {
        assert_eq!(
            Key::for_message(Phase::Post, Language::Kinyarwanda),
            Key::PostGestureMessageKinyarwanda
        );
        assert_eq!(Key::GestureArm.message(), None);
    }
}
