//! The fixes of a file's findings, kept without the findings: what `ekb fix` applies.
//!
//! A file can have a million findings to fix (a key miscased on every line). Kept as
//! findings, each with its message, help and fix, they took 450 MB for a 34 MB file; kept
//! here, a fix takes 36 bytes: the finding's span and rule, whether it is safe, and its
//! edits, each a span and the index of its replacement, a string kept once however many
//! edits write it (a key's name, a line ending).

use std::collections::HashMap;

use crate::diagnostic::Edit;
use crate::rules::Rule;
use crate::syntax::Span;

/// Replacements no longer than this are kept once, however many edits write them.
const SHARED_LENGTH: usize = 64;

/// At most this many replacements are looked up to be shared (the fixed strings of the
/// rules are a few dozen).
const MOST_SHARED: usize = 1024;

/// Fixes in the order their findings were made, or sorted by their findings' positions.
#[derive(Debug, Default)]
pub struct FixList {
    fixes: Vec<Entry>,
    edits: Vec<CompactEdit>,
    replacements: Replacements,
}

/// One fix.
#[derive(Debug, Clone, Copy)]
struct Entry {
    rule: &'static Rule,
    /// Its finding's span: the order fixes are taken in, and the line a suppression names.
    start: u32,
    end: u32,
    /// Its edits in [`FixList::edits`].
    first_edit: u32,
    edit_count: u16,
    safe: bool,
}

/// One edit of a fix: its span and its replacement's index in [`Replacements`].
#[derive(Debug, Clone, Copy)]
struct CompactEdit {
    start: u32,
    end: u32,
    replacement: u32,
}

/// The replacements of the edits, the short ones each kept once.
#[derive(Debug, Default)]
struct Replacements {
    strings: Vec<Box<str>>,
    shared: HashMap<Box<str>, u32>,
}

impl Replacements {
    fn add(&mut self, replacement: String) -> u32 {
        if let Some(&index) = self.shared.get(replacement.as_str()) {
            return index;
        }
        let index = self.strings.len() as u32;
        if replacement.len() <= SHARED_LENGTH && self.shared.len() < MOST_SHARED {
            self.shared
                .insert(replacement.clone().into_boxed_str(), index);
        }
        self.strings.push(replacement.into_boxed_str());
        index
    }
}

/// A fix of a [`FixList`], as it is read.
#[derive(Debug, Clone, Copy)]
pub struct ListedFix<'l> {
    pub rule: &'static Rule,
    /// Its finding's span.
    pub span: Span,
    pub safe: bool,
    list: &'l FixList,
    entry: Entry,
}

impl<'l> ListedFix<'l> {
    /// Its edits, in the order the rule made them: each span and replacement.
    pub fn edits(&self) -> impl ExactSizeIterator<Item = (Span, &'l str)> + 'l {
        let list = self.list;
        let first = self.entry.first_edit as usize;
        list.edits[first..first + usize::from(self.entry.edit_count)]
            .iter()
            .map(|edit| {
                let replacement = &list.replacements.strings[edit.replacement as usize];
                (
                    Span::new(edit.start as usize, edit.end as usize),
                    &**replacement,
                )
            })
    }

    /// Its edits, made again.
    pub fn to_edits(&self) -> Vec<Edit> {
        self.edits()
            .map(|(span, replacement)| Edit::replace(span, replacement))
            .collect()
    }
}

impl FixList {
    /// Keeps the fix of a finding of `rule` at `span`: its `edits`, and whether it is safe.
    pub fn push(&mut self, rule: &'static Rule, span: Span, safe: bool, edits: Vec<Edit>) {
        let first_edit = self.edits.len() as u32;
        // A fix with more edits than this is no fix a rule makes; its edits past the
        // first 65,535 are not kept (and clash with nothing).
        let edit_count = edits.len().min(usize::from(u16::MAX)) as u16;
        for edit in edits.into_iter().take(usize::from(edit_count)) {
            let replacement = self.replacements.add(edit.replacement);
            self.edits.push(CompactEdit {
                start: edit.span.start,
                end: edit.span.end,
                replacement,
            });
        }
        self.fixes.push(Entry {
            rule,
            start: span.start,
            end: span.end,
            first_edit,
            edit_count,
            safe,
        });
    }

