//! Output safety: text from a knowledge base (its values, keys and file names) is untrusted,
//! so everything `ekb` prints of it goes through [`escape`] (or, for JSON, the same choice of
//! characters in [`safe_json`](super::safe_json)):
//!
//! - characters that could drive a terminal or hide (controls, bidirectional overrides,
//!   zero-width characters, a newline in a file name) are written as `\u{…}` escapes;
//! - characters that look like others — a Unicode space that looks like a plain one, a
//!   Cyrillic `е` or a Kelvin sign `K` among Latin letters, a Unicode minus before a digit —
//!   are escaped and named (`\u{00A0 NO-BREAK SPACE}`), so that two strings that look the
//!   same in a message differ visibly;
//! - text that a CI log would take for a command of its own is broken up: a GitHub Actions
//!   runner obeys a line that begins (after blanks) with `::` and one that holds `##[`
//!   anywhere (Azure Pipelines: `##vso[`), and `ekb`'s output wraps text, so content may begin
//!   a line. A `:` that begins the text or follows another `:` is escaped, and so is the `[`
//!   of `##[` and `##vso[`: no line that `ekb` prints begins with `::` or holds `##[` unless
//!   it is a `--format github` command.
//!
//! The escapes are ASCII and escaping is idempotent: escaping escaped text changes nothing.

use std::borrow::Cow;
use std::fmt::Write as _;

/// Whether `ch` could change what a terminal shows, or hide: controls (a newline too),
/// bidirectional overrides, isolates and marks, and zero-width and other invisible
/// characters (including the byte-order mark and tag characters). Always escaped, in every
/// output (JSON included).
pub fn is_unsafe(ch: char) -> bool {
    ch.is_control()
        || matches!(
            ch,
            '\u{202A}'..='\u{202E}'
                | '\u{2066}'..='\u{2069}'
                | '\u{200B}'..='\u{200F}'
                | '\u{2060}'..='\u{2064}'
                | '\u{061C}'
                | '\u{00AD}'
                | '\u{034F}'
                | '\u{115F}'
                | '\u{1160}'
                | '\u{180E}'
                | '\u{3164}'
                | '\u{FFA0}'
                | '\u{FEFF}'
                | '\u{E0000}'..='\u{E007F}'
        )
}

/// Whitespace that is not a plain space: a tab, a no-break space, an em space, …; where a
/// file has one, it looks like a space and is none to the robot's reader.
pub fn is_odd_space(ch: char) -> bool {
    ch.is_whitespace() && ch != ' '
}

/// Whether a JSON string must spell `ch` as a `\u` escape: what [`escape`] always escapes.
/// (Lookalike letters are escaped only among Latin letters, where they deceive; JSON keeps
/// them, as its reader sees them for what they are.)
pub fn is_hidden(ch: char) -> bool {
    is_unsafe(ch) || is_odd_space(ch)
}

/// `text`, safe to print on one line: every [`is_hidden`] character escaped (a tab as `\t`),
/// lookalikes among Latin letters and digits escaped, named characters named, and CI
/// commands broken up (see the module documentation).
pub fn escape(text: &str) -> Cow<'_, str> {
    escape_with(text, false)
}

/// [`escape`] for text of several lines: its newlines are kept (each line is escaped as
/// [`escape`] escapes a text, so none begins with `::`).
pub fn escape_lines(text: &str) -> Cow<'_, str> {
    escape_with(text, true)
}

fn escape_with(text: &str, keep_newlines: bool) -> Cow<'_, str> {
    if is_plain(text, keep_newlines) {
        return Cow::Borrowed(text);
    }
    let mut out = String::with_capacity(text.len() + 16);
    let mut pieces = text.split('\n');
    let first = pieces.next().unwrap_or("");
    escape_line(first, &mut out);
    for piece in pieces {
        if keep_newlines {
            out.push('\n');
        } else {
            push_escape(&mut out, '\n');
        }
        escape_line(piece, &mut out);
    }
    if out == text {
        return Cow::Borrowed(text);
    }
    Cow::Owned(out)
}

