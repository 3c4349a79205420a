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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::lsp::handlers::with_snapshot;
    use crate::rules::{Category, Rule};
    use crate::syntax::Span;

    #[test]
    fn a_duplicate_points_at_the_other_line() {
        let text = "robotLocationDescription 1 A\nrobotLocationDescription 1 B\n";
        let duplicate = with_snapshot(text, |snapshot| {
            publish(snapshot)
                .diagnostics
                .into_iter()
                .find(|d| d.code == Some(NumberOrString::String("duplicate-key".into())))
                .expect("a duplicate-key finding")
        });
        assert_eq!(duplicate.range.start.line, 1);
        let related = duplicate.related_information.expect("the earlier line");
        assert_eq!(related[0].location.range.start.line, 0);
        assert_eq!(related[0].message, "first given here");
        assert_eq!(duplicate.severity, Some(DiagnosticSeverity::WARNING));
        assert!(duplicate.message.contains("\nhelp: delete the line"));
    }

    #[test]
    fn a_missing_field_points_at_the_miscased_line_that_causes_it() {
        let text = "robotLocationDescription 1 A\nrobotLocation 1 1 1 1\ngestureTarget 1 1 1 1\n\
                    preGestureMessageEnglish 1 Hi\npreGestureMessageIsiZulu 1 Sawubona\n\
                    preGestureMessageKinyarwanda 1 Muraho\npostGestureMessageEnglish 1 Bye\n\
                    postGestureMessageIsiZulu 1 Hamba kahle\n\
                    postgestureMessageKinyarwanda 1 Murabeho\ntourSpecification 1 1\n";
        let missing = with_snapshot(text, |snapshot| {
            publish(snapshot)
                .diagnostics
                .into_iter()
                .find(|d| d.code == Some(NumberOrString::String("missing-field".into())))
                .expect("a missing-field finding")
        });
        assert_eq!(missing.range.start.line, 0);
        let related = missing.related_information.expect("its cause");
        assert_eq!(related[0].location.range.start.line, 8);
        assert_eq!(related[0].message, "because of this (key-case)");
    }

    #[test]
    fn an_unused_suppression_is_unnecessary() {
        // The rule comes with suppression comments (SPEC §7); what matters here is its name.
        static UNUSED: Rule = Rule {
            name: UNNECESSARY,
            category: Category::Structure,
            severity: Severity::Warning,
            fixable: true,
            summary: "",
            doc: "",
        };
        let finding = Diagnostic::new(&UNUSED, Span::new(0, 5), "nothing to ignore");
        let tags = with_snapshot("# ekb\n", |snapshot| to_lsp(snapshot, &finding).tags);
        assert_eq!(tags, Some(vec![DiagnosticTag::UNNECESSARY]));
    }
}
