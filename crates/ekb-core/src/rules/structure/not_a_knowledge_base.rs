use crate::diagnostic::Diagnostic;
use crate::model::Key;
use crate::rules::{declare_rule, excerpt};
use crate::syntax::{self, Body};

declare_rule! {
    /// ## What it does
    /// Flags a file that is not an environment knowledge base at all: it has several
    /// `key value` lines, and not one of them has a key of the environment knowledge base,
    /// even ignoring case. It is reported once, instead of an `unknown-key` error per line.
    ///
    /// ## Why it matters
    /// The robot's reader ignores every line it does not know, so given such a file it
    /// loads no location and no tour, without a word. Most often it is the wrong file: the
    /// culture knowledge base, which sits beside the environment knowledge base in the
    /// robot's `data/` folder, or a configuration file.
    ///
    /// ## Example
    /// ```text
    /// passingDistance                           100
    /// passingPositionPreferred                  BEHIND
    /// phraseGreetingEnglish                     Greetings
    /// ```
    /// These are lines of the culture knowledge base (`cultureKnowledgeBaseInput.dat`).
    pub static NOT_AN_ENVIRONMENT_KNOWLEDGE_BASE = {
        name: "not-an-environment-knowledge-base",
        category: Structure,
        severity: Error,
        fixable: false,
        summary: "a file with several `key value` lines and no key of the environment knowledge base",
    };
}

/// Fewer `key value` lines than this are a knowledge base too broken to tell, not another
/// kind of file: each is reported as an `unknown-key`.
const MIN_FOREIGN_ENTRIES: usize = 3;

/// The finding, if `text` is not an environment knowledge base. Pointed at the first line's
/// key; the other rules' findings on such a file say nothing more.
pub fn check(text: &str) -> Option<Diagnostic> {
    let mut first_key = None;
    let mut entries = 0;
    for line in syntax::lines(text) {
        let Body::Entry { key, args } = line.body else {
            continue;
        };
        let name = key.text(text);
        // A known key, even miscased, makes it a knowledge base; ending here also keeps
        // the check to the first line of nearly every file. So does a known key that a
        // vertical tab or a form feed ends: the robot's reader takes either for a space.
        let read_as_key = name.split(['\u{B}', '\u{C}']).next().unwrap_or(name);
        if Key::from_name_ignoring_case(read_as_key).is_some() {
            return None;
        }
        if !args.is_empty() {
            entries += 1;
            first_key.get_or_insert((key, name));
        }
    }
    let (span, name) = first_key.filter(|_| entries >= MIN_FOREIGN_ENTRIES)?;
    Some(
        Diagnostic::new(
            &NOT_AN_ENVIRONMENT_KNOWLEDGE_BASE,
            span,
            format!(
                "this is not an environment knowledge base: none of its {entries} `key value` \
                 lines has one of its keys (the first is `{}`), so the robot's reader would \
                 load no location and no tour from it",
                excerpt(name)
            ),
        )
        .with_help(
            "is this the file you meant? An environment knowledge base has lines such as \
             `robotLocationDescription 1 Roomba`; this looks like another kind of file, such \
             as the culture knowledge base or a configuration",
        ),
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    const BAD: &str = include_str!(
        "../../../../../tests/fixtures/rules/not-an-environment-knowledge-base/bad.dat"
    );
    const GOOD: &str = include_str!(
        "../../../../../tests/fixtures/rules/not-an-environment-knowledge-base/good.dat"
    );
    const CULTURE: &str = include_str!(
        "../../../../../tests/fixtures/corpus/upstream-2025-06-cultureKnowledgeBaseInput.dat"
    );

    #[test]
    fn the_culture_knowledge_base_is_one_finding() {
        let finding = check(CULTURE).expect("a finding");
        assert_eq!(finding.rule.name, "not-an-environment-knowledge-base");
        assert_eq!(finding.span.text(CULTURE), "passingDistance");
        assert!(
            finding.message.starts_with(
                "this is not an environment knowledge base: none of its 78 `key value` lines"
            ),
            "{}",
            finding.message
        );
        assert!(finding.fix.is_none());
    }

    #[test]
    fn the_fixtures_are_a_finding_and_its_near_miss() {
        let finding = check(BAD).expect("a finding");
        assert_eq!(finding.span.start, 0);
        assert_eq!(check(GOOD), None);
    }

    #[test]
    fn one_known_key_even_miscased_makes_a_knowledge_base() {
        let foreign = "passingDistance 100\nphraseLanguage English\npauseDuration 2\n";
        assert!(check(foreign).is_some());
        assert_eq!(check(&format!("{foreign}tourSpecification 1 1\n")), None);
        assert_eq!(check(&format!("{foreign}RobotLocation 1 1 2 3\n")), None);
        // The robot's reader reads a key that a vertical tab ends.
        let tabbed = "robotLocationDescription\u{B}2 a\nb\u{B}1 c\nd\u{C}1 e\n";
        assert_eq!(check(tabbed), None);
    }

    #[test]
    fn a_few_unknown_lines_are_left_to_unknown_key() {
        assert_eq!(check(""), None);
        assert_eq!(check("# only\n# comments\n\n# here\n"), None);
        assert_eq!(check("passingDistance 100\nphraseLanguage English\n"), None);
        // Keys alone, with no value, are no `key value` lines.
        assert_eq!(check("one\ntwo\nthree\nfour\n"), None);
    }
}