/// Whether `text` (one line) is printable ASCII with nothing that CI would obey, which
/// [`escape`] gives back as it is: the text of nearly every value and message.
pub fn is_plain_line(text: &str) -> bool {
    is_plain(text, false)
}

/// Whether `text` is printable ASCII (newlines if `keep_newlines`) with nothing that CI
/// would obey: the text of nearly every value and message, returned as it is.
fn is_plain(text: &str, keep_newlines: bool) -> bool {
    let bytes = text.as_bytes();
    if printable_without_marks(bytes) {
        return true;
    }
    // Without stopping early, so that the check is vectorised.
    let printable = |ok, &b: &u8| ok & (matches!(b, b' '..=b'~') || (keep_newlines && b == b'\n'));
    bytes.iter().fold(true, printable)
        && lacks_pairs(bytes)
        && !text.trim_start().starts_with(':')
        && !(keep_newlines && text.split('\n').any(|l| l.trim_start().starts_with(':')))
}

/// Whether `bytes` is printable ASCII without a `:` or a `#` (nearly every line of a
/// knowledge base): then it is plain, whatever is around it.
fn printable_without_marks(bytes: &[u8]) -> bool {
    bytes
        .iter()
        .all(|&byte| matches!(byte, b' '..=b'~') && byte != b':' && byte != b'#')
}

/// Whether `bytes` holds neither `::` nor `##`. (A search for each pair builds a searcher
/// per call, which costs more than the check of a short line.)
fn lacks_pairs(bytes: &[u8]) -> bool {
    !memchr::memchr2_iter(b':', b'#', bytes).any(|at| bytes.get(at + 1) == Some(&bytes[at]))
}

/// Escapes `line` (no newline in it) onto `out`.
fn escape_line(line: &str, out: &mut String) {
    let bytes = line.as_bytes();
    let mut at_start = true;
    let mut previous = None;
    // The character before `previous`: a `::` that starts a word is one wrapping could move
    // to a line's start.
    let mut before_previous = None;
    // Whether the word being escaped holds an ASCII letter or digit, once a lookalike in it
    // asked: each word is read at most twice more, however many lookalikes it has.
    let mut latin_word = None;
    let mut index = 0;
    while index < line.len() {
        // A run of characters that are never escaped is copied whole (nearly every line of
        // a knowledge base is one, but for a letter or two).
        let run = bytes[index..]
            .iter()
            .position(|&b| !is_inert(b))
            .unwrap_or(line.len() - index);
        if run > 0 {
            let piece = &bytes[index..index + run];
            out.push_str(&line[index..index + run]);
            at_start &= piece.iter().all(|&b| b == b' ');
            if !piece.iter().all(u8::is_ascii_alphanumeric) {
                latin_word = None;
            }
            before_previous = match run {
                1 => previous,
                _ => Some(piece[run - 2] as char),
            };
            previous = Some(piece[run - 1] as char);
            index += run;
            continue;
        }
        let ch = line[index..]
            .chars()
            .next()
            .expect("a character at a boundary");
        if !is_word_char(ch) {
            latin_word = None;
        }
        let escaped = match ch {
            _ if is_hidden(ch) => true,
            // A line beginning with `::`, or a `::` that wrapping could put at a line's start
            // and that a CI runner would obey (`ekb::KnowledgeBase` is left as it is).
            ':' => {
                at_start
                    || (previous == Some(':')
                        && (before_previous.is_none_or(char::is_whitespace)
                            || names_workflow_command(&line[index + 1..])))
            }
            '[' => ends_with_ci_marker(&line[..index]),
            _ if is_compatibility_form(ch) => true,
            _ if is_lookalike(ch) => *latin_word.get_or_insert_with(|| in_latin_word(line, index)),
            _ => false,
        };
        match ch {
            '\t' => out.push_str("\\t"),
            _ if escaped => push_escape(out, ch),
            _ => out.push(ch),
        }
        at_start &= ch == ' ';
        before_previous = previous;
        previous = Some(ch);
        index += ch.len_utf8();
    }
}

