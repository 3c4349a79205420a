//! gettext PO (SPEC §8), the interchange with translators' tools (Poedit, Weblate, Pootle,
//! Lokalize): one entry per message, `msgctxt "location 3 preGestureMessage"`, `msgid` the
//! English text, `msgstr` the translation.
//!
//! [`write`] makes a PO file of one language, or the template (POT) of all; [`parse`] reads
//! one back for `ekb import --po`. Both are this module's own: a translator's file is
//! untrusted input, every entry must be told by its line, and the header must hold what
//! `msgfmt -c` asks for (the `polib` crate's writer leaves out empty fields, and its reader
//! panics on some malformed lines). The tests check the output with `polib` and `msgfmt`.

use std::fmt::Write as _;
use std::time::SystemTime;

use super::{Catalog, State, Unit};
use crate::model::{Language, Phase};
use crate::present::language::iso_code;

/// `location 3 preGestureMessage`: which message of the knowledge base an entry is.
pub fn context(location: u32, phase: Phase) -> String {
    format!("location {location} {}", phase_key(phase))
}

/// The key of a phase's messages without the language: `preGestureMessage`.
fn phase_key(phase: Phase) -> &'static str {
    match phase {
        Phase::Pre => "preGestureMessage",
        Phase::Post => "postGestureMessage",
    }
}

/// The location and phase a `msgctxt` names, if it is one [`context`] writes.
pub fn parse_context(msgctxt: &str) -> Option<(u32, Phase)> {
    let rest = msgctxt.strip_prefix("location ")?;
    let (id, key) = rest.split_once(' ')?;
    let phase = Phase::ALL
        .into_iter()
        .find(|&phase| phase_key(phase) == key)?;
    Some((crate::model::build::parse_id(id)?, phase))
}

/// The PO file of `language`'s translations of `catalog` (`None`: the template, POT, with
/// every `msgstr` empty), its references naming `file`, last revised at `revised` (the
/// knowledge base's modification time). A message with no English to translate from has no
/// entry. A translation that is the English text is marked fuzzy, to be reviewed (and is
/// not imported back while it is).
pub fn write(
    catalog: &Catalog<'_>,
    file: &str,
    language: Option<Language>,
    revised: SystemTime,
) -> String {
    let mut out = String::new();
    let header = [
        ("Project-Id-Version", file_name(file)),
        ("PO-Revision-Date", &revision_date(revised)),
        ("Last-Translator", ""),
        ("Language-Team", language.map_or("", Language::name)),
        ("Language", language.map_or("", iso_code)),
        ("MIME-Version", "1.0"),
        ("Content-Type", "text/plain; charset=UTF-8"),
        ("Content-Transfer-Encoding", "8bit"),
        ("Plural-Forms", "nplurals=2; plural=(n != 1);"),
    ];
    out.push_str("msgid \"\"\nmsgstr \"\"\n");
    for (field, value) in header {
        let _ = writeln!(out, "\"{field}: {}\\n\"", escape(value));
    }
    for unit in &catalog.units {
        let Some(source) = unit.source else {
            continue;
        };
        let (translation, fuzzy) = match language.map(|l| &unit.messages[l.index()]) {
            Some(message) if message.state == State::Translated => (message.value, false),
            Some(message) if message.state == State::SameAsSource => (message.value, true),
            _ => (None, false),
        };
        out.push('\n');
        for line in said(unit).lines() {
            let _ = writeln!(out, "#. {}", one_line(line));
        }
        let _ = writeln!(out, "#: {}:{}", reference(file), source.line);
        if fuzzy {
            out.push_str("#, fuzzy\n");
        }
        let _ = writeln!(out, "msgctxt \"{}\"", context(unit.location, unit.phase));
        let _ = writeln!(out, "msgid \"{}\"", escape(source.text.value));
        let _ = writeln!(
            out,
            "msgstr \"{}\"",
            escape(translation.map_or("", |t| t.value))
        );
    }
    out
}

/// `text` as a PO string's contents: backslash, quote and control characters escaped as C
/// writes them.
pub fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '\\' => out.push_str("\\\\"),
            '"' => out.push_str("\\\""),
            '\n' => out.push_str("\\n"),
            '\t' => out.push_str("\\t"),
            '\r' => out.push_str("\\r"),
            c if c.is_control() && (c as u32) < 0x80 => {
                let _ = write!(out, "\\{:03o}", c as u32);
            }
            c => out.push(c),
        }
    }
    out
}

