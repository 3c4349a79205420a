//! The counts of a check's findings, by severity and by rule, in catalogue order: the
//! closing line of `ekb check` and the tallies of the other commands.

use serde::Serialize;

use crate::diagnostic::{Diagnostic, Fix, Rule, Severity};

/// Counts of findings by severity, and by rule.
#[derive(Debug, Clone, Default, PartialEq, Eq, Serialize)]
pub struct Summary {
    pub files: usize,
    pub errors: usize,
    pub warnings: usize,
    pub infos: usize,
    #[serde(skip)]
    pub fixable: usize,
    /// How many only `ekb fix --unsafe-fixes` can fix.
    #[serde(skip)]
    pub unsafe_fixable: usize,
    /// How many findings of each rule, at each severity, in catalogue order.
    #[serde(skip)]
    pub by_rule: Vec<RuleCount>,
    /// How many findings are counted but not shown (below `--level`).
    #[serde(skip)]
    pub hidden: Option<Hidden>,
}

/// The findings of one rule at one severity.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct RuleCount {
    pub rule: &'static Rule,
    pub severity: Severity,
    pub count: usize,
    /// How many of them `ekb fix` can fix.
    pub fixable: usize,
    /// How many of them only `ekb fix --unsafe-fixes` can fix.
    pub unsafe_fixable: usize,
}

/// Findings counted but not shown: those less grave than `level`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Hidden {
    pub count: usize,
    pub level: Severity,
}

impl Summary {
    /// Counts the findings of `counted`'s rule at its severity.
    pub fn count(&mut self, counted: RuleCount) {
        match counted.severity {
            Severity::Error => self.errors += counted.count,
            Severity::Warning => self.warnings += counted.count,
            Severity::Info => self.infos += counted.count,
        }
        self.fixable += counted.fixable;
        self.unsafe_fixable += counted.unsafe_fixable;
        let same = |c: &&mut RuleCount| {
            std::ptr::eq(c.rule, counted.rule) && c.severity == counted.severity
        };
        match self.by_rule.iter_mut().find(same) {
            Some(known) => {
                known.count += counted.count;
                known.fixable += counted.fixable;
                known.unsafe_fixable += counted.unsafe_fixable;
            }
            None => {
                self.by_rule.push(counted);
                let place = |c: &RuleCount| crate::rules::index_of(c.rule);
                self.by_rule.sort_by_key(|c| (place(c), c.severity));
            }
        }
    }

    pub fn add(&mut self, diagnostic: &Diagnostic) {
        let safe = diagnostic.fix.as_ref().map(Fix::is_safe);
        self.count(RuleCount {
            rule: diagnostic.rule,
            severity: diagnostic.severity(),
            count: 1,
            fixable: usize::from(safe == Some(true)),
            unsafe_fixable: usize::from(safe == Some(false)),
        });
    }

    /// Adds the counts of another file (or files).
    pub fn merge(&mut self, other: &Summary) {
        self.files += other.files;
        for &counted in &other.by_rule {
            self.count(counted);
        }
    }

    /// `Found 2 errors, 21 warnings (1 fixable with ekb fix)`, or `No problems found`.
    pub fn sentence(&self) -> String {
        self.found(|_, count, word| format!("{count} {word}"), false)
    }

    /// [`Summary::sentence`] with each severity broken down by rule: `Found 2 errors:
    /// key-case, missing-field · 21 warnings: 20 untranslated-message, 1 repeated-word (1
    /// fixable with ekb fix: key-case)`. A severity whose rules have one finding each lists
    /// only their names; otherwise each rule comes with its count, the most frequent first.
    /// The fixable ones are named, or the count would read as the last rule's.
    pub fn breakdown(&self) -> String {
        self.found(
            |severity, count, word| {
                let mut rules: Vec<&RuleCount> = self
                    .by_rule
                    .iter()
                    .filter(|c| c.severity == severity && c.count > 0)
                    .collect();
                rules.sort_by_key(|c| std::cmp::Reverse(c.count));
                let singles = rules.iter().all(|c| c.count == 1);
                let named: Vec<String> = rules
                    .iter()
                    .map(|c| match singles {
                        true => c.rule.name.to_string(),
                        false => format!("{} {}", c.count, c.rule.name),
                    })
                    .collect();
                format!("{count} {word}: {}", named.join(", "))
            },
            true,
        )
    }

    /// The rules with findings that `ekb fix` fixes (`unsafe_fixes`: only with
    /// `--unsafe-fixes`), in catalogue order: `: key-case`, or nothing if none is known.
    fn fixable_rules(&self, unsafe_fixes: bool) -> String {
        let mut names: Vec<&str> = self
            .by_rule
            .iter()
            .filter(|c| match unsafe_fixes {
                true => c.unsafe_fixable > 0,
                false => c.fixable > 0,
            })
            .map(|c| c.rule.name)
            .collect();
        names.dedup();
        match names.is_empty() {
            true => String::new(),
            false => format!(": {}", names.join(", ")),
        }
    }

    /// `Found …`, each severity with findings described by `part`.
    fn found(
        &self,
        part: impl Fn(Severity, usize, String) -> String,
        name_fixable: bool,
    ) -> String {
        let mut parts = Vec::new();
        for (severity, count) in [
            (Severity::Error, self.errors),
            (Severity::Warning, self.warnings),
            (Severity::Info, self.infos),
        ] {
            if count > 0 {
                let word = severity.name();
                let plural = if count == 1 || severity == Severity::Info {
                    ""
                } else {
                    "s"
                };
                parts.push(part(severity, count, format!("{word}{plural}")));
            }
        }
        let separator = if parts.iter().any(|p| p.contains(':')) {
            " · "
        } else {
            ", "
        };
        let mut sentence = if parts.is_empty() {
            "No problems found".to_string()
        } else {
            format!("Found {}", parts.join(separator))
        };
        let mut notes = Vec::new();
        let rules = |unsafe_fixes| match name_fixable {
            true => self.fixable_rules(unsafe_fixes),
            false => String::new(),
        };
        if self.fixable > 0 {
            notes.push(format!(
                "{} fixable with ekb fix{}",
                self.fixable,
                rules(false)
            ));
        }
        if self.unsafe_fixable > 0 {
            let n = self.unsafe_fixable;
            notes.push(format!("{n} with ekb fix --unsafe-fixes{}", rules(true)));
        }
        if let Some(hidden) = self.hidden.filter(|hidden| hidden.count > 0) {
            let level = hidden.level.name();
            notes.push(format!("{} below --level {level} not shown", hidden.count));
        }
        if !notes.is_empty() {
            sentence.push_str(&format!(" ({})", notes.join("; ")));
        }
        sentence
    }
}
