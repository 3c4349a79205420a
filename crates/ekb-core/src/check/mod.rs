//! The whole check of one file: the model and every finding, sorted by position.
//!
//! A huge or broken file can have millions of findings of one rule (a binary file has an
//! `unknown-key` on nearly every line, each finding a few hundred bytes). So that memory
//! stays bounded, only the first findings of each rule are kept in [`Checked::diagnostics`]
//! (in the order the rules find them; see [`kept_at_most`]). What is *shown*
//! ([`Checked::shown`]) is capped at [`MAX_SHOWN_PER_RULE`] of each rule, followed by one
//! note saying how many more there are. Every output format shows the same capped list, so
//! output stays bounded whatever the input. Of a rule that `ekb fix` can fix, up to
//! [`crate::source::MAX_KEPT_PER_RULE`] are kept, so that one run of `fix` applies that many fixes.

use crate::diagnostic::fix_list::FixList;
use crate::diagnostic::{
    kept_at_most, Diagnostic, Diagnostics, Label, Rule, RuleCounts, Severity, MAX_SHOWN_PER_RULE,
};
use crate::map::LabMap;
use crate::model::build::{build, Options, Unheeded};
use crate::model::KnowledgeBase;
use crate::robot::Reader;
use crate::rules::selection::{RuleSelector, RuleSet};
use crate::rules::{self, compat, structure};
use crate::syntax::Span;
use std::collections::HashMap;

pub use summary::{Hidden, RuleCount, Summary};

mod summary;
pub mod suppression;
use crate::source::SourceFile;

/// Which of the robot's files a checked file is (SPEC §11): most are environment knowledge
/// bases; `ekb check` also takes the mission and the culture knowledge base's two files.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FileKind {
    EnvironmentKnowledgeBase,
    /// The behaviour tree (`labTour.xml`).
    Mission,
    /// `cultureKnowledgeBaseInput.dat`.
    CultureKnowledgeBase,
    /// `cultureKnowledgeValueTypesInput.dat`.
    CultureValueTypes,
}

/// A checked file: what the robot would load, and what is wrong with it.
#[derive(Debug)]
pub struct Checked<'a> {
    pub source: &'a SourceFile,
    pub kind: FileKind,
    /// Empty unless the file is an environment knowledge base.
    pub kb: KnowledgeBase<'a>,
    /// The version of the robot's reader it was checked against (of an environment
    /// knowledge base; the other kinds of file have readers of their own).
    pub reader: Reader,
    /// The findings (at most [`kept_at_most`] of each rule), sorted by position.
    pub diagnostics: Vec<Diagnostic>,
    /// For each rule with more than [`MAX_SHOWN_PER_RULE`] findings, a note
    /// "… and N more", placed where the first finding not shown is.
    pub omitted: Vec<Diagnostic>,
    /// How many findings of each rule were reported, kept or not.
    counts: RuleCounts,
    /// The rules that ran, and their severities.
    rules: RuleSet,
    /// Of a [`check_for_fix`], the fix of every finding, kept or not, in the order of the
    /// findings; empty otherwise.
    pub fixes: FixList,
}

