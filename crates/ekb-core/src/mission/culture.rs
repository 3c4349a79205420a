//! The culture knowledge base (SPEC §11) as the robot's `CultureKnowledgeBase` reads it:
//! the types file (`cultureKnowledgeValueTypesInput.dat`, `key TYPE` lines) declares each
//! key, and the knowledge base (`cultureKnowledgeBaseInput.dat`, `key value` lines) gives
//! values, each read as its key's type says.
//!
//! Both are read with `fgets` and a 200-byte buffer (300 in `2026-02`'s copy,
//! [`crate::robot::Reader::culture_line_buffer`]): a longer line is cut, and its rest
//! read as a line of its own. Every line, blank lines and comments included, is scanned
//! with `sscanf(" %s %s")` into a key and a second word that are not cleared between
//! lines: a line with one word keeps the second word of an earlier line, and a blank line
//! keeps both. So a types line with no type takes the type of the line before, and a
//! value line with no value takes the value of the line before.
//!
//! - Types file: a line whose second word is a type declares its key (the first
//!   declaration wins); any other line declares nothing, but while nothing is declared
//!   yet it stores a node without a key, on which the robot's next lookup crashes.
//! - Knowledge base: a `NUMBER` is the second word read with `%d` (a line that does not
//!   read keeps the earlier value), a `WORD` the second word, a `PHRASE` the bytes of the
//!   line buffer from the first letter or digit at or after the key's length (past the end
//!   of a line without one, into what earlier lines left in the buffer), less the last
//!   byte (taken to be the newline). Later values overwrite earlier ones. A key that the
//!   types file does not declare, or declares `UNDEFINED`, gets no value.

use std::borrow::Cow;
use std::collections::HashMap;

use crate::reader::chunks;
use crate::syntax::{floor_char_boundary, Span};

/// The buffer (`STRING_LENGTH`) of `2025-06`'s culture reader, which `ekb` reads both files
/// with unless it is told another reader's.
pub const LINE_BUFFER: usize = 200;

/// The robot copies each word into a buffer of this many bytes (`KEY_LENGTH`): a word
/// of this length or more overflows it.
pub const WORD_BUFFER: usize = 100;

/// The type of a key's value.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ValueType {
    /// No value is read for it.
    Undefined,
    /// An integer.
    Number,
    /// One word.
    Word,
    /// The rest of the line.
    Phrase,
}

impl ValueType {
    pub const NAMES: [&'static str; 4] = ["UNDEFINED", "NUMBER", "WORD", "PHRASE"];

    pub fn parse(word: &str) -> Option<ValueType> {
        match word {
            "UNDEFINED" => Some(ValueType::Undefined),
            "NUMBER" => Some(ValueType::Number),
            "WORD" => Some(ValueType::Word),
            "PHRASE" => Some(ValueType::Phrase),
            _ => None,
        }
    }

    pub fn name(self) -> &'static str {
        Self::NAMES[self as usize]
    }
}

/// One line of either file as the robot reads it (a piece of a cut line is a line too).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Entry<'a> {
    /// The piece `fgets` returned, newline included.
    pub span: Span,
    pub key: &'a str,
    pub key_span: Span,
    /// The words after the key, as `sscanf` sees them.
    pub words: Vec<(&'a str, Span)>,
    /// The text after the key, blanks and line ending trimmed (may be empty).
    pub rest: &'a str,
    pub rest_span: Span,
    /// The rest of a line cut by the buffer, not a line of the file.
    pub continuation: bool,
}

impl Entry<'_> {
    /// The first word after the key: a `NUMBER`'s or `WORD`'s value, a type's name.
    pub fn first_word(&self) -> Option<(&str, Span)> {
        self.words.first().copied()
    }
}

/// A line as `fgets` returns it: where it starts, its words, and its entry if it has one
/// (blank lines and comments have none).
struct Line<'a> {
    start: usize,
    bytes: &'a [u8],
    /// Its first two words.
    first: Option<&'a str>,
    second: Option<&'a str>,
    entry: Option<usize>,
}

