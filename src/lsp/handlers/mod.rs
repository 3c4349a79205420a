//! One module per kind of request. Each answers from a [`Snapshot`] of one document and
//! asks the library for everything it shows: the findings of `check`, the fixes of `fix`,
//! the layout of `fmt`, the rules' documentation, what the robot's reader loads.

pub mod code_actions;
pub mod completion;
pub mod diagnostics;
pub mod formatting;
pub mod hover;
pub mod inlay_hints;
pub mod navigation;
pub mod symbols;

use std::time::{Duration, Instant};

use lsp_server::{ErrorCode, ResponseError};
use lsp_types::{TextEdit, Uri};
use similar::{Algorithm, DiffTag, TextDiff};

use super::documents::Analysed;
use super::position::Positions;
use super::workspace::Workspace;
use crate::syntax::Span;

/// One version of one document, checked, as every request sees it (`'q`: the life of the
/// checked text, which the check borrows).
#[derive(Debug, Clone, Copy)]
pub struct Snapshot<'a, 'q> {
    pub uri: &'a Uri,
    /// The document's file, if it is one.
    pub path: Option<&'a std::path::Path>,
    pub version: i32,
    /// The configuration the document is read with, for what lies outside it.
    pub workspace: &'a Workspace,
    pub positions: Positions<'a>,
    pub analysed: &'a Analysed<'q>,
}

impl Snapshot<'_, '_> {
    pub fn text(&self) -> &str {
        self.positions.text
    }
}

/// What a handler answers: its result, or why it has none.
pub type Answer<T> = Result<T, ResponseError>;

/// A request that was understood but cannot be done, and why (shown to the user).
pub fn failed(message: impl Into<String>) -> ResponseError {
    ResponseError {
        code: ErrorCode::RequestFailed as i32,
        message: message.into(),
        data: None,
    }
}

/// The one edit that turns `old` into `new`: the part between what they start and end
/// with alike (so that the editor keeps the cursor and folds where nothing changed).
/// `None` when they are the same.
pub fn edit_between(positions: &Positions<'_>, new: &str) -> Option<TextEdit> {
    let old = positions.text;
    if old == new {
        return None;
    }
    let (old_bytes, new_bytes) = (old.as_bytes(), new.as_bytes());
    let both_boundaries =
        |old_at: usize, new_at: usize| old.is_char_boundary(old_at) && new.is_char_boundary(new_at);
    let mut prefix = old_bytes
        .iter()
        .zip(new_bytes)
        .take_while(|(a, b)| a == b)
        .count();
    while !both_boundaries(prefix, prefix) {
        prefix -= 1;
    }
    let longest_suffix = old.len().min(new.len()) - prefix;
    let mut suffix = old_bytes
        .iter()
        .rev()
        .zip(new_bytes.iter().rev())
        .take(longest_suffix)
        .take_while(|(a, b)| a == b)
        .count();
    while !both_boundaries(old.len() - suffix, new.len() - suffix) {
        suffix -= 1;
    }
    let span = Span::new(prefix, old.len() - suffix);
    Some(TextEdit::new(
        positions.range(span),
        new[prefix..new.len() - suffix].to_string(),
    ))
}

/// How long [`line_edits`] looks for the smallest line diff before it settles for coarser
/// hunks (a large file laid out anew).
const DIFF_TIME: Duration = Duration::from_millis(100);

/// The edits that turn the document into `new`, one per run of changed lines (so that the
/// editor keeps its cursor, folds and marks on the lines between).
pub fn line_edits(positions: &Positions<'_>, new: &str) -> Vec<TextEdit> {
    let diff = TextDiff::configure()
        .algorithm(Algorithm::Myers)
        .deadline(Instant::now() + DIFF_TIME)
        .diff_lines(positions.text, new);
    let mut old_starts = vec![0];
    for line in diff.old_slices() {
        old_starts.push(old_starts[old_starts.len() - 1] + line.len());
    }
    let new_slices = diff.new_slices();
    let mut edits: Vec<TextEdit> = Vec::new();
    let mut run: Option<(std::ops::Range<usize>, std::ops::Range<usize>)> = None;
    let ops = diff.ops().iter().map(Some).chain([None]);
    for op in ops {
        match op.filter(|op| op.tag() != DiffTag::Equal) {
            Some(op) => {
                let (old, new) = (op.old_range(), op.new_range());
                run = Some(match run {
                    Some((run_old, run_new)) => (run_old.start..old.end, run_new.start..new.end),
                    None => (old, new),
                });
            }
            None => {
                if let Some((old, new)) = run.take() {
                    let span = Span::new(old_starts[old.start], old_starts[old.end]);
                    edits.push(TextEdit::new(
                        positions.range(span),
                        new_slices[new].concat(),
                    ));
                }
            }
        }
    }
    edits
}

