//! The versions of the robot's reader (SPEC §2.1) and what sets each apart.

use super::{Dialect, Key};

/// One version of the robot's `EnvironmentKnowledgeBase` reader. The names are the contract
/// of `--reader`, `EKB_READER` and `reader` in `ekb.toml`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Reader {
    /// The document's class (D5.4.2, appendix A).
    D542,
    /// `main`, June 2025 (still `main` in April 2026).
    V2025_06,
    /// The `bc_service` branch, February 2026.
    V2026_02,
    /// The workspace branch, March 2026: reads `gestureArm`.
    V2026_03,
    /// "behaviorController v1.1", April 2026: the arm comes from the culture knowledge base.
    V2026_04,
}

impl Reader {
    pub const ALL: [Reader; 5] = [
        Reader::D542,
        Reader::V2025_06,
        Reader::V2026_02,
        Reader::V2026_03,
        Reader::V2026_04,
    ];

    /// The name of SPEC §2.1.
    pub fn name(self) -> &'static str {
        match self {
            Reader::D542 => "d5.4.2",
            Reader::V2025_06 => "2025-06",
            Reader::V2026_02 => "2026-02",
            Reader::V2026_03 => "2026-03",
            Reader::V2026_04 => "2026-04",
        }
    }

    /// What this version is, in a line (`ekb --help` shows it beside the name).
    pub fn summary(self) -> &'static str {
        match self {
            Reader::D542 => "The document's class (D5.4.2, appendix A)",
            Reader::V2025_06 => "`main`, June 2025 (still `main` in April 2026)",
            Reader::V2026_02 => "The `bc_service` branch, February 2026",
            Reader::V2026_03 => "The workspace branch, March 2026: reads `gestureArm`",
            Reader::V2026_04 => {
                "\"behaviorController v1.1\", April 2026: the arm comes from the culture knowledge base"
            }
        }
    }

    /// Which of the robot's software this version is, in words a content editor knows:
    /// "the robot's software {of June 2025}".
    pub fn in_words(self) -> &'static str {
        match self {
            Reader::D542 => "of document D5.4.2",
            Reader::V2025_06 => "of June 2025",
            Reader::V2026_02 => "of February 2026",
            Reader::V2026_03 => "of March 2026",
            Reader::V2026_04 => "of April 2026",
        }
    }

    /// The versions' names, for messages: `d5.4.2, 2025-06, …`.
    pub fn names() -> String {
        Reader::ALL.map(Reader::name).join(", ")
    }

    /// The version with this name.
    pub fn from_name(name: &str) -> Option<Reader> {
        Reader::ALL
            .into_iter()
            .find(|reader| reader.name() == name.trim())
    }

    /// The reader a file is checked against when none is chosen: the document's for a file
    /// in its dialect, today's robot's for any other.
    pub fn default_for(dialect: Option<Dialect>) -> Reader {
        match dialect {
            Some(Dialect::Seed) => Reader::D542,
            _ => Reader::V2025_06,
        }
    }

    /// The line buffer of the document's reader and `2025-06`, the smallest of all.
    pub const SMALLEST_LINE_BUFFER: usize = 200;

    /// The size of its line buffer: `fgets` reads at most one byte less per call, so a
    /// line of this many bytes or more (newline included) is split.
    pub fn line_buffer(self) -> usize {
        match self {
            Reader::D542 | Reader::V2025_06 => 200,
            Reader::V2026_02 => 300,
            Reader::V2026_03 | Reader::V2026_04 => 600,
        }
    }

    /// The line buffer of the same robot's culture knowledge base reader: 300 in
    /// `2026-02`'s copy (`include/utilities`), 200 in `2025-06`'s. The document has no culture
    /// knowledge base, and the culture readers of `2026-03` and `2026-04` are not public:
    /// 200, the smallest, which reports every line that any of them cuts.
    pub fn culture_line_buffer(self) -> usize {
        match self {
            Reader::V2026_02 => 300,
            _ => 200,
        }
    }

    /// The size of its word buffers (`Keyword`, `KEY_LENGTH`), which `%s` fills with the
    /// first word of each line and each culturalKnowledge word: 200 in the headers of
    /// `2026-03` and `2026-04`, 100 in the others'.
    pub fn key_buffer(self) -> usize {
        match self {
            Reader::V2026_03 | Reader::V2026_04 => 200,
            _ => super::key_buffer::KEY_BUFFER,
        }
    }

    /// The key it reads a location's pose from.
    pub fn pose_key(self) -> Key {
        match self {
            Reader::D542 => Key::RobotLocation,
            _ => Key::RobotLocationPose,
        }
    }

    /// Whether it reads lines of `key` (exactly spelled) at all.
    pub fn reads(self, key: Key) -> bool {
        match key {
            Key::RobotLocation | Key::RobotLocationPose => key == self.pose_key(),
            Key::GestureArm => self == Reader::V2026_03,
            Key::CulturalKnowledge => self != Reader::D542,
            _ => true,
        }
    }

    /// The bytes of one location's record, which the reader copies at every level of its
    /// recursion: a text of a line buffer for each of its text fields (seven, and the arm
    /// on `2026-03`, whose record holds `gestureArm` too).
    pub fn record_bytes(self) -> usize {
        let texts = if self.reads(Key::GestureArm) { 8 } else { 7 };
        texts * self.line_buffer()
    }

    /// The depth of the tree of locations from which loading overflows its 8 MB stack: the
    /// lowest measured on files of ascending ids over the two builds of SPEC §2 (the robot's
    /// own `-O0 -fstack-protector-strong`, and `-O2`, which crashes a little deeper). The
    /// document's class is taken to behave as `2025-06`. `2026-03`'s larger record (its
    /// `gestureArm`) crashes it sooner than `2026-04`.
    pub fn crash_depth(self) -> usize {
        match self {
            Reader::D542 | Reader::V2025_06 => 5_455,
            Reader::V2026_02 => 3_740,
            Reader::V2026_03 => 1_695,
            Reader::V2026_04 => 1_932,
        }
    }

    /// The depth from which `ekb` warns that a tree comes near [`Reader::crash_depth`]:
    /// 90% of it, since the exact point depends on the build and on what else is on the
    /// stack.
    pub fn crash_margin_depth(self) -> usize {
        self.crash_depth() * 9 / 10
    }
}