/// Every line of `text` as `fgets` with a buffer of `line_buffer` bytes returns it, and the
/// entries: the lines with a key that is not a comment (`#`).
fn read_lines(text: &str, line_buffer: usize) -> (Vec<Line<'_>>, Vec<Entry<'_>>) {
    let mut lines = Vec::new();
    let mut entries = Vec::new();
    let mut continuation = false;
    for (start, piece) in chunks(text.as_bytes(), line_buffer) {
        let is_continuation = continuation;
        continuation = !piece.ends_with(b"\n");
        // A cut may fall inside a character: take the piece's whole characters.
        let (from, end) = (
            floor_char_boundary(text, start),
            floor_char_boundary(text, start + piece.len()),
        );
        let mut words = c_words(&text[from..end], from);
        let first = words.first().map(|&(word, _)| word);
        let second = words.get(1).map(|&(word, _)| word);
        let entry = match first {
            Some(key) if !key.starts_with('#') => {
                let (_, key_span) = words.remove(0);
                let after_key = key_span.end as usize;
                let rest_text = &text[after_key..end];
                let trimmed =
                    rest_text.trim_matches(|c: char| c.is_ascii_whitespace() || c == '\x0b');
                let rest_start = match trimmed.is_empty() {
                    true => after_key,
                    false => after_key + rest_text.find(trimmed).unwrap_or(0),
                };
                entries.push(Entry {
                    span: Span::new(from, end),
                    key,
                    key_span,
                    words,
                    rest: trimmed,
                    rest_span: Span::new(rest_start, rest_start + trimmed.len()),
                    continuation: is_continuation,
                });
                Some(entries.len() - 1)
            }
            _ => None,
        };
        lines.push(Line {
            start,
            bytes: piece,
            first,
            second,
            entry,
        });
    }
    (lines, entries)
}

/// The lines of a file of `key value` lines, as `fgets` with [`LINE_BUFFER`] returns them.
/// Blank lines and comments (`#`) are left out.
pub fn entries(text: &str) -> Vec<Entry<'_>> {
    read_lines(text, LINE_BUFFER).1
}

/// The words of `line` split at C's blanks (`isspace`), with their spans (`line` starts at
/// `offset` in its file).
fn c_words(line: &str, offset: usize) -> Vec<(&str, Span)> {
    let is_space = |c: char| matches!(c, ' ' | '\t' | '\n' | '\r' | '\x0b' | '\x0c');
    let mut words = Vec::new();
    let mut at = 0;
    for word in line.split(is_space) {
        if !word.is_empty() {
            words.push((word, Span::new(offset + at, offset + at + word.len())));
        }
        at += word.len() + 1;
    }
    words
}

/// A line, the key `sscanf` holds after it with the entry of the line that wrote it, and
/// the second word it holds.
type Scanned<'l, 'a> = (
    &'l Line<'a>,
    Option<(&'a str, Option<usize>)>,
    Option<&'a str>,
);

/// The key and the second word `sscanf(" %s %s")` leaves after each line: a line with
/// fewer words keeps those of the lines before. Gives, for each line, the pair and the
/// entry of the line that wrote the key.
fn scanned<'l, 'a>(lines: &'l [Line<'a>]) -> impl Iterator<Item = Scanned<'l, 'a>> {
    let mut key: Option<(&'a str, Option<usize>)> = None;
    let mut second: Option<&'a str> = None;
    lines.iter().map(move |line| {
        if let Some(word) = line.first {
            key = Some((word, line.entry));
        }
        if let Some(word) = line.second {
            second = Some(word);
        }
        (line, key, second)
    })
}

/// A key the robot declares, and how.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Declared {
    pub value_type: ValueType,
    /// The entry of the line that declared it.
    pub entry: usize,
    /// The line names no type, and the key took the type of a line before.
    pub borrowed: bool,
}

/// The types file: the keys of the culture knowledge base and the type of each.
#[derive(Debug, Clone, Default)]
pub struct ValueTypes<'a> {
    pub entries: Vec<Entry<'a>>,
    declared: HashMap<&'a str, Declared>,
    /// The first line, while nothing is declared yet, that declares nothing: the robot
    /// stores a node without a key there, and crashes (segmentation fault) on its next
    /// lookup. An empty place at the start when the file declares nothing at all.
    pub crash: Option<Span>,
    /// Keys starting with `#` that the robot declares (a comment with a type second).
    comment_keys: Vec<&'a str>,
    /// The last line that names a type, when it names a key already declared with another
    /// type: the robot still holds that line's declaration, and stores it over the key's
    /// if the knowledge base's first line names no declared key.
    pub last_redeclared: Option<(&'a str, ValueType)>,
}

