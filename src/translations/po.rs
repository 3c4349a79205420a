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
use crate::canonical::VALUE_COLUMN;
use crate::model::{Key, Language, Phase};
use crate::present::language::iso_code;
use crate::robot::Reader;

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
        let _ = writeln!(
            out,
            "#. {}",
            byte_limits(unit, language, catalog.line_buffer)
        );
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

/// The most bytes the robot's reader reads of the translation (in `language`, or in each
/// language of a template), its line laid out as `ekb fmt` and `ekb import --po` write it:
/// the line, its key, id and newline included, is shorter than `line_buffer`.
fn byte_limits(unit: &Unit<'_>, language: Option<Language>, line_buffer: usize) -> String {
    let limit = |language: Language| {
        let key = Key::ALL
            .into_iter()
            .find(|key| key.message() == Some((unit.phase, language)))
            .expect("a message key for each phase and language");
        // A line the smallest buffer cuts anyway is padded (`crate::canonical::padding`).
        let key_and_blanks = match line_buffer > Reader::SMALLEST_LINE_BUFFER {
            true => (key.name().len() + 1).max(VALUE_COLUMN - 1),
            false => key.name().len() + 1,
        };
        let prefix = key_and_blanks + unit.location.to_string().len() + 1;
        line_buffer.saturating_sub(prefix + "\n".len() + 1)
    };
    let accents = "a letter with an accent takes 2";
    match language {
        Some(language) => format!(
            "at most {} bytes: the robot's reader cuts a longer message ({accents})",
            limit(language)
        ),
        None => format!(
            "at most {} bytes in isiZulu, {} in Kinyarwanda: the robot's reader cuts a longer \
             message ({accents})",
            limit(Language::IsiZulu),
            limit(Language::Kinyarwanda)
        ),
    }
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

/// A PO file as `ekb import --po` reads it.
#[derive(Debug, Default, PartialEq)]
pub struct PoFile {
    /// The header's `Language:` field, if it has one.
    pub language: Option<String>,
    /// The entries, obsolete ones (`#~`) left out, in file order.
    pub entries: Vec<Entry>,
}

/// One entry of a PO file.
#[derive(Debug, Default, Clone, PartialEq)]
pub struct Entry {
    /// The line of its first keyword (`msgctxt`, else `msgid`), 1-based.
    pub line: u32,
    pub msgctxt: Option<String>,
    pub msgid: String,
    /// The translation.
    pub msgstr: String,
    /// `#, fuzzy`: a translation to review, not to use.
    pub fuzzy: bool,
}

/// Why a PO file could not be read: the line and what is wrong there.
#[derive(Debug, Clone, PartialEq)]
pub struct ParseError {
    pub line: u32,
    pub message: String,
}

/// The field a string continuation line adds to.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Field {
    Context,
    Id,
    Str,
}

/// An entry being read.
#[derive(Debug, Default)]
struct Pending {
    entry: Entry,
    has_context: bool,
    has_id: bool,
    has_str: bool,
    field: Option<Field>,
}

