//! The rule catalogue (SPEC §4): one module per rule, grouped by category.
//!
//! Each rule is declared with [`declare_rule!`]: its doc comment is both its rustdoc and the
//! text of `ekb explain RULE`, so the documentation has a single source. Rules that need
//! the text of a line run while the model is built: [`crate::model::build`] reports what
//! it finds on each line as facts, and hands over each line, to [`line_rules`], which makes
//! the findings (the model layer names no rule). Rules that need whole locations or the
//! tour, and those that depend on the version of the robot's reader ([`compat::check_file`],
//! which asks [`crate::reader`] what each version loads), run afterwards, over the model
//! ([`check_model`]).

use crate::diagnostic::Diagnostics;
pub use crate::diagnostic::{Category, Rule};
use crate::model::{Dialect, IdSet, Key, KnowledgeBase, Location};
use crate::robot::Reader;

pub mod compat;
mod consequence;
pub mod content;
pub mod culture;
pub mod line_rules;
pub mod map;
pub mod mission;
pub mod selection;
pub mod structure;
pub mod tour;
pub mod translation;

/// Declares a rule as a `static` [`Rule`] whose doc comment becomes [`Rule::doc`].
macro_rules! declare_rule {
    (
        $(#[doc = $doc:literal])+
        pub static $ident:ident = {
            name: $name:literal,
            category: $category:ident,
            severity: $severity:ident,
            fixable: $fixable:literal,
            summary: $summary:literal $(,)?
        };
    ) => {
        $(#[doc = $doc])+
        pub static $ident: $crate::diagnostic::Rule = $crate::diagnostic::Rule {
            name: $name,
            category: $crate::diagnostic::Category::$category,
            severity: $crate::diagnostic::Severity::$severity,
            fixable: $fixable,
            summary: $summary,
            doc: concat!($($doc, "\n"),+),
        };
    };
}
pub(crate) use declare_rule;

/// Every rule, in catalogue order.
pub static ALL: &[&Rule] = &[
    &structure::invalid_utf8::INVALID_UTF8,
    &structure::unknown_key::UNKNOWN_KEY,
    &structure::key_case::KEY_CASE,
    &structure::missing_id::MISSING_ID,
    &structure::invalid_id::INVALID_ID,
    &structure::invalid_number::INVALID_NUMBER,
    &structure::wrong_arity::WRONG_ARITY,
    &structure::empty_value::EMPTY_VALUE,
    &structure::invalid_value::INVALID_VALUE,
    &structure::duplicate_key::DUPLICATE_KEY,
    &structure::missing_field::MISSING_FIELD,
    &structure::mixed_dialect::MIXED_DIALECT,
    &structure::legacy_key::LEGACY_KEY,
    &structure::control_character::CONTROL_CHARACTER,
    &structure::unicode_space::UNICODE_SPACE,
    &structure::not_a_knowledge_base::NOT_AN_ENVIRONMENT_KNOWLEDGE_BASE,
    &structure::unused_suppression::UNUSED_SUPPRESSION,
    &tour::tour_missing::TOUR_MISSING,
    &tour::tour_duplicate_spec::TOUR_DUPLICATE_SPEC,
    &tour::tour_count_mismatch::TOUR_COUNT_MISMATCH,
    &tour::tour_empty::TOUR_EMPTY,
    &tour::tour_unknown_location::TOUR_UNKNOWN_LOCATION,
    &tour::tour_too_long::TOUR_TOO_LONG,
    &tour::tour_repeated_stop::TOUR_REPEATED_STOP,
    &tour::unused_location::UNUSED_LOCATION,
    &content::untranslated_message::UNTRANSLATED_MESSAGE,
    &content::repeated_word::REPEATED_WORD,
    &content::trailing_whitespace::TRAILING_WHITESPACE,
    &content::theta_out_of_range::THETA_OUT_OF_RANGE,
    &content::gesture_target_sums_to_zero::GESTURE_TARGET_SUMS_TO_ZERO,
    &content::gesture_behind_robot::GESTURE_BEHIND_ROBOT,
    &compat::compat_line_too_long::COMPAT_LINE_TOO_LONG,
    &compat::compat_leading_symbol::COMPAT_LEADING_SYMBOL,
    &compat::compat_float_overflow::COMPAT_FLOAT_OVERFLOW,
    &compat::compat_no_final_newline::COMPAT_NO_FINAL_NEWLINE,
    &compat::compat_crlf::COMPAT_CRLF,
    &compat::compat_bom::COMPAT_BOM,
    &compat::compat_too_many_cultural_keys::COMPAT_TOO_MANY_CULTURAL_KEYS,
    &compat::compat_indented_line::COMPAT_INDENTED_LINE,
    &compat::compat_key_too_long::COMPAT_KEY_TOO_LONG,
    &compat::compat_cultural_word_split::COMPAT_CULTURAL_WORD_SPLIT,
    &compat::compat_reader_crash::COMPAT_READER_CRASH,
    &compat::compat_slow_load::COMPAT_SLOW_LOAD,
    &compat::compat_ignored_key::COMPAT_IGNORED_KEY,
    &map::pose_outside_map::POSE_OUTSIDE_MAP,
    &map::pose_in_obstacle::POSE_IN_OBSTACLE,
    &map::target_outside_map::TARGET_OUTSIDE_MAP,
    &map::tour_leg_unreachable::TOUR_LEG_UNREACHABLE,
    &mission::mission_invalid_xml::MISSION_INVALID_XML,
    &mission::mission_unknown_node::MISSION_UNKNOWN_NODE,
    &mission::mission_bad_children::MISSION_BAD_CHILDREN,
    &mission::mission_unknown_attribute::MISSION_UNKNOWN_ATTRIBUTE,
    &mission::mission_bad_port_value::MISSION_BAD_PORT_VALUE,
    &mission::mission_unknown_tree::MISSION_UNKNOWN_TREE,
    &mission::mission_bad_include::MISSION_BAD_INCLUDE,
    &mission::mission_invalid_name::MISSION_INVALID_NAME,
    &mission::mission_language_invalid::MISSION_LANGUAGE_INVALID,
    &mission::mission_language_not_spoken::MISSION_LANGUAGE_NOT_SPOKEN,
    &mission::mission_missing_phrase::MISSION_MISSING_PHRASE,
    &mission::mission_untranslated_tour::MISSION_UNTRANSLATED_TOUR,
    &mission::mission_missing_format::MISSION_MISSING_FORMAT,
    &mission::mission_unreachable_tree::MISSION_UNREACHABLE_TREE,
    &mission::cultural_knowledge_unknown_key::CULTURAL_KNOWLEDGE_UNKNOWN_KEY,
    &culture::culture_unknown_key::CULTURE_UNKNOWN_KEY,
    &culture::culture_type_mismatch::CULTURE_TYPE_MISMATCH,
    &culture::culture_unknown_type::CULTURE_UNKNOWN_TYPE,
    &culture::culture_duplicate_key::CULTURE_DUPLICATE_KEY,
    &culture::culture_line_too_long::CULTURE_LINE_TOO_LONG,
    &culture::culture_no_final_newline::CULTURE_NO_FINAL_NEWLINE,
    &culture::culture_crlf::CULTURE_CRLF,
    &culture::culture_word_too_long::CULTURE_WORD_TOO_LONG,
    &translation::same_as_source::SAME_AS_SOURCE,
    &translation::end_punctuation_mismatch::END_PUNCTUATION_MISMATCH,
    &translation::double_space::DOUBLE_SPACE,
    &translation::space_before_punctuation::SPACE_BEFORE_PUNCTUATION,
    &translation::repeated_punctuation::REPEATED_PUNCTUATION,
    &translation::unbalanced_delimiters::UNBALANCED_DELIMITERS,
    &translation::wrong_language::WRONG_LANGUAGE,
    &translation::length_mismatch::LENGTH_MISMATCH,
];

/// `text` from the file, cut to a length that fits in a one-line message.
pub fn excerpt(text: &str) -> std::borrow::Cow<'_, str> {
    const MAX_CHARS: usize = 40;
    match text.char_indices().nth(MAX_CHARS) {
        Some((cut, _)) => format!("{}…", &text[..cut]).into(),
        None => text.into(),
    }
}

/// The rule with this name.
pub fn by_name(name: &str) -> Option<&'static Rule> {
    ALL.iter().copied().find(|rule| rule.name == name)
}