impl Checked<'_> {
    /// The counts of findings, including those not kept (counted at their rule's severity).
    pub fn summary(&self) -> Summary {
        let mut summary = Summary {
            files: 1,
            ..Summary::default()
        };
        let mut kept = RuleCounts::default();
        for diagnostic in &self.diagnostics {
            summary.add(diagnostic);
            kept.bump(diagnostic.rule);
        }
        for &(rule, count) in &self.counts.0 {
            let not_kept = count.saturating_sub(kept.get(rule));
            if not_kept > 0 {
                summary.count(RuleCount {
                    rule,
                    severity: self.rules.severity(rule),
                    count: not_kept,
                    // Each one `ekb fix` fixes, kept here or not.
                    fixable: if rule.fixable { not_kept } else { 0 },
                    unsafe_fixable: 0,
                });
            }
        }
        summary
    }

    /// This check as it would be without the rules that `ignored` selects, or `None` if
    /// that cannot be told without checking again: a suppression comment in the file may
    /// name them (one that silences nothing is only an `unused-suppression` finding while
    /// the rules it names run).
    pub fn ignoring(mut self, ignored: &[RuleSelector]) -> Option<Self> {
        // The model counted the comments that may be one as it was built: where it did,
        // the text is not searched again.
        let may_have_suppressions = match self.kb.lines.suppression_lines {
            Some(lines) => lines > 0,
            None => crate::syntax::suppression::may_have_suppressions(self.source.text()),
        };
        if may_have_suppressions {
            return None;
        }
        let kept = |rule: &Rule| !ignored.iter().any(|selector| selector.matches(rule));
        self.diagnostics.retain(|d| kept(d.rule));
        self.omitted.retain(|d| kept(d.rule));
        self.counts.0.retain(|(rule, _)| kept(rule));
        self.fixes.retain(|fix| kept(fix.rule));
        self.rules.ignore(ignored);
        Some(self)
    }

    pub fn has_errors(&self) -> bool {
        self.diagnostics
            .iter()
            .any(|d| d.severity() == crate::Severity::Error)
    }

    /// The same file with only its errors (for commands that stop on errors and would bury
    /// them under the warnings).
    pub fn errors_only(mut self) -> Self {
        let is_error = |d: &Diagnostic| d.severity() == crate::Severity::Error;
        self.diagnostics.retain(is_error);
        self.omitted.retain(is_error);
        self
    }

    /// Adds findings made about this file from another file's point of view (the mission's
    /// about its tour), keeping them in order.
    pub fn extend(&mut self, more: Vec<Diagnostic>) {
        if more.is_empty() {
            return;
        }
        self.diagnostics.extend(more);
        sort_by_position(&mut self.diagnostics);
    }

    /// The findings that say the reader crashes on the file (a tree too deep, more
    /// culturalKnowledge words in one location than the reader holds, as it counts them,
    /// with another line of that location).
    pub fn reader_crashes(&self) -> Vec<Diagnostic> {
        use rules::compat::{
            compat_cultural_word_split as split, compat_indented_line as indented,
            compat_reader_crash as crash, compat_too_many_cultural_keys as too_many,
        };
        let crashes_at = |id: Option<u32>| {
            id.and_then(|id| self.kb.location(id))
                .is_some_and(|location| too_many::crashes(location, self.reader))
        };
        let about_words = |rule| {
            std::ptr::eq(rule, &split::COMPAT_CULTURAL_WORD_SPLIT)
                || std::ptr::eq(rule, &too_many::COMPAT_TOO_MANY_CULTURAL_KEYS)
        };
        self.diagnostics
            .iter()
            .filter(|d| {
                (std::ptr::eq(d.rule, &crash::COMPAT_READER_CRASH)
                    && d.severity() == Severity::Error)
                    || (about_words(d.rule) && crashes_at(d.location_id))
                    || (std::ptr::eq(d.rule, &indented::COMPAT_INDENTED_LINE)
                        && indented::crashes_on_words_of(
                            &self.kb,
                            d.location_id,
                            d.span.start as usize,
                            self.reader,
                        ))
            })
            .cloned()
            .collect()
    }

    /// The findings to show, in order: the first [`MAX_SHOWN_PER_RULE`] of each rule, and
    /// in place of the others the rule's note from [`Checked::omitted`].
    pub fn shown(&self) -> impl Iterator<Item = &Diagnostic> {
        let mut counts = RuleCounts::default();
        self.diagnostics
            .iter()
            .filter_map(move |diagnostic| match counts.bump(diagnostic.rule) {
                n if n <= MAX_SHOWN_PER_RULE => Some(diagnostic),
                n if n == MAX_SHOWN_PER_RULE + 1 => self
                    .omitted
                    .iter()
                    .find(|note| std::ptr::eq(note.rule, diagnostic.rule)),
                _ => None,
            })
    }
}

/// The model of `source` alone, as [`check`] builds it, without a rule run or a finding
/// kept: what `ekb diff` compares. (A file that is no knowledge base has an empty model,
/// as in the check.)
pub fn load<'a>(source: &'a SourceFile, options: &Options) -> KnowledgeBase<'a> {
    if structure::not_a_knowledge_base::check(source.text()).is_some() {
        return KnowledgeBase::default();
    }
    build(source.text(), options, &mut Unheeded)
}

/// Builds the model of `source` and runs every rule on it.
pub fn check<'a>(source: &'a SourceFile, options: &Options) -> Checked<'a> {
    check_with(source, options, &RuleSet::default())
}

/// Builds the model of `source` and runs the rules of `rules` on it, at their severities;
/// the file's suppression comments silence what they name. A fix that the robot's reader
/// would misread the result of is not offered ([`verify_fixes`]).
pub fn check_with<'a>(source: &'a SourceFile, options: &Options, rules: &RuleSet) -> Checked<'a> {
    check_on_map(source, options, rules, None)
}

