//! The lines of a document as the editor features see them: what is under the cursor (a
//! key, a location's id, a tour stop, a value), and where each location's lines and tour
//! stops are. Built on the lossless syntax layer, so lines the model does not take (a key
//! in the wrong case, a tour that a later one overrides) are still found and renamed.

use crate::model::build::{parse_id, tour_items};
use crate::model::Key;
use crate::syntax::{self, first_token, Body, Line, Span};

/// What a line is, split into the parts the features point at.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Entry {
    /// A location's line: key, id (as written, perhaps not a valid one) and value.
    Location { key: Span, id: Span, value: Span },
    /// A `tourSpecification` line (in any case); its items are [`tour_items`].
    Tour { key: Span, items: Span },
}

impl Entry {
    /// The entry of a keyed line, `None` for a blank or comment line.
    pub fn of(text: &str, line: &Line) -> Option<Entry> {
        let Body::Entry { key, args } = line.body else {
            return None;
        };
        if key
            .text(text)
            .eq_ignore_ascii_case(Key::TourSpecification.name())
        {
            return Some(Entry::Tour { key, items: args });
        }
        let (id, value) = first_token(text, args);
        Some(Entry::Location { key, id, value })
    }

    pub fn key(&self) -> Span {
        match *self {
            Entry::Location { key, .. } | Entry::Tour { key, .. } => key,
        }
    }

    /// The location id of a location's line, if it is a valid one.
    pub fn location_id(&self, text: &str) -> Option<u32> {
        match *self {
            Entry::Location { id, .. } => parse_id(id.text(text)),
            Entry::Tour { .. } => None,
        }
    }
}

/// The items of a tour line: the count, then each stop.
pub fn tour_tokens(text: &str, items: Span) -> impl Iterator<Item = (Span, &str)> {
    tour_items(items.text(text), items.start as usize)
}

/// The syntax line that holds byte `offset`.
pub fn line_at(text: &str, offset: u32) -> Option<Line> {
    let offset = (offset as usize).min(text.len());
    let start = text[..offset].rfind('\n').map_or(0, |newline| newline + 1);
    syntax::lines_from(text, start).next().or_else(|| {
        // The empty last line of a text that ends with a newline.
        (start == text.len()).then(|| Line {
            number: 0,
            span: Span::empty_at(start),
            indent: Span::empty_at(start),
            body: Body::Blank,
            trailing: Span::empty_at(start),
            ending: syntax::LineEnding::None,
        })
    })
}

/// What the cursor is on.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Target {
    /// A line's key.
    Key(Span),
    /// The id of a location's line, or a stop of a tour: a reference to location `id`.
    Location { id: u32, span: Span },
    /// Something else on a keyed line (a value, a tour's count, an invalid id).
    Other,
}

/// What is at byte `offset` (a cursor just after a word is on it, as editors mean it).
pub fn target_at(text: &str, offset: u32) -> Target {
    let Some(entry) = line_at(text, offset).and_then(|line| Entry::of(text, &line)) else {
        return Target::Other;
    };
    let touches = |span: Span| span.start <= offset && offset <= span.end && !span.is_empty();
    if touches(entry.key()) {
        return Target::Key(entry.key());
    }
    let location = |span: Span, token: &str| match parse_id(token) {
        Some(id) => Target::Location { id, span },
        None => Target::Other,
    };
    match entry {
        Entry::Location { id, .. } if touches(id) => location(id, id.text(text)),
        Entry::Tour { items, .. } => tour_tokens(text, items)
            .skip(1)
            .find(|&(span, _)| touches(span))
            .map_or(Target::Other, |(span, token)| location(span, token)),
        _ => Target::Other,
    }
}

/// Every place that names location `id`: the id of each of its lines, and each tour stop
/// (of every tour line, the overridden ones too), in file order.
pub fn references(text: &str, id: u32) -> Vec<Span> {
    let mut found = Vec::new();
    for line in syntax::lines(text) {
        match Entry::of(text, &line) {
            Some(entry @ Entry::Location { id: span, .. })
                if entry.location_id(text) == Some(id) =>
            {
                found.push(span)
            }
            Some(Entry::Tour { items, .. }) => found.extend(
                tour_tokens(text, items)
                    .skip(1)
                    .filter(|&(_, token)| parse_id(token) == Some(id))
                    .map(|(span, _)| span),
            ),
            _ => {}
        }
    }
    found
}

#[cfg(test)]
mod tests {
    use super::*;

    const TEXT: &str = "robotLocationDescription 4 Roomba\n\
                        # a comment 4\n\
                        postGestureMessageenglish +4 Hi\n\
                        tourSpecification 2 4, 5\n\
                        TourSpecification 1 4\n";

    fn at(needle: &str, nth: usize) -> u32 {
        TEXT.match_indices(needle).nth(nth).unwrap().0 as u32
    }

    #[test]
    fn what_the_cursor_is_on() {
        assert_eq!(target_at(TEXT, 3), Target::Key(Span::new(0, 24)));
        let id = at(" 4 ", 0) + 1;
        assert_eq!(
            target_at(TEXT, id),
            Target::Location {
                id: 4,
                span: Span::new(id as usize, id as usize + 1)
            }
        );
        // Just after the id is still on it.
        assert!(matches!(
            target_at(TEXT, id + 1),
            Target::Location { id: 4, .. }
        ));
        assert_eq!(target_at(TEXT, at("Roomba", 0) + 2), Target::Other);
        assert_eq!(target_at(TEXT, at("comment", 0)), Target::Other);
        // A tour's count is not a location; its stops are, commas or not.
        assert_eq!(target_at(TEXT, at("2 4,", 0)), Target::Other);
        assert!(matches!(
            target_at(TEXT, at("5\n", 0)),
            Target::Location { id: 5, .. }
        ));
        assert_eq!(target_at(TEXT, TEXT.len() as u32), Target::Other);
    }

    #[test]
    fn every_line_and_stop_of_a_location() {
        let found: Vec<&str> = references(TEXT, 4).iter().map(|s| s.text(TEXT)).collect();
        assert_eq!(found, ["4", "+4", "4", "4"]);
        assert_eq!(references(TEXT, 5).len(), 1);
        assert!(references(TEXT, 6).is_empty());
    }
}
