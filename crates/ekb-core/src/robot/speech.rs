//! What the robot can say, and how long it takes (SPEC §10.2, §15): the robot profile of
//! `ekb.toml`'s `[robot]` ([`RobotProfile`]), which languages its text-to-speech speaks,
//! and the seconds it takes to say a message.
//!
//! - English goes to the robot's own text-to-speech, which returns at once; the robot
//!   then waits `wordCount / 3.0` seconds ([`ENGLISH_WORDS_PER_SECOND`]), words being
//!   whitespace-separated tokens.
//! - isiZulu and Kinyarwanda take their syllables at the profile's `syllables-per-second`,
//!   a syllable being a group of consecutive vowels ([`syllables`]).
//! - A language the profile does not speak is silence: [`RobotProfile::speech_seconds`]
//!   gives `None`.
//!
//! ```
//! use ekb_core::robot::speech::RobotProfile;
//! use ekb_core::robot::Language;
//!
//! let robot = RobotProfile::default();
//! assert_eq!(robot.speech_seconds(Language::English, "Welcome to the lab"), Some(4.0 / 3.0));
//! // mu-ra-ka-za ne-za: 6 syllables at 5 a second.
//! assert_eq!(robot.speech_seconds(Language::Kinyarwanda, "Murakaza neza"), Some(6.0 / 5.0));
//! assert_eq!(robot.speech_seconds(Language::IsiZulu, "Sawubona"), None);
//! ```

use super::Language;

/// The words a second the robot's English wait assumes (`wordCount / 3.0`).
pub const ENGLISH_WORDS_PER_SECOND: f64 = 3.0;

/// The languages the robot's text-to-speech speaks by default: English and Kinyarwanda
/// (it has no isiZulu engine).
pub const DEFAULT_SPEAKS: [Language; 2] = [Language::English, Language::Kinyarwanda];

/// The robot's speed by default, in metres a second.
pub const DEFAULT_SPEED: f64 = 0.27;

/// The robot's turning speed by default, in radians a second.
pub const DEFAULT_TURN_SPEED: f64 = 0.9;

/// The syllables a second by default (people speak 5.0–5.3 in each language).
pub const DEFAULT_SYLLABLES_PER_SECOND: f64 = 5.0;

/// What the robot can do on the tour: the languages it speaks, how fast it drives, turns
/// and speaks. `ekb.toml`'s `[robot]`; [`Default`] is the lab's robot.
#[derive(Debug, Clone, PartialEq)]
pub struct RobotProfile {
    /// The languages its text-to-speech speaks, in the order given.
    pub speaks: Vec<Language>,
    /// Metres a second.
    pub speed: f64,
    /// Radians a second.
    pub turn_speed: f64,
    /// Syllables a second, for every language but English.
    pub syllables_per_second: f64,
}

impl Default for RobotProfile {
    fn default() -> Self {
        RobotProfile {
            speaks: DEFAULT_SPEAKS.to_vec(),
            speed: DEFAULT_SPEED,
            turn_speed: DEFAULT_TURN_SPEED,
            syllables_per_second: DEFAULT_SYLLABLES_PER_SECOND,
        }
    }
}

impl RobotProfile {
    /// Whether the robot's text-to-speech speaks `language`.
    pub fn speaks(&self, language: Language) -> bool {
        self.speaks.contains(&language)
    }

    /// The seconds the robot takes to say `text` in `language`; `None` when it does not
    /// speak the language (it says nothing).
    pub fn speech_seconds(&self, language: Language, text: &str) -> Option<f64> {
        if !self.speaks(language) {
            return None;
        }
        Some(match language {
            Language::English => words(text) as f64 / ENGLISH_WORDS_PER_SECOND,
            Language::IsiZulu | Language::Kinyarwanda => {
                syllables(text) as f64 / self.syllables_per_second
            }
        })
    }
}

/// The words of `text`: its whitespace-separated tokens.
pub fn words(text: &str) -> usize {
    text.split_whitespace().count()
}

/// The syllables of `text`: its groups of consecutive vowels (a, e, i, o, u and their
/// accented forms, in any case; `y` is no vowel).
pub fn syllables(text: &str) -> usize {
    let mut count = 0;
    let mut in_vowels = false;
    for c in text.chars() {
        let vowel = is_vowel(c);
        if vowel && !in_vowels {
            count += 1;
        }
        in_vowels = vowel;
    }
    count
}