/// [`check_with`], and with a `map`, the map rules (SPEC §10) too, on the poses as the
/// robot's reader loads them: their findings are chosen, suppressed and graded with the
/// others ([`finish`]), so that a suppression only they use is used.
pub fn check_on_map<'a>(
    source: &'a SourceFile,
    options: &Options,
    rules: &RuleSet,
    map: Option<&LabMap>,
) -> Checked<'a> {
    check_verified(source, options, rules, Diagnostics::default(), map)
}

/// [`check_with`], and the fix of every finding in [`Checked::fixes`], not only of those
/// kept: for `ekb fix`, which then applies every fix in one pass over the file, however
/// many there are (a pass for each ten thousand made a million fixes quadratic). A fix
/// takes a few dozen bytes there, a finding hundreds. The map rules do not run (none has a
/// fix), so a suppression of theirs is never unused here, and never removed.
pub fn check_for_fix<'a>(
    source: &'a SourceFile,
    options: &Options,
    rules: &RuleSet,
) -> Checked<'a> {
    check_verified(
        source,
        options,
        rules,
        Diagnostics::keeping_every_fix(),
        None,
    )
}

/// [`check_on_map`], reporting into `out` (which says what it keeps).
fn check_verified<'a>(
    source: &'a SourceFile,
    options: &Options,
    rules: &RuleSet,
    out: Diagnostics,
    map: Option<&LabMap>,
) -> Checked<'a> {
    let mut checked = check_unverified(source, options, rules, out, map);
    verify_fixes(&mut checked, options);
    checked
}

/// The check of `source` (with the map rules when there is a `map`), reported into `out`
/// (which says what it keeps), its fixes as the rules made them.
fn check_unverified<'a>(
    source: &'a SourceFile,
    options: &Options,
    rules: &RuleSet,
    mut out: Diagnostics,
    map: Option<&LabMap>,
) -> Checked<'a> {
    // Without a map the map rules do not run: a suppression of theirs cannot be judged
    // unused.
    let without_map;
    let rules = match map {
        Some(_) => rules,
        None => {
            let mut off = rules.clone();
            off.ignore(&[RuleSelector::Category(rules::Category::Map)]);
            without_map = off;
            &without_map
        }
    };
    structure::invalid_utf8::check(source, &mut out);
    compat::compat_bom::check(source.text(), &mut out);
    // The source keeps the first invalid range of a bounded number of lines only.
    let unrecorded = source.invalid_utf8_lines() - source.invalid_utf8().len();
    out.count(&structure::invalid_utf8::INVALID_UTF8, unrecorded);
    let foreign = match source.wide() {
        // One finding says it all: the robot loads nothing from it.
        Some(wide) => Some(structure::invalid_utf8::wide(wide)),
        None => structure::not_a_knowledge_base::check(source.text()),
    };
    if let Some(foreign) = foreign {
        // One finding says it all: each of its lines would be an `unknown-key`.
        out.push(foreign);
        let reader = options
            .reader
            .unwrap_or(Reader::default_for(options.dialect));
        let kind = FileKind::EnvironmentKnowledgeBase;
        return finish(source, kind, KnowledgeBase::default(), reader, out, rules);
    }
    let kb = build(source.text(), options, &mut out);
    let reader = options
        .reader
        .unwrap_or_else(|| Reader::default_for(options.dialect.or(kb.dialect)));
    rules::check_model(&kb, source.text(), reader, &mut out);
    if let Some(map) = map {
        let loaded = crate::reader::load(source.text().as_bytes(), reader);
        rules::map::check(&kb, &loaded, map, &mut out);
    }
    finish(
        source,
        FileKind::EnvironmentKnowledgeBase,
        kb,
        reader,
        out,
        rules,
    )
}