impl<'a> ValueTypes<'a> {
    /// The types file as a reader with a buffer of `line_buffer` bytes reads it.
    pub fn parse(text: &'a str, line_buffer: usize) -> ValueTypes<'a> {
        let (lines, entries) = read_lines(text, line_buffer);
        let mut declared = HashMap::new();
        // The robot's tree holds a node once any key is declared, a comment's included.
        let mut any_declared = false;
        let mut crash = None;
        let mut comment_keys = Vec::new();
        let mut last_assigned = None;
        for (line, key, second) in scanned(&lines) {
            let value_type = second.and_then(ValueType::parse);
            if let (Some((key, _)), Some(value_type)) = (key, value_type) {
                last_assigned = Some((key, value_type));
            }
            match (key, value_type) {
                // A comment's key is declared too, but no lookup reaches it.
                (Some((key, Some(entry))), Some(value_type)) => {
                    any_declared = true;
                    let borrowed = entries[entry].first_word().is_none();
                    declared.entry(key).or_insert(Declared {
                        value_type,
                        entry,
                        borrowed,
                    });
                }
                (Some((key, None)), Some(_)) => {
                    any_declared = true;
                    comment_keys.push(key);
                }
                _ if !any_declared && crash.is_none() => {
                    let end = line.start + line.bytes.len();
                    crash = Some(Span::new(
                        floor_char_boundary(text, line.start),
                        floor_char_boundary(text, end),
                    ));
                }
                _ => {}
            }
        }
        if !any_declared && crash.is_none() {
            // Nothing declared at all: the first lookup of any key fails on an empty
            // dictionary and the robot makes a string of a null pointer.
            crash = Some(Span::empty_at(0));
        }
        let last_redeclared = last_assigned.filter(|&(key, value_type)| {
            declared
                .get(key)
                .is_some_and(|d: &Declared| d.value_type != value_type)
        });
        ValueTypes {
            entries,
            declared,
            crash,
            comment_keys,
            last_redeclared,
        }
    }

    /// Whether the robot finds `key` in its dictionary.
    fn knows(&self, key: &str) -> bool {
        self.declared.contains_key(key) || self.comment_keys.contains(&key)
    }

    /// The first line that names `key` (the robot keeps its type, if it declares one).
    pub fn declaration(&self, key: &str) -> Option<&Entry<'a>> {
        self.entries.iter().find(|entry| entry.key == key)
    }

    /// How the robot declares `key`; `None` if it does not.
    pub fn declared(&self, key: &str) -> Option<Declared> {
        self.declared.get(key).copied()
    }

    /// The type the robot gives `key`; `None` if it does not declare it (no line names it,
    /// or its line names no known type).
    pub fn type_of(&self, key: &str) -> Option<ValueType> {
        self.declared(key).map(|declared| declared.value_type)
    }

    /// Every key a line names, in file order.
    pub fn keys(&self) -> impl Iterator<Item = &'a str> + '_ {
        self.entries.iter().map(|entry| entry.key)
    }
}

/// What one line of the knowledge base gives its key (the key and value may be an
/// earlier line's), for each type the key may have.
#[derive(Debug, Clone)]
struct Reading<'a> {
    /// The entry of the line that wrote the key.
    entry: usize,
    /// The second word.
    word: Option<&'a str>,
    /// What a `PHRASE` copies; `None` when the copy starts past what the file wrote into
    /// the buffer.
    phrase: Option<Cow<'a, str>>,
}

/// The culture knowledge base's `key value` lines.
#[derive(Debug, Clone, Default)]
pub struct CultureKnowledgeBase<'a> {
    pub text: &'a str,
    pub entries: Vec<Entry<'a>>,
    /// What each line gives, by key, in file order.
    readings: HashMap<&'a str, Vec<Reading<'a>>>,
    /// The key of the first line: `None` for an empty file, `Some(None)` for a first line
    /// with no word (the robot looks up whatever its key buffer holds).
    first_key: Option<Option<&'a str>>,
}

