//! The open documents: their text as the editor has it (kept in step by incremental
//! changes), and each one's check, made once per version and shared by every request.

use std::cell::OnceCell;
use std::collections::HashMap;
use std::path::PathBuf;

use lsp_types::{TextDocumentContentChangeEvent, Uri};

use super::position::{Encoding, LineIndex, Positions};
use std::rc::Rc;

use crate::check::{check_on_map, Checked};
use crate::map::LabMap;
use crate::model::build::Options;
use crate::reader::{self, Loaded};
use crate::rules::selection::RuleSet;
use crate::source::SourceFile;

/// A file's check and, when a request needs it, the file as the robot's reader loads it.
#[derive(Debug)]
pub struct Analysed<'a> {
    pub checked: Checked<'a>,
    /// How the file was read (`fix` reads it again so).
    pub options: Options,
    loaded: OnceCell<Loaded<'a>>,
}

impl<'a> Analysed<'a> {
    /// What the chosen reader loads from the file (loaded on first use: only hovers and
    /// inlay hints ask).
    pub fn loaded(&self) -> &Loaded<'a> {
        self.loaded.get_or_init(|| {
            let source: &'a SourceFile = self.checked.source;
            reader::load(source.text().as_bytes(), self.checked.reader)
        })
    }
}

self_cell::self_cell!(
    /// A version of a document and what was found in it (which borrows from its text).
    pub struct Analysis {
        owner: SourceFile,
        // Not covariant: the reader's view is filled in later, through a cell.
        #[not_covariant]
        dependent: Analysed,
    }
    impl {Debug}
);

/// What a document holds: its text, checked or not yet.
#[derive(Debug)]
enum Content {
    Text(String),
    Checked(Analysis),
}

impl Content {
    fn text(&self) -> &str {
        match self {
            Content::Text(text) => text,
            Content::Checked(analysis) => analysis.borrow_owner().text(),
        }
    }

    fn into_text(self) -> String {
        match self {
            Content::Text(text) => text,
            Content::Checked(analysis) => analysis.into_owner().into_text(),
        }
    }
}

/// One open document.
#[derive(Debug)]
pub struct Document {
    pub version: i32,
    /// The file on disk it is, for a `file:` URI (settings are found from there).
    pub path: Option<PathBuf>,
    content: Content,
    index: LineIndex,
    /// Whether the diagnostics of this version have been sent.
    pub published: bool,
}

impl Document {
    pub fn new(version: i32, path: Option<PathBuf>, text: String) -> Document {
        Document {
            version,
            path,
            index: LineIndex::new(&text),
            content: Content::Text(text),
            published: false,
        }
    }

    pub fn text(&self) -> &str {
        self.content.text()
    }

    /// Converts positions in this version's text.
    pub fn positions(&self, encoding: Encoding) -> Positions<'_> {
        Positions {
            text: self.content.text(),
            index: &self.index,
            encoding,
        }
    }

    /// Applies the editor's changes, in order (each range is in the text as the changes
    /// before it left it).
    pub fn change(
        &mut self,
        version: i32,
        changes: Vec<TextDocumentContentChangeEvent>,
        encoding: Encoding,
    ) {
        let content = std::mem::replace(&mut self.content, Content::Text(String::new()));
        let mut text = content.into_text();
        for change in changes {
            match change.range {
                Some(range) => {
                    let span = self.positions_of(&text, encoding).span(range);
                    text.replace_range(span.range(), &change.text);
                    self.index.edited(&text, span, &change.text);
                }
                None => {
                    text = change.text;
                    self.index = LineIndex::new(&text);
                }
            }
        }
        self.content = Content::Text(text);
        self.version = version;
        self.published = false;
    }

    fn positions_of<'t>(&'t self, text: &'t str, encoding: Encoding) -> Positions<'t> {
        Positions {
            text,
            index: &self.index,
            encoding,
        }
    }

    /// Checks this version (with `how`: how to read this file, the rules `ekb.toml`
    /// chooses for it, and the lab map it names, if any), unless it was checked already.
    pub fn check(
        &mut self,
        name: &str,
        how: impl FnOnce() -> (Options, RuleSet, Option<Rc<LabMap>>),
    ) {
        if let Content::Text(text) = &mut self.content {
            let source = SourceFile::from_text(name, std::mem::take(text));
            let (options, rules, map) = how();
            self.content = Content::Checked(Analysis::new(source, |source| Analysed {
                checked: check_on_map(source, &options, &rules, map.as_deref()),
                options,
                loaded: OnceCell::new(),
            }));
        }
    }

    /// Calls `f` with this version's check, if [`Document::check`] made it.
    pub fn with_analysed<'d, R>(
        &'d self,
        f: impl for<'q> FnOnce(&'d Analysed<'q>) -> R,
    ) -> Option<R> {
        match &self.content {
            Content::Checked(analysis) => Some(analysis.with_dependent(|_, analysed| f(analysed))),
            Content::Text(_) => None,
        }
    }
}