/// Calls `f` with a snapshot of `text`, checked with the default options (for tests).
#[cfg(test)]
pub fn with_snapshot<R>(text: &str, f: impl FnOnce(&Snapshot<'_, '_>) -> R) -> R {
    use super::documents::Document;
    use super::position::Encoding;
    use crate::config::Config;
    use crate::context::Context;
    let uri: Uri = "untitled:test".parse().expect("a URI");
    let (workspace, _) = Workspace::new(&Context::with_config(Config::default()), None);
    let mut document = Document::new(1, None, text.to_string());
    document.check("test", Default::default);
    let positions = document.positions(Encoding::Utf16);
    document
        .with_analysed(|analysed| {
            f(&Snapshot {
                uri: &uri,
                path: None,
                version: 1,
                workspace: &workspace,
                positions,
                analysed,
            })
        })
        .expect("checked")
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::lsp::position::{Encoding, LineIndex};

    fn apply(old: &str, new: &str) -> String {
        let index = LineIndex::new(old);
        let positions = Positions {
            text: old,
            index: &index,
            encoding: Encoding::Utf8,
        };
        let Some(edit) = edit_between(&positions, new) else {
            return old.to_string();
        };
        let span = positions.span(edit.range);
        let mut out = old.to_string();
        out.replace_range(span.range(), &edit.new_text);
        out
    }

    #[test]
    fn line_edits_make_the_new_text_hunk_by_hunk() {
        let old = "a\nb\nc\nd\ne\n";
        let new = "a\nB\nc\nd\nx\ne";
        let index = LineIndex::new(old);
        let positions = Positions {
            text: old,
            index: &index,
            encoding: Encoding::Utf16,
        };
        let edits = line_edits(&positions, new);
        assert_eq!(edits.len(), 2, "{edits:?}");
        let mut out = old.to_string();
        for edit in edits.iter().rev() {
            out.replace_range(positions.span(edit.range).range(), &edit.new_text);
        }
        assert_eq!(out, new);
    }

    #[test]
    fn one_edit_makes_the_new_text() {
        for (old, new) in [
            ("abc\ndef\n", "abc\nxyz\ndef\n"),
            ("aaa", "aa"),
            ("", "x"),
            ("é", "ê"),
            ("xé", "x😀é"),
            ("same", "same"),
        ] {
            assert_eq!(apply(old, new), new, "{old:?} -> {new:?}");
        }
    }

    /// Every handler, at every kind of position of any text: an answer, never a panic.
    mod any_text {
        use super::*;
        use lsp_types::{
            CodeActionContext, CodeActionParams, CompletionParams, GotoDefinitionParams,
            HoverParams, InlayHintParams, Position, Range, ReferenceContext, ReferenceParams,
            RenameParams, TextDocumentIdentifier, TextDocumentPositionParams,
        };
        use proptest::prelude::*;

        fn text() -> impl Strategy<Value = String> {
            let pieces = vec![
                "robotLocationDescription",
                "robotLocation",
                "robotLocationPose",
                "gestureArm",
                "preGestureMessageEnglish",
                "postGestureMessageenglish",
                "tourSpecification",
                "culturalKnowledge",
                "# ekb: ignore[key-case]",
                "#",
                " ",
                "\t",
                "\n",
                "\r\n",
                "\r",
                "1",
                "2",
                "0",
                "-1",
                "+4",
                "2147483648",
                "2.6",
                "-90",
                ",",
                "left",
                "x",
                "No message in isiZulu",
                "\u{feff}",
                "\u{0}",
                "Ùmuntu",
                "😀",
                "\u{202e}",
            ];
            prop::collection::vec(prop::sample::select(pieces), 0..60).prop_map(|p| p.concat())
        }

        proptest! {
            #![proptest_config(ProptestConfig::with_cases(64))]
            #[test]
            fn every_request_gets_an_answer(text in text(), line in 0u32..8, character in 0u32..40) {
                with_snapshot(&text, |snapshot| {
                    let document = TextDocumentIdentifier::new(snapshot.uri.clone());
                    let at = TextDocumentPositionParams::new(document.clone(), Position::new(line, character));
                    let range = Range::new(Position::new(0, 0), Position::new(line, character));
                    let _ = hover::hover(snapshot, &HoverParams {
                        text_document_position_params: at.clone(),
                        work_done_progress_params: Default::default(),
                    });
                    let _ = completion::completion(snapshot, &CompletionParams {
                        text_document_position: at.clone(),
                        work_done_progress_params: Default::default(),
                        partial_result_params: Default::default(),
                        context: None,
                    });
                    let _ = navigation::definition(snapshot, &GotoDefinitionParams {
                        text_document_position_params: at.clone(),
                        work_done_progress_params: Default::default(),
                        partial_result_params: Default::default(),
                    });
                    let _ = navigation::references(snapshot, &ReferenceParams {
                        text_document_position: at.clone(),
                        work_done_progress_params: Default::default(),
                        partial_result_params: Default::default(),
                        context: ReferenceContext { include_declaration: true },
                    });
                    let _ = navigation::prepare_rename(snapshot, &at);
                    let _ = navigation::rename(snapshot, &RenameParams {
                        text_document_position: at,
                        new_name: "7".into(),
                        work_done_progress_params: Default::default(),
                    });
                    let _ = code_actions::code_actions(snapshot, &CodeActionParams {
                        text_document: document.clone(),
                        range,
                        context: CodeActionContext::default(),
                        work_done_progress_params: Default::default(),
                        partial_result_params: Default::default(),
                    }, false);
                    let _ = inlay_hints::inlay_hints(snapshot, &InlayHintParams {
                        text_document: document,
                        range,
                        work_done_progress_params: Default::default(),
                    });
                    let _ = symbols::symbols(snapshot);
                    let _ = formatting::formatting(snapshot);
                    let _ = diagnostics::publish(snapshot);
                });
            }
        }
    }
}