    /// Adds the fixes of `later`, after these.
    pub fn append(&mut self, later: FixList) {
        let edits_before = self.edits.len() as u32;
        let mut replaced = Vec::with_capacity(later.replacements.strings.len());
        for replacement in later.replacements.strings {
            replaced.push(self.replacements.add(replacement.into_string()));
        }
        self.edits.reserve_exact(later.edits.len());
        self.edits
            .extend(later.edits.into_iter().map(|edit| CompactEdit {
                replacement: replaced[edit.replacement as usize],
                ..edit
            }));
        self.fixes.reserve_exact(later.fixes.len());
        self.fixes
            .extend(later.fixes.into_iter().map(|entry| Entry {
                first_edit: entry.first_edit + edits_before,
                ..entry
            }));
    }

    pub fn len(&self) -> usize {
        self.fixes.len()
    }

    pub fn is_empty(&self) -> bool {
        self.fixes.is_empty()
    }

    /// Sorts the fixes by their findings' positions; ties keep their order.
    pub fn sort_by_position(&mut self) {
        if !self
            .fixes
            .is_sorted_by_key(|entry| (entry.start, entry.end))
        {
            self.fixes.sort_by_key(|entry| (entry.start, entry.end));
        }
    }

    /// Keeps only the fixes for which `keep` is true.
    pub fn retain(&mut self, mut keep: impl FnMut(ListedFix<'_>) -> bool) {
        let mut fixes = std::mem::take(&mut self.fixes);
        fixes.retain(|&entry| keep(self.listed(entry)));
        self.fixes = fixes;
    }

    /// The fixes, in order.
    pub fn iter(&self) -> impl ExactSizeIterator<Item = ListedFix<'_>> + '_ {
        self.fixes.iter().map(|&entry| self.listed(entry))
    }

    fn listed(&self, entry: Entry) -> ListedFix<'_> {
        ListedFix {
            rule: entry.rule,
            span: Span::new(entry.start as usize, entry.end as usize),
            safe: entry.safe,
            list: self,
            entry,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rules::content::trailing_whitespace::TRAILING_WHITESPACE;
    use crate::rules::structure::key_case::KEY_CASE;

    fn listed(list: &FixList) -> Vec<(u32, Vec<(Span, String)>)> {
        list.iter()
            .map(|fix| {
                let edits = fix.edits().map(|(s, r)| (s, r.to_string())).collect();
                (fix.span.start, edits)
            })
            .collect()
    }

    #[test]
    fn keeps_each_fix_and_shares_its_replacements() {
        let mut list = FixList::default();
        for start in [10, 0] {
            let span = Span::new(start, start + 3);
            list.push(&KEY_CASE, span, true, vec![Edit::replace(span, "Key")]);
        }
        let two = vec![Edit::delete(Span::new(5, 6)), Edit::insert(7, "Key")];
        list.push(&TRAILING_WHITESPACE, Span::new(5, 6), false, two);
        assert_eq!(list.replacements.strings.len(), 2, "`Key` and ``");
        list.sort_by_position();
        let key = |start| (Span::new(start, start + 3), "Key".to_string());
        assert_eq!(
            listed(&list),
            [
                (0, vec![key(0)]),
                (
                    5,
                    vec![
                        (Span::new(5, 6), String::new()),
                        (Span::new(7, 7), "Key".into())
                    ]
                ),
                (10, vec![key(10)]),
            ]
        );
        list.retain(|fix| std::ptr::eq(fix.rule, &KEY_CASE));
        assert_eq!(list.len(), 2);
    }

    #[test]
    fn appended_fixes_come_after_with_their_own_edits() {
        let mut first = FixList::default();
        let edit = |start: usize, new: &str| vec![Edit::replace(Span::new(start, start + 1), new)];
        first.push(&KEY_CASE, Span::new(0, 1), true, edit(0, "a"));
        let mut later = FixList::default();
        later.push(&KEY_CASE, Span::new(4, 5), true, edit(4, "b"));
        first.append(later);
        assert_eq!(
            listed(&first),
            [
                (0, vec![(Span::new(0, 1), "a".into())]),
                (4, vec![(Span::new(4, 5), "b".into())]),
            ]
        );
    }
}
