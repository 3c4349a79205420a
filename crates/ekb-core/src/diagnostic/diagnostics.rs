//! Where the rules report their findings ([`Diagnostics`]), and how many of each rule are
//! kept: bounded whatever the input.

use super::fix_list::FixList;
use super::{Diagnostic, Edit, Rule};
use crate::source::MAX_KEPT_PER_RULE;
use crate::syntax::Span;

/// The most findings of one rule shown for one file; the rest are summed up in a note.
pub const MAX_SHOWN_PER_RULE: usize = 1000;

/// How many findings of `rule` are kept for one file: those shown and the first one not
/// shown (where the "… and N more" note stands), or for a fixable rule, the fixes one run
/// of `ekb fix` applies. Keeping no more than that matters on a large file: every location
/// past the 20 the tour can visit has an `unused-location` note.
pub fn kept_at_most(rule: &Rule) -> usize {
    if rule.fixable {
        MAX_KEPT_PER_RULE
    } else {
        MAX_SHOWN_PER_RULE + 1
    }
}

/// Where the rules report their findings: it keeps the first [`kept_at_most`] of each
/// rule, in the order reported, and only counts the others, so that memory stays bounded on
/// any input. A rule that can find something on every line or location makes its findings
/// through [`Diagnostics::push_with`], so that those past the cap are never even built
/// (formatting 100,000 `unused-location` messages to drop 90,000 of them was a tenth of the
/// time of a check; `unknown-key` computes an edit distance to every key). For `ekb fix`,
/// it keeps the fix of every finding as well ([`Diagnostics::keeping_every_fix`]).
#[derive(Debug, Default)]
pub struct Diagnostics {
    kept: Vec<Diagnostic>,
    counts: RuleCounts,
    /// The fix of every finding, kept or not ([`Diagnostics::keeping_every_fix`]).
    fixes: Option<FixList>,
}

impl Diagnostics {
    /// Where the findings are reported for `ekb fix`, which keeps the fix of every finding
    /// as well, kept or not.
    pub fn keeping_every_fix() -> Diagnostics {
        Diagnostics {
            fixes: Some(FixList::default()),
            ..Diagnostics::default()
        }
    }

    /// The findings kept, in the order reported; how many of each rule were reported; and
    /// the fix of every finding, if every fix was kept.
    pub(crate) fn into_parts(self) -> (Vec<Diagnostic>, RuleCounts, Option<FixList>) {
        (self.kept, self.counts, self.fixes)
    }

    /// Where the findings of a part of the file (or of its locations) are reported, to be
    /// [appended](Diagnostics::append) here: kept as these are.
    pub fn part(&self) -> Diagnostics {
        Diagnostics {
            fixes: self.fixes.as_ref().map(|_| FixList::default()),
            ..Diagnostics::default()
        }
    }

    /// Reports a finding.
    pub fn push(&mut self, diagnostic: Diagnostic) {
        let count = self.counts.bump(diagnostic.rule);
        self.keep(diagnostic, count);
    }

    /// Reports a finding of `rule`, made by `make` only if it is kept (or its fix is).
    pub fn push_with(&mut self, rule: &'static Rule, make: impl FnOnce() -> Diagnostic) {
        let count = self.counts.bump(rule);
        if count <= kept_at_most(rule) || (rule.fixable && self.fixes.is_some()) {
            let diagnostic = make();
            debug_assert!(std::ptr::eq(diagnostic.rule, rule), "{}", rule.name);
            self.keep(diagnostic, count);
        }
    }

    /// Reports a finding of `rule` at `span` with a safe fix, made by `make` only if it is
    /// kept; if only its fix is, that fix's edits are made by `edits` alone (the words of a
    /// million findings that nobody reads took most of the time of `ekb fix`).
    pub fn push_fixable_with(
        &mut self,
        rule: &'static Rule,
        span: Span,
        make: impl FnOnce() -> Diagnostic,
        edits: impl FnOnce() -> Vec<Edit>,
    ) {
        let count = self.counts.bump(rule);
        if count <= kept_at_most(rule) {
            let diagnostic = make();
            debug_assert!(std::ptr::eq(diagnostic.rule, rule), "{}", rule.name);
            self.keep(diagnostic, count);
        } else if let Some(fixes) = &mut self.fixes {
            fixes.push(rule, span, true, edits());
        }
    }