/// The commands of GitHub's runner (`::error file=…::…`), which it matches in any case.
pub const WORKFLOW_COMMANDS: [&str; 15] = [
    "add-mask",
    "add-matcher",
    "add-path",
    "debug",
    "echo",
    "endgroup",
    "error",
    "group",
    "notice",
    "remove-matcher",
    "save-state",
    "set-env",
    "set-output",
    "stop-commands",
    "warning",
];

/// Whether `rest`, what follows a `::`, begins with the name of a workflow command.
fn names_workflow_command(rest: &str) -> bool {
    let end = rest
        .find(|c: char| !(c.is_ascii_alphanumeric() || c == '-'))
        .unwrap_or(rest.len());
    WORKFLOW_COMMANDS
        .iter()
        .any(|command| rest[..end].eq_ignore_ascii_case(command))
}

/// Whether `byte` is printable ASCII that [`escape_line`] never escapes, wherever it is
/// (`:` and `[` it escapes in some places).
fn is_inert(byte: u8) -> bool {
    matches!(byte, b' '..=b'~') && byte != b':' && byte != b'['
}

/// Whether `before` ends with `##` or `##vso` (any case): a `[` after it would make a line
/// that a CI runner obeys.
pub fn ends_with_ci_marker(before: &str) -> bool {
    let bytes = before.as_bytes();
    bytes.ends_with(b"##")
        || bytes
            .len()
            .checked_sub(5)
            .is_some_and(|start| bytes[start..].eq_ignore_ascii_case(b"##vso"))
}

/// `\u{00A0 NO-BREAK SPACE}`, or `\u{0007}` for a character without a name here.
fn push_escape(out: &mut String, ch: char) {
    let code = ch as u32;
    match name(ch) {
        Some(name) => write!(out, "\\u{{{code:04X} {name}}}"),
        None => write!(out, "\\u{{{code:04X}}}"),
    }
    .expect("a String takes any text");
}

/// Whether `ch` looks like a Latin letter, a digit or `-` and is none (a compatibility form
/// such as the Kelvin sign included).
fn is_lookalike(ch: char) -> bool {
    is_compatibility_form(ch) || confusable_name(ch).is_some()
}

/// A character that is another's compatibility spelling (a fullwidth `Ａ`, the Kelvin sign
/// `K`, a Roman numeral `Ⅴ`): never meant where ASCII is, so always escaped.
fn is_compatibility_form(ch: char) -> bool {
    matches!(ch, '\u{FF01}'..='\u{FF5E}' | '\u{212A}' | '\u{212B}' | '\u{2160}'..='\u{217F}')
}

/// What a word is made of, for [`in_latin_word`]: letters, digits and lookalikes.
fn is_word_char(ch: char) -> bool {
    ch.is_alphanumeric() || is_lookalike(ch)
}

/// Whether the word around `line[index..]` holds an ASCII letter or digit: there a Cyrillic
/// `е` or a Unicode minus passes for what it is not. Alone or among their own script's
/// letters, they are shown as they are.
fn in_latin_word(line: &str, index: usize) -> bool {
    let before = line[..index]
        .chars()
        .rev()
        .take_while(|&ch| is_word_char(ch));
    let after = line[index..]
        .chars()
        .skip(1)
        .take_while(|&ch| is_word_char(ch));
    before.chain(after).any(|ch| ch.is_ascii_alphanumeric())
}