/// The rule a person means by `query` (`ekb explain`): its name in any case, or a prefix
/// of only one rule's name (`untranslated`); else why none, with the nearest name.
pub fn lookup(query: &str) -> Result<&'static Rule, String> {
    let lower = query.to_lowercase();
    if let Some(rule) = by_name(&lower) {
        return Ok(rule);
    }
    let starting: Vec<&'static Rule> = ALL
        .iter()
        .copied()
        .filter(|rule| !lower.is_empty() && rule.name.starts_with(&lower))
        .collect();
    match starting.as_slice() {
        [one] => Ok(one),
        [] => Err(
            match selection::nearest(query, ALL.iter().map(|rule| rule.name)) {
                Some(name) => format!("no rule named `{query}`; did you mean `{name}`?"),
                None => format!("no rule named `{query}`; `ekb rules` lists them"),
            },
        ),
        several => {
            let names: Vec<&str> = several.iter().map(|rule| rule.name).collect();
            Err(format!(
                "`{query}` starts the names of {} rules ({}); give more of the name",
                names.len(),
                names.join(", ")
            ))
        }
    }
}

/// Where `rule` is in [`ALL`] (a rule's identity is its address: rules are statics).
pub fn index_of(rule: &Rule) -> usize {
    ALL.iter()
        .position(|known| std::ptr::eq(*known, rule))
        .expect("every rule is in the catalogue")
}

