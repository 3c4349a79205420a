//! What suppression comments silence (SPEC §7): `# ekb: ignore[RULE, …]` silences those
//! rules' findings on the line it covers, `# ekb: ignore-file[RULE, …]` in the whole file
//! ([`crate::syntax::suppression`] reads them). A name may also be a category (`content`).
//! A suppression that silences nothing is an `unused-suppression` finding.
//! `ekb check --add-ignore` writes one above every line with findings ([`add_ignores`]).

use std::collections::BTreeMap;

use crate::diagnostic::{Diagnostic, Rule};
use crate::rules::selection::{RuleSelector, RuleSet};
use crate::rules::structure::unused_suppression;
use crate::syntax::suppression::{find, may_have_suppressions, Name, Scope, Suppression};
use crate::syntax::{lines_from, Body, Span, BOM};

/// Drops the findings of `diagnostics` (sorted by position) that `text`'s suppressions
/// silence, and adds an `unused-suppression` finding for each suppression that silences
/// nothing (if `rules` runs that rule). `dropped` tells how many findings of a rule were
/// counted but not kept: a suppression of such a rule may silence one of them, so it is
/// never called unused.
///
/// `lines`, if known, is how many lines [`crate::syntax::suppression::may_be_one`] holds
/// for: with none, the text is not read again.
pub fn apply(
    text: &str,
    lines: Option<u32>,
    diagnostics: &mut Vec<Diagnostic>,
    rules: &RuleSet,
    dropped: impl Fn(&'static Rule) -> usize,
) -> Suppressed {
    let mut suppressed = Suppressed::default();
    if lines == Some(0) || !may_have_suppressions(text) {
        return suppressed;
    }
    let (suppressions, malformed) = find(text);
    let resolved = resolve(text, &suppressions);
    // For each suppression, which of its names silenced something.
    let mut used: Vec<Vec<bool>> = suppressions
        .iter()
        .map(|s| vec![false; s.names.len()])
        .collect();
    let scopes = Scopes::new(&suppressions, &resolved);
    let file_wide = &scopes.file_wide;
    let silences = |diagnostic: &Diagnostic, used: &mut Vec<Vec<bool>>| {
        let mut hit = false;
        for (index, n, selector) in scopes.at(text, diagnostic.span.start) {
            if selector.matches(diagnostic.rule) {
                used[index][n] = true;
                hit = true;
            }
        }
        hit
    };
    diagnostics.retain(|diagnostic| {
        let hit = silences(diagnostic, &mut used);
        if hit {
            suppressed.add(diagnostic.rule, 1);
        }
        !hit
    });
    // A file-wide suppression silences the findings not kept as well.
    for &(index, n, selector) in file_wide {
        for rule in crate::rules::ALL
            .iter()
            .filter(|rule| selector.matches(rule))
        {
            let more = dropped(rule);
            if more > 0 {
                used[index][n] = true;
                suppressed.add(rule, more);
            }
        }
    }
    let mut unused = Vec::new();
    for ((suppression, used), resolved) in suppressions.iter().zip(&used).zip(&resolved) {
        let unused_names: Vec<(&Name, Option<&str>)> = suppression
            .names
            .iter()
            .zip(used)
            .zip(resolved)
            .filter(|&((_, &used), selector)| {
                !used
                    && match selector {
                        // Off for this file, or with findings not kept: it may well be needed.
                        Ok(selector) => crate::rules::ALL.iter().any(|rule| {
                            selector.matches(rule) && rules.is_enabled(rule) && dropped(rule) == 0
                        }),
                        Err(_) => true,
                    }
            })
            .map(|((name, _), selector)| (name, selector.as_ref().err().map(String::as_str)))
            .collect();
        if !unused_names.is_empty() {
            unused.push(unused_suppression::finding(
                text,
                suppression,
                &unused_names,
            ));
        }
    }
    unused.extend(
        malformed
            .iter()
            .map(|m| unused_suppression::malformed(text, m)),
    );
    if rules.is_enabled(&unused_suppression::UNUSED_SUPPRESSION) {
        for finding in unused {
            // Only a file-wide suppression reaches a comment line.
            if !silences(&finding, &mut used) {
                diagnostics.push(finding);
                suppressed.unused += 1;
            }
        }
    }
    suppressed
}

/// What each name of each suppression selects, or why it names nothing (read once: a name
/// that is no rule's is compared with every rule's to suggest one).
type Resolved = Vec<Vec<Result<RuleSelector, String>>>;

fn resolve(text: &str, suppressions: &[Suppression]) -> Resolved {
    suppressions
        .iter()
        .map(|suppression| {
            let names = suppression.names.iter();
            names
                .map(|name| RuleSelector::parse(name.span.text(text)))
                .collect()
        })
        .collect()
}

/// The names of the suppressions of a file, by what they cover, each as (suppression,
/// name, selector).
struct Scopes {
    file_wide: Vec<(usize, usize, RuleSelector)>,
    /// By the start of the line they cover.
    by_line: BTreeMap<u32, Vec<(usize, usize, RuleSelector)>>,
}

impl Scopes {
    fn new(suppressions: &[Suppression], resolved: &Resolved) -> Scopes {
        let mut by_line: BTreeMap<u32, Vec<_>> = BTreeMap::new();
        for (index, suppression) in suppressions.iter().enumerate() {
            if let Scope::Line(Some(target)) = suppression.scope {
                for (n, selector) in resolved[index].iter().enumerate() {
                    if let Ok(selector) = *selector {
                        by_line
                            .entry(target.start)
                            .or_default()
                            .push((index, n, selector));
                    }
                }
            }
        }
        Scopes {
            file_wide: selectors_of(suppressions, resolved, Scope::File),
            by_line,
        }
    }

    /// The names that cover offset `at` of `text`: those of its line, and the file's.
    fn at(&self, text: &str, at: u32) -> impl Iterator<Item = (usize, usize, RuleSelector)> + '_ {
        let line_start = text[..at as usize]
            .rfind('\n')
            .map_or(0, |newline| newline + 1) as u32;
        let on_line = self.by_line.get(&line_start).into_iter().flatten();
        on_line.chain(&self.file_wide).copied()
    }
}