/// The Unicode name of a character that [`escape`] escapes and that a person could not tell
/// from another without it.
fn name(ch: char) -> Option<Cow<'static, str>> {
    if let Some(name) = confusable_name(ch) {
        return Some(Cow::Borrowed(name));
    }
    let code = ch as u32;
    let ascii = |offset: u32| char::from_u32(code - offset).and_then(ascii_name);
    match ch {
        '\u{FF01}'..='\u{FF5E}' => ascii(0xFEE0).map(|n| Cow::Owned(format!("FULLWIDTH {n}"))),
        '\u{E0020}'..='\u{E007E}' => ascii(0xE0000).map(|n| Cow::Owned(format!("TAG {n}"))),
        '\u{2160}'..='\u{216F}' => Some(Cow::Owned(format!(
            "ROMAN NUMERAL {}",
            roman(code - 0x2160)
        ))),
        '\u{2170}'..='\u{217F}' => Some(Cow::Owned(format!(
            "SMALL ROMAN NUMERAL {}",
            roman(code - 0x2170)
        ))),
        _ => lookup(INVISIBLE_NAMES, ch).map(Cow::Borrowed),
    }
}

fn roman(index: u32) -> &'static str {
    const NUMERALS: [&str; 16] = [
        "ONE",
        "TWO",
        "THREE",
        "FOUR",
        "FIVE",
        "SIX",
        "SEVEN",
        "EIGHT",
        "NINE",
        "TEN",
        "ELEVEN",
        "TWELVE",
        "FIFTY",
        "ONE HUNDRED",
        "FIVE HUNDRED",
        "ONE THOUSAND",
    ];
    NUMERALS[index as usize]
}

/// Spaces, invisible characters and marks that [`is_hidden`] escapes, by name, sorted.
const INVISIBLE_NAMES: &[(char, &str)] = &[
    ('\u{00A0}', "NO-BREAK SPACE"),
    ('\u{00AD}', "SOFT HYPHEN"),
    ('\u{034F}', "COMBINING GRAPHEME JOINER"),
    ('\u{061C}', "ARABIC LETTER MARK"),
    ('\u{115F}', "HANGUL CHOSEONG FILLER"),
    ('\u{1160}', "HANGUL JUNGSEONG FILLER"),
    ('\u{1680}', "OGHAM SPACE MARK"),
    ('\u{180E}', "MONGOLIAN VOWEL SEPARATOR"),
    ('\u{2000}', "EN QUAD"),
    ('\u{2001}', "EM QUAD"),
    ('\u{2002}', "EN SPACE"),
    ('\u{2003}', "EM SPACE"),
    ('\u{2004}', "THREE-PER-EM SPACE"),
    ('\u{2005}', "FOUR-PER-EM SPACE"),
    ('\u{2006}', "SIX-PER-EM SPACE"),
    ('\u{2007}', "FIGURE SPACE"),
    ('\u{2008}', "PUNCTUATION SPACE"),
    ('\u{2009}', "THIN SPACE"),
    ('\u{200A}', "HAIR SPACE"),
    ('\u{200B}', "ZERO WIDTH SPACE"),
    ('\u{200C}', "ZERO WIDTH NON-JOINER"),
    ('\u{200D}', "ZERO WIDTH JOINER"),
    ('\u{200E}', "LEFT-TO-RIGHT MARK"),
    ('\u{200F}', "RIGHT-TO-LEFT MARK"),
    ('\u{2028}', "LINE SEPARATOR"),
    ('\u{2029}', "PARAGRAPH SEPARATOR"),
    ('\u{202A}', "LEFT-TO-RIGHT EMBEDDING"),
    ('\u{202B}', "RIGHT-TO-LEFT EMBEDDING"),
    ('\u{202C}', "POP DIRECTIONAL FORMATTING"),
    ('\u{202D}', "LEFT-TO-RIGHT OVERRIDE"),
    ('\u{202E}', "RIGHT-TO-LEFT OVERRIDE"),
    ('\u{202F}', "NARROW NO-BREAK SPACE"),
    ('\u{205F}', "MEDIUM MATHEMATICAL SPACE"),
    ('\u{2060}', "WORD JOINER"),
    ('\u{2061}', "FUNCTION APPLICATION"),
    ('\u{2062}', "INVISIBLE TIMES"),
    ('\u{2063}', "INVISIBLE SEPARATOR"),
    ('\u{2064}', "INVISIBLE PLUS"),
    ('\u{2066}', "LEFT-TO-RIGHT ISOLATE"),
    ('\u{2067}', "RIGHT-TO-LEFT ISOLATE"),
    ('\u{2068}', "FIRST STRONG ISOLATE"),
    ('\u{2069}', "POP DIRECTIONAL ISOLATE"),
    ('\u{3000}', "IDEOGRAPHIC SPACE"),
    ('\u{3164}', "HANGUL FILLER"),
    ('\u{FEFF}', "ZERO WIDTH NO-BREAK SPACE"),
    ('\u{FFA0}', "HALFWIDTH HANGUL FILLER"),
    ('\u{E0001}', "LANGUAGE TAG"),
    ('\u{E007F}', "CANCEL TAG"),
];

