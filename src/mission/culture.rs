//! The culture knowledge base (SPEC §11) as the robot's `CultureKnowledgeBase` reads it:
//! the types file (`cultureKnowledgeValueTypesInput.dat`, `key TYPE` lines) declares each
//! key, and the knowledge base (`cultureKnowledgeBaseInput.dat`, `key value` lines) gives
//! values, each read as its key's type says.
//!
//! Both are read with `fgets` and a 200-byte buffer: a longer line is cut, and its rest
//! read as a line of its own. The first word of a line is its key; a `NUMBER` or a `WORD`
//! is the next word (`sscanf`); a `PHRASE` is the rest of the line from the first letter or
//! digit after the key's length, less its last character (taken to be the newline).
//! Later values of a key overwrite earlier ones; a key declared twice in the types file
//! keeps its first type. A key that the types file does not declare gets no value.

use std::borrow::Cow;

use crate::reader::chunks;
use crate::syntax::{floor_char_boundary, Span};

/// The robot reads both files with this buffer (`STRING_LENGTH`).
pub const LINE_BUFFER: usize = 200;

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

/// The lines of a file of `key value` lines, as `fgets` with [`LINE_BUFFER`] returns them.
/// Blank lines and comments (`#`) are left out: the robot gets nothing from them.
pub fn entries(text: &str) -> Vec<Entry<'_>> {
    let mut out = Vec::new();
    let mut continuation = false;
    for (start, piece) in chunks(text.as_bytes(), LINE_BUFFER) {
        let is_continuation = continuation;
        continuation = !piece.ends_with(b"\n");
        // A cut may fall inside a character: take the piece's whole characters.
        let (start, end) = (
            floor_char_boundary(text, start),
            floor_char_boundary(text, start + piece.len()),
        );
        let line = &text[start..end];
        let mut words = c_words(line, start);
        let Some((key, key_span)) = (!words.is_empty()).then(|| words.remove(0)) else {
            continue;
        };
        if key.starts_with('#') {
            continue;
        }
        let after_key = key_span.end as usize;
        let rest_text = &text[after_key..end];
        let rest = rest_text.trim_matches(|c: char| c.is_ascii_whitespace() || c == '\x0b');
        let rest_start = if rest.is_empty() {
            after_key
        } else {
            after_key + rest_text.find(rest).unwrap_or(0)
        };
        out.push(Entry {
            span: Span::new(start, end),
            key,
            key_span,
            words,
            rest,
            rest_span: Span::new(rest_start, rest_start + rest.len()),
            continuation: is_continuation,
        });
    }
    out
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

/// The types file: the keys of the culture knowledge base and the type of each.
#[derive(Debug, Clone, Default)]
pub struct ValueTypes<'a> {
    pub entries: Vec<Entry<'a>>,
}

impl<'a> ValueTypes<'a> {
    pub fn parse(text: &'a str) -> ValueTypes<'a> {
        ValueTypes {
            entries: entries(text),
        }
    }

    /// The entry that declares `key`: the first (the robot keeps it).
    pub fn declaration(&self, key: &str) -> Option<&Entry<'a>> {
        self.entries.iter().find(|entry| entry.key == key)
    }

    /// The type of `key`; `None` if it is not declared, or declared with no known type (the
    /// robot then keeps whatever type the line before declared, a case reported apart).
    pub fn type_of(&self, key: &str) -> Option<ValueType> {
        let (word, _) = self.declaration(key)?.first_word()?;
        ValueType::parse(word)
    }

    /// Every declared key, in file order.
    pub fn keys(&self) -> impl Iterator<Item = &'a str> + '_ {
        self.entries.iter().map(|entry| entry.key)
    }
}

/// The culture knowledge base's `key value` lines.
#[derive(Debug, Clone, Default)]
pub struct CultureKnowledgeBase<'a> {
    pub text: &'a str,
    pub entries: Vec<Entry<'a>>,
}

/// What the robot holds for a key after reading both files.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Held<'a> {
    /// The types file does not declare the key: its lines are skipped.
    NotDeclared,
    /// Declared `UNDEFINED` (or with an unknown type): no value is ever read for it.
    Undefined,
    /// Declared, but no line gives it a value.
    Missing,
    /// A line gives it a value that does not read as its type.
    Unreadable(&'a Entry<'a>),
    Number(i64, &'a Entry<'a>),
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

