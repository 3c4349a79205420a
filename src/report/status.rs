//! How far each language's messages are translated, counted over every location's two
//! messages, with SPEC §8's names. (`ekb translations` counts the same with its own
//! translation rules; this is the report's own count, from the file alone.)

use crate::model::{words, KnowledgeBase, Language, Phase};
use crate::present::Message;

/// One language's counts (SPEC §8 names).
#[derive(Debug, Clone, Default, PartialEq)]
pub struct LanguageStatus {
    pub language: Option<Language>,
    pub total: usize,
    pub translated: usize,
    pub translated_percent: f64,
    /// Placeholders and missing messages.
    pub untranslated: usize,
    /// Messages that are the English text itself.
    pub same_as_source: usize,
    /// Messages with a finding on their line.
    pub failing_checks: usize,
    /// Words of the English messages, and of those translated in this language.
    pub total_words: usize,
    pub translated_words: usize,
}

/// Counts each language's messages in `kb`; `failing(line_span_start)` says whether a
/// finding stands on the message that starts there.
pub fn count_messages_per_language(
    kb: &KnowledgeBase<'_>,
    failing: impl Fn(u32) -> bool,
) -> Vec<LanguageStatus> {
    Language::ALL
        .into_iter()
        .map(|language| {
            let mut status = LanguageStatus {
                language: Some(language),
                ..LanguageStatus::default()
            };
            for location in kb.locations() {
                for phase in Phase::ALL {
                    let english = location.message(phase, Language::English).map(|m| m.value);
                    let source_words = english.map_or(0, |text| words(text).count());
                    status.total += 1;
                    status.total_words += source_words;
                    match Message::of(location, phase, language) {
                        Message::Written(value) => {
                            if language != Language::English && Some(value.value) == english {
                                status.same_as_source += 1;
                            } else {
                                status.translated += 1;
                                status.translated_words += source_words;
                            }
                            if failing(value.span.start) {
                                status.failing_checks += 1;
                            }
                        }
                        Message::Placeholder(_) | Message::Missing => status.untranslated += 1,
                    }
                }
            }
            if status.total > 0 {
                status.translated_percent =
                    (1000.0 * status.translated as f64 / status.total as f64).round() / 10.0;
            }
            status
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn placeholders_missing_and_copies_of_the_english_are_not_translated() {
        let text = "\
preGestureMessageEnglish 1 Hello there
preGestureMessageIsiZulu 1 Sawubona
preGestureMessageKinyarwanda 1 Hello there
postGestureMessageEnglish 1 Goodbye
postGestureMessageIsiZulu 1 No message in isiZulu
";
        let mut found = crate::check::Diagnostics::default();
        let kb = crate::model::build::build(text, &Default::default(), &mut found);
        let status = count_messages_per_language(&kb, |start| start == 66);
        let [english, zulu, kinyarwanda] = &status[..] else {
            panic!("three languages")
        };
        assert_eq!(
            (english.total, english.translated, english.untranslated),
            (2, 2, 0)
        );
        assert_eq!(
            (zulu.translated, zulu.untranslated, zulu.translated_percent),
            (1, 1, 50.0)
        );
        assert_eq!((zulu.total_words, zulu.translated_words), (3, 2));
        assert_eq!(zulu.failing_checks, 1, "Sawubona starts at byte 66");
        assert_eq!(
            (kinyarwanda.same_as_source, kinyarwanda.untranslated),
            (1, 1)
        );
    }
}