/// The name of a letter of another script, or a sign, that looks like a Latin letter, a
/// digit or `-`.
fn confusable_name(ch: char) -> Option<&'static str> {
    match ch {
        '\u{0391}'..='\u{051D}' | '\u{2010}'..='\u{2212}' | '\u{FE63}' => lookup(CONFUSABLES, ch),
        _ => None,
    }
}

/// The name of `ch` in `table`, sorted by character.
fn lookup(table: &'static [(char, &'static str)], ch: char) -> Option<&'static str> {
    let found = table.binary_search_by_key(&ch, |&(named, _)| named);
    found.ok().map(|at| table[at].1)
}

/// Sorted by character.
const CONFUSABLES: &[(char, &str)] = &[
    ('\u{0391}', "GREEK CAPITAL LETTER ALPHA"),
    ('\u{0392}', "GREEK CAPITAL LETTER BETA"),
    ('\u{0395}', "GREEK CAPITAL LETTER EPSILON"),
    ('\u{0396}', "GREEK CAPITAL LETTER ZETA"),
    ('\u{0397}', "GREEK CAPITAL LETTER ETA"),
    ('\u{0399}', "GREEK CAPITAL LETTER IOTA"),
    ('\u{039A}', "GREEK CAPITAL LETTER KAPPA"),
    ('\u{039C}', "GREEK CAPITAL LETTER MU"),
    ('\u{039D}', "GREEK CAPITAL LETTER NU"),
    ('\u{039F}', "GREEK CAPITAL LETTER OMICRON"),
    ('\u{03A1}', "GREEK CAPITAL LETTER RHO"),
    ('\u{03A4}', "GREEK CAPITAL LETTER TAU"),
    ('\u{03A5}', "GREEK CAPITAL LETTER UPSILON"),
    ('\u{03A7}', "GREEK CAPITAL LETTER CHI"),
    ('\u{03B1}', "GREEK SMALL LETTER ALPHA"),
    ('\u{03B9}', "GREEK SMALL LETTER IOTA"),
    ('\u{03BD}', "GREEK SMALL LETTER NU"),
    ('\u{03BF}', "GREEK SMALL LETTER OMICRON"),
    ('\u{03C1}', "GREEK SMALL LETTER RHO"),
    ('\u{03C5}', "GREEK SMALL LETTER UPSILON"),
    ('\u{0405}', "CYRILLIC CAPITAL LETTER DZE"),
    (
        '\u{0406}',
        "CYRILLIC CAPITAL LETTER BYELORUSSIAN-UKRAINIAN I",
    ),
    ('\u{0408}', "CYRILLIC CAPITAL LETTER JE"),
    ('\u{0410}', "CYRILLIC CAPITAL LETTER A"),
    ('\u{0412}', "CYRILLIC CAPITAL LETTER VE"),
    ('\u{0415}', "CYRILLIC CAPITAL LETTER IE"),
    ('\u{041A}', "CYRILLIC CAPITAL LETTER KA"),
    ('\u{041C}', "CYRILLIC CAPITAL LETTER EM"),
    ('\u{041D}', "CYRILLIC CAPITAL LETTER EN"),
    ('\u{041E}', "CYRILLIC CAPITAL LETTER O"),
    ('\u{0420}', "CYRILLIC CAPITAL LETTER ER"),
    ('\u{0421}', "CYRILLIC CAPITAL LETTER ES"),
    ('\u{0422}', "CYRILLIC CAPITAL LETTER TE"),
    ('\u{0423}', "CYRILLIC CAPITAL LETTER U"),
    ('\u{0425}', "CYRILLIC CAPITAL LETTER HA"),
    ('\u{0430}', "CYRILLIC SMALL LETTER A"),
    ('\u{0435}', "CYRILLIC SMALL LETTER IE"),
    ('\u{043E}', "CYRILLIC SMALL LETTER O"),
    ('\u{0440}', "CYRILLIC SMALL LETTER ER"),
    ('\u{0441}', "CYRILLIC SMALL LETTER ES"),
    ('\u{0443}', "CYRILLIC SMALL LETTER U"),
    ('\u{0445}', "CYRILLIC SMALL LETTER HA"),
    ('\u{0455}', "CYRILLIC SMALL LETTER DZE"),
    ('\u{0456}', "CYRILLIC SMALL LETTER BYELORUSSIAN-UKRAINIAN I"),
    ('\u{0458}', "CYRILLIC SMALL LETTER JE"),
    ('\u{04AE}', "CYRILLIC CAPITAL LETTER STRAIGHT U"),
    ('\u{04AF}', "CYRILLIC SMALL LETTER STRAIGHT U"),
    ('\u{04BA}', "CYRILLIC CAPITAL LETTER SHHA"),
    ('\u{04BB}', "CYRILLIC SMALL LETTER SHHA"),
    ('\u{04C0}', "CYRILLIC LETTER PALOCHKA"),
    ('\u{04CF}', "CYRILLIC SMALL LETTER PALOCHKA"),
    ('\u{0501}', "CYRILLIC SMALL LETTER KOMI DE"),
    ('\u{051A}', "CYRILLIC CAPITAL LETTER QA"),
    ('\u{051B}', "CYRILLIC SMALL LETTER QA"),
    ('\u{051C}', "CYRILLIC CAPITAL LETTER WE"),
    ('\u{051D}', "CYRILLIC SMALL LETTER WE"),
    ('\u{2010}', "HYPHEN"),
    ('\u{2011}', "NON-BREAKING HYPHEN"),
    ('\u{2012}', "FIGURE DASH"),
    ('\u{2013}', "EN DASH"),
    ('\u{2014}', "EM DASH"),
    ('\u{2126}', "OHM SIGN"),
    ('\u{212A}', "KELVIN SIGN"),
    ('\u{212B}', "ANGSTROM SIGN"),
    ('\u{2212}', "MINUS SIGN"),
    ('\u{FE63}', "SMALL HYPHEN-MINUS"),
];

