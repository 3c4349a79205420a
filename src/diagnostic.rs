//! Findings: what a rule reports, where, and how to fix it.

use serde::Serialize;

use crate::rules::Rule;
use crate::syntax::Span;

/// How serious a finding is (graver first: `Error < Warning`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize, clap::ValueEnum)]
#[serde(rename_all = "lowercase")]
pub enum Severity {
    Error,
    Warning,
    Info,
}

impl Severity {
    pub fn name(self) -> &'static str {
        match self {
            Severity::Error => "error",
            Severity::Warning => "warning",
            Severity::Info => "info",
        }
    }
}

/// Replace the bytes of `span` with `replacement`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Edit {
    pub span: Span,
    pub replacement: String,
}

impl Edit {
    pub fn replace(span: Span, replacement: impl Into<String>) -> Edit {
        Edit {
            span,
            replacement: replacement.into(),
        }
    }

    pub fn delete(span: Span) -> Edit {
        Edit::replace(span, "")
    }

    pub fn insert(offset: u32, text: impl Into<String>) -> Edit {
        Edit::replace(
            Span {
                start: offset,
                end: offset,
            },
            text,
        )
    }
}

/// Whether `ekb fix` applies a fix on its own (ruff's split).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Applicability {
    /// It keeps what the file means: `ekb fix` applies it.
    Safe,
    /// It guesses what was meant (a dash was a minus, a comma a decimal point): applied only
    /// with `ekb fix --unsafe-fixes`.
    Unsafe,
}

/// A machine-applicable fix: edits that never overlap one another.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Fix {
    pub message: String,
    pub edits: Vec<Edit>,
    pub applicability: Applicability,
}

impl Fix {
    pub fn is_safe(&self) -> bool {
        self.applicability == Applicability::Safe
    }
}

/// A secondary place a finding points at (e.g. the earlier of two duplicate lines).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Label {
    pub span: Span,
    pub message: String,
}

/// One finding of one rule.
#[derive(Debug, Clone, PartialEq)]
pub struct Diagnostic {
    pub rule: &'static Rule,
    /// The rule's severity, unless this finding is graver (or milder) than most of its rule's.
    severity: Severity,
    /// What is wrong and what the robot would do.
    pub message: String,
    pub span: Span,
    pub location_id: Option<u32>,
    /// What to do about it.
    pub help: Option<String>,
    pub fix: Option<Fix>,
    pub labels: Vec<Label>,
}

impl Diagnostic {
    pub fn new(rule: &'static Rule, span: Span, message: impl Into<String>) -> Diagnostic {
        Diagnostic {
            rule,
            severity: rule.severity,
            message: message.into(),
            span,
            location_id: None,
            help: None,
            fix: None,
            labels: Vec::new(),
        }
    }

    pub fn severity(&self) -> Severity {
        self.severity
    }

    pub fn with_severity(mut self, severity: Severity) -> Diagnostic {
        self.set_severity(severity);
        self
    }

    pub fn set_severity(&mut self, severity: Severity) {
        self.severity = severity;
    }

    pub fn at_location(mut self, id: Option<u32>) -> Diagnostic {
        self.location_id = id;
        self
    }

    pub fn with_help(mut self, help: impl Into<String>) -> Diagnostic {
        self.help = Some(help.into());
        self
    }

    pub fn with_fix(mut self, message: impl Into<String>, edits: Vec<Edit>) -> Diagnostic {
        self.fix = Some(Fix {
            message: message.into(),
            edits,
            applicability: Applicability::Safe,
        });
        self
    }

    /// A fix that guesses what was meant ([`Applicability::Unsafe`]).
    pub fn with_unsafe_fix(self, message: impl Into<String>, edits: Vec<Edit>) -> Diagnostic {
        let mut diagnostic = self.with_fix(message, edits);
        if let Some(fix) = &mut diagnostic.fix {
            fix.applicability = Applicability::Unsafe;
        }
        diagnostic
    }

    pub fn with_label(mut self, span: Span, message: impl Into<String>) -> Diagnostic {
        self.labels.push(Label {
            span,
            message: message.into(),
        });
        self
    }
}

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