/// Whether a suppression of `text` silences a finding of a rule at an offset, asked of
/// findings not kept as findings (the fixes `ekb fix` keeps of them); `None` if `text`
/// has no suppression (`lines`: as [`apply`] takes it).
pub fn silencer(text: &str, lines: Option<u32>) -> Option<impl Fn(&Rule, u32) -> bool + '_> {
    if lines == Some(0) || !may_have_suppressions(text) {
        return None;
    }
    let suppressions = find(text).0;
    let scopes = Scopes::new(&suppressions, &resolve(text, &suppressions));
    Some(move |rule: &Rule, at: u32| {
        scopes
            .at(text, at)
            .any(|(_, _, selector)| selector.matches(rule))
    })
}

/// The names of the suppressions of `scope`, as (suppression, name, selector).
fn selectors_of(
    suppressions: &[Suppression],
    resolved: &Resolved,
    scope: Scope,
) -> Vec<(usize, usize, RuleSelector)> {
    let mut selectors = Vec::new();
    for (index, suppression) in suppressions.iter().enumerate() {
        if suppression.scope == scope {
            for (n, selector) in resolved[index].iter().enumerate() {
                if let Ok(selector) = *selector {
                    selectors.push((index, n, selector));
                }
            }
        }
    }
    selectors
}