/// The Unicode name of a printable ASCII character, for the names of its fullwidth and tag
/// forms.
fn ascii_name(ch: char) -> Option<String> {
    const DIGITS: [&str; 10] = [
        "ZERO", "ONE", "TWO", "THREE", "FOUR", "FIVE", "SIX", "SEVEN", "EIGHT", "NINE",
    ];
    const SIGNS: &[(char, &str)] = &[
        (' ', "SPACE"),
        ('!', "EXCLAMATION MARK"),
        ('"', "QUOTATION MARK"),
        ('#', "NUMBER SIGN"),
        ('$', "DOLLAR SIGN"),
        ('%', "PERCENT SIGN"),
        ('&', "AMPERSAND"),
        ('\'', "APOSTROPHE"),
        ('(', "LEFT PARENTHESIS"),
        (')', "RIGHT PARENTHESIS"),
        ('*', "ASTERISK"),
        ('+', "PLUS SIGN"),
        (',', "COMMA"),
        ('-', "HYPHEN-MINUS"),
        ('.', "FULL STOP"),
        ('/', "SOLIDUS"),
        (':', "COLON"),
        (';', "SEMICOLON"),
        ('<', "LESS-THAN SIGN"),
        ('=', "EQUALS SIGN"),
        ('>', "GREATER-THAN SIGN"),
        ('?', "QUESTION MARK"),
        ('@', "COMMERCIAL AT"),
        ('[', "LEFT SQUARE BRACKET"),
        ('\\', "REVERSE SOLIDUS"),
        (']', "RIGHT SQUARE BRACKET"),
        ('^', "CIRCUMFLEX ACCENT"),
        ('_', "LOW LINE"),
        ('`', "GRAVE ACCENT"),
        ('{', "LEFT CURLY BRACKET"),
        ('|', "VERTICAL LINE"),
        ('}', "RIGHT CURLY BRACKET"),
        ('~', "TILDE"),
    ];
    match ch {
        'A'..='Z' => Some(format!("LATIN CAPITAL LETTER {ch}")),
        'a'..='z' => Some(format!("LATIN SMALL LETTER {}", ch.to_ascii_uppercase())),
        '0'..='9' => Some(format!("DIGIT {}", DIGITS[ch as usize - '0' as usize])),
        _ => SIGNS
            .iter()
            .find(|(sign, _)| *sign == ch)
            .map(|(_, name)| name.to_string()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn plain_text_is_borrowed() {
        for text in ["plain isiZulu", "Ùmuntu", "Привет мир", "5 − 3", "a: b"] {
            assert!(matches!(escape(text), Cow::Borrowed(_)), "{text}");
        }
    }

    #[test]
    fn plain_lines_are_told_from_lines_to_escape() {
        for plain in ["", "a: b # [c]", "#a#b:c:", "1234567:8", "  a:"] {
            assert!(is_plain_line(plain), "{plain:?}");
        }
        // `::` and `##` anywhere.
        for at in 0..12 {
            for pair in ["::", "##"] {
                let line = format!("{}{pair}x", "a".repeat(at));
                assert!(!is_plain_line(&line), "{line:?}");
            }
        }
        for odd in [
            ":x",
            "   :x",
            "a\tb",
            "a\x7f",
            "caf\u{e9}",
            "\x1b[0m",
            "1234567\x01",
        ] {
            assert!(!is_plain_line(odd), "{odd:?}");
        }
    }

    #[test]
    fn the_quick_check_of_a_plain_line_passes_only_plain_lines() {
        // Every byte value at every place of lines of every length up to two chunks and
        // a half (a word or two; chunks, the last read twice).
        for length in 1..40 {
            for at in 0..length {
                for byte in 0..=255u8 {
                    let mut line = vec![b'a'; length];
                    line[at] = byte;
                    let quick = printable_without_marks(&line);
                    let expected = matches!(byte, b' '..=b'~') && byte != b':' && byte != b'#';
                    assert_eq!(quick, expected, "{line:?}");
                }
            }
        }
        assert!(printable_without_marks(b""));
    }

    #[test]
    fn escapes_controls_and_bidi() {
        assert_eq!(escape("a\x1b[31mb"), "a\\u{001B}[31mb");
        assert_eq!(
            escape("x\u{202E}y\tz"),
            "x\\u{202E RIGHT-TO-LEFT OVERRIDE}y\\tz"
        );
        assert_eq!(escape("a\rb\0"), "a\\u{000D}b\\u{0000}");
        assert_eq!(
            escape("\u{FEFF}key"),
            "\\u{FEFF ZERO WIDTH NO-BREAK SPACE}key"
        );
    }

    #[test]
    fn newlines_are_escaped_on_one_line_and_kept_in_lines() {
        assert_eq!(
            escape("kb\n::error x.dat"),
            "kb\\u{000A}\\u{003A}\\u{003A}error x.dat"
        );
        assert_eq!(escape_lines("one\n::two"), "one\n\\u{003A}\\u{003A}two");
    }

    #[test]
    fn odd_spaces_are_escaped_and_named() {
        assert_eq!(escape("key 1"), "key 1");
        assert_eq!(escape("key\u{A0}1"), "key\\u{00A0 NO-BREAK SPACE}1");
        assert_eq!(
            escape("a\u{2003}b\u{3000}c"),
            "a\\u{2003 EM SPACE}b\\u{3000 IDEOGRAPHIC SPACE}c"
        );
    }

    #[test]
    fn lookalikes_among_latin_letters_are_escaped_and_named() {
        assert_eq!(
            escape("robotLocationD\u{0435}scription"),
            "robotLocationD\\u{0435 CYRILLIC SMALL LETTER IE}scription"
        );
        assert_eq!(escape("\u{212A}eft"), "\\u{212A KELVIN SIGN}eft");
        assert_eq!(escape("`\u{212A}`"), "`\\u{212A KELVIN SIGN}`");
        assert_eq!(escape("\u{2212}90"), "\\u{2212 MINUS SIGN}90");
        assert_eq!(
            escape("\u{FF52}obot"),
            "\\u{FF52 FULLWIDTH LATIN SMALL LETTER R}obot"
        );
        assert_eq!(escape("\u{2164}"), "\\u{2164 ROMAN NUMERAL FIVE}");
        // In their own script, or standing alone, letters and dashes are what they are.
        assert_eq!(escape("Привет — мир"), "Привет — мир");
        assert_eq!(escape("Ελλάδα"), "Ελλάδα");
        // Told word by word, across the runs copied whole.
        assert_eq!(
            escape("ab\u{0435} \u{0435}: [x]"),
            "ab\\u{0435 CYRILLIC SMALL LETTER IE} \u{0435}: [x]"
        );
    }

    #[test]
    fn ci_commands_are_broken_up() {
        assert_eq!(
            escape("::error file=a::x"),
            "\\u{003A}\\u{003A}error file=a::x"
        );
        assert_eq!(escape("see ::error x"), "see :\\u{003A}error x");
        assert_eq!(escape("word::Warning x"), "word:\\u{003A}Warning x");
        assert_eq!(escape("ekb::KnowledgeBase"), "ekb::KnowledgeBase");
        assert_eq!(escape("  ::warning"), "  \\u{003A}\\u{003A}warning");
        assert_eq!(escape(":"), "\\u{003A}");
        assert_eq!(escape("see ##[warning]x"), "see ##\\u{005B}warning]x");
        assert_eq!(escape("##VSO[task]"), "##VSO\\u{005B}task]");
        assert_eq!(escape("a: b # [c]"), "a: b # [c]");
        assert_eq!(escape("\u{E0068}i"), "\\u{E0068 TAG LATIN SMALL LETTER H}i");
    }

    #[test]
    fn name_tables_are_sorted() {
        for table in [INVISIBLE_NAMES, CONFUSABLES] {
            assert!(table.windows(2).all(|pair| pair[0].0 < pair[1].0));
        }
    }

    #[test]
    fn a_long_word_of_lookalikes_is_escaped_in_linear_time() {
        let word = "\u{0435}".repeat(200_000);
        assert_eq!(escape(&word), word);
        let latin = format!("a{word}");
        assert_eq!(
            escape(&latin).len(),
            1 + 200_000 * "\\u{0435 CYRILLIC SMALL LETTER IE}".len()
        );
    }

    #[test]
    fn escaping_is_idempotent() {
        for text in [
            "::error ##[x] \u{A0}\u{0435}a \x1b \u{202E}",
            "a\n::b",
            "\u{FF1A}\u{FF1A}",
        ] {
            let once = escape(text).into_owned();
            assert_eq!(escape(&once), once);
            let lines = escape_lines(text).into_owned();
            assert_eq!(escape_lines(&lines), lines);
        }
    }
}
