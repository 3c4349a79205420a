//! The fixes of a file's findings, kept without the findings: what `ekb fix` applies.
//!
//! A file can have a million findings to fix (a key miscased on every line). Kept as
//! findings, each with its message, help and fix, they took 450 MB for a 34 MB file; kept
//! here, a fix takes 16 bytes: the finding's span, its rule, whether it is safe, and its
//! one edit of that span, or where its edits are (12 bytes each: a span and the index of a
//! replacement). A replacement is kept once however many edits write it (a key's name).

use std::collections::HashMap;

use super::{Edit, Rule};
use crate::syntax::Span;

/// Replacements no longer than this are kept once, however many edits write them.
const SHARED_LENGTH: usize = 64;

/// At most this many replacements are looked up to be shared (the fixed strings of the
/// rules are a few dozen).
const MOST_SHARED: usize = 1024;

/// The `edit_count` of a fix whose one edit replaces its finding's span.
const ONE_EDIT_OF_ITS_SPAN: u16 = u16::MAX;

/// Fixes in the order their findings were made, or sorted by their findings' positions.
#[derive(Debug, Default)]
pub struct FixList {
    fixes: Vec<Entry>,
    /// The edits of the fixes that have more than one, or one of another span.
    edits: Vec<CompactEdit>,
    replacements: Replacements,
    /// The rules of the fixes, each once, in the order first kept (a handful: a fix names
    /// its rule by its index here).
    rules: Vec<&'static Rule>,
    /// The rule of the last fix kept, and its index.
    last_rule: Option<(&'static Rule, u8)>,
}

/// One fix.
#[derive(Debug, Clone, Copy)]
struct Entry {
    /// Its finding's span: the order fixes are taken in, and the line a suppression names.
    start: u32,
    end: u32,
    /// The index of the replacement of its one edit, of the finding's span, if
    /// `edit_count` is [`ONE_EDIT_OF_ITS_SPAN`] (most fixes); else where its edits start in
    /// [`FixList::edits`].
    edits: u32,
    edit_count: u16,
    /// Its rule's index in [`FixList::rules`].
    rule: u8,
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
#[derive(Clone, Copy)]
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
    pub fn edits(&self) -> impl Iterator<Item = (Span, &'l str)> + 'l {
        let list = self.list;
        let entry = self.entry;
        let (one, others) = match entry.edit_count {
            ONE_EDIT_OF_ITS_SPAN => {
                let one = CompactEdit {
                    start: entry.start,
                    end: entry.end,
                    replacement: entry.edits,
                };
                (Some(one), &list.edits[..0])
            }
            count => {
                let first = entry.edits as usize;
                (None, &list.edits[first..first + usize::from(count)])
            }
        };
        one.into_iter().chain(others.iter().copied()).map(|edit| {
            let replacement = &list.replacements.strings[edit.replacement as usize];
            let span = Span::new(edit.start as usize, edit.end as usize);
            (span, &**replacement)
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
    pub fn push(&mut self, rule: &'static Rule, span: Span, safe: bool, mut edits: Vec<Edit>) {
        let rule = self.rule_index(rule);
        let (edits, edit_count) = match edits.as_mut_slice() {
            [one] if one.span == span => {
                let replacement = std::mem::take(&mut one.replacement);
                (self.replacements.add(replacement), ONE_EDIT_OF_ITS_SPAN)
            }
            _ => {
                let first = self.edits.len() as u32;
                // A fix with more edits than this is no fix a rule makes; its edits past
                // those are not kept (and clash with nothing).
                let count = edits.len().min(usize::from(ONE_EDIT_OF_ITS_SPAN - 1));
                for edit in edits.into_iter().take(count) {
                    let replacement = self.replacements.add(edit.replacement);
                    self.edits.push(CompactEdit {
                        start: edit.span.start,
                        end: edit.span.end,
                        replacement,
                    });
                }
                (first, count as u16)
            }
        };
        self.fixes.push(Entry {
            start: span.start,
            end: span.end,
            edits,
            edit_count,
            rule,
            safe,
        });
    }

    /// The index of `rule` in [`FixList::rules`], added if it is new there; found at once
    /// if it is the last one asked for.
    fn rule_index(&mut self, rule: &'static Rule) -> u8 {
        match self.last_rule {
            Some((last, index)) if std::ptr::eq(last, rule) => index,
            _ => {
                let index = match self
                    .rules
                    .iter()
                    .position(|&known| std::ptr::eq(known, rule))
                {
                    Some(index) => index,
                    None => {
                        self.rules.push(rule);
                        self.rules.len() - 1
                    }
                };
                // The catalogue has fewer than 256 rules.
                let index = u8::try_from(index).expect("fewer than 256 rules");
                self.last_rule = Some((rule, index));
                index
            }
        }
    }

    /// Adds the fixes of `later`, after these.
    pub fn append(&mut self, later: FixList) {
        let edits_before = self.edits.len() as u32;
        let replaced: Vec<u32> = later
            .replacements
            .strings
            .into_iter()
            .map(|replacement| self.replacements.add(replacement.into_string()))
            .collect();
        self.edits.reserve_exact(later.edits.len());
        let edits = later.edits.into_iter().map(|edit| CompactEdit {
            replacement: replaced[edit.replacement as usize],
            ..edit
        });
        self.edits.extend(edits);
        let rules: Vec<u8> = later
            .rules
            .iter()
            .map(|&rule| self.rule_index(rule))
            .collect();
        self.fixes.reserve_exact(later.fixes.len());
        let fixes = later.fixes.into_iter().map(|entry| Entry {
            edits: match entry.edit_count {
                ONE_EDIT_OF_ITS_SPAN => replaced[entry.edits as usize],
                _ => entry.edits + edits_before,
            },
            rule: rules[usize::from(entry.rule)],
            ..entry
        });
        self.fixes.extend(fixes);
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
            rule: self.rules[usize::from(entry.rule)],
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
        assert_eq!(
            list.edits.len(),
            2,
            "the one edit of a finding's span is the fix's own"
        );
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
        later.push(&TRAILING_WHITESPACE, Span::new(2, 3), true, edit(2, ""));
        later.push(&KEY_CASE, Span::new(4, 5), true, edit(4, "b"));
        first.append(later);
        assert_eq!(
            listed(&first),
            [
                (0, vec![(Span::new(0, 1), "a".into())]),
                (2, vec![(Span::new(2, 3), String::new())]),
                (4, vec![(Span::new(4, 5), "b".into())]),
            ]
        );
        let rules: Vec<&str> = first.iter().map(|fix| fix.rule.name).collect();
        assert_eq!(rules, ["key-case", "trailing-whitespace", "key-case"]);
    }
}
