//! The values of a file as the page edits them, the version of a file, and the merge of the
//! page's edits with a file changed on disk since the page loaded it (SPEC §14, "Saving").

use std::collections::HashMap;
use std::hash::{DefaultHasher, Hasher};

use serde::Serialize;

use crate::edit::ValueEdit;
use crate::model::build::parse_id;
use crate::model::Key;
use crate::syntax::{self, Body};

/// One value of the file: the text after the id on the line the robot reads for this key
/// of this location (the last one of that key, exactly spelled).
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct Field {
    pub id: u32,
    pub key: &'static str,
    pub value: String,
    /// 1-based.
    pub line: u32,
}

/// What the page shows of a file: its values, and the ids of the tour in order.
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Default)]
pub struct Fields {
    pub fields: Vec<Field>,
    pub tour: Vec<u32>,
}

/// The values of `text`, in file order, and its tour.
pub fn fields(text: &str) -> Fields {
    let mut at: HashMap<(u32, Key), usize> = HashMap::new();
    let mut found = Fields::default();
    for (index, line) in syntax::lines(text).enumerate() {
        let Body::Entry { key, args } = line.body else {
            continue;
        };
        let Some(key) = Key::from_name(key.text(text)) else {
            continue;
        };
        let number = u32::try_from(index + 1).unwrap_or(u32::MAX);
        if key == Key::TourSpecification {
            found.tour = syntax::tokens(args.text(text), args.start as usize)
                .skip(1)
                .filter_map(|(_, token)| parse_id(token))
                .collect();
            continue;
        }
        let (id, value) = syntax::first_token(text, args);
        let Some(id) = parse_id(id.text(text)) else {
            continue;
        };
        let field = Field {
            id,
            key: key.name(),
            value: value.text(text).to_string(),
            line: number,
        };
        match at.get(&(id, key)) {
            Some(&index) => found.fields[index] = field,
            None => {
                at.insert((id, key), found.fields.len());
                found.fields.push(field);
            }
        }
    }
    found
}

/// `text` with its tour made `stops`: the arguments of its `tourSpecification` line (the
/// last one, which the robot reads) rewritten as `N id…`, every other byte as it was; a file
/// with no tour line gets one at its end.
pub fn set_tour(text: &str, stops: &[u32]) -> String {
    let mut args = stops.len().to_string();
    for stop in stops {
        args.push(' ');
        args.push_str(&stop.to_string());
    }
    let mut last = None;
    for line in syntax::lines(text) {
        if let Body::Entry { key, args } = line.body {
            if Key::from_name(key.text(text)) == Some(Key::TourSpecification) {
                last = Some(args);
            }
        }
    }
    match last {
        Some(span) if !span.is_empty() => {
            let (start, end) = (span.start as usize, span.end as usize);
            format!("{}{args}{}", &text[..start], &text[end..])
        }
        _ => {
            let ending = if text.contains("\r\n") { "\r\n" } else { "\n" };
            let gap = if text.is_empty() || text.ends_with('\n') {
                ""
            } else {
                ending
            };
            format!("{text}{gap}tourSpecification {args}{ending}")
        }
    }
}

/// The id of a conflict over the tour, which belongs to no location (ids start at 1).
pub const TOUR_ID: u32 = 0;

/// The page's tour `mine` over `disk`, the file on disk, given `base`, the tour the page
/// loaded (`None`: unknown): the tour to write, or a conflict when both changed it.
pub fn merge_tour(
    base: Option<&[u32]>,
    disk: &[u32],
    mine: &[u32],
) -> Result<Option<Vec<u32>>, Conflict> {
    let line = |stops: &[u32]| {
        let ids: Vec<String> = stops.iter().map(u32::to_string).collect();
        ids.join(" ")
    };
    if disk == mine {
        return Ok(None);
    }
    if base == Some(disk) {
        return Ok(Some(mine.to_vec()));
    }
    Err(Conflict {
        id: TOUR_ID,
        key: Key::TourSpecification.name(),
        mine: line(mine),
        theirs: Some(line(disk)),
    })
}

/// The values of `text` by location and key.
fn values(text: &str) -> HashMap<(u32, &'static str), String> {
    fields(text)
        .fields
        .into_iter()
        .map(|field| ((field.id, field.key), field.value))
        .collect()
}

/// The version of a file's bytes: a hash, in hex (the same bytes, the same version, for as
/// long as the server runs).
pub fn version(bytes: &[u8]) -> String {
    let mut hasher = DefaultHasher::new();
    hasher.write(bytes);
    format!("{:016x}-{}", hasher.finish(), bytes.len())
}

/// A value changed on both sides to different values: nothing is written.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct Conflict {
    pub id: u32,
    pub key: &'static str,
    /// The page's value.
    pub mine: String,
    /// The value on disk now; `null` when the disk has no line for it any more.
    pub theirs: Option<String>,
}