/// Gives each finding that follows from another ([`Diagnostic::follows_from`]) a label at
/// its cause's place, the first finding of that rule at its location: an editor shows it as
/// related information, and a report drawn in full underlines the cause's line with it.
fn point_at_causes(diagnostics: &mut [Diagnostic]) {
    if diagnostics.iter().all(|d| d.follows_from.is_none()) {
        return;
    }
    let mut first_of: HashMap<(&'static str, Option<u32>), Span> = HashMap::new();
    for diagnostic in diagnostics.iter() {
        first_of
            .entry((diagnostic.rule.name, diagnostic.location_id))
            .or_insert(diagnostic.span);
    }
    for diagnostic in diagnostics.iter_mut() {
        let Some(cause) = diagnostic.follows_from else {
            continue;
        };
        if let Some(&span) = first_of.get(&(cause.name, diagnostic.location_id)) {
            diagnostic.labels.push(Label {
                span,
                message: format!("because of this ({})", cause.name),
            });
        }
    }
}

/// A checked file of `kind`: the findings of `found` that `rules` chose and no suppression
/// silenced, sorted, at the severities of `rules`. `kb` is empty unless the file is an
/// environment knowledge base.
pub fn finish<'a>(
    source: &'a SourceFile,
    kind: FileKind,
    kb: KnowledgeBase<'a>,
    reader: Reader,
    found: Diagnostics,
    rules: &RuleSet,
) -> Checked<'a> {
    let (mut diagnostics, mut counts, fixes) = found.into_parts();
    let finds_fixes = fixes.is_some();
    let mut fixes = fixes.unwrap_or_default();
    if !rules.is_default() {
        diagnostics.retain(|d| rules.is_enabled(d.rule));
        counts.0.retain(|(rule, _)| rules.is_enabled(rule));
        fixes.retain(|fix| rules.is_enabled(fix.rule));
    }
    sort_by_position(&mut diagnostics);
    fixes.sort_by_position();
    let not_kept = |rule| counts.get(rule).saturating_sub(kept_at_most(rule));
    let suppression_lines = kb.lines.suppression_lines;
    let suppressed = suppression::apply(
        source.text(),
        suppression_lines,
        &mut diagnostics,
        rules,
        not_kept,
    );
    for (rule, n) in suppressed.silenced {
        counts.subtract(rule, n);
    }
    // Only `ekb fix` keeps fixes: a plain check does not read the suppressions again.
    if !fixes.is_empty() {
        if let Some(silenced) = suppression::silencer(source.text(), suppression_lines) {
            fixes.retain(|fix| !silenced(fix.rule, fix.span.start));
        }
    }
    if suppressed.unused > 0 {
        let unused = &structure::unused_suppression::UNUSED_SUPPRESSION;
        counts.add(unused, suppressed.unused);
        sort_by_position(&mut diagnostics);
        if finds_fixes {
            // Their fixes, which remove what silences nothing, are fixes too.
            for d in diagnostics.iter().filter(|d| std::ptr::eq(d.rule, unused)) {
                if let Some(fix) = &d.fix {
                    fixes.push(d.rule, d.span, fix.is_safe(), fix.edits.clone());
                }
            }
            fixes.sort_by_position();
        }
    }
    if !rules.is_default() {
        for diagnostic in &mut diagnostics {
            if let Some(severity) = rules.severity_override(diagnostic.rule) {
                diagnostic.set_severity(severity);
            }
        }
    }
    point_at_causes(&mut diagnostics);
    let omitted = omitted_notes(&diagnostics, &counts);
    Checked {
        source,
        kind,
        kb,
        reader,
        diagnostics,
        omitted,
        counts,
        rules: rules.clone(),
        fixes,
    }
}

/// Drops each fix that guesses (an unsafe one, or one that turns a Unicode space into a
/// plain one) whose line, once fixed, the robot's `reader` would still misread where the
/// fix changed it: the fixed line, checked alone, has an error there about how the robot
/// reads it (`-2.5` as a pose's first number loses its minus on the robot).
fn verify_fixes(checked: &mut Checked<'_>, options: &Options) {
    let guesses = |rule: &Rule, safe: bool| {
        !safe || std::ptr::eq(rule, &structure::unicode_space::UNICODE_SPACE)
    };
    let text = checked.source.text();
    let options = Options {
        reader: Some(checked.reader),
        verbose: false,
        ..*options
    };
    for diagnostic in &mut checked.diagnostics {
        let misread = diagnostic.fix.as_ref().is_some_and(|fix| {
            guesses(diagnostic.rule, fix.is_safe())
                && misread_once_fixed(text, &fix.edits, &options)
        });
        if misread {
            diagnostic.fix = None;
        }
    }
    checked.fixes.retain(|fix| {
        !(guesses(fix.rule, fix.safe) && misread_once_fixed(text, &fix.to_edits(), &options))
    });
}

