//! Which rules run on a file, and how grave their findings are (SPEC §7): `select`,
//! `extend-select`, `ignore` and `severity` in `ekb.toml`, and `--select`, `--extend-select`
//! and `--ignore` on the command line, following ruff's conventions.
//!
//! A selector names a rule (`key-case`) or a category (`content`). The choices come in
//! layers, the settings file's first and then the command line's. Within a layer, the most
//! specific selector that matches a rule decides (a rule's name beats its category), and
//! `ignore` wins a tie; a layer whose selectors do not match a rule leaves it as the layers
//! before it left it, except that a layer with a `select` of its own starts afresh: what it
//! does not select is off. So `select = ["content"]` with `ignore = ["repeated-word"]` runs
//! every content rule but one, and `--select key-case` on the command line runs only
//! `key-case`, whatever the settings file selected.

use std::fmt;

use super::{by_name, categories, index_of, Category, Rule, ALL};
use crate::diagnostic::Severity;

/// A rule, or every rule of a category.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RuleSelector {
    Rule(&'static Rule),
    Category(Category),
}

impl RuleSelector {
    /// The selector written `text`, or why there is none (with the nearest name).
    pub fn parse(text: &str) -> Result<RuleSelector, String> {
        if let Some(rule) = by_name(text) {
            return Ok(RuleSelector::Rule(rule));
        }
        if let Some(category) = categories().into_iter().find(|c| c.name() == text) {
            return Ok(RuleSelector::Category(category));
        }
        let hint = match nearest(text, all_names()) {
            Some(name) => format!("did you mean `{name}`?"),
            None => "`ekb rules` lists the rules and their categories".to_string(),
        };
        Err(format!("`{text}` is no rule or category; {hint}"))
    }

    pub fn name(self) -> &'static str {
        match self {
            RuleSelector::Rule(rule) => rule.name,
            RuleSelector::Category(category) => category.name(),
        }
    }

    pub fn matches(self, rule: &Rule) -> bool {
        match self {
            RuleSelector::Rule(selected) => std::ptr::eq(selected, rule),
            RuleSelector::Category(category) => rule.category == category,
        }
    }

    /// How narrowly it selects: a rule's name is more specific than its category.
    fn specificity(self) -> u8 {
        match self {
            RuleSelector::Category(_) => 1,
            RuleSelector::Rule(_) => 2,
        }
    }

    /// The most specific of `selectors` that matches `rule`.
    fn best(selectors: &[RuleSelector], rule: &Rule) -> Option<u8> {
        selectors
            .iter()
            .filter(|selector| selector.matches(rule))
            .map(|selector| selector.specificity())
            .max()
    }
}

impl fmt::Display for RuleSelector {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// Every rule's name and every category's, for suggestions.
fn all_names() -> impl Iterator<Item = &'static str> {
    let categories = categories().into_iter().map(Category::name);
    ALL.iter().map(|rule| rule.name).chain(categories)
}

/// The name of `known` nearest to `text` (ignoring case), to suggest; `None` when none is
/// near: then `text` is no typo but some other word.
pub fn nearest<'a>(text: &str, known: impl Iterator<Item = &'a str>) -> Option<&'a str> {
    let lower = text.to_lowercase();
    known
        .map(|name| (strsim::levenshtein(&lower, &name.to_lowercase()), name))
        .min_by_key(|&(distance, _)| distance)
        .filter(|&(distance, name)| distance <= (name.len() / 3).max(2))
        .map(|(_, name)| name)
}

/// One layer of choices: the settings file's or the command line's.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct Choice {
    /// The rules to run; `None` keeps those of the layers before.
    pub select: Option<Vec<RuleSelector>>,
    /// Rules to run as well.
    pub extend_select: Vec<RuleSelector>,
    /// Rules not to run.
    pub ignore: Vec<RuleSelector>,
}

/// The rules that run on one file, and the severity of each.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct RuleSet {
    /// By index in [`ALL`].
    enabled: Vec<bool>,
    severity: Vec<Severity>,
}

impl Default for RuleSet {
    /// Every rule, at its own severity.
    fn default() -> RuleSet {
        RuleSet {
            enabled: vec![true; ALL.len()],
            severity: ALL.iter().map(|rule| rule.severity).collect(),
        }
    }
}

impl RuleSet {
    /// The rules that `layers`, in order, choose.
    pub fn chosen(layers: &[&Choice]) -> RuleSet {
        let mut set = RuleSet::default();
        for (rule, enabled) in ALL.iter().zip(&mut set.enabled) {
            for layer in layers {
                let selected = layer.select.as_deref().unwrap_or_default();
                let selected = RuleSelector::best(selected, rule)
                    .max(RuleSelector::best(&layer.extend_select, rule));
                let ignored = RuleSelector::best(&layer.ignore, rule);
                *enabled = match (selected, ignored) {
                    (Some(selected), Some(ignored)) => selected > ignored,
                    (Some(_), None) => true,
                    (None, Some(_)) => false,
                    (None, None) => *enabled && layer.select.is_none(),
                };
            }
        }
        set
    }

    /// Turns off the rules of `selectors` (a file's `per-file-ignores`).
    pub fn ignore(&mut self, selectors: &[RuleSelector]) {
        for (rule, enabled) in ALL.iter().zip(&mut self.enabled) {
            *enabled &= !selectors.iter().any(|selector| selector.matches(rule));
        }
    }