impl std::fmt::Display for Reader {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_round_trip() {
        for reader in Reader::ALL {
            assert_eq!(Reader::from_name(reader.name()), Some(reader));
        }
        assert_eq!(Reader::from_name("2024-01"), None);
    }

    #[test]
    fn what_each_version_reads() {
        assert!(Reader::D542.reads(Key::RobotLocation));
        assert!(!Reader::D542.reads(Key::CulturalKnowledge));
        for reader in &Reader::ALL[1..] {
            assert!(!reader.reads(Key::RobotLocation), "{reader}");
            assert!(reader.reads(Key::RobotLocationPose), "{reader}");
            assert_eq!(reader.reads(Key::GestureArm), *reader == Reader::V2026_03);
        }
        assert_eq!(Reader::default_for(Some(Dialect::Seed)), Reader::D542);
        assert_eq!(Reader::default_for(None), Reader::V2025_06);
        assert_eq!(Reader::V2026_03.crash_margin_depth(), 1_525);
        assert_eq!(Reader::V2026_04.crash_margin_depth(), 1_738);
        assert_eq!(Reader::V2026_04.key_buffer(), 200);
        assert_eq!(Reader::V2026_02.key_buffer(), 100);
        assert_eq!(Reader::V2025_06.record_bytes(), 1_400);
        assert_eq!(Reader::V2026_03.record_bytes(), 4_800);
    }
}
