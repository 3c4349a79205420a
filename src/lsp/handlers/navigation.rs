//! Between a location's lines and the tour stops that name it: go to definition (a tour
//! stop's location), find references (every line and stop of a location), and rename a
//! location's id everywhere.

use std::collections::HashMap;

use lsp_types::{
    GotoDefinitionParams, GotoDefinitionResponse, Location, PrepareRenameResponse, ReferenceParams,
    RenameParams, TextDocumentPositionParams, TextEdit, WorkspaceEdit,
};

use super::{failed, Answer, Snapshot};
use crate::lsp::lines::{line_at, references as places, target_at, Target};
use crate::model::build::parse_id;
use crate::syntax::Span;

/// The location under the cursor: its id and the span of the id.
fn location_at(
    snapshot: &Snapshot<'_, '_>,
    at: &TextDocumentPositionParams,
) -> Option<(u32, Span)> {
    let offset = snapshot.positions.offset(at.position);
    match target_at(snapshot.text(), offset) {
        Target::Location { id, span } => Some((id, span)),
        _ => None,
    }
}

/// A tour stop (or a location's id) goes to the location's first line.
pub fn definition(
    snapshot: &Snapshot<'_, '_>,
    params: &GotoDefinitionParams,
) -> Answer<Option<GotoDefinitionResponse>> {
    let Some((id, _)) = location_at(snapshot, &params.text_document_position_params) else {
        return Ok(None);
    };
    let Some(location) = snapshot.analysed.checked.kb.location(id) else {
        return Ok(None);
    };
    let text = snapshot.text();
    let first_line =
        line_at(text, location.first_line.start).map_or(location.first_line, |line| line.content());
    Ok(Some(GotoDefinitionResponse::Scalar(Location::new(
        snapshot.uri.clone(),
        snapshot.positions.range(first_line),
    ))))
}

/// Every line and tour stop of the location under the cursor (without the id of its first
/// line unless the declaration is asked for).
pub fn references(
    snapshot: &Snapshot<'_, '_>,
    params: &ReferenceParams,
) -> Answer<Option<Vec<Location>>> {
    let Some((id, _)) = location_at(snapshot, &params.text_document_position) else {
        return Ok(None);
    };
    let declaration = snapshot
        .analysed
        .checked
        .kb
        .location(id)
        .map(|location| location.first_line);
    let with_declaration = params.context.include_declaration;
    let found = places(snapshot.text(), id)
        .into_iter()
        .filter(|span| {
            with_declaration
                || !declaration.is_some_and(|line| line.start <= span.start && span.end <= line.end)
        })
        .map(|span| Location::new(snapshot.uri.clone(), snapshot.positions.range(span)))
        .collect();
    Ok(Some(found))
}

pub fn prepare_rename(
    snapshot: &Snapshot<'_, '_>,
    params: &TextDocumentPositionParams,
) -> Answer<Option<PrepareRenameResponse>> {
    let Some((id, span)) = location_at(snapshot, params) else {
        return Err(failed("only a location's id can be renamed: put the cursor on one (on a location's line or in the tour)"));
    };
    Ok(Some(PrepareRenameResponse::RangeWithPlaceholder {
        range: snapshot.positions.range(span),
        placeholder: id.to_string(),
    }))
}

/// Gives the location under the cursor a new id, on all its lines and tour stops.
pub fn rename(snapshot: &Snapshot<'_, '_>, params: &RenameParams) -> Answer<Option<WorkspaceEdit>> {
    let Some((id, _)) = location_at(snapshot, &params.text_document_position) else {
        return Err(failed("only a location's id can be renamed: put the cursor on one (on a location's line or in the tour)"));
    };
    let new_name = params.new_name.trim();
    let Some(new_id) = parse_id(new_name) else {
        return Err(failed(format!(
            "`{new_name}` is not a location id: an id is a whole number from 1 to 2147483647"
        )));
    };
    if new_id != id && snapshot.analysed.checked.kb.location(new_id).is_some() {
        return Err(failed(format!(
            "location {new_id} exists already: renaming {id} to it would merge the two locations"
        )));
    }
    let edits: Vec<TextEdit> = places(snapshot.text(), id)
        .into_iter()
        .map(|span| TextEdit::new(snapshot.positions.range(span), new_id.to_string()))
        .collect();
    Ok(Some(WorkspaceEdit::new(HashMap::from([(
        snapshot.uri.clone(),
        edits,
    )]))))
}
