//! A rule's identity: its name, category, severity and documentation. The rules
//! themselves, one module each, and the catalogue of them are [`crate::rules`]'s; a finding
//! names its rule by this.

use super::Severity;

/// A rule's identity and documentation.
#[derive(Debug, PartialEq, Eq)]
pub struct Rule {
    /// Stable kebab-case name (part of the contract).
    pub name: &'static str,
    pub category: Category,
    pub severity: Severity,
    /// Whether `ekb fix` can repair what it finds.
    pub fixable: bool,
    /// One line: when the rule fires.
    pub summary: &'static str,
    /// Markdown: what it does, why it matters, an example.
    pub doc: &'static str,
}

impl Rule {
    /// [`Rule::doc`] as plain Markdown (doc comments keep the space after `///`).
    pub fn markdown(&self) -> String {
        let mut out = String::with_capacity(self.doc.len());
        for line in self.doc.lines() {
            out.push_str(line.strip_prefix(' ').unwrap_or(line));
            out.push('\n');
        }
        out
    }
}

/// The sections of the catalogue.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum Category {
    Structure,
    Tour,
    Content,
    Compat,
    Map,
    /// The behaviour tree, and what it needs of both knowledge bases (SPEC §11).
    Mission,
    /// The culture knowledge base and its types file (SPEC §11).
    Culture,
    Translation,
}

impl Category {
    /// The name `select`, `ignore` and `--select` use: `structure`, `compat`, ….
    pub fn name(self) -> &'static str {
        match self {
            Category::Structure => "structure",
            Category::Tour => "tour",
            Category::Content => "content",
            Category::Compat => "compat",
            Category::Mission => "mission",
            Category::Culture => "culture",
            Category::Translation => "translation",
            Category::Map => "map",
        }
    }

    pub fn title(self) -> &'static str {
        match self {
            Category::Structure => "Structure",
            Category::Tour => "Tour",
            Category::Content => "Content",
            Category::Compat => "Reference-reader compatibility",
            Category::Map => "Map",
            Category::Mission => "Mission",
            Category::Culture => "Culture knowledge base",
            Category::Translation => "Translation",
        }
    }
}
