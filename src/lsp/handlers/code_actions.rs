//! `textDocument/codeAction` and `codeAction/resolve`: on the lines of the cursor or
//! selection, each finding's fix (as `ekb fix` would make it) and "ignore RULE" comments
//! (SPEC §7); for the whole document, "fix all" (`source.fixAll.ekb`), which editors also
//! run on save.

use std::collections::HashMap;

use lsp_types::{
    CodeAction, CodeActionKind, CodeActionOrCommand, CodeActionParams, TextEdit, WorkspaceEdit,
};
use serde::{Deserialize, Serialize};

use super::diagnostics::to_lsp;
use super::{edit_between, failed, line_edits, Answer, Snapshot};
use crate::diagnostic::Diagnostic;
use crate::fixing;
use crate::lsp::lines::line_at;
use crate::syntax::{Body, LineEnding, Span};

/// The kind of "fix all": ekb's own under `source.fixAll`, as ruff names its own.
pub fn fix_all_kind() -> CodeActionKind {
    CodeActionKind::new("source.fixAll.ekb")
}

/// What "fix all" carries until it is resolved: which document.
#[derive(Debug, Serialize, Deserialize)]
pub struct FixAllData {
    pub uri: lsp_types::Uri,
}

/// The actions for `params`' range. "Fix all" is only offered, its edit computed when
/// resolved, if `lazy` (the client resolves), since on a large file it is a whole `ekb fix`.
pub fn code_actions(
    snapshot: &Snapshot<'_, '_>,
    params: &CodeActionParams,
    lazy: bool,
) -> Answer<Option<Vec<CodeActionOrCommand>>> {
    let wanted = |kind: &CodeActionKind| {
        params.context.only.as_ref().is_none_or(|only| {
            only.iter().any(|asked| {
                let (asked, kind) = (asked.as_str(), kind.as_str());
                kind == asked || kind.starts_with(&format!("{asked}."))
            })
        })
    };
    let mut actions = Vec::new();
    if wanted(&CodeActionKind::QUICKFIX) {
        let lines = whole_lines(snapshot, snapshot.positions.span(params.range));
        let touched = snapshot
            .analysed
            .checked
            .diagnostics
            .iter()
            .filter(|d| d.span.start <= lines.end && lines.start <= d.span.end);
        let mut ignores = Vec::new();
        for diagnostic in touched {
            actions.extend(quick_fix(snapshot, diagnostic));
            if let Some(ignore) = ignore_on_line(snapshot, diagnostic) {
                if !ignores.contains(&ignore.title) {
                    ignores.push(ignore.title.clone());
                    actions.push(ignore);
                }
            }
        }
    }
    let fixable = |d: &Diagnostic| d.rule.fixable;
    if wanted(&fix_all_kind()) && snapshot.analysed.checked.diagnostics.iter().any(fixable) {
        let mut action = CodeAction {
            title: "Fix all that ekb can fix".into(),
            kind: Some(fix_all_kind()),
            data: Some(serde_json::json!(FixAllData {
                uri: snapshot.uri.clone()
            })),
            ..CodeAction::default()
        };
        if !lazy {
            action = resolve(snapshot, action)?;
        }
        actions.push(action);
    }
    Ok(Some(
        actions
            .into_iter()
            .map(CodeActionOrCommand::CodeAction)
            .collect(),
    ))
}

/// Fills in the edit of a "fix all": every fix `ekb fix` would apply now.
pub fn resolve(snapshot: &Snapshot<'_, '_>, mut action: CodeAction) -> Answer<CodeAction> {
    if action.kind.as_ref() != Some(&fix_all_kind()) {
        return Err(failed(format!(
            "ekb resolves only its \"fix all\" action, not `{}`",
            action.title
        )));
    }
    let fixed = fixing::fix(snapshot.analysed.checked.source, &snapshot.analysed.options);
    let edits = line_edits(&snapshot.positions, &fixed.text);
    action.edit = Some(workspace_edit(snapshot, edits));
    Ok(action)
}

/// The finding's fix, as `ekb fix` applies it (a renamed key keeps the id's column).
fn quick_fix(snapshot: &Snapshot<'_, '_>, diagnostic: &Diagnostic) -> Option<CodeAction> {
    let fix = diagnostic.fix.as_ref()?;
    let (fixed, _) = fixing::apply(snapshot.text(), std::slice::from_ref(diagnostic))?;
    let edit = edit_between(&snapshot.positions, &fixed)?;
    Some(CodeAction {
        title: fix.message.clone(),
        kind: Some(CodeActionKind::QUICKFIX),
        diagnostics: Some(vec![to_lsp(snapshot, diagnostic)]),
        edit: Some(workspace_edit(snapshot, vec![edit])),
        is_preferred: Some(true),
        ..CodeAction::default()
    })
}

