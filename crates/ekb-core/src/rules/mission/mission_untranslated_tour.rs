use crate::diagnostic::Diagnostic;
use crate::diagnostic::Diagnostics;
use crate::model::{is_placeholder, KnowledgeBase, Language, Phase};
use crate::rules::declare_rule;

declare_rule! {
    /// ## What it does
    /// Flags a tour stop whose message before or after the gesture, in the mission's
    /// language (the culture knowledge base's `phraseLanguage`), is missing or a
    /// placeholder such as `No message in isiZulu`.
    ///
    /// ## Why it matters
    /// `SelectExhibit` takes each stop's messages in the mission's language: the robot
    /// would say the placeholder aloud, or nothing, at every such stop. Unlike
    /// `untranslated-message`, which flags every placeholder, this is an error: the
    /// mission will say it.
    ///
    /// ## Example
    /// ```text
    /// preGestureMessageIsiZulu      4 No message in isiZulu
    /// ```
    /// with `phraseLanguage IsiZulu` and 4 on the tour.
    pub static MISSION_UNTRANSLATED_TOUR = {
        name: "mission-untranslated-tour",
        category: Mission,
        severity: Error,
        fixable: false,
        summary: "a tour stop whose messages in the mission language are placeholders or missing",
    };
}

pub fn check(kb: &KnowledgeBase<'_>, language: Language, out: &mut Diagnostics) {
    let mut seen = Vec::new();
    for (index, id) in kb.tour_stops().enumerate() {
        let stop = index + 1;
        if seen.contains(&id) {
            continue;
        }
        seen.push(id);
        let Some(location) = kb.location(id) else {
            continue;
        };
        for phase in Phase::ALL {
            let (span, what) = match location.message(phase, language) {
                Some(message) if is_placeholder(message.value) => (
                    message.span,
                    format!(
                        "is a placeholder: the robot would say \"{}\" aloud",
                        message.value
                    ),
                ),
                Some(_) => continue,
                None => (
                    location.first_line,
                    "is missing: the robot would say nothing".into(),
                ),
            };
            out.push(
                Diagnostic::new(
                    &MISSION_UNTRANSLATED_TOUR,
                    span,
                    format!(
                        "the mission speaks {}, and the message of location {id} (stop {stop} \
                         of the tour) {} the gesture {what}",
                        language.name(),
                        phase.name()
                    ),
                )
                .at_location(Some(id))
                .with_help(format!(
                    "translate the message into {}, or set the culture knowledge base's \
                     phraseLanguage to a language the tour has",
                    language.name()
                )),
            );
        }
    }
}