/// Reads a PO file. Lines may end in CRLF; strings may continue on lines of their own.
pub fn parse(text: &str) -> Result<PoFile, ParseError> {
    let mut file = PoFile::default();
    let mut pending = Pending::default();
    let mut entries = Vec::new();
    // Some editors on Windows start a UTF-8 file with a byte-order mark.
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    for (index, raw) in text.lines().enumerate() {
        let number = index as u32 + 1;
        let line = raw.trim();
        let fail = |message: String| ParseError {
            line: number,
            message,
        };
        if line.is_empty() {
            continue;
        }
        if let Some(comment) = line.strip_prefix('#') {
            // A comment starts the next entry's comments; `#~` lines are an obsolete entry,
            // whose flags must not reach the next one.
            if pending.has_str {
                entries.push(finish(std::mem::take(&mut pending))?);
            }
            if comment.starts_with('~') {
                pending = Pending::default();
            } else if let Some(flags) = comment.strip_prefix(',') {
                pending.entry.fuzzy |= flags.split(',').any(|flag| flag.trim() == "fuzzy");
            }
            continue;
        }
        if line.starts_with('"') {
            let field = pending.field.ok_or_else(|| {
                fail("a string that continues no `msgid` or `msgstr`".to_string())
            })?;
            let more = string(line).map_err(fail)?;
            field_text(&mut pending, field).push_str(&more);
            continue;
        }
        let (keyword, rest) = line.split_once([' ', '\t']).unwrap_or((line, ""));
        let value = string(rest.trim()).map_err(|message| fail(format!("{keyword}: {message}")))?;
        let field = match keyword {
            "msgctxt" => Field::Context,
            "msgid" => Field::Id,
            "msgstr" => Field::Str,
            // Importing the first form would drop the others, and mean one of them.
            "msgid_plural" => return Err(fail(PLURAL.to_string())),
            _ if keyword.starts_with("msgstr[") && keyword.ends_with(']') => {
                return Err(fail(format!("`{keyword}`: {PLURAL}")))
            }
            _ => {
                return Err(fail(format!(
                    "`{}` is no PO keyword (msgctxt, msgid, msgid_plural, msgstr)",
                    crate::rules::excerpt(keyword)
                )))
            }
        };
        let starts_entry = match field {
            Field::Context => true,
            Field::Id => !pending.has_context || pending.has_id,
            _ => false,
        };
        if starts_entry && (pending.has_id || pending.has_context) {
            entries.push(finish(std::mem::take(&mut pending))?);
        }
        if matches!(field, Field::Context | Field::Id) && pending.entry.line == 0 {
            pending.entry.line = number;
        }
        match field {
            Field::Context => pending.has_context = true,
            Field::Id => pending.has_id = true,
            Field::Str if !pending.has_id => {
                return Err(fail(format!("`{keyword}` before the entry's `msgid`")))
            }
            Field::Str => pending.has_str = true,
        }
        pending.field = Some(field);
        *field_text(&mut pending, field) = value;
    }
    if pending.has_id || pending.has_context {
        entries.push(finish(pending)?);
    }
    for entry in entries {
        if entry.msgid.is_empty() && entry.msgctxt.is_none() {
            file.language = header_field(&entry.msgstr, "Language");
        } else {
            file.entries.push(entry);
        }
    }
    Ok(file)
}

/// Why an entry with plural forms is refused.
const PLURAL: &str = "an entry with plural forms (`msgid_plural`, `msgstr[N]`): a message of \
                      the robot has no plural, and ekb writes none; give the entry one \
                      `msgstr` (nothing was imported)";

/// The text a field's strings go to.
fn field_text(pending: &mut Pending, field: Field) -> &mut String {
    match field {
        Field::Context => pending.entry.msgctxt.get_or_insert_with(String::new),
        Field::Id => &mut pending.entry.msgid,
        Field::Str => &mut pending.entry.msgstr,
    }
}

/// An entry read whole: it has a `msgid` and a `msgstr`.
fn finish(pending: Pending) -> Result<Entry, ParseError> {
    if !pending.has_id || !pending.has_str {
        return Err(ParseError {
            line: pending.entry.line,
            message: "an entry without its `msgid` or its `msgstr`".to_string(),
        });
    }
    Ok(pending.entry)
}

/// The value of a field of a PO header (`Language: zu`).
fn header_field(header: &str, name: &str) -> Option<String> {
    header.lines().find_map(|line| {
        let (field, value) = line.split_once(':')?;
        (field.trim().eq_ignore_ascii_case(name) && !value.trim().is_empty())
            .then(|| value.trim().to_string())
    })
}

