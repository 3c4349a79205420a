//! The semantic difference of two knowledge bases: what the robot would load differently.
//!
//! Layout, comments, line order, the spelling of numbers (`2.60` is `2.6`) and the blanks
//! between words do not count. A change of dialect is one difference, not a change to every
//! pose: poses are compared by value, whichever key holds them.

use std::cell::OnceCell;
use std::collections::HashMap;

use serde::Serialize;

use crate::model::{Dialect, KnowledgeBase, Location, Tour};
use crate::present::field::{Field, FieldValue};
use crate::present::Lines;

/// Everything that differs between an old and a new knowledge base.
#[derive(Debug, Serialize)]
#[serde(rename_all = "camelCase")]
pub struct Diff<'a> {
    pub dialect: Option<Change<Option<Dialect>>>,
    /// Locations only in the new file, in id order.
    pub added: Vec<LocationRef<'a>>,
    /// Locations only in the old file, in id order.
    pub removed: Vec<LocationRef<'a>>,
    /// Locations in both whose fields differ, in id order.
    pub changed: Vec<LocationChange<'a>>,
    pub tour: Option<TourChange>,
}

/// A value before and after.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Change<T> {
    pub old: T,
    pub new: T,
}

/// A location added or removed, with where it is in its file.
#[derive(Debug, Serialize)]
pub struct LocationRef<'a> {
    pub id: u32,
    pub description: Option<&'a str>,
    /// The first and last line that hold its values.
    pub lines: [u32; 2],
}

/// The fields of one location that differ.
#[derive(Debug, Serialize)]
pub struct LocationChange<'a> {
    pub id: u32,
    /// The new description (the old one if the new file has none).
    pub description: Option<&'a str>,
    pub fields: Vec<FieldChange<'a>>,
}

/// One field, before and after (`null` where the file has no valid value).
#[derive(Debug, Serialize)]
#[serde(rename_all = "camelCase")]
pub struct FieldChange<'a> {
    #[serde(serialize_with = "field_name")]
    pub field: Field,
    pub old: Option<FieldValue<'a>>,
    pub new: Option<FieldValue<'a>>,
    pub old_line: Option<u32>,
    pub new_line: Option<u32>,
}

fn field_name<S: serde::Serializer>(field: &Field, s: S) -> Result<S::Ok, S::Error> {
    s.serialize_str(field.name())
}

/// How the tour changed.
#[derive(Debug, Serialize)]
#[serde(rename_all = "camelCase")]
pub struct TourChange {
    /// `null` when that file has no tour.
    pub old: Option<TourSide>,
    pub new: Option<TourSide>,
    /// Stops only in the new tour (an id visited once more counts once more).
    pub added: Vec<u32>,
    /// Stops only in the old tour.
    pub removed: Vec<u32>,
    /// Whether the stops both tours share are visited in another order.
    pub reordered: bool,
}

/// One side of a tour change.
#[derive(Debug, Serialize)]
pub struct TourSide {
    pub stops: Vec<u32>,
    /// The declared number of stops, `n`, which the robot's reader trusts (SPEC §2.8).
    pub declared: Option<u64>,
    pub line: u32,
}

impl Diff<'_> {
    /// No difference at all.
    pub fn is_empty(&self) -> bool {
        self.dialect.is_none()
            && self.added.is_empty()
            && self.removed.is_empty()
            && self.changed.is_empty()
            && self.tour.is_none()
    }
}

/// One side of a diff: a file's text and the model it loads as.
#[derive(Clone, Copy)]
pub struct Side<'a> {
    pub text: &'a str,
    pub kb: &'a KnowledgeBase<'a>,
}

/// The line numbers of a text, indexed when a difference first needs one: two files that
/// load the same need none.
struct LazyLines<'a> {
    text: &'a str,
    lines: OnceCell<Lines<'a>>,
}

impl<'a> LazyLines<'a> {
    fn new(text: &'a str) -> LazyLines<'a> {
        LazyLines {
            text,
            lines: OnceCell::new(),
        }
    }

    fn get(&self) -> &Lines<'a> {
        self.lines.get_or_init(|| Lines::new(self.text))
    }
}