/// Whether the line of `edits`, once they are applied, has an error about how the robot
/// reads it where they changed it. Edits over more than one line are not checked.
fn misread_once_fixed(text: &str, edits: &[crate::diagnostic::Edit], options: &Options) -> bool {
    let (Some(first), Some(last)) = (
        edits.iter().map(|e| e.span.start as usize).min(),
        edits.iter().map(|e| e.span.end as usize).max(),
    ) else {
        return false;
    };
    if text[first..last].contains('\n') {
        return false;
    }
    let line_start = text[..first].rfind('\n').map_or(0, |newline| newline + 1);
    let line_end = text[last..]
        .find('\n')
        .map_or(text.len(), |at| last + at + 1);
    let mut sorted: Vec<&crate::diagnostic::Edit> = edits.iter().collect();
    sorted.sort_by_key(|edit| edit.span.start);
    let (mut line, mut changed, mut at) = (String::new(), Vec::new(), line_start);
    for edit in sorted {
        line.push_str(&text[at..edit.span.start as usize]);
        let start = line.len();
        line.push_str(&edit.replacement);
        changed.push(crate::syntax::Span::new(start, line.len().max(start + 1)));
        at = edit.span.end as usize;
    }
    line.push_str(&text[at..line_end]);
    let fixed = SourceFile::from_bytes("the fixed line", line.into_bytes());
    let about_reading = |d: &Diagnostic| {
        d.rule.category == rules::Category::Compat
            || [
                "invalid-number",
                "wrong-arity",
                "unicode-space",
                "unknown-key",
                "invalid-id",
            ]
            .contains(&d.rule.name)
    };
    let overlaps = |d: &Diagnostic| {
        changed
            .iter()
            .any(|span| d.span.start < span.end && span.start < d.span.end.max(d.span.start + 1))
    };
    let rules = RuleSet::default();
    check_unverified(&fixed, options, &rules, Diagnostics::default(), None)
        .diagnostics
        .iter()
        .any(|d| d.severity() == crate::Severity::Error && about_reading(d) && overlaps(d))
}

/// Sorts findings by span; byte order is line-then-column order. Ties keep the order the
/// rules reported them in. Sorts small keys and then moves each finding once, in place,
/// instead of merge-sorting the findings themselves with a buffer of half of them.
fn sort_by_position(diagnostics: &mut [Diagnostic]) {
    if diagnostics.is_sorted_by_key(|d| (d.span.start, d.span.end)) {
        return;
    }
    let mut order: Vec<(u32, u32, u32)> = (0..)
        .zip(diagnostics.iter())
        .map(|(i, d)| (d.span.start, d.span.end, i))
        .collect();
    order.sort_unstable();
    // `source[p]` is the index of the finding that belongs at `p`; follow each cycle once.
    let mut source: Vec<u32> = order.into_iter().map(|(_, _, i)| i).collect();
    for start in 0..source.len() {
        let mut at = start;
        while source[at] as usize != at {
            let from = source[at] as usize;
            source[at] = at as u32;
            if from == start {
                break;
            }
            diagnostics.swap(at, from);
            at = from;
        }
    }
}

