//! Findings: what a rule reports, where, and how to fix it.

use serde::Serialize;

use crate::rules::Rule;
use crate::syntax::Span;

/// How serious a finding is.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize)]
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

/// A machine-applicable fix: edits that never overlap one another.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Fix {
    pub message: String,
    pub edits: Vec<Edit>,
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
        });
        self
    }

    pub fn with_label(mut self, span: Span, message: impl Into<String>) -> Diagnostic {
        self.labels.push(Label {
            span,
            message: message.into(),
        });
        self
    }
}

/// Counts of findings by severity.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Serialize)]
pub struct Summary {
    pub files: usize,
    pub errors: usize,
    pub warnings: usize,
    pub infos: usize,
    #[serde(skip)]
    pub fixable: usize,
}

impl Summary {
    pub fn add(&mut self, diagnostic: &Diagnostic) {
        match diagnostic.severity() {
            Severity::Error => self.errors += 1,
            Severity::Warning => self.warnings += 1,
            Severity::Info => self.infos += 1,
        }
        if diagnostic.fix.is_some() {
            self.fixable += 1;
        }
    }

    /// `Found 2 errors, 21 warnings (1 fixable with ekb fix)`, or `No problems found`.
    pub fn sentence(&self) -> String {
        let mut parts = Vec::new();
        for (count, word) in [
            (self.errors, "error"),
            (self.warnings, "warning"),
            (self.infos, "info"),
        ] {
            if count > 0 {
                let plural = if count == 1 || word == "info" {
                    ""
                } else {
                    "s"
                };
                parts.push(format!("{count} {word}{plural}"));
            }
        }
        if parts.is_empty() {
            return "No problems found".to_string();
        }
        let mut sentence = format!("Found {}", parts.join(", "));
        if self.fixable > 0 {
            sentence.push_str(&format!(" ({} fixable with ekb fix)", self.fixable));
        }
        sentence
    }
}