/// What the robot holds for a key after reading both files.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Held<'a> {
    /// The types file does not declare the key: its lines are skipped.
    NotDeclared,
    /// Declared `UNDEFINED`: no value is ever read for it.
    Undefined,
    /// Declared, but no line gives it a value.
    Missing,
    /// Lines give it values, but none reads as its type (this is the last).
    Unreadable(&'a Entry<'a>),
    Number(i32, &'a Entry<'a>),
    Text(Cow<'a, str>, &'a Entry<'a>),
}

impl<'a> Held<'a> {
    /// The text the robot holds, if any.
    pub fn text(&self) -> Option<&str> {
        match self {
            Held::Text(text, _) => Some(text),
            _ => None,
        }
    }
}

/// `fgets`'s buffer: each line overwrites its start and ends with a NUL; the bytes after
/// are what longer lines before left. Each byte remembers where in the file it came from.
struct LineBuffer {
    bytes: Vec<u8>,
    from: Vec<usize>,
    /// How many bytes the file has written.
    written: usize,
}

impl LineBuffer {
    fn new(size: usize) -> LineBuffer {
        LineBuffer {
            bytes: vec![0; size],
            from: vec![0; size],
            written: 0,
        }
    }

    fn read(&mut self, line: &Line<'_>) {
        let length = line.bytes.len();
        self.bytes[..length].copy_from_slice(line.bytes);
        self.bytes[length] = 0;
        for (at, from) in self.from[..length].iter_mut().enumerate() {
            *from = line.start + at;
        }
        self.written = self.written.max(length + 1);
    }

    /// What the robot copies for a `PHRASE` whose key is `key_length` bytes long: the
    /// file's byte range, from the first letter or digit at or after `key_length` to the
    /// NUL, less one byte. `None` if the copy would start past what the file wrote.
    fn phrase(&self, key_length: usize) -> Option<std::ops::Range<usize>> {
        let first =
            (key_length..self.written).find(|&at| self.bytes[at].is_ascii_alphanumeric())?;
        let nul = (first..self.written).find(|&at| self.bytes[at] == 0)?;
        // The bytes up to the NUL come from one line of the file, in order.
        Some(self.from[first]..self.from[first] + (nul - first - 1))
    }
}

impl<'a> CultureKnowledgeBase<'a> {
    /// The knowledge base as a reader with a buffer of `line_buffer` bytes reads it.
    pub fn parse(text: &'a str, line_buffer: usize) -> CultureKnowledgeBase<'a> {
        let (lines, entries) = read_lines(text, line_buffer);
        let mut buffer = LineBuffer::new(line_buffer);
        let mut readings: HashMap<&'a str, Vec<Reading<'a>>> = HashMap::new();
        for (line, key, word) in scanned(&lines) {
            buffer.read(line);
            let Some((key, Some(entry))) = key else {
                continue;
            };
            let phrase = buffer
                .phrase(key.len())
                .map(|range| String::from_utf8_lossy(&text.as_bytes()[range]));
            readings.entry(key).or_default().push(Reading {
                entry,
                word,
                phrase,
            });
        }
        let first_key = lines.first().map(|line| line.first);
        CultureKnowledgeBase {
            text,
            entries,
            readings,
            first_key,
        }
    }

    /// The type the robot reads `key`'s values as: its declaration, unless the types
    /// file's last line re-declares it and this file's first line is no lookup that
    /// succeeds.
    pub fn value_type(&self, types: &ValueTypes<'_>, key: &str) -> Option<ValueType> {
        let first_misses = match self.first_key {
            Some(first) => first.is_none_or(|first| !types.knows(first)),
            None => false,
        };
        match types.last_redeclared {
            Some((redeclared, value_type)) if redeclared == key && first_misses => Some(value_type),
            _ => types.type_of(key),
        }
    }

    /// The last line that names `key`.
    pub fn last(&self, key: &str) -> Option<&Entry<'a>> {
        self.entries.iter().rev().find(|entry| entry.key == key)
    }