    /// Sets the severity of the rules of each selector, the most specific selector last
    /// winning: a rule's own severity beats its category's, whatever their order.
    pub fn set_severities(&mut self, severities: &[(RuleSelector, Severity)]) {
        let mut ordered: Vec<&(RuleSelector, Severity)> = severities.iter().collect();
        ordered.sort_by_key(|(selector, _)| selector.specificity());
        for (selector, severity) in ordered {
            for (rule, slot) in ALL.iter().zip(&mut self.severity) {
                if selector.matches(rule) {
                    *slot = *severity;
                }
            }
        }
    }

    pub fn is_enabled(&self, rule: &Rule) -> bool {
        self.enabled[index_of(rule)]
    }

    /// The severity of `rule`'s findings.
    pub fn severity(&self, rule: &Rule) -> Severity {
        self.severity[index_of(rule)]
    }

    /// The severity of `rule`'s findings, if the settings change it.
    pub fn severity_override(&self, rule: &Rule) -> Option<Severity> {
        let severity = self.severity[index_of(rule)];
        (severity != rule.severity).then_some(severity)
    }

    /// The rules that run, in catalogue order.
    pub fn enabled(&self) -> impl Iterator<Item = &'static Rule> + '_ {
        ALL.iter()
            .zip(&self.enabled)
            .filter(|(_, enabled)| **enabled)
            .map(|(rule, _)| *rule)
    }

    /// Whether every rule runs at its own severity (nothing to filter or change).
    pub fn is_default(&self) -> bool {
        *self == RuleSet::default()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn selectors(names: &[&str]) -> Vec<RuleSelector> {
        names
            .iter()
            .map(|name| RuleSelector::parse(name).unwrap())
            .collect()
    }

    fn enabled(set: &RuleSet) -> Vec<&'static str> {
        set.enabled().map(|rule| rule.name).collect()
    }

    #[test]
    fn selectors_are_rules_or_categories_and_typos_get_a_suggestion() {
        assert_eq!(RuleSelector::parse("content").unwrap().name(), "content");
        assert_eq!(RuleSelector::parse("key-case").unwrap().name(), "key-case");
        assert_eq!(
            RuleSelector::parse("untranslated-mesage").unwrap_err(),
            "`untranslated-mesage` is no rule or category; did you mean `untranslated-message`?"
        );
        assert_eq!(
            RuleSelector::parse("Compat").unwrap_err(),
            "`Compat` is no rule or category; did you mean `compat`?"
        );
        assert!(RuleSelector::parse("pizza")
            .unwrap_err()
            .ends_with("`ekb rules` lists the rules and their categories"));
    }

    #[test]
    fn the_most_specific_selector_decides_and_ignore_wins_a_tie() {
        let settings = Choice {
            select: Some(selectors(&["content"])),
            ignore: selectors(&["repeated-word"]),
            ..Choice::default()
        };
        let set = RuleSet::chosen(&[&settings]);
        assert!(!enabled(&set).contains(&"repeated-word"));
        assert!(enabled(&set).contains(&"trailing-whitespace"));
        assert!(!enabled(&set).contains(&"key-case"));
        // A rule selected by name beats its category's ignore.
        let narrow = Choice {
            extend_select: selectors(&["key-case"]),
            ignore: selectors(&["structure"]),
            ..Choice::default()
        };
        let set = RuleSet::chosen(&[&narrow]);
        assert!(enabled(&set).contains(&"key-case"));
        assert!(!enabled(&set).contains(&"missing-field"));
        let tie = Choice {
            select: Some(selectors(&["key-case"])),
            ignore: selectors(&["key-case"]),
            ..Choice::default()
        };
        assert!(enabled(&RuleSet::chosen(&[&tie])).is_empty());
    }

    #[test]
    fn a_later_select_starts_afresh_and_a_later_ignore_adds_up() {
        let settings = Choice {
            ignore: selectors(&["untranslated-message"]),
            ..Choice::default()
        };
        let command_line = Choice {
            extend_select: selectors(&["untranslated-message"]),
            ignore: selectors(&["tour"]),
            ..Choice::default()
        };
        let set = RuleSet::chosen(&[&settings, &command_line]);
        assert!(enabled(&set).contains(&"untranslated-message"));
        assert!(!enabled(&set).contains(&"tour-missing"));
        let only = Choice {
            select: Some(selectors(&["key-case"])),
            ..Choice::default()
        };
        assert_eq!(enabled(&RuleSet::chosen(&[&settings, &only])), ["key-case"]);
        assert_eq!(RuleSet::chosen(&[]), RuleSet::default());
    }

    #[test]
    fn a_rules_severity_beats_its_categorys() {
        let mut set = RuleSet::default();
        let untranslated = by_name("untranslated-message").unwrap();
        let repeated = by_name("repeated-word").unwrap();
        set.set_severities(&[
            (RuleSelector::Rule(untranslated), Severity::Info),
            (RuleSelector::Category(Category::Content), Severity::Error),
        ]);
        assert_eq!(set.severity_override(untranslated), Some(Severity::Info));
        assert_eq!(set.severity_override(repeated), Some(Severity::Error));
        set.ignore(&selectors(&["content"]));
        assert!(!set.is_enabled(repeated));
    }
}