/// The contents of a quoted PO string, unescaped.
fn string(quoted: &str) -> Result<String, String> {
    let inner = quoted
        .strip_prefix('"')
        .and_then(|rest| rest.strip_suffix('"'))
        .filter(|_| quoted.len() >= 2)
        .ok_or_else(|| "expected a string in double quotes".to_string())?;
    let mut out = String::with_capacity(inner.len());
    let mut chars = inner.chars();
    while let Some(c) = chars.next() {
        match c {
            '"' => return Err("a double quote inside a string must be written \\\"".to_string()),
            '\\' => out.push(match chars.next() {
                Some('n') => '\n',
                Some('t') => '\t',
                Some('r') => '\r',
                Some('a') => '\u{7}',
                Some('b') => '\u{8}',
                Some('f') => '\u{c}',
                Some('v') => '\u{b}',
                Some(c @ ('\\' | '"' | '\'' | '?')) => c,
                Some(first @ '0'..='7') => {
                    let mut code = first.to_digit(8).unwrap_or(0);
                    for _ in 0..2 {
                        match chars.clone().next().and_then(|c| c.to_digit(8)) {
                            Some(digit) => {
                                code = code * 8 + digit;
                                chars.next();
                            }
                            None => break,
                        }
                    }
                    char::from_u32(code).ok_or("an escape that is no character")?
                }
                Some(other) => return Err(format!("unknown escape `\\{other}`")),
                None => return Err("a string that ends with a lone backslash".to_string()),
            }),
            c => out.push(c),
        }
    }
    Ok(out)
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
    fn reads_what_it_writes_and_what_translators_tools_write() {
        let po = "\u{feff}# translator comment\r\n\
                  msgid \"\"\nmsgstr \"\"\n\"Language: zu\\n\"\n\n\
                  #, fuzzy, c-format\nmsgctxt \"location 1 preGestureMessage\"\n\
                  msgid \"Hello\"\nmsgstr \"\"\n\"Saw\"\n\"ubona\"\n\n\
                  #~ msgid \"gone\"\n#~ msgstr \"\"\n\n\
                  msgctxt \"location 1 postGestureMessage\"\nmsgid \"Say \\\"bye\\\"\"\n\
                  msgstr \"Hamba\\tkahle\"\n";
        let file = parse(po).unwrap();
        assert_eq!(file.language.as_deref(), Some("zu"));
        assert_eq!(file.entries.len(), 2);
        let first = &file.entries[0];
        assert_eq!((first.line, first.fuzzy), (7, true));
        assert_eq!(first.msgstr, "Sawubona");
        let second = &file.entries[1];
        assert_eq!((second.line, second.fuzzy), (16, false));
        assert_eq!(second.msgid, "Say \"bye\"");
        assert_eq!(second.msgstr, "Hamba\tkahle");
    }

    #[test]
    fn an_entry_with_plural_forms_is_refused_at_its_line() {
        let po = "msgctxt \"location 1 preGestureMessage\"\nmsgid \"Hello\"\n\
                  msgid_plural \"Hellos\"\nmsgstr[0] \"Sawubona\"\nmsgstr[1] \"Sanibonani\"\n";
        let error = parse(po).unwrap_err();
        assert_eq!(error.line, 3);
        assert!(
            error.message.starts_with("an entry with plural forms"),
            "{}",
            error.message
        );
        let error = parse("msgid \"Hello\"\nmsgstr[0] \"Sawubona\"\n").unwrap_err();
        assert_eq!(error.line, 2);
        assert!(
            error
                .message
                .starts_with("`msgstr[0]`: an entry with plural"),
            "{}",
            error.message
        );
    }

    #[test]
    fn a_malformed_line_is_an_error_at_its_line() {
        for (po, line) in [
            ("msgid \"a\"\nmsgstr \"b\n", 2),
            ("msgid \"a\"\nmsgstr\n", 2),
            ("\"orphan\"\n", 1),
            ("msgid \"a\"\nmsgstr \"\\q\"\n", 2),
            ("msgid \"a\"\nmsgctxt \"b\"\n", 1),
            ("msgstr \"a\"\n", 1),
            ("msgid \"a\"\ntranslation \"b\"\n", 2),
            ("msgid \"é\"\nmsgstr \"\u{7}", 2),
        ] {
            let error = parse(po).unwrap_err();
            assert_eq!(error.line, line, "{po:?}: {error:?}");
        }
    }

    #[test]
    fn escapes_as_c() {
        assert_eq!(escape("say \"hi\"\\\t\u{7}é"), r#"say \"hi\"\\\t\007é"#);
    }
}
