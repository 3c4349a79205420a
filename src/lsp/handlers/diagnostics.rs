//! `textDocument/publishDiagnostics`: the findings of `ekb check`, as `check` shows them
//! (the first of each rule, then a note of how many more).

use lsp_types::{
    DiagnosticRelatedInformation, DiagnosticSeverity, DiagnosticTag, Location, NumberOrString,
    PublishDiagnosticsParams,
};

use super::Snapshot;
use crate::diagnostic::{Diagnostic, Severity};

/// The name diagnostics give as their source.
pub const SOURCE: &str = "ekb";

/// The rule whose findings are code to delete, which editors grey out.
const UNNECESSARY: &str = "unused-suppression";

/// The diagnostics of a document's version.
pub fn publish(snapshot: &Snapshot<'_, '_>) -> PublishDiagnosticsParams {
    let diagnostics = snapshot
        .analysed
        .checked
        .shown()
        .map(|diagnostic| to_lsp(snapshot, diagnostic))
        .collect();
    PublishDiagnosticsParams::new(snapshot.uri.clone(), diagnostics, Some(snapshot.version))
}

/// A finding as LSP has it: the rule as its code, its help after its message, the other
/// places it points at as related information.
pub fn to_lsp(snapshot: &Snapshot<'_, '_>, diagnostic: &Diagnostic) -> lsp_types::Diagnostic {
    let positions = &snapshot.positions;
    let related: Vec<DiagnosticRelatedInformation> = diagnostic
        .labels
        .iter()
        .map(|label| DiagnosticRelatedInformation {
            location: Location::new(snapshot.uri.clone(), positions.range(label.span)),
            message: label.message.clone(),
        })
        .collect();
    let message = match &diagnostic.help {
        Some(help) => format!("{}\nhelp: {help}", diagnostic.message),
        None => diagnostic.message.clone(),
    };
    lsp_types::Diagnostic {
        range: positions.range(diagnostic.span),
        severity: Some(match diagnostic.severity() {
            Severity::Error => DiagnosticSeverity::ERROR,
            Severity::Warning => DiagnosticSeverity::WARNING,
            Severity::Info => DiagnosticSeverity::INFORMATION,
        }),
        code: Some(NumberOrString::String(diagnostic.rule.name.to_string())),
        code_description: None,
        source: Some(SOURCE.to_string()),
        message,
        related_information: (!related.is_empty()).then_some(related),
        tags: (diagnostic.rule.name == UNNECESSARY).then(|| vec![DiagnosticTag::UNNECESSARY]),
        data: None,
    }
}
