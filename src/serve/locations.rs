//! Locations added and removed by the page: whole lines, every other byte kept.

use std::collections::HashSet;

use crate::model::build::parse_id;
use crate::model::Key;
use crate::syntax::{self, Body};

/// The ids that have a line of a location's key (in any case) in `text`.
fn ids_with_lines(text: &str) -> HashSet<u32> {
    syntax::lines(text)
        .filter_map(|line| {
            let Body::Entry { key, args } = line.body else {
                return None;
            };
            Key::from_name_ignoring_case(key.text(text))
                .filter(|key| *key != Key::TourSpecification)?;
            parse_id(syntax::first_token(text, args).0.text(text))
        })
        .collect()
}

/// The column of the ids where the file pads its keys to align them (as `ekb fmt` writes),
/// from its first padded line: the new lines are aligned with it (and the lines `edit` adds
/// after them align with those).
fn id_column(text: &str) -> Option<usize> {
    syntax::lines(text).find_map(|line| {
        let Body::Entry { key, args } = line.body else {
            return None;
        };
        let gap = &text[key.end as usize..args.start as usize];
        (gap.len() >= 2 && gap.bytes().all(|byte| byte == b' '))
            .then(|| key.text(text).chars().count() + gap.len())
    })
}

/// `text` with a first line, `robotLocationDescription ID DESCRIPTION`, for each of `added`
/// that has no line yet (`description` gives each its text), so that the page's edits have a
/// location to go to: before the tour line, else at the end.
pub fn add(text: &str, added: &[u32], description: impl Fn(u32) -> String) -> String {
    let existing = ids_with_lines(text);
    let spaces = id_column(text).map_or(1, |column| {
        column
            .saturating_sub(Key::RobotLocationDescription.name().len())
            .max(1)
    });
    let ending = if text.contains("\r\n") { "\r\n" } else { "\n" };
    let mut new_lines = String::new();
    let mut seen = HashSet::new();
    for &id in added {
        if existing.contains(&id) || !seen.insert(id) {
            continue;
        }
        let key = Key::RobotLocationDescription.name();
        let pad = " ".repeat(spaces);
        new_lines.push_str(&format!("{key}{pad}{id} {}{ending}", description(id)));
    }
    if new_lines.is_empty() {
        return text.to_string();
    }
    let tour = syntax::lines(text)
        .filter(|line| match line.body {
            Body::Entry { key, .. } => {
                Key::from_name(key.text(text)) == Some(Key::TourSpecification)
            }
            _ => false,
        })
        .last();
    match tour {
        Some(line) => {
            let at = line.span.start as usize;
            format!("{}{new_lines}{}", &text[..at], &text[at..])
        }
        None => {
            let gap = if text.is_empty() || text.ends_with('\n') {
                ""
            } else {
                ending
            };
            format!("{text}{gap}{new_lines}")
        }
    }
}

/// `text` without any line of the locations `removed` (every key of a location, in any case).
pub fn remove(text: &str, removed: &[u32]) -> String {
    if removed.is_empty() {
        return text.to_string();
    }
    let removed: HashSet<u32> = removed.iter().copied().collect();
    let mut kept = String::with_capacity(text.len());
    for line in syntax::lines(text) {
        let drop = match line.body {
            Body::Entry { key, args } => {
                Key::from_name_ignoring_case(key.text(text))
                    .is_some_and(|key| key != Key::TourSpecification)
                    && parse_id(syntax::first_token(text, args).0.text(text))
                        .is_some_and(|id| removed.contains(&id))
            }
            _ => false,
        };
        if !drop {
            kept.push_str(line.span.text(text));
        }
    }
    kept
}

#[cfg(test)]
mod tests {
    use super::*;

    const TEXT: &str = "robotLocationDescription 1 Hall\n\
                        gestureTarget            1 0 0 0\n\
                        # the lab\n\
                        robotLocationDescription 2 Lab\n\
                        robotlocation 2 1 1 1\n\
                        tourSpecification 2 1 2\n";

    #[test]
    fn an_added_location_gets_its_first_line_before_the_tour() {
        let added = add(TEXT, &[3, 1, 3], |id| format!("New location {id}"));
        assert_eq!(
            added,
            TEXT.replace(
                "tourSpecification",
                "robotLocationDescription 3 New location 3\ntourSpecification"
            )
        );
        let padded = "robotLocationDescription      1 Hall\ntourSpecification 1 1\n";
        assert_eq!(
            add(padded, &[7], |_| "X".into()),
            "robotLocationDescription      1 Hall\nrobotLocationDescription      7 X\ntourSpecification 1 1\n"
        );
        assert_eq!(
            add("robotLocationDescription 1 Hall", &[2], |_| "X".into()),
            "robotLocationDescription 1 Hall\nrobotLocationDescription 2 X\n"
        );
    }

    #[test]
    fn a_removed_location_loses_every_line_and_nothing_else() {
        assert_eq!(
            remove(TEXT, &[2]),
            "robotLocationDescription 1 Hall\n\
             gestureTarget            1 0 0 0\n\
             # the lab\n\
             tourSpecification 2 1 2\n"
        );
        assert_eq!(remove(TEXT, &[]), TEXT);
    }
}