/// What [`apply`] did.
#[derive(Debug, Default)]
pub struct Suppressed {
    /// How many findings of each rule suppressions silenced (a file-wide one, all of them,
    /// kept or only counted).
    pub silenced: Vec<(&'static Rule, usize)>,
    /// How many `unused-suppression` findings it added.
    pub unused: usize,
}

impl Suppressed {
    fn add(&mut self, rule: &'static Rule, n: usize) {
        match self
            .silenced
            .iter_mut()
            .find(|(r, _)| std::ptr::eq(*r, rule))
        {
            Some((_, count)) => *count += n,
            None => self.silenced.push((rule, n)),
        }
    }
}

/// `text` with a suppression above every line that has findings in `diagnostics`, naming
/// their rules (`ekb check --add-ignore`), and how many comments were written or extended. A
/// line that already has a suppression above it gets the new names added to that one. A
/// finding on a comment or blank line (which an `ignore` cannot reach), or past the last
/// line, is silenced for the whole file by an `ignore-file` at the top.
pub fn add_ignores(text: &str, diagnostics: &[Diagnostic]) -> (String, usize) {
    let (suppressions, _) = find(text);
    // The names each line start needs, and those the whole file needs.
    let mut per_line: BTreeMap<usize, Vec<&'static str>> = BTreeMap::new();
    let mut file_wide: Vec<&'static str> = Vec::new();
    for diagnostic in diagnostics {
        let at = diagnostic.span.start as usize;
        let line_start = text[..at.min(text.len())]
            .rfind('\n')
            .map_or(0, |newline| newline + 1);
        let line = lines_from(text, line_start).next();
        match line {
            Some(line) if matches!(line.body, Body::Entry { .. }) && at < text.len() => per_line
                .entry(line_start)
                .or_default()
                .push(diagnostic.rule.name),
            _ => file_wide.push(diagnostic.rule.name),
        }
    }
    let mut edits: Vec<(Span, String)> = Vec::new();
    for (&line_start, names) in &per_line {
        let above = suppressions.iter().rev().find(|s| {
            s.scope == Scope::Line(Some(Span::new(line_start, line_end(text, line_start))))
        });
        match above {
            Some(existing) => edits.push(extend(text, existing, names)),
            None => {
                let ending = match lines_from(text, line_start).next() {
                    Some(line) if line.ending.as_str() == "\r\n" => "\r\n",
                    _ => "\n",
                };
                let start = skip_bom(text, line_start);
                edits.push((
                    Span::empty_at(start),
                    format!("# ekb: ignore[{}]{ending}", joined(names)),
                ));
            }
        }
    }
    if !file_wide.is_empty() {
        match suppressions.iter().find(|s| s.scope == Scope::File) {
            Some(existing) => edits.push(extend(text, existing, &file_wide)),
            None => edits.push((
                Span::empty_at(skip_bom(text, 0)),
                format!("# ekb: ignore-file[{}]\n", joined(&file_wide)),
            )),
        }
    }
    edits.sort_by_key(|(span, _)| (span.start, span.end));
    let mut out = String::with_capacity(text.len() + edits.len() * 40);
    let mut at = 0;
    for (span, replacement) in &edits {
        out.push_str(&text[at..span.start as usize]);
        out.push_str(replacement);
        at = span.end as usize;
    }
    out.push_str(&text[at..]);
    (out, edits.len())
}

/// Where the line starting at `start` ends (after its newline).
fn line_end(text: &str, start: usize) -> usize {
    lines_from(text, start)
        .next()
        .map_or(text.len(), |line| line.span.end as usize)
}

/// After a byte-order mark at `offset` 0: a comment put before it would move it into the
/// file, where it is no byte-order mark.
fn skip_bom(text: &str, offset: usize) -> usize {
    if offset == 0 && text.starts_with(BOM) {
        BOM.len()
    } else {
        offset
    }
}

/// The edit that adds `names` to `existing`'s list.
fn extend(text: &str, existing: &Suppression, names: &[&str]) -> (Span, String) {
    let mut all: Vec<&str> = existing.names.iter().map(|n| n.span.text(text)).collect();
    all.extend_from_slice(names);
    (existing.list, joined(&all))
}

/// The names, sorted, each once, comma-separated.
fn joined(names: &[&str]) -> String {
    let mut names = names.to_vec();
    names.sort_unstable();
    names.dedup();
    names.join(", ")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_category_silences_its_rules_and_an_off_rule_is_never_unused() {
        use crate::model::build::Options;
        use crate::rules::selection::Choice;
        let text = "# ekb: ignore[content]\n\
                    preGestureMessageEnglish 1 the the  \n\
                    # ekb: ignore[tour-missing, key-case]\n\
                    preGestureMessageIsiZulu 1 Sawubona\n";
        let source = crate::SourceFile::from_bytes("t", text.into());
        let names = |rules: &RuleSet| -> Vec<&str> {
            let checked = crate::check::check_with(&source, &Options::default(), rules);
            checked
                .diagnostics
                .iter()
                .map(|d| d.rule.name)
                .filter(|n| *n != "missing-field")
                .collect()
        };
        // repeated-word and trailing-whitespace are silenced; tour-missing is at line 1,
        // not below the second comment, and key-case finds nothing there.
        assert_eq!(
            names(&RuleSet::default()),
            ["tour-missing", "unused-suppression"]
        );
        let without_tour = Choice {
            ignore: vec![
                RuleSelector::parse("tour").unwrap(),
                RuleSelector::parse("key-case").unwrap(),
            ],
            ..Choice::default()
        };
        assert!(names(&RuleSet::chosen(&[&without_tour])).is_empty());
    }

    #[test]
    fn a_misspelt_name_is_unused_with_the_name_it_may_mean() {
        use crate::model::build::Options;
        let text = "# ekb: ignore[repeated-word, repeated-wrod]\n\
                    preGestureMessageEnglish 1 the the\n";
        let source = crate::SourceFile::from_bytes("t", text.into());
        let checked = crate::check::check(&source, &Options::default());
        let unused: Vec<_> = checked
            .diagnostics
            .iter()
            .filter(|d| d.rule.name == "unused-suppression")
            .collect();
        assert_eq!(unused.len(), 1, "{:?}", checked.diagnostics);
        assert_eq!(
            unused[0].message,
            "this suppression of `repeated-wrod` silences nothing (`repeated-wrod` is no rule or \
             category; did you mean `repeated-word`?): the robot skips the comment, but it would \
             hide a later finding here"
        );
        let fix = unused[0].fix.as_ref().expect("a fix");
        assert_eq!(fix.edits[0].replacement, "repeated-word");
        assert!(checked
            .diagnostics
            .iter()
            .all(|d| d.rule.name != "repeated-word"));
    }

    #[test]
    fn ignores_are_added_above_lines_and_merged_into_those_there() {
        let rule = |name| crate::rules::by_name(name).unwrap();
        let at = |name, start: usize| Diagnostic::new(rule(name), Span::new(start, start + 1), "x");
        let text = "# ekb: ignore[key-case]\nkey 1 x\r\nother 2 y\r\n\n";
        let diagnostics = [
            at("repeated-word", 24),
            at("untranslated-message", 35),
            at("unknown-key", 35),
            at("trailing-whitespace", 44),
        ];
        let (new, count) = add_ignores(text, &diagnostics);
        assert_eq!(count, 3);
        assert_eq!(
            new,
            "# ekb: ignore-file[trailing-whitespace]\n# ekb: ignore[key-case, repeated-word]\nkey 1 x\r\n\
             # ekb: ignore[unknown-key, untranslated-message]\r\nother 2 y\r\n\n"
        );
    }
}