    /// What the robot holds for `key`.
    pub fn held(&'a self, types: &ValueTypes<'_>, key: &str) -> Held<'a> {
        let Some(value_type) = self.value_type(types, key) else {
            return Held::NotDeclared;
        };
        if value_type == ValueType::Undefined {
            return Held::Undefined;
        }
        let readings = self.readings.get(key).map_or(&[][..], Vec::as_slice);
        // A PHRASE line always stores what it copies, even bytes the file never wrote.
        let readings = match value_type {
            ValueType::Phrase => &readings[readings.len().saturating_sub(1)..],
            _ => readings,
        };
        let value = readings.iter().rev().find_map(|reading| {
            let entry = &self.entries[reading.entry];
            match value_type {
                ValueType::Number => reading
                    .word
                    .and_then(c_integer)
                    .map(|number| Held::Number(number, entry)),
                ValueType::Word => reading
                    .word
                    .map(|word| Held::Text(Cow::Borrowed(word), entry)),
                _ => reading
                    .phrase
                    .clone()
                    .map(|phrase| Held::Text(phrase, entry)),
            }
        });
        match (value, readings.last()) {
            (Some(value), _) => value,
            (None, Some(last)) => Held::Unreadable(&self.entries[last.entry]),
            (None, None) => Held::Missing,
        }
    }

    /// Where in `entry`'s line the robot starts copying a `PHRASE`: the first letter or
    /// digit at or after the key's length; `None` if the line has none there.
    pub fn phrase_start(&self, entry: &Entry<'a>) -> Option<usize> {
        let line = &self.text.as_bytes()[entry.span.range()];
        (entry.key.len()..line.len()).find(|&at| line[at].is_ascii_alphanumeric())
    }

    /// A `PHRASE` as the robot copies it from `entry`'s line alone: from the first letter
    /// or digit at or after the key's length into the line, to the end of the line less
    /// its last byte.
    pub fn phrase(&self, entry: &Entry<'a>) -> Cow<'a, str> {
        let line = &self.text.as_bytes()[entry.span.range()];
        let from = self.phrase_start(entry).unwrap_or(line.len());
        let copied = &line[from..];
        let kept = &copied[..copied.len().saturating_sub(1)];
        String::from_utf8_lossy(kept)
    }
}

/// The phrases of a mission's language: what the robot holds for each key, or why it
/// holds nothing.
#[derive(Debug, Clone, Copy)]
pub struct PhraseBook<'a> {
    /// The culture knowledge base and its types, if given.
    pub culture: Option<(&'a CultureKnowledgeBase<'a>, &'a ValueTypes<'a>)>,
    /// The language phrases are said in; `None` if the robot has none it accepts.
    pub language: Option<crate::model::Language>,
}

impl<'a> PhraseBook<'a> {
    /// What the robot holds for `key`; `None` without a culture knowledge base.
    pub fn held(&self, key: &str) -> Option<Held<'a>> {
        let (culture, types) = self.culture?;
        Some(culture.held(types, key))
    }

    /// The text the robot holds for `key`, or why it holds none.
    pub fn phrase(&self, key: &str) -> Result<String, String> {
        let Some(held) = self.held(key) else {
            return Err("(no culture knowledge base given)".to_string());
        };
        match held {
            Held::Text(text, _) => Ok(text.into_owned()),
            Held::Number(number, _) => Ok(number.to_string()),
            Held::NotDeclared => Err("is not declared in the types file".to_string()),
            Held::Undefined => Err("is typed UNDEFINED in the types file".to_string()),
            Held::Missing => Err("has no value in the culture knowledge base".to_string()),
            Held::Unreadable(_) => Err("has a value the robot cannot read".to_string()),
        }
    }
}

