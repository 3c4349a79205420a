//! The whole check of one file: the model and every finding, sorted by position.

use crate::diagnostic::{Diagnostic, Summary};
use crate::model::build::{build, Options};
use crate::model::KnowledgeBase;
use crate::rules::{self, compat, structure};
use crate::source::SourceFile;

/// A checked file: what the robot would load, and what is wrong with it.
#[derive(Debug)]
pub struct Checked<'a> {
    pub source: &'a SourceFile,
    pub kb: KnowledgeBase<'a>,
    /// Sorted by position in the file.
    pub diagnostics: Vec<Diagnostic>,
}

impl Checked<'_> {
    pub fn summary(&self) -> Summary {
        let mut summary = Summary {
            files: 1,
            ..Summary::default()
        };
        self.diagnostics.iter().for_each(|d| summary.add(d));
        summary
    }

    pub fn has_errors(&self) -> bool {
        self.diagnostics
            .iter()
            .any(|d| d.severity() == crate::Severity::Error)
    }
}

/// Builds the model of `source` and runs every rule on it.
pub fn check<'a>(source: &'a SourceFile, options: &Options) -> Checked<'a> {
    let mut diagnostics = Vec::new();
    structure::invalid_utf8::check(source, &mut diagnostics);
    compat::compat_bom::check(source.text(), &mut diagnostics);
    let kb = build(source.text(), options, &mut diagnostics);
    rules::check_model(&kb, source.text(), &mut diagnostics);
    // Byte order is line-then-column order; the sort is stable, so rule order breaks ties.
    diagnostics.sort_by_key(|d| (d.span.start, d.span.end));
    Checked {
        source,
        kb,
        diagnostics,
    }
}