/// Whether `c` is a, e, i, o or u, plain or accented, in any case.
fn is_vowel(c: char) -> bool {
    let lower = c.to_lowercase().next().unwrap_or(c);
    matches!(lower, 'a' | 'e' | 'i' | 'o' | 'u')
        || "àáâãäåāăąèéêëēĕėęěìíîïĩīĭįòóôõöøōŏőùúûüũūŭůűų".contains(lower)
}

/// What every view says of a language the robot does not speak, once, at the top of what
/// it shows in that language.
pub fn silence_notice(language: Language) -> String {
    let name = language.name();
    format!(
        "the robot does not speak {name}: it says nothing at these stops (its text-to-speech \
         has no {name} engine; `[robot] speaks` in ekb.toml says otherwise if yours does)"
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_default_profile_is_the_labs_robot() {
        let robot = RobotProfile::default();
        assert_eq!(robot.speaks, [Language::English, Language::Kinyarwanda]);
        assert_eq!(robot.speed, 0.27);
        assert_eq!(robot.turn_speed, 0.9);
        assert_eq!(robot.syllables_per_second, 5.0);
        assert!(robot.speaks(Language::English));
        assert!(robot.speaks(Language::Kinyarwanda));
        assert!(!robot.speaks(Language::IsiZulu));
    }

    #[test]
    fn english_is_the_robots_own_wait_of_three_words_a_second() {
        let robot = RobotProfile::default();
        let seconds = |text| robot.speech_seconds(Language::English, text);
        assert_eq!(seconds("one two three"), Some(1.0));
        assert_eq!(seconds("  Welcome,\tto the\nlab  "), Some(4.0 / 3.0));
        assert_eq!(seconds(""), Some(0.0));
        // Syllables do not count in English.
        assert_eq!(seconds("extraordinarily"), Some(1.0 / 3.0));
    }

    #[test]
    fn other_languages_are_syllables_at_the_profiles_rate() {
        let robot = RobotProfile::default();
        // mu-ra-ka-za ne-za: 6 syllables at 5 a second.
        assert_eq!(
            robot.speech_seconds(Language::Kinyarwanda, "Murakaza neza"),
            Some(6.0 / 5.0)
        );
        let zulu = RobotProfile {
            speaks: vec![Language::IsiZulu],
            syllables_per_second: 4.0,
            ..RobotProfile::default()
        };
        // sa-wu-bo-na: 4 syllables at 4 a second.
        assert_eq!(
            zulu.speech_seconds(Language::IsiZulu, "Sawubona"),
            Some(1.0)
        );
        assert_eq!(zulu.speech_seconds(Language::English, "Hello"), None);
    }

    #[test]
    fn a_language_the_robot_does_not_speak_is_silence() {
        let robot = RobotProfile::default();
        assert_eq!(robot.speech_seconds(Language::IsiZulu, "Sawubona"), None);
        let mute = RobotProfile {
            speaks: Vec::new(),
            ..RobotProfile::default()
        };
        for language in Language::ALL {
            assert_eq!(mute.speech_seconds(language, "hello"), None);
        }
    }

    #[test]
    fn a_syllable_is_a_group_of_vowels() {
        assert_eq!(syllables(""), 0);
        assert_eq!(syllables("bcd"), 0);
        assert_eq!(syllables("a"), 1);
        assert_eq!(syllables("Sawubona"), 4);
        // Consecutive vowels, across case, are one group; `y` is no vowel.
        assert_eq!(syllables("AEiou"), 1);
        assert_eq!(syllables("Rwanda"), 2);
        assert_eq!(syllables("yyy"), 0);
        assert_eq!(syllables("ya ye"), 2);
        // Accented vowels count, in any case; a space or a consonant separates groups.
        assert_eq!(syllables("café"), 2);
        assert_eq!(syllables("ÉCOLE"), 3);
        assert_eq!(syllables("naïve"), 2);
        assert_eq!(syllables("a a"), 2);
        assert_eq!(words(" a  b\tc\n"), 3);
    }

    #[test]
    fn the_notice_names_the_language_and_the_setting() {
        let notice = silence_notice(Language::IsiZulu);
        assert!(notice.starts_with("the robot does not speak isiZulu: it says nothing"));
        assert!(notice.contains("no isiZulu engine"));
        assert!(notice.contains("`[robot] speaks`"));
    }
}