/// The open documents, by URI.
#[derive(Debug, Default)]
pub struct Documents {
    open: HashMap<Uri, Document>,
}

impl Documents {
    pub fn open(&mut self, uri: Uri, document: Document) {
        self.open.insert(uri, document);
    }

    pub fn close(&mut self, uri: &Uri) -> Option<Document> {
        self.open.remove(uri)
    }

    pub fn get(&self, uri: &Uri) -> Option<&Document> {
        self.open.get(uri)
    }

    pub fn get_mut(&mut self, uri: &Uri) -> Option<&mut Document> {
        self.open.get_mut(uri)
    }

    /// The documents whose diagnostics have not been sent since they last changed.
    pub fn unpublished(&self) -> Vec<Uri> {
        let mut uris: Vec<Uri> = self
            .open
            .iter()
            .filter(|(_, document)| !document.published)
            .map(|(uri, _)| uri.clone())
            .collect();
        uris.sort();
        uris
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use lsp_types::{Position, Range};

    fn change(
        range: Option<((u32, u32), (u32, u32))>,
        text: &str,
    ) -> TextDocumentContentChangeEvent {
        TextDocumentContentChangeEvent {
            range: range.map(|((l1, c1), (l2, c2))| {
                Range::new(Position::new(l1, c1), Position::new(l2, c2))
            }),
            range_length: None,
            text: text.to_string(),
        }
    }

    #[test]
    fn changes_apply_in_order_each_in_the_text_the_last_left() {
        let mut document = Document::new(1, None, "ab\ncd\n".to_string());
        document.change(
            2,
            vec![
                change(Some(((1, 0), (1, 1))), "X"),
                change(Some(((0, 2), (1, 0))), ""),
                change(Some(((0, 0), (0, 0))), "Ù"),
            ],
            Encoding::Utf16,
        );
        assert_eq!(document.text(), "ÙabXd\n");
        assert_eq!(document.version, 2);
        document.change(3, vec![change(Some(((0, 1), (0, 2))), "")], Encoding::Utf16);
        assert_eq!(document.text(), "ÙbXd\n");
        document.change(4, vec![change(None, "new")], Encoding::Utf16);
        assert_eq!(document.text(), "new");
    }

    #[test]
    fn a_check_is_kept_until_the_text_changes() {
        let mut document = Document::new(1, None, "robotLocation 1 1 2 3\n".to_string());
        let findings = |document: &Document| {
            document.with_analysed(|analysed| analysed.checked.diagnostics.len())
        };
        assert_eq!(findings(&document), None);
        document.check("t", || (Options::default(), RuleSet::default(), None));
        let findings = findings(&document).unwrap();
        assert!(findings > 0);
        let mut asked = false;
        document.check("t", || {
            asked = true;
            Default::default()
        });
        assert!(!asked, "checked once per version");
        document.change(2, vec![change(Some(((0, 0), (0, 0))), "#")], Encoding::Utf8);
        assert_eq!(document.text(), "#robotLocation 1 1 2 3\n");
        document.check("t", || (Options::default(), RuleSet::default(), None));
        let locations = document.with_analysed(|analysed| analysed.checked.kb.locations().len());
        assert_eq!(locations, Some(0));
    }
}
