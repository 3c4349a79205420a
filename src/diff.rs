//! The semantic difference of two knowledge bases: what the robot would load differently.
//!
//! Layout, comments, line order, the spelling of numbers (`2.60` is `2.6`) and the blanks
//! between words do not count. A change of dialect is one difference, not a change to every
//! pose: poses are compared by value, whichever key holds them.

use serde::Serialize;
use std::cell::OnceCell;

use crate::model::{Dialect, IdMap, KnowledgeBase, Location, Tour};
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
    pub tour: Option<TourChange<'a>>,
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
pub struct TourChange<'a> {
    /// `null` when that file has no tour.
    pub old: Option<TourSide<'a>>,
    pub new: Option<TourSide<'a>>,
    /// Stops only in the new tour (an id visited once more counts once more).
    pub added: Vec<u32>,
    /// Stops only in the old tour.
    pub removed: Vec<u32>,
    /// Whether the stops both tours share are visited in another order.
    pub reordered: bool,
}

/// One side of a tour change.
#[derive(Debug, Serialize)]
pub struct TourSide<'a> {
    /// Its stops, read from the tour's line when they are written out, not held: a tour may
    /// have a million.
    #[serde(rename = "stops", serialize_with = "stop_ids")]
    pub tour: &'a Tour<'a>,
    /// The declared number of stops, `n`, which the robot's reader trusts (SPEC §2.8).
    pub declared: Option<u64>,
    pub line: u32,
}

impl TourSide<'_> {
    /// The ids of the stops, in order.
    pub fn stops(&self) -> impl Iterator<Item = u32> + '_ {
        self.tour.stops().map(|stop| stop.value)
    }
}

fn stop_ids<S: serde::Serializer>(tour: &&Tour<'_>, s: S) -> Result<S::Ok, S::Error> {
    s.collect_seq(tour.stops().map(|stop| stop.value))
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
    lines: OnceCell<Lines>,
}

impl<'a> LazyLines<'a> {
    fn new(text: &'a str) -> LazyLines<'a> {
        LazyLines {
            text,
            lines: OnceCell::new(),
        }
    }

    fn get(&self) -> &Lines {
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
    let mut tour = tour_change(old.kb.tour.as_ref(), new.kb.tour.as_ref());
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

/// How the tour changed, if it did; each side's line still to be found (0). The stops are
/// compared as they are read from the lines, and counted by id, so that two tours of a
/// million stops cost no list of them, unless they differ (then the stops added or removed).
fn tour_change<'a>(old: Option<&'a Tour<'a>>, new: Option<&'a Tour<'a>>) -> Option<TourChange<'a>> {
    let stops = |tour: Option<&'a Tour<'a>>| {
        tour.into_iter()
            .flat_map(|tour| tour.stops().map(|stop| stop.value))
    };
    let declared = |tour: Option<&Tour>| tour.map(|tour| tour.declared.map(|n| n.value));
    if old.is_some() == new.is_some() && stops(old).eq(stops(new)) && declared(old) == declared(new)
    {
        return None;
    }
    let removed: Vec<u32> = without(stops(old), stops(new)).collect();
    let added: Vec<u32> = without(stops(new), stops(old)).collect();
    let reordered = !without(stops(old), removed.iter().copied())
        .eq(without(stops(new), added.iter().copied()));
    let side = |tour: &'a Tour<'a>| TourSide {
        tour,
        declared: tour.declared.map(|n| n.value),
        line: 0,
    };
    Some(TourChange {
        old: old.map(side),
        new: new.map(side),
        added,
        removed,
        reordered,
    })
}

/// The stops of `a` that `b` lacks, counting repeats: `[1, 2, 2]` without `[2]` is `[2]`.
fn without(
    a: impl Iterator<Item = u32>,
    b: impl Iterator<Item = u32>,
) -> impl Iterator<Item = u32> {
    let mut available: IdMap<usize> = IdMap::default();
    for id in b {
        *available.entry(id).or_default() += 1;
    }
    a.filter(move |id| match available.get_mut(id) {
        Some(n) if *n > 0 => {
            *n -= 1;
            false
        }
        _ => true,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::syntax::Span;

    #[test]
    fn multiset_difference() {
        let without = |a: &[u32], b: &[u32]| -> Vec<u32> {
            super::without(a.iter().copied(), b.iter().copied()).collect()
        };
        assert_eq!(without(&[1, 2, 2, 3], &[2, 3]), [1, 2]);
        assert_eq!(without(&[1, 4, 3, 2, 5], &[1, 3, 4, 2, 5]), [0u32; 0]);
    }

    #[test]
    fn tour_changes() {
        // The arguments of a `tourSpecification` line: `n`, then the stops.
        let tour = |text: &'static str| {
            let n = text.split(' ').next().unwrap();
            let declared = crate::model::Value {
                value: n.parse().unwrap(),
                span: Span::new(0, n.len()),
            };
            Tour::new(Span::new(0, text.len()), text, Some(declared))
        };
        let (two, two_again) = (tour("2 1 2"), tour("2 1 2"));
        assert!(tour_change(Some(&two), Some(&two_again)).is_none());
        let (old, new) = (tour("5 1 4 3 2 5"), tour("5 1 3 4 2 6"));
        let change = tour_change(Some(&old), Some(&new)).unwrap();
        assert_eq!(change.added, [6]);
        assert_eq!(change.removed, [5]);
        assert!(change.reordered);
        let three = tour("3 1 2 3");
        let change = tour_change(Some(&two), Some(&three)).unwrap();
        assert!(!change.reordered);
        let miscounted = tour("3 1 2");
        assert!(tour_change(Some(&two), Some(&miscounted)).is_some());
        assert!(tour_change(None, Some(&two)).unwrap().old.is_none());
    }
}
