//! `textDocument/documentSymbol`: the outline, each location (its id and description, from
//! its first line to its last) and the tour with its stops.

use std::collections::HashMap;

use lsp_types::{DocumentSymbol, DocumentSymbolResponse, SymbolKind};

use super::{Answer, Snapshot};
use crate::lsp::lines::Entry;
use crate::present::TourPositions;
use crate::syntax::{self, Span};

pub fn symbols(snapshot: &Snapshot<'_, '_>) -> Answer<Option<DocumentSymbolResponse>> {
    let text = snapshot.text();
    let kb = &snapshot.analysed.checked.kb;
    // Each location's lines: from the first line's id to the end of its last line.
    let mut extents: HashMap<u32, (Span, Span)> = HashMap::new();
    for line in syntax::lines(text) {
        let Some(entry @ Entry::Location { id, .. }) = Entry::of(text, &line) else {
            continue;
        };
        if let Some(location) = entry.location_id(text) {
            let whole = Span::new(line.span.start as usize, line.content().end as usize);
            extents
                .entry(location)
                .and_modify(|(all, _)| *all = all.cover(whole))
                .or_insert((whole, id));
        }
    }
    let positions = TourPositions::new(kb);
    let range = |span| snapshot.positions.range(span);
    let mut symbols: Vec<DocumentSymbol> = kb
        .locations()
        .iter()
        .filter_map(|location| {
            let &(whole, id) = extents.get(&location.id)?;
            let description = location
                .description()
                .map_or("(no description)", |d| d.value);
            let stops = positions.of(location.id);
            Some(symbol(
                format!("{} {description}", location.id),
                match stops {
                    [] => "not on the tour".to_string(),
                    [first, ..] => format!("tour stop {first}"),
                },
                SymbolKind::OBJECT,
                (range(whole), range(id)),
                None,
            ))
        })
        .collect();
    if let Some(tour) = &kb.tour {
        let line = crate::lsp::lines::line_at(text, tour.span.start)
            .map_or(tour.span, |line| line.content());
        let stops: Vec<_> = tour
            .stops()
            .enumerate()
            .map(|(index, stop)| {
                let description = kb
                    .location(stop.value)
                    .and_then(|location| location.description())
                    .map_or("(no such location)", |d| d.value);
                symbol(
                    format!("{}. {} {description}", index + 1, stop.value),
                    String::new(),
                    SymbolKind::NUMBER,
                    (range(stop.span), range(stop.span)),
                    None,
                )
            })
            .collect();
        let count = stops.len();
        symbols.push(symbol(
            "tour".to_string(),
            format!("{count} stop{}", if count == 1 { "" } else { "s" }),
            SymbolKind::ARRAY,
            (range(line), range(tour.span)),
            Some(stops),
        ));
    }
    symbols.sort_by_key(|symbol| (symbol.range.start.line, symbol.range.start.character));
    Ok(Some(DocumentSymbolResponse::Nested(symbols)))
}

fn symbol(
    name: String,
    detail: String,
    kind: SymbolKind,
    (range, selection_range): (lsp_types::Range, lsp_types::Range),
    children: Option<Vec<DocumentSymbol>>,
) -> DocumentSymbol {
    #[allow(deprecated)] // `deprecated` must be written; `tags` replaces it.
    DocumentSymbol {
        name,
        detail: (!detail.is_empty()).then_some(detail),
        kind,
        tags: None,
        deprecated: None,
        range,
        selection_range,
        children,
    }
}