/// `sscanf(word, "%d")` as glibc does it: an optional sign and the digits that follow,
/// read as a `long` (saturating) and cut to an `int` (wrapping); `None` without digits.
pub fn c_integer(word: &str) -> Option<i32> {
    let negative = word.starts_with('-');
    let digits = word.strip_prefix(['+', '-']).unwrap_or(word);
    let digits = &digits[..digits.bytes().take_while(u8::is_ascii_digit).count()];
    if digits.is_empty() {
        return None;
    }
    let magnitude = digits.bytes().try_fold(0i64, |n, b| {
        n.checked_mul(10)?.checked_sub(i64::from(b - b'0'))
    });
    let long = match (magnitude, negative) {
        (Some(n), true) => n,
        (Some(n), false) => n.checked_neg().unwrap_or(i64::MAX),
        (None, true) => i64::MIN,
        (None, false) => i64::MAX,
    };
    Some(long as i32)
}

/// Whether `word` is a whole integer, as a `NUMBER` must be (`2.5` loads as 2).
pub fn is_integer(word: &str) -> bool {
    let digits = word.strip_prefix(['+', '-']).unwrap_or(word);
    !digits.is_empty() && digits.bytes().all(|b| b.is_ascii_digit())
}

#[cfg(test)]
mod tests {
    use super::*;

    const TYPES: &str = "phraseLanguage WORD\nutilityPhraseEnglish1 PHRASE\n\
                         utilityPhraseIsiZulu1 UNDEFINED\npauseDuration NUMBER\n";

    #[test]
    fn values_are_read_as_their_types_say() {
        let types = ValueTypes::parse(TYPES, LINE_BUFFER);
        let text = "phraseLanguage   English \nutilityPhraseEnglish1\t \"Hello there\" \n\
                    pauseDuration 2.5\nutilityPhraseIsiZulu1 Sawubona\nstray 1\n";
        let kb = CultureKnowledgeBase::parse(text, LINE_BUFFER);
        assert_eq!(kb.held(&types, "phraseLanguage").text(), Some("English"));
        // The quote is skipped, the trailing blank kept, the newline dropped.
        assert_eq!(
            kb.held(&types, "utilityPhraseEnglish1").text(),
            Some("Hello there\" ")
        );
        assert!(matches!(
            kb.held(&types, "pauseDuration"),
            Held::Number(2, _)
        ));
        assert_eq!(kb.held(&types, "utilityPhraseIsiZulu1"), Held::Undefined);
        assert_eq!(kb.held(&types, "stray"), Held::NotDeclared);
    }

    #[test]
    fn a_phrase_on_the_last_line_without_a_newline_loses_its_last_letter() {
        let types = ValueTypes::parse(TYPES, LINE_BUFFER);
        let kb = CultureKnowledgeBase::parse("utilityPhraseEnglish1 Goodbye", LINE_BUFFER);
        assert_eq!(
            kb.held(&types, "utilityPhraseEnglish1").text(),
            Some("Goodby")
        );
        let crlf = CultureKnowledgeBase::parse("utilityPhraseEnglish1 Goodbye\r\n", LINE_BUFFER);
        assert_eq!(
            crlf.held(&types, "utilityPhraseEnglish1").text(),
            Some("Goodbye\r")
        );
    }

    #[test]
    fn a_phrase_copied_from_bytes_the_file_never_wrote_replaces_the_one_before() {
        let types = ValueTypes::parse("k PHRASE\n", LINE_BUFFER);
        let kb = CultureKnowledgeBase::parse("k Hi\nk \u{e9}\n", LINE_BUFFER);
        assert!(matches!(kb.held(&types, "k"), Held::Unreadable(_)));
    }

    #[test]
    fn a_long_line_is_cut_into_two() {
        let line = format!("utilityPhraseEnglish1 {}\n", "a".repeat(250));
        let kb = CultureKnowledgeBase::parse(&line, LINE_BUFFER);
        assert_eq!(kb.entries.len(), 2);
        assert!(kb.entries[1].continuation);
        assert_eq!(kb.entries[0].span.len(), LINE_BUFFER - 1);
        // `2026-02`'s reader holds it whole.
        assert_eq!(CultureKnowledgeBase::parse(&line, 300).entries.len(), 1);
    }

    #[test]
    fn integers_as_sscanf_reads_them() {
        assert_eq!(c_integer("100"), Some(100));
        assert_eq!(c_integer("-3x"), Some(-3));
        assert_eq!(c_integer("x"), None);
        assert!(is_integer("40") && !is_integer("2.5") && !is_integer("-"));
    }
}
