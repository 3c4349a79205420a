//! The syntax of suppression comments (SPEC §7): `# ekb: ignore[NAME, …]` on a comment
//! line covers the next line that is neither a comment nor blank; `# ekb: ignore-file[NAME,
//! …]` covers the whole file. Here they are only read, their names as written; what a name
//! selects, and what it silences, is the check's ([`crate::check::suppression`]).
//!
//! A comment cannot follow a value on its line: the robot would read it as part of the value.
//! So a suppression is always a line of its own, and `ekb fmt` keeps it with the line below.
//!
//! Files are scanned for `ekb:` first (memchr), so a file without suppressions costs one
//! quick pass and no line is lexed for this.

use super::{lines_from, Body, Line, Span};

/// What marks a suppression, after the `#` and any blanks.
const MARK: &str = "ekb:";

/// One suppression comment.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Suppression {
    /// The whole line, its ending included (what removing it removes).
    pub line: Span,
    /// The comment, from `#` to its last non-blank character.
    pub comment: Span,
    pub scope: Scope,
    /// The names between the brackets, each with its span; empty if the brackets are.
    pub names: Vec<Name>,
    /// The span between the brackets, where names are rewritten.
    pub list: Span,
}

/// What a suppression covers.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Scope {
    /// The next line that is neither a comment nor blank (`None` if there is none).
    Line(Option<Span>),
    File,
}

/// One name of a suppression, as written: a rule's or a category's, or neither.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Name {
    pub span: Span,
}

/// A comment that starts like a suppression (`# ekb: ignore`) but cannot be read as one.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Malformed {
    /// The whole line, its ending included.
    pub line: Span,
    pub comment: Span,
}

/// Whether `comment`, the text of a comment line, may be a suppression (well formed or not).
pub fn may_be_one(comment: &str) -> bool {
    memchr::memmem::find(comment.as_bytes(), MARK.as_bytes()).is_some()
}

/// The suppression comments of `text`, and those that cannot be read.
pub fn find(text: &str) -> (Vec<Suppression>, Vec<Malformed>) {
    let (mut found, mut malformed) = (Vec::new(), Vec::new());
    let mut last_line_start = None;
    // What the last suppression of a line covers (once one was found): no entry lies
    // between that suppression and its line, so a suppression before that line covers it
    // too (100,000 suppressions in a row are read once, not each to the end of the run).
    let mut last_target: Option<Option<Span>> = None;
    for at in memchr::memmem::find_iter(text.as_bytes(), MARK) {
        let line_start = text[..at].rfind('\n').map_or(0, |newline| newline + 1);
        if last_line_start == Some(line_start) {
            continue;
        }
        last_line_start = Some(line_start);
        let mut lines = lines_from(text, line_start);
        let Some(line) = lines.next() else { continue };
        let Body::Comment(comment) = line.body else {
            continue;
        };
        match parse(text, comment) {
            Parsed::Suppression(scope, list, names) => {
                let scope = match scope {
                    ParsedScope::File => Scope::File,
                    ParsedScope::Line => {
                        let covered = match last_target {
                            Some(Some(target)) if line.span.start < target.start => Some(target),
                            // No entry after the last one: none after this one either.
                            Some(None) => None,
                            _ => target(lines),
                        };
                        last_target = Some(covered);
                        Scope::Line(covered)
                    }
                };
                found.push(Suppression {
                    line: line.span,
                    comment,
                    scope,
                    names,
                    list,
                });
            }
            Parsed::Malformed => malformed.push(Malformed {
                line: line.span,
                comment,
            }),
            Parsed::Other => {}
        }
    }
    (found, malformed)
}

/// Whether `comment` (from its `#`) is a suppression of the line below it.
pub fn is_for_next_line(comment: &str) -> bool {
    let span = Span::new(0, comment.len());
    matches!(
        parse(comment, span),
        Parsed::Suppression(ParsedScope::Line, ..)
    )
}

/// The next line that is neither a comment nor blank.
fn target(lines: impl Iterator<Item = Line>) -> Option<Span> {
    lines
        .into_iter()
        .find(|line| matches!(line.body, Body::Entry { .. }))
        .map(|line| line.span)
}