    /// Keeps `diagnostic`, the `count`th of its rule, if it is one of the first
    /// [`kept_at_most`]; and its fix, if every fix is kept.
    fn keep(&mut self, mut diagnostic: Diagnostic, count: usize) {
        let kept = count <= kept_at_most(diagnostic.rule);
        if let Some(fixes) = &mut self.fixes {
            let fix = match kept {
                true => diagnostic.fix.clone(),
                false => diagnostic.fix.take(),
            };
            if let Some(fix) = fix {
                fixes.push(diagnostic.rule, diagnostic.span, fix.is_safe(), fix.edits);
            }
        }
        if kept {
            self.kept.push(diagnostic);
        }
    }

    /// Adds the findings of `later`, made over a later part of the file (or of its
    /// locations), as if they had been reported here after these: each rule's cap still
    /// keeps only the first ones.
    pub fn append(&mut self, later: Diagnostics) {
        let mut taken = RuleCounts::default();
        for diagnostic in later.kept {
            let rule = diagnostic.rule;
            if self.counts.get(rule) + taken.bump(rule) <= kept_at_most(rule) {
                self.kept.push(diagnostic);
            }
        }
        for (rule, count) in later.counts.0 {
            self.counts.add(rule, count);
        }
        if let (Some(fixes), Some(later)) = (&mut self.fixes, later.fixes) {
            fixes.append(later);
        }
    }

    /// The findings kept, to be made graver where the robot's reader makes them so.
    pub fn iter_mut(&mut self) -> std::slice::IterMut<'_, Diagnostic> {
        self.kept.iter_mut()
    }

    /// How many findings of `rule` were reported so far, kept or not.
    pub fn reported(&self, rule: &'static Rule) -> usize {
        self.counts.get(rule)
    }

    /// Reports `n` findings of `rule` that are known not to be kept (never made).
    pub fn count(&mut self, rule: &'static Rule, n: usize) {
        if n > 0 {
            self.counts.add(rule, n);
        }
    }
}

/// The findings kept, in the order reported.
impl std::ops::Deref for Diagnostics {
    type Target = [Diagnostic];

    fn deref(&self) -> &[Diagnostic] {
        &self.kept
    }
}

/// How many findings of each rule have been seen (a handful of rules: a list is enough).
#[derive(Debug, Default)]
pub(crate) struct RuleCounts(pub(crate) Vec<(&'static Rule, usize)>);

impl RuleCounts {
    /// Counts one more finding of `rule` and returns its count so far.
    pub(crate) fn bump(&mut self, rule: &'static Rule) -> usize {
        self.add(rule, 1)
    }

    /// Counts `n` more findings of `rule` and returns its count so far.
    pub(crate) fn add(&mut self, rule: &'static Rule, n: usize) -> usize {
        match self.0.iter_mut().find(|(r, _)| std::ptr::eq(*r, rule)) {
            Some((_, count)) => {
                *count += n;
                *count
            }
            None => {
                self.0.push((rule, n));
                n
            }
        }
    }

    /// Counts `n` fewer findings of `rule` (silenced ones).
    pub(crate) fn subtract(&mut self, rule: &'static Rule, n: usize) {
        if let Some((_, count)) = self.0.iter_mut().find(|(r, _)| std::ptr::eq(*r, rule)) {
            *count = count.saturating_sub(n);
        }
    }

    pub(crate) fn get(&self, rule: &'static Rule) -> usize {
        self.0
            .iter()
            .find(|(r, _)| std::ptr::eq(*r, rule))
            .map_or(0, |&(_, count)| count)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn findings_past_the_cap_are_counted_but_never_made() {
        let rule = &crate::rules::content::trailing_whitespace::TRAILING_WHITESPACE;
        let mut out = Diagnostics::default();
        let mut made = 0;
        for _ in 0..MAX_KEPT_PER_RULE + 3 {
            out.push_with(rule, || {
                made += 1;
                Diagnostic::new(rule, Span::new(0, 1), "x")
            });
        }
        out.count(rule, 4);
        assert_eq!((made, out.len()), (MAX_KEPT_PER_RULE, MAX_KEPT_PER_RULE));
        assert_eq!(out.reported(rule), MAX_KEPT_PER_RULE + 7);
    }

    #[test]
    fn appended_findings_keep_the_first_ones_and_count_all() {
        let rule = &crate::rules::tour::unused_location::UNUSED_LOCATION;
        let findings = |from: usize, n: usize| {
            let mut out = Diagnostics::default();
            for start in from..from + n {
                out.push(Diagnostic::new(rule, Span::new(start, start + 1), "x"));
            }
            out
        };
        let mut out = findings(0, 600);
        out.append(findings(600, 700));
        let starts: Vec<u32> = out.iter().map(|d| d.span.start).collect();
        assert_eq!(starts, (0..=MAX_SHOWN_PER_RULE as u32).collect::<Vec<_>>());
        assert_eq!(out.reported(rule), 1300);
    }
}