/// A file name as a `#:` reference writes it: one with a space between the isolating marks
/// U+2068 and U+2069, as gettext does (a reference ends at a space).
fn reference(file: &str) -> String {
    let file = one_line(file);
    match file.contains(' ') {
        true => format!("\u{2068}{file}\u{2069}"),
        false => file,
    }
}

/// Text for a comment line: control characters (a line break above all) become spaces.
fn one_line(text: &str) -> String {
    text.chars()
        .map(|c| if c.is_control() { ' ' } else { c })
        .collect()
}

/// `2026-11-24 06:00+0000`, as gettext writes dates, in UTC.
fn revision_date(time: SystemTime) -> String {
    let seconds = time
        .duration_since(SystemTime::UNIX_EPOCH)
        .map_or(0, |elapsed| elapsed.as_secs());
    let (days, rest) = (seconds / 86_400, seconds % 86_400);
    let (year, month, day) = civil_date(days as i64);
    format!(
        "{year:04}-{month:02}-{day:02} {:02}:{:02}+0000",
        rest / 3600,
        rest % 3600 / 60
    )
}

/// The Gregorian date `days` after 1970-01-01 (Howard Hinnant's `civil_from_days`).
fn civil_date(days: i64) -> (i64, u32, u32) {
    let z = days + 719_468;
    let era = z.div_euclid(146_097);
    let day_of_era = z.rem_euclid(146_097);
    let year_of_era =
        (day_of_era - day_of_era / 1460 + day_of_era / 36_524 - day_of_era / 146_096) / 365;
    let day_of_year = day_of_era - (365 * year_of_era + year_of_era / 4 - year_of_era / 100);
    let month_index = (5 * day_of_year + 2) / 153;
    let day = (day_of_year - (153 * month_index + 2) / 5 + 1) as u32;
    let month = if month_index < 10 {
        month_index + 3
    } else {
        month_index - 9
    } as u32;
    let year = year_of_era + era * 400 + i64::from(month <= 2);
    (year, month, day)
}

/// The last part of a path.
fn file_name(file: &str) -> &str {
    file.rsplit(['/', '\\']).next().unwrap_or(file)
}

/// What the robot is doing when it says the message: `said before pointing at the Roomba
/// (location 4, stop 2 of the tour)`.
fn said(unit: &Unit<'_>) -> String {
    let place = unit
        .description
        .unwrap_or("this location")
        .replace('\n', " ");
    let points = unit.target.is_some_and(|target| {
        matches!(
            crate::present::Gesture::of(&target),
            crate::present::Gesture::At(_)
        )
    });
    let what = match (unit.phase, points) {
        (Phase::Pre, true) => format!("said before pointing at {place}"),
        (Phase::Post, true) => format!("said after pointing at {place}"),
        (Phase::Pre, false) => format!("said first at {place}, where the robot does not point"),
        (Phase::Post, false) => format!("said next at {place}, where the robot does not point"),
    };
    let stops = match unit.stops.as_slice() {
        [] => "not on the tour".to_string(),
        [stop] => format!("stop {stop} of the tour"),
        stops => format!(
            "stops {} of the tour",
            stops
                .iter()
                .map(usize::to_string)
                .collect::<Vec<_>>()
                .join(", ")
        ),
    };
    let mut comment = format!("{what} (location {}, {stops})", unit.location);
    if unit.source.is_some_and(|s| s.miscased) {
        comment.push_str(
            "\nthe English line's key is in the wrong case: the robot does not say it yet (`ekb fix` corrects it)",
        );
    }
    comment
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dates_as_gettext_writes_them() {
        let at = |seconds: u64| {
            revision_date(SystemTime::UNIX_EPOCH + std::time::Duration::from_secs(seconds))
        };
        assert_eq!(at(0), "1970-01-01 00:00+0000");
        assert_eq!(at(951_782_400), "2000-02-29 00:00+0000");
        assert_eq!(at(1_795_500_000), "2026-11-24 06:00+0000");
    }

    #[test]
    fn contexts_round_trip() {
        assert_eq!(context(3, Phase::Pre), "location 3 preGestureMessage");
        assert_eq!(
            parse_context("location 3 postGestureMessage"),
            Some((3, Phase::Post))
        );
        assert_eq!(parse_context("location 0 preGestureMessage"), None);
        assert_eq!(parse_context("location 3 gestureTarget"), None);
    }

    #[test]
    fn escapes_as_c() {
        assert_eq!(escape("say \"hi\"\\\t\u{7}é"), r#"say \"hi\"\\\t\007é"#);
    }
}