/// The edits to make on `disk`, the file as it is now, for the page's `edits` of `base`,
/// the file as the page loaded it (`None`: a version the server no longer knows, so every
/// value that differs on disk from the page's is a conflict). An edit of a value that the
/// disk still has as in `base` is made; one that the disk already has is dropped; one whose
/// value the disk changed otherwise is a conflict.
pub fn merge(
    base: Option<&str>,
    disk: &str,
    edits: &[ValueEdit],
) -> Result<Vec<ValueEdit>, Vec<Conflict>> {
    let base = base.map(values);
    let disk = values(disk);
    let mut kept = Vec::new();
    let mut conflicts = Vec::new();
    for edit in edits {
        let slot = (edit.id, edit.key.name());
        let theirs = disk.get(&slot);
        if theirs == Some(&edit.value) {
            continue;
        }
        let unchanged_on_disk = base.as_ref().is_some_and(|base| base.get(&slot) == theirs);
        if unchanged_on_disk {
            kept.push(edit.clone());
        } else {
            conflicts.push(Conflict {
                id: edit.id,
                key: edit.key.name(),
                mine: edit.value.clone(),
                theirs: theirs.cloned(),
            });
        }
    }
    match conflicts.is_empty() {
        true => Ok(kept),
        false => Err(conflicts),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const BASE: &str = "robotLocationDescription 1 Hall\n\
                        robotLocation            1 1.0 2.0 90\n\
                        robotLocationDescription 2 Lab\n\
                        tourSpecification 2 2 1\n";

    fn edit(id: u32, key: Key, value: &str) -> ValueEdit {
        ValueEdit {
            id,
            key,
            value: value.to_string(),
        }
    }

    #[test]
    fn fields_are_the_values_the_robot_reads() {
        let text = format!("{BASE}robotLocationDescription 2 Lab two\nrobotlocation 1 9 9 9\n");
        let found = fields(&text);
        assert_eq!(found.tour, vec![2, 1]);
        let got: Vec<(u32, &str, &str, u32)> = found
            .fields
            .iter()
            .map(|f| (f.id, f.key, f.value.as_str(), f.line))
            .collect();
        assert_eq!(
            got,
            vec![
                (1, "robotLocationDescription", "Hall", 1),
                (1, "robotLocation", "1.0 2.0 90", 2),
                (2, "robotLocationDescription", "Lab two", 5),
            ]
        );
    }

    #[test]
    fn the_tour_line_is_rewritten_in_place() {
        let text =
            "# the tour\ntourSpecification   3 1 2 3 \r\nrobotLocationDescription 1 Hall\r\n";
        assert_eq!(
            set_tour(text, &[3, 1]),
            "# the tour\ntourSpecification   2 3 1 \r\nrobotLocationDescription 1 Hall\r\n"
        );
        assert_eq!(
            set_tour("robotLocationDescription 1 Hall", &[1]),
            "robotLocationDescription 1 Hall\ntourSpecification 1 1\n"
        );
        assert_eq!(fields(&set_tour(BASE, &[1, 2, 1])).tour, vec![1, 2, 1]);
    }

    #[test]
    fn a_tour_changed_on_both_sides_is_a_conflict() {
        assert_eq!(
            merge_tour(Some(&[1, 2]), &[1, 2], &[2, 1]),
            Ok(Some(vec![2, 1]))
        );
        assert_eq!(merge_tour(Some(&[1, 2]), &[2, 1], &[2, 1]), Ok(None));
        let conflict = merge_tour(Some(&[1, 2]), &[1], &[2, 1]).unwrap_err();
        assert_eq!(
            (
                conflict.id,
                conflict.mine.as_str(),
                conflict.theirs.as_deref()
            ),
            (TOUR_ID, "2 1", Some("1"))
        );
    }

    #[test]
    fn the_version_follows_the_bytes() {
        assert_eq!(version(b"a"), version(b"a"));
        assert_ne!(version(b"a"), version(b"b"));
    }

    #[test]
    fn values_changed_on_one_side_only_are_merged() {
        let disk = BASE.replace("Lab", "Laboratory");
        let mine = [edit(1, Key::RobotLocationDescription, "Entrance hall")];
        assert_eq!(merge(Some(BASE), &disk, &mine), Ok(mine.to_vec()));
        // The same change on both sides is no change to make.
        let mine = [edit(2, Key::RobotLocationDescription, "Laboratory")];
        assert_eq!(merge(Some(BASE), &disk, &mine), Ok(vec![]));
    }

    #[test]
    fn a_value_changed_on_both_sides_is_a_conflict() {
        let disk = BASE.replace("Hall", "Foyer");
        let mine = [
            edit(1, Key::RobotLocationDescription, "Entrance hall"),
            edit(2, Key::RobotLocationDescription, "Workshop"),
        ];
        assert_eq!(
            merge(Some(BASE), &disk, &mine),
            Err(vec![Conflict {
                id: 1,
                key: "robotLocationDescription",
                mine: "Entrance hall".to_string(),
                theirs: Some("Foyer".to_string()),
            }])
        );
        // A base the server does not know: every value that differs on disk is a conflict.
        let unknown = merge(None, BASE, &mine[1..]).unwrap_err();
        assert_eq!(unknown[0].theirs.as_deref(), Some("Lab"));
    }
}
