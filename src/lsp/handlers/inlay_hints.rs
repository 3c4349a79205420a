//! `textDocument/inlayHint`: after each value the robot's reader loads otherwise than it is
//! written (a dropped sign, a cut message, a key it does not read, another tour), what it
//! loads.

use lsp_types::{InlayHint, InlayHintLabel, InlayHintParams, InlayHintTooltip};

use super::{Answer, Snapshot};
use crate::model::Dialect;
use crate::present::field::Field;
use crate::present::robot;
use crate::reader::view::{self, Held};
use crate::rules::excerpt;
use crate::syntax::Span;

pub fn inlay_hints(
    snapshot: &Snapshot<'_, '_>,
    params: &InlayHintParams,
) -> Answer<Option<Vec<InlayHint>>> {
    let visible = snapshot.positions.span(params.range);
    let in_view = |span: Span| visible.start <= span.end && span.start <= visible.end;
    let checked = &snapshot.analysed.checked;
    let loaded = snapshot.analysed.loaded();
    let text = snapshot.text().as_bytes();
    let dialect = checked.kb.dialect.unwrap_or(Dialect::Seed);
    let mut hints = Vec::new();
    for location in checked.kb.locations() {
        for field in Field::ALL {
            let Some((value, span)) = field.get(location).filter(|(_, span)| in_view(*span)) else {
                continue;
            };
            let key = field.key_at(location, dialect);
            let held = view::held(loaded, text, location.id, key);
            if robot::agrees(field, &value, &held) {
                continue;
            }
            let label = match held {
                Held::NotRead => format!("not read by reader {}", checked.reader),
                _ => format!("robot: {}", excerpt(&robot::shown(field, &held))),
            };
            let tooltip = format!(
                "Reader {} loads {}",
                checked.reader,
                robot::as_loaded(field, &value, &held, checked.reader)
            );
            hints.push(hint(snapshot, span, label, tooltip));
        }
    }
    let tour = checked.kb.tour.as_ref().filter(|tour| in_view(tour.span));
    if let Some((tour, other)) = tour.zip(robot::other_tour(&checked.kb, loaded)) {
        let stops = robot::tour_text(&other);
        let tooltip = format!(
            "Reader {} loads this tour: {stops} (the findings say why)",
            checked.reader
        );
        hints.push(hint(
            snapshot,
            tour.span,
            format!("robot: {}", excerpt(&stops)),
            tooltip,
        ));
    }
    Ok(Some(hints))
}

/// A hint after `span`.
fn hint(snapshot: &Snapshot<'_, '_>, span: Span, label: String, tooltip: String) -> InlayHint {
    InlayHint {
        position: snapshot.positions.position(span.end),
        label: InlayHintLabel::String(label),
        kind: None,
        text_edits: None,
        tooltip: Some(InlayHintTooltip::String(tooltip)),
        padding_left: Some(true),
        padding_right: None,
        data: None,
    }
}
