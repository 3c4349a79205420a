//! The limits of the document's fixed-size types, for the drop-in class.
//!
//! The drop-in `Environment::EnvironmentKnowledgeBase` hands out the document's
//! `KeyValueType` and `TourSpecificationType`: texts in `char[STRING_LENGTH]`, at most
//! `MAX_NUMBER_OF_TOUR_LOCATIONS` stops, at most `MAX_CULTURE_KEYS` culture words. A value
//! they cannot hold is refused with a finding that names the limit, never cut (SPEC §12).
//! `STRING_LENGTH` is the one the program was compiled with
//! ([`Options::string_length`](super::Options), the document's 200 by default): 600 for a
//! program built for the `2026-04` header.
//! The library's own API has no such limits, so these are not rules of `ekb check`: only
//! a load with [`Options::fixed_size_limits`](super::Options) adds them.
//!
//! ```text
//! preGestureMessageEnglish 1 <a message of 200 bytes or more>
//! ```

use crate::diagnostic::Diagnostic;
use crate::model::{KnowledgeBase, Language, Phase, Value};
use crate::rules::declare_rule;

/// The document's `STRING_LENGTH`: a text field's bytes, its terminating NUL included (the
/// default of [`Options::string_length`](super::Options)).
pub const STRING_LENGTH: usize = 200;
/// The smallest and the largest `STRING_LENGTH` a load accepts: a field holds one byte and
/// its NUL at least, and no knowledge base has a text of a mebibyte.
pub const STRING_LENGTH_RANGE: std::ops::RangeInclusive<usize> = 2..=1 << 20;
/// `MAX_NUMBER_OF_TOUR_LOCATIONS`.
pub const MAX_NUMBER_OF_TOUR_LOCATIONS: usize = 20;
/// `MAX_CULTURE_KEYS`.
pub const MAX_CULTURE_KEYS: usize = 2;

declare_rule! {
    /// ## What it does
    /// Refuses, in the drop-in class, a text of `STRING_LENGTH` bytes or more (200 in the
    /// document, 600 in the `2026-04` header: the program's own).
    ///
    /// ## Why it matters
    /// The document's `KeyValueType` holds each text in `char[STRING_LENGTH]`, its NUL
    /// included: a longer text would be cut.
    pub static DROP_IN_STRING_LENGTH = {
        name: "drop-in-string-length",
        category: Compat,
        severity: Error,
        fixable: false,
        summary: "a text the document's char[STRING_LENGTH] cannot hold",
    };
}

declare_rule! {
    /// ## What it does
    /// Refuses, in the drop-in class, a tour of more than `MAX_NUMBER_OF_TOUR_LOCATIONS`
    /// (20) stops.
    ///
    /// ## Why it matters
    /// The document's `TourSpecificationType` holds 20 ids: the rest would be dropped.
    pub static DROP_IN_TOUR_LENGTH = {
        name: "drop-in-tour-length",
        category: Compat,
        severity: Error,
        fixable: false,
        summary: "a tour the document's TourSpecificationType cannot hold",
    };
}

declare_rule! {
    /// ## What it does
    /// Refuses, in the drop-in class, more than `MAX_CULTURE_KEYS` (2) culture words.
    ///
    /// ## Why it matters
    /// The document's `CulturalKnowledgeType` holds 2 words: the rest would be dropped.
    pub static DROP_IN_CULTURE_KEYS = {
        name: "drop-in-culture-keys",
        category: Compat,
        severity: Error,
        fixable: false,
        summary: "culture words the document's CulturalKnowledgeType cannot hold",
    };
}

/// A finding for every value of `kb` that the document's types cannot hold, their texts
/// `char[string_length]`.
pub fn check(kb: &KnowledgeBase<'_>, string_length: usize) -> Vec<Diagnostic> {
    let mut out = Vec::new();
    for location in kb.locations().iter() {
        let messages = Phase::ALL.into_iter().flat_map(|phase| {
            Language::ALL
                .into_iter()
                .map(move |language| location.message(phase, language))
        });
        let texts = std::iter::once(location.description()).chain(messages);
        for Value { value, span } in texts.flatten() {
            if value.len() >= string_length {
                out.push(
                    Diagnostic::new(
                        &DROP_IN_STRING_LENGTH,
                        span,
                        format!(
                            "this text is {} bytes, but the document's class holds at most {} (STRING_LENGTH {string_length}, with its NUL): it would be cut",
                            value.len(),
                            string_length - 1
                        ),
                    )
                    .at_location(Some(location.id))
                    .with_help("shorten the text, or load the file with ekb::KnowledgeBase, which has no such limit"),
                );
            }
        }
        let words = location.cultural_words().count();
        if let Some(knowledge) = location
            .cultural_knowledge()
            .filter(|_| words > MAX_CULTURE_KEYS)
        {
            out.push(
                Diagnostic::new(
                    &DROP_IN_CULTURE_KEYS,
                    knowledge.span,
                    format!(
                        "location {} has {words} culture words, but the document's class holds at most {MAX_CULTURE_KEYS} (MAX_CULTURE_KEYS): the rest would be dropped",
                        location.id
                    ),
                )
                .at_location(Some(location.id))
                .with_help("keep at most 2 words, or load the file with ekb::KnowledgeBase"),
            );
        }
    }
    let stops = kb.tour_stops().count();
    if let Some(tour) = kb
        .tour
        .as_ref()
        .filter(|_| stops > MAX_NUMBER_OF_TOUR_LOCATIONS)
    {
        out.push(
            Diagnostic::new(
                &DROP_IN_TOUR_LENGTH,
                tour.span,
                format!(
                    "the tour has {stops} stops, but the document's class holds at most {MAX_NUMBER_OF_TOUR_LOCATIONS} (MAX_NUMBER_OF_TOUR_LOCATIONS): the rest would be dropped"
                ),
            )
            .with_help("keep at most 20 stops, or load the file with ekb::KnowledgeBase"),
        );
    }
    out
}
