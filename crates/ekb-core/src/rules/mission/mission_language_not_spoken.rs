use crate::diagnostic::{Diagnostic, Diagnostics};
use crate::mission::culture::{CultureKnowledgeBase, Held, ValueTypes};
use crate::mission::LANGUAGE_KEY;
use crate::model::Language;
use crate::robot::speech::RobotProfile;
use crate::rules::declare_rule;

declare_rule! {
    /// ## What it does
    /// Flags a culture knowledge base whose `phraseLanguage`, the mission's language, is one
    /// that the robot profile (`[robot] speaks` in `ekb.toml`; by default English and
    /// Kinyarwanda) does not speak.
    ///
    /// ## Why it matters
    /// The robot's text-to-speech has no isiZulu engine: each request fails, the mission's
    /// fallback swallows the failure, and the robot says nothing. The tour runs, stop after
    /// stop, in silence: no phrase, no talk at an exhibit.
    ///
    /// ## Example
    /// ```text
    /// phraseLanguage                            IsiZulu
    /// ```
    /// Write `English` or `Kinyarwanda`; or, if your robot does speak isiZulu, say so in
    /// `ekb.toml`: `[robot] speaks = ["english", "isiZulu", "kinyarwanda"]`.
    pub static MISSION_LANGUAGE_NOT_SPOKEN = {
        name: "mission-language-not-spoken",
        category: Mission,
        severity: Error,
        fixable: false,
        summary: "`phraseLanguage` is a language the robot's text-to-speech does not speak (`[robot] speaks`)",
    };
}

/// Reports the mission's `language` (read from `phraseLanguage`) if `robot` does not speak
/// it, at the word of the culture knowledge base that sets it.
pub fn check(
    culture: &CultureKnowledgeBase<'_>,
    types: &ValueTypes<'_>,
    language: Language,
    robot: &RobotProfile,
    out: &mut Diagnostics,
) {
    if robot.speaks(language) {
        return;
    }
    let Held::Text(_, entry) = culture.held(types, LANGUAGE_KEY) else {
        return;
    };
    let span = entry.first_word().map_or(entry.key_span, |(_, span)| span);
    let name = language.name();
    let spoken: Vec<&str> = robot.speaks.iter().map(|l| l.name()).collect();
    let speaks = match spoken.as_slice() {
        [] => "no language".to_string(),
        [one] => one.to_string(),
        [first @ .., last] => format!("{} and {last}", first.join(", ")),
    };
    out.push(
        Diagnostic::new(
            &MISSION_LANGUAGE_NOT_SPOKEN,
            span,
            format!(
                "the mission speaks {name}, which the robot's text-to-speech does not speak: \
                 every phrase and every talk of the tour is silent"
            ),
        )
        .with_help(format!(
            "the robot speaks {speaks} (`[robot] speaks` in ekb.toml): choose one of them, or \
             add {name} to `[robot] speaks` if your robot has a {name} engine"
        )),
    );
}