/// What changed from `old` to `new`.
pub fn diff<'a>(old: Side<'a>, new: Side<'a>) -> Diff<'a> {
    let old_lines = LazyLines::new(old.text);
    let new_lines = LazyLines::new(new.text);
    let location_ref = |location: &Location<'a>, lines: &LazyLines| {
        let (first, last) = lines.get().range(location);
        LocationRef {
            id: location.id,
            description: location.description().map(|d| d.value),
            lines: [first, last],
        }
    };
    let removed = old
        .kb
        .locations()
        .iter()
        .filter(|l| new.kb.location(l.id).is_none())
        .map(|l| location_ref(l, &old_lines))
        .collect();
    let added = new
        .kb
        .locations()
        .iter()
        .filter(|l| old.kb.location(l.id).is_none())
        .map(|l| location_ref(l, &new_lines))
        .collect();
    let changed = new
        .kb
        .locations()
        .iter()
        .filter_map(|after| {
            let before = old.kb.location(after.id)?;
            let fields: Vec<FieldChange> = Field::ALL
                .into_iter()
                .filter_map(|field| {
                    let old = field.get(before);
                    let new = field.get(after);
                    let same = old.as_ref().map(|(v, _)| v) == new.as_ref().map(|(v, _)| v);
                    (!same).then(|| FieldChange {
                        field,
                        old_line: old.as_ref().map(|(_, span)| old_lines.get().of(*span)),
                        new_line: new.as_ref().map(|(_, span)| new_lines.get().of(*span)),
                        old: old.map(|(v, _)| v),
                        new: new.map(|(v, _)| v),
                    })
                })
                .collect();
            (!fields.is_empty()).then(|| LocationChange {
                id: after.id,
                description: after
                    .description()
                    .or(before.description())
                    .map(|d| d.value),
                fields,
            })
        })
        .collect();
    let dialect = (old.kb.dialect != new.kb.dialect).then_some(Change {
        old: old.kb.dialect,
        new: new.kb.dialect,
    });
    let mut tour = tour_change(
        old.kb.tour.as_ref().map(side),
        new.kb.tour.as_ref().map(side),
    );
    if let Some(tour) = &mut tour {
        for (side, tour, lines) in [
            (&mut tour.old, &old.kb.tour, &old_lines),
            (&mut tour.new, &new.kb.tour, &new_lines),
        ] {
            if let (Some(side), Some(tour)) = (side, tour) {
                side.line = lines.get().of(tour.span);
            }
        }
    }
    Diff {
        dialect,
        added,
        removed,
        changed,
        tour,
    }
}

/// A tour's side of a change, its line still to be found (0).
fn side(tour: &Tour) -> TourSide {
    TourSide {
        stops: tour.stops.iter().map(|stop| stop.value).collect(),
        declared: tour.declared.map(|n| n.value),
        line: 0,
    }
}

fn tour_change(old: Option<TourSide>, new: Option<TourSide>) -> Option<TourChange> {
    let stops = |side: &Option<TourSide>| side.as_ref().map_or(Vec::new(), |s| s.stops.clone());
    let declared = |side: &Option<TourSide>| side.as_ref().map(|s| s.declared);
    let (old_stops, new_stops) = (stops(&old), stops(&new));
    if old.is_some() == new.is_some() && old_stops == new_stops && declared(&old) == declared(&new)
    {
        return None;
    }
    let removed = without(&old_stops, &new_stops);
    let added = without(&new_stops, &old_stops);
    let reordered = without(&old_stops, &removed) != without(&new_stops, &added);
    Some(TourChange {
        old,
        new,
        added,
        removed,
        reordered,
    })
}

/// The stops of `a` that `b` lacks, counting repeats: `[1, 2, 2]` without `[2]` is `[2]`.
fn without(a: &[u32], b: &[u32]) -> Vec<u32> {
    let mut available: HashMap<u32, usize> = HashMap::new();
    for &id in b {
        *available.entry(id).or_default() += 1;
    }
    a.iter()
        .filter(|&&id| match available.get_mut(&id) {
            Some(n) if *n > 0 => {
                *n -= 1;
                false
            }
            _ => true,
        })
        .copied()
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn multiset_difference() {
        assert_eq!(without(&[1, 2, 2, 3], &[2, 3]), [1, 2]);
        assert_eq!(
            without(&[1, 4, 3, 2, 5], &[1, 3, 4, 2, 5]),
            Vec::<u32>::new()
        );
    }

    #[test]
    fn tour_changes() {
        let side = |stops: &[u32]| {
            Some(TourSide {
                stops: stops.to_vec(),
                declared: Some(stops.len() as u64),
                line: 1,
            })
        };
        assert!(tour_change(side(&[1, 2]), side(&[1, 2])).is_none());
        let change = tour_change(side(&[1, 4, 3, 2, 5]), side(&[1, 3, 4, 2, 6])).unwrap();
        assert_eq!(change.added, [6]);
        assert_eq!(change.removed, [5]);
        assert!(change.reordered);
        let change = tour_change(side(&[1, 2]), side(&[1, 2, 3])).unwrap();
        assert!(!change.reordered);
        assert!(tour_change(None, side(&[1])).unwrap().old.is_none());
    }
}
