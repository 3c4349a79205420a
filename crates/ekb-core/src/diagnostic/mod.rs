//! Findings: what a rule reports, where, and how to fix it; the identity of the rule that
//! reports it ([`Rule`]); where the rules report them, a bounded number of each rule
//! ([`Diagnostics`]); and the compact fixes `ekb fix` applies ([`fix_list`]).

use serde::Serialize;

use crate::syntax::Span;

mod diagnostics;
pub mod fix_list;
mod rule;

pub(crate) use diagnostics::RuleCounts;
pub use diagnostics::{kept_at_most, Diagnostics, MAX_SHOWN_PER_RULE};
pub use rule::{Category, Rule};

/// How serious a finding is (graver first: `Error < Warning`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Severity {
    Error,
    Warning,
    Info,
}

impl Severity {
    pub const ALL: [Severity; 3] = [Severity::Error, Severity::Warning, Severity::Info];

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
    /// The rule whose finding at the same location causes this one (a `missing-field`
    /// because the line is there with its key miscased): people read this finding right
    /// after its cause ([`crate::render::located::FileReport::in_reading_order`]).
    pub follows_from: Option<&'static Rule>,
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
            follows_from: None,
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

    /// This finding is a consequence of `cause`'s finding at the same location.
    pub fn following(mut self, cause: &'static Rule) -> Diagnostic {
        self.follows_from = Some(cause);
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
