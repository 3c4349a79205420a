//! `textDocument/formatting`: the canonical layout of `ekb fmt`.

use lsp_types::TextEdit;

use super::{failed, line_edits, Answer, Snapshot};
use crate::canonical;

/// The edit that lays the document out canonically (none when it is already).
pub fn formatting(snapshot: &Snapshot<'_, '_>) -> Answer<Option<Vec<TextEdit>>> {
    let formatted = canonical::format(snapshot.text())
        .map_err(|reason| failed(format!("ekb cannot format this file: {reason}")))?;
    let edits = formatted.map(|formatted| line_edits(&snapshot.positions, &formatted));
    Ok(Some(edits.unwrap_or_default()))
}