impl<'a> CultureKnowledgeBase<'a> {
    pub fn parse(text: &'a str) -> CultureKnowledgeBase<'a> {
        CultureKnowledgeBase {
            text,
            entries: entries(text),
        }
    }

    /// The last line that gives `key` a value (the robot keeps the last).
    pub fn last(&self, key: &str) -> Option<&Entry<'a>> {
        self.entries.iter().rev().find(|entry| entry.key == key)
    }

    /// What the robot holds for `key`.
    pub fn held(&'a self, types: &ValueTypes<'_>, key: &str) -> Held<'a> {
        let Some(declared) = types.declaration(key) else {
            return Held::NotDeclared;
        };
        let value_type = declared.first_word().and_then(|(w, _)| ValueType::parse(w));
        let Some(value_type) = value_type.filter(|t| *t != ValueType::Undefined) else {
            return Held::Undefined;
        };
        let Some(entry) = self.last(key) else {
            return Held::Missing;
        };
        match value_type {
            ValueType::Number => match entry.first_word().and_then(|(w, _)| c_integer(w)) {
                Some(number) => Held::Number(number, entry),
                None => Held::Unreadable(entry),
            },
            ValueType::Word => match entry.first_word() {
                Some((word, _)) => Held::Text(Cow::Borrowed(word), entry),
                None => Held::Unreadable(entry),
            },
            ValueType::Phrase => Held::Text(self.phrase(entry), entry),
            ValueType::Undefined => Held::Undefined,
        }
    }

    /// A `PHRASE` as the robot copies it: from the first letter or digit at or after the
    /// key's length into the line, to the end of the line less its last byte.
    pub fn phrase(&self, entry: &Entry<'a>) -> Cow<'a, str> {
        let line = &self.text.as_bytes()[entry.span.range()];
        let from = line
            .iter()
            .enumerate()
            .skip(entry.key.len())
            .find(|(_, b)| b.is_ascii_alphanumeric())
            .map_or(line.len(), |(at, _)| at);
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

/// `sscanf(word, "%d")`: an optional sign and the digits that follow; `None` without digits.
fn c_integer(word: &str) -> Option<i64> {
    let digits_from = usize::from(word.starts_with(['+', '-']));
    let digits = word[digits_from..]
        .bytes()
        .take_while(u8::is_ascii_digit)
        .count();
    if digits == 0 {
        return None;
    }
    word[..digits_from + digits]
        .parse::<i64>()
        .ok()
        .map(|n| n.clamp(i32::MIN.into(), i32::MAX.into()))
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
        let types = ValueTypes::parse(TYPES);
        let text = "phraseLanguage   English \nutilityPhraseEnglish1\t \"Hello there\" \n\
                    pauseDuration 2.5\nutilityPhraseIsiZulu1 Sawubona\nstray 1\n";
        let kb = CultureKnowledgeBase::parse(text);
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
        let types = ValueTypes::parse(TYPES);
        let kb = CultureKnowledgeBase::parse("utilityPhraseEnglish1 Goodbye");
        assert_eq!(
            kb.held(&types, "utilityPhraseEnglish1").text(),
            Some("Goodby")
        );
        let crlf = CultureKnowledgeBase::parse("utilityPhraseEnglish1 Goodbye\r\n");
        assert_eq!(
            crlf.held(&types, "utilityPhraseEnglish1").text(),
            Some("Goodbye\r")
        );
    }

    #[test]
    fn a_long_line_is_cut_into_two() {
        let line = format!("utilityPhraseEnglish1 {}\n", "a".repeat(250));
        let kb = CultureKnowledgeBase::parse(&line);
        assert_eq!(kb.entries.len(), 2);
        assert!(kb.entries[1].continuation);
        assert_eq!(kb.entries[0].span.len(), LINE_BUFFER - 1);
    }

    #[test]
    fn integers_as_sscanf_reads_them() {
        assert_eq!(c_integer("100"), Some(100));
        assert_eq!(c_integer("-3x"), Some(-3));
        assert_eq!(c_integer("x"), None);
        assert!(is_integer("40") && !is_integer("2.5") && !is_integer("-"));
    }
}