/// The comment that makes `ekb` ignore the finding's rule on its line (SPEC §7): a new
/// `# ekb: ignore[RULE]` line above it, or the rule added to the one already there.
fn ignore_on_line(snapshot: &Snapshot<'_, '_>, diagnostic: &Diagnostic) -> Option<CodeAction> {
    let text = snapshot.text();
    let rule = diagnostic.rule.name;
    let line = line_at(text, diagnostic.span.start)?;
    // A suppression applies to the next non-comment line: a finding on a comment (an
    // unused suppression) or on a blank line cannot be ignored so.
    if !matches!(line.body, Body::Entry { .. }) {
        return None;
    }
    let above = line
        .span
        .start
        .checked_sub(1)
        .and_then(|end| line_at(text, end))
        .and_then(|above| match above.body {
            Body::Comment(comment) => Some(comment),
            _ => None,
        });
    let edit = match above.and_then(|comment| suppression_list(text, comment)) {
        Some((listed, _)) if listed.split(',').any(|name| name.trim() == rule) => return None,
        Some((_, close)) => insert(snapshot, close, &format!(", {rule}")),
        None => {
            let ending = match line.ending {
                LineEnding::CrLf => "\r\n",
                _ => "\n",
            };
            let comment = format!("# ekb: ignore[{rule}]{ending}");
            insert(snapshot, line.span.start, &comment)
        }
    };
    Some(CodeAction {
        title: format!("Ignore `{rule}` on this line"),
        kind: Some(CodeActionKind::QUICKFIX),
        diagnostics: Some(vec![to_lsp(snapshot, diagnostic)]),
        edit: Some(workspace_edit(snapshot, vec![edit])),
        ..CodeAction::default()
    })
}

/// The rules listed by an `# ekb: ignore[…]` comment, and the offset of its `]`.
fn suppression_list(text: &str, comment: Span) -> Option<(&str, u32)> {
    let written = comment.text(text);
    let inside = written
        .strip_prefix('#')?
        .trim_start()
        .strip_prefix("ekb:")?
        .trim_start()
        .strip_prefix("ignore[")?
        .strip_suffix(']')?;
    Some((inside, comment.end - 1))
}

fn insert(snapshot: &Snapshot<'_, '_>, offset: u32, text: &str) -> TextEdit {
    let at = snapshot.positions.range(Span::empty_at(offset as usize));
    TextEdit::new(at, text.to_string())
}

/// `span` grown to whole lines: an action applies to any finding on the cursor's line.
fn whole_lines(snapshot: &Snapshot<'_, '_>, span: Span) -> Span {
    let text = snapshot.text();
    let start = line_at(text, span.start).map_or(span.start, |line| line.span.start);
    let end = line_at(text, span.end).map_or(span.end, |line| line.content().end);
    Span {
        start,
        end: end.max(start),
    }
}

fn workspace_edit(snapshot: &Snapshot<'_, '_>, edits: Vec<TextEdit>) -> WorkspaceEdit {
    WorkspaceEdit::new(HashMap::from([(snapshot.uri.clone(), edits)]))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::lsp::handlers::with_snapshot;
    use lsp_types::{CodeActionContext, Position, Range, TextDocumentIdentifier};

    /// The "ignore" action's edits on `line` of `text`.
    fn ignore_edits(text: &str, line: u32) -> Vec<TextEdit> {
        with_snapshot(text, |snapshot| {
            let params = CodeActionParams {
                text_document: TextDocumentIdentifier::new(snapshot.uri.clone()),
                range: Range::new(Position::new(line, 0), Position::new(line, 0)),
                context: CodeActionContext::default(),
                work_done_progress_params: Default::default(),
                partial_result_params: Default::default(),
            };
            let actions = code_actions(snapshot, &params, true).unwrap().unwrap();
            let ignore = actions.into_iter().find_map(|action| match action {
                CodeActionOrCommand::CodeAction(a)
                    if a.title == "Ignore `key-case` on this line" =>
                {
                    Some(a)
                }
                _ => None,
            });
            ignore
                .and_then(|a| a.edit?.changes?.into_values().next())
                .unwrap_or_default()
        })
    }

    #[test]
    fn an_ignore_comment_above_gets_the_rule_added() {
        let text = "# ekb: ignore[trailing-whitespace]\nRobotLocation 1 1 2 3\n";
        let edits = ignore_edits(text, 1);
        assert_eq!(edits.len(), 1);
        assert_eq!(edits[0].new_text, ", key-case");
        assert_eq!(edits[0].range.start, Position::new(0, 33));
        // Already listed: nothing to offer.
        let listed = "# ekb: ignore[key-case]\r\nRobotLocation 1 1 2 3\r\n";
        assert!(ignore_edits(listed, 1).is_empty());
        // A new comment keeps the file's line ending.
        let crlf = "RobotLocation 1 1 2 3\r\n";
        assert_eq!(
            ignore_edits(crlf, 0)[0].new_text,
            "# ekb: ignore[key-case]\r\n"
        );
    }

    #[test]
    fn suppression_comments_are_read() {
        let text = "# ekb: ignore[key-case, trailing-whitespace]";
        let (listed, close) = suppression_list(text, Span::new(0, text.len())).unwrap();
        assert_eq!(listed, "key-case, trailing-whitespace");
        assert_eq!(&text[close as usize..], "]");
        let other = "# ekb: ignore-file[key-case]";
        assert_eq!(suppression_list(other, Span::new(0, other.len())), None);
    }
}