/// The categories of the catalogue, in its order (those that have a rule).
pub fn categories() -> Vec<Category> {
    let mut categories: Vec<Category> = ALL.iter().map(|rule| rule.category).collect();
    categories.dedup();
    categories
}

/// Runs the rules that look at whole locations and the tour, and those that depend on the
/// version of the robot's reader.
pub fn check_model(kb: &KnowledgeBase<'_>, source: &str, reader: Reader, out: &mut Diagnostics) {
    compat::check_file(kb, source, reader, out);
    let context = LocationContext::new(kb, source, reader);
    let mut found = out.part();
    // Whether the model's order of ids is the reader's, from the line findings so far.
    let from_model = compat::model_tree_is_the_readers(kb, source, reader, out);
    check_tour(kb, &mut found);
    for location in kb.locations() {
        check_location(location, &context, &mut found);
    }
    // The tree's findings first, as if made first: findings at one place are listed in the
    // order in which they are reported.
    let shape = compat::tree_shape(kb, source, reader, from_model);
    compat::check_tree(kb, &shape, reader, out);
    out.append(found);
}

/// Runs the rules about the tour.
fn check_tour(kb: &KnowledgeBase<'_>, out: &mut Diagnostics) {
    tour::tour_missing::check(kb, out);
    if let Some(tour) = &kb.tour {
        tour::tour_empty::check(tour, out);
        let listed = tour.listed().count() as u64;
        tour::tour_count_mismatch::check(tour, listed, out);
        tour::tour_too_long::check(tour, listed, out);
        tour::tour_repeated_stop::check(tour, out);
    }
    tour::tour_unknown_location::check(kb, out);
}

/// What the rules about one location need to know of the rest of the file.
pub struct LocationContext<'k> {
    pub source: &'k str,
    /// The key a location's pose must be written with, in the file's dialect.
    pub pose_key: Key,
    /// The ids the tour visits; `None` if there is no tour.
    pub visited: Option<IdSet>,
    /// The version of the robot's reader the file is checked against.
    pub reader: Reader,
}

impl<'k> LocationContext<'k> {
    fn new(kb: &KnowledgeBase<'_>, source: &'k str, reader: Reader) -> Self {
        LocationContext {
            source,
            pose_key: kb.dialect.unwrap_or(Dialect::Seed).pose_key(),
            visited: kb.tour.is_some().then(|| kb.tour_stops().collect()),
            reader,
        }
    }
}

/// Runs the rules about one location.
fn check_location(location: &Location<'_>, context: &LocationContext<'_>, out: &mut Diagnostics) {
    structure::missing_field::check(location, context, out);
    tour::unused_location::check(location, context, out);
    content::untranslated_message::check(location, out);
    content::repeated_word::check(location, out);
    content::theta_out_of_range::check(location, context, out);
    content::gesture_target_sums_to_zero::check(location, out);
    content::gesture_behind_robot::check(location, out);
    compat::compat_too_many_cultural_keys::check(location, context.reader, out);
    compat::compat_cultural_word_split::check(location, context.reader, out);
    translation::check(location, out);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_are_unique_kebab_case_and_documented() {
        let mut names: Vec<&str> = ALL.iter().map(|rule| rule.name).collect();
        names.sort_unstable();
        names.dedup();
        assert_eq!(names.len(), ALL.len());
        for rule in ALL {
            assert!(rule
                .name
                .bytes()
                .all(|b| b.is_ascii_lowercase() || b.is_ascii_digit() || b == b'-'));
            for section in ["## What it does", "## Why it matters", "## Example"] {
                assert!(rule.doc.contains(section), "{} lacks {section}", rule.name);
            }
        }
    }

    #[test]
    fn excerpts_cut_long_text() {
        assert_eq!(excerpt("8,1"), "8,1");
        let long = "9".repeat(400);
        assert_eq!(excerpt(&long), format!("{}…", "9".repeat(40)));
        assert_eq!(excerpt(&"û".repeat(41)), format!("{}…", "û".repeat(40)));
    }
}