enum ParsedScope {
    Line,
    File,
}

enum Parsed {
    Suppression(ParsedScope, Span, Vec<Name>),
    Malformed,
    /// Some other comment that mentions `ekb:`.
    Other,
}

/// Reads `# ekb: ignore[a, b]` or `# ekb: ignore-file[a]` (blanks allowed around each part).
fn parse(text: &str, comment: Span) -> Parsed {
    let body = comment.text(text);
    let start = comment.start as usize;
    let rest = body[1..].trim_start_matches([' ', '\t']);
    let Some(rest) = rest.strip_prefix(MARK) else {
        return Parsed::Other;
    };
    let directive = rest.trim_start_matches([' ', '\t']);
    let (scope, after) = if let Some(after) = directive.strip_prefix("ignore-file") {
        (ParsedScope::File, after)
    } else if let Some(after) = directive.strip_prefix("ignore") {
        (ParsedScope::Line, after)
    } else {
        return Parsed::Other;
    };
    let after = after.trim_start_matches([' ', '\t']);
    let Some(list) = after.strip_prefix('[').and_then(|l| l.strip_suffix(']')) else {
        return Parsed::Malformed;
    };
    if list.contains(['[', ']']) {
        return Parsed::Malformed;
    }
    // The list ends where the comment does, before its `]`.
    let list_start = start + body.len() - 1 - list.len();
    let mut names = Vec::new();
    let mut offset = list_start;
    for part in list.split(',') {
        let name = part.trim_matches([' ', '\t']);
        if !name.is_empty() {
            let name_start = offset + (part.len() - part.trim_start_matches([' ', '\t']).len());
            names.push(Name {
                span: Span::new(name_start, name_start + name.len()),
            });
        }
        offset += part.len() + 1;
    }
    if names.is_empty() {
        return Parsed::Malformed;
    }
    Parsed::Suppression(scope, Span::new(list_start, list_start + list.len()), names)
}

/// Whether `text` may hold a suppression comment: it has the mark of one.
pub fn may_have_suppressions(text: &str) -> bool {
    // No `#`, no comment: that one byte is found faster than the mark.
    let bytes = text.as_bytes();
    memchr::memchr(b'#', bytes).is_some() && memchr::memmem::find(bytes, MARK.as_bytes()).is_some()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn suppressions_are_read_with_blanks_anywhere() {
        let text = "#ekb:ignore[ key-case ,repeated-word]\n\n# note\nkey 1 x\n  # ekb: ignore-file[content]\n# ekb: ignore\n# ekb: to do\n";
        let (found, malformed) = find(text);
        assert_eq!(found.len(), 2);
        let names: Vec<&str> = found[0].names.iter().map(|n| n.span.text(text)).collect();
        assert_eq!(names, ["key-case", "repeated-word"]);
        let key = text.find("key 1").unwrap();
        assert_eq!(found[0].scope, Scope::Line(Some(Span::new(key, key + 8))));
        assert_eq!(found[0].list.text(text), " key-case ,repeated-word");
        assert_eq!(found[1].scope, Scope::File);
        assert_eq!(malformed.len(), 1, "`# ekb: ignore` names no rule");
    }

    #[test]
    fn suppressions_in_a_row_cover_the_line_after_them_all() {
        let text = "# ekb: ignore[a]\n# ekb: ignore[b]\n\n# ekb: ignore[c]\nkey 1 x\n\
                    # ekb: ignore[d]\nkey 2 y\n# ekb: ignore[e]\n# ekb: ignore[f]\n";
        let (found, _) = find(text);
        let line = |start: &str| {
            let at = text.find(start).unwrap();
            Some(Span::new(at, at + 8))
        };
        let scopes: Vec<Scope> = found.iter().map(|s| s.scope).collect();
        assert_eq!(
            scopes,
            [
                Scope::Line(line("key 1")),
                Scope::Line(line("key 1")),
                Scope::Line(line("key 1")),
                Scope::Line(line("key 2")),
                Scope::Line(None),
                Scope::Line(None),
            ]
        );
    }
}