/// The "… and N more" note of each rule that has more findings than are shown.
fn omitted_notes(diagnostics: &[Diagnostic], counts: &RuleCounts) -> Vec<Diagnostic> {
    let mut seen = RuleCounts::default();
    let mut first_omitted = Vec::new();
    for diagnostic in diagnostics {
        if seen.bump(diagnostic.rule) == MAX_SHOWN_PER_RULE + 1 {
            first_omitted.push(diagnostic);
        }
    }
    first_omitted
        .into_iter()
        .map(|first| {
            let more = counts.get(first.rule).saturating_sub(MAX_SHOWN_PER_RULE);
            Diagnostic::new(
                first.rule,
                first.span,
                format!(
                    "… and {more} more `{}` findings in this file, not shown (ekb shows the first {MAX_SHOWN_PER_RULE} of each rule)",
                    first.rule.name
                ),
            )
            .with_help("fix the ones shown and run ekb check again; the summary counts them all")
            .with_severity(first.severity())
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::source::MAX_KEPT_PER_RULE;

    #[test]
    fn a_check_for_fix_keeps_the_fix_of_every_finding() {
        let lines = 2 * MAX_KEPT_PER_RULE + 1;
        let text = "robotLocationDescription 1 x \n".repeat(lines);
        let source = SourceFile::from_bytes("t", text.into_bytes());
        let checked = check(&source, &Options::default());
        let for_fix = check_for_fix(&source, &Options::default(), &RuleSet::default());
        // The findings are those of a check, and every fix is kept, in order.
        assert_eq!(for_fix.diagnostics, checked.diagnostics);
        assert_eq!(for_fix.summary(), checked.summary());
        assert!(checked.fixes.is_empty());
        assert_eq!(for_fix.fixes.len(), lines);
        let starts: Vec<u32> = for_fix.fixes.iter().map(|fix| fix.span.start).collect();
        assert!(starts.is_sorted());
        assert!(for_fix
            .fixes
            .iter()
            .all(|fix| fix.rule.name == "trailing-whitespace"));
    }

    #[test]
    fn a_suppression_silences_the_fixes_of_findings_not_kept() {
        let lines = MAX_KEPT_PER_RULE + 3;
        let mut text = "robotLocationDescription 1 x \n".repeat(lines);
        text.push_str("# ekb: ignore[trailing-whitespace]\nrobotLocationDescription 1 y \n");
        let source = SourceFile::from_bytes("t", text.into_bytes());
        let for_fix = check_for_fix(&source, &Options::default(), &RuleSet::default());
        assert_eq!(for_fix.fixes.len(), lines);
        let text = format!("# ekb: ignore-file[trailing-whitespace]\n{}", source.text());
        let source = SourceFile::from_bytes("t", text.into_bytes());
        let for_fix = check_for_fix(&source, &Options::default(), &RuleSet::default());
        assert!(for_fix.fixes.is_empty());
    }

    #[test]
    fn findings_beyond_what_is_kept_are_only_counted() {
        let lines = MAX_KEPT_PER_RULE + 7;
        let text = "x \n".repeat(lines);
        let source = SourceFile::from_bytes("t", text.into_bytes());
        let checked = check(&source, &Options::default());
        let kept = |name| {
            let of_rule = |d: &&Diagnostic| d.rule.name == name;
            checked.diagnostics.iter().filter(of_rule).count()
        };
        assert_eq!(kept("unknown-key"), MAX_SHOWN_PER_RULE + 1);
        assert_eq!(kept("trailing-whitespace"), MAX_KEPT_PER_RULE, "fixable");
        assert_eq!(
            checked.summary().errors,
            lines + 1,
            "unknown keys and tour-missing"
        );
        let note = &checked.omitted[0];
        let more = lines - MAX_SHOWN_PER_RULE;
        assert!(note.message.starts_with(&format!("… and {more} more")));
    }

    #[test]
    fn sorting_by_position_is_stable() {
        let rule = rules::ALL[0];
        let at = |start: usize, message: &str| {
            Diagnostic::new(rule, crate::syntax::Span::new(start, start + 1), message)
        };
        let mut diagnostics = vec![
            at(5, "a"),
            at(1, "b"),
            at(5, "c"),
            at(0, "d"),
            at(1, "e"),
            at(9, "f"),
            at(2, "g"),
        ];
        sort_by_position(&mut diagnostics);
        let messages: Vec<&str> = diagnostics.iter().map(|d| d.message.as_str()).collect();
        assert_eq!(messages, ["d", "b", "e", "g", "a", "c", "f"]);
    }

    #[test]
    fn findings_beyond_the_cap_are_summed_up_in_one_note_per_rule() {
        let lines = MAX_SHOWN_PER_RULE + 5;
        // One known key: a file of none is no knowledge base at all (one finding).
        let text = "bogusKey 1 x\n".repeat(lines) + "robotLocationDescription 1 a\n";
        let source = SourceFile::from_bytes("t", text.into_bytes());
        let checked = check(&source, &Options::default());
        let unknown = |d: &&Diagnostic| d.rule.name == "unknown-key";
        let kept = checked.diagnostics.iter().filter(unknown).count();
        assert_eq!(kept, MAX_SHOWN_PER_RULE + 1);
        let shown: Vec<&Diagnostic> = checked.shown().filter(unknown).collect();
        assert_eq!(shown.len(), MAX_SHOWN_PER_RULE + 1);
        let note = shown.last().unwrap();
        assert!(
            note.message
                .starts_with("… and 5 more `unknown-key` findings"),
            "{}",
            note.message
        );
        // The note stands where the first finding not shown is: line 1001.
        assert_eq!(note.span.start as usize, MAX_SHOWN_PER_RULE * 13);
        // And tour-missing, and missing-field of location 1.
        assert_eq!(checked.summary().errors, lines + 2);
        // Other rules (tour-missing, one finding) are untouched.
        assert!(checked.shown().any(|d| d.rule.name == "tour-missing"));
    }
}
