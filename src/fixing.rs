//! Applying the machine-applicable fixes of the diagnostics (`ekb fix`).
//!
//! Each pass checks the text, applies every fix that does not touch the bytes of a fix
//! already taken, and goes again: a fix can make another one possible (a key in the wrong
//! case becomes a key of the other dialect, which `legacy-key` then renames). Only the bytes
//! of the edits change, and the padding after a renamed key, so that an id aligned by
//! `ekb fmt` stays aligned. The passes stop when nothing is left to fix, or after
//! [`MAX_PASSES`] (no rule's fix undoes another's, so this bound is never reached in practice).
//!
//! Each pass checks with [`check_for_fix`], which keeps every finding of a fixable rule
//! (`check` keeps the first [`MAX_KEPT_PER_RULE`](crate::source::MAX_KEPT_PER_RULE)): a file with a million lines to fix is
//! fixed in one pass, in time linear in the file and the fixes.

use std::borrow::Cow;
use std::collections::{BTreeMap, BTreeSet};

use crate::canonical::Document;
use crate::check::{check_for_fix, Checked};
use crate::diagnostic::fix_list::{FixList, ListedFix};
use crate::diagnostic::{Diagnostic, Edit};
use crate::model::build::Options;
use crate::rules::compat::compat_reader_crash::COMPAT_READER_CRASH;
use crate::rules::selection::RuleSet;
use crate::source::SourceFile;
use crate::syntax::Span;

/// The most passes [`fix`] makes.
pub const MAX_PASSES: usize = 10;

/// The outcome of [`fix`].
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Fixed {
    pub text: String,
    /// How many findings of each rule were fixed, by rule name.
    pub counts: BTreeMap<&'static str, usize>,
}

/// Which fixes to apply: those of the rules that run, and the unsafe ones too or not.
#[derive(Debug, Clone, Default)]
pub struct Choice {
    pub rules: RuleSet,
    /// `--unsafe-fixes`: apply the fixes that guess what was meant as well.
    pub unsafe_fixes: bool,
}

/// Applies every safe fix the checks of `source` offer, pass after pass.
pub fn fix(source: &SourceFile, options: &Options) -> Fixed {
    fixes(source, options, &Choice::default(), |fixes| Fixed {
        text: match fixes.outcome {
            Outcome::Unchanged => source.text().to_string(),
            Outcome::Edited(file) => file.text().to_string(),
            Outcome::Balanced { document, .. } => document.render(),
        },
        counts: fixes.counts,
    })
}

/// What the fixes of a file make of it.
#[derive(Debug)]
pub enum Outcome<'f> {
    /// Nothing to fix: the file is checked as it is, never copied (two copies of 60 MB were
    /// most of `ekb fix --diff`'s memory).
    Unchanged,
    /// The text after the fixes' edits.
    Edited(&'f SourceFile),
    /// The file, or its text after the edits, with the location blocks
    /// in the order that builds a balanced tree in the robot's reader: the fix of
    /// `compat-reader-crash`, the one fix that is no edit. Laid out as `ekb fmt` writes,
    /// and not written out yet (`ekb fix --diff` shows it from the layout).
    Balanced {
        /// The text laid out: the file, or its text after the edits.
        file: &'f SourceFile,
        document: Document<'f>,
    },
}

/// What the passes of [`fixes`] made of a file.
#[derive(Debug)]
pub struct Fixes<'f> {
    pub outcome: Outcome<'f>,
    /// How many findings of each rule the fixes fix, by rule name.
    pub counts: BTreeMap<&'static str, usize>,
    /// The check of the text the edits ended with (before any balance: the file itself if
    /// nothing was edited), as [`check_with`](crate::check::check_with) makes it with the
    /// chosen rules; `None` if the passes stopped at [`MAX_PASSES`] before checking it. What
    /// is left to fix by hand is told from it, without checking the text once more.
    pub last_check: Option<Checked<'f>>,
}

/// The fixes of `source` that `choice` allows, pass after pass, given to `then` (which
/// borrows the text they made, held only while it runs).
pub fn fixes<R>(
    source: &SourceFile,
    options: &Options,
    choice: &Choice,
    then: impl FnOnce(Fixes<'_>) -> R,
) -> R {
    let start = Passes {
        counts: BTreeMap::new(),
        done: 0,
        crashes_reader: false,
    };
    pass(source, None, options, choice, start, then)
}

/// Where the passes are.
struct Passes {
    counts: Counts,
    /// How many passes fixed something.
    done: usize,
    /// Whether the order of ids crashes the reader, as the last check found: no edit
    /// changes that order.
    crashes_reader: bool,
}

/// The next pass over `file` (`source` itself, or the text its edits made, `edited`), and
/// the next one after it if it fixed anything. Each pass owns the text it makes, which the
/// next one checks: no text is copied.
fn pass<R>(
    file: &SourceFile,
    edited: Option<&SourceFile>,
    options: &Options,
    choice: &Choice,
    mut passes: Passes,
    then: impl FnOnce(Fixes<'_>) -> R,
) -> R {
    let text = edited.unwrap_or(file);
    // The bound only guards against fixes that would make each other again, which no
    // rule's do.
    if passes.done == MAX_PASSES {
        return then(finish(file, edited, None, passes, choice));
    }
    let mut checked = check_for_fix(text, options, &choice.rules);
    passes.crashes_reader = checked
        .diagnostics
        .iter()
        .any(|d| std::ptr::eq(d.rule, &COMPAT_READER_CRASH));
    let allowed = |fix: &ListedFix<'_>| choice.unsafe_fixes || fix.safe;
    let Some(chosen) = choose(text.text(), &checked.fixes, allowed) else {
        return then(finish(file, edited, Some(checked), passes, choice));
    };
    // The check is done with: only the fixes are kept while the new text is written.
    let fixes = std::mem::take(&mut checked.fixes);
    drop(checked);
    // The text read is let go of as the new one is written (a mapped file's pages): the
    // two are not held whole at once.
    let new = chosen.write(text.text(), &fixes, |end| text.release_before(end));
    drop(fixes);
    for (rule, count) in chosen.counts {
        *passes.counts.entry(rule).or_insert(0) += count;
    }
    passes.done += 1;
    let next = SourceFile::from_bytes(file.name(), new.into_bytes());
    // `--verbose` shows the file as read, once; later passes read it again.
    let options = Options {
        verbose: false,
        ..*options
    };
    pass(file, Some(&next), &options, choice, passes, then)
}

/// What the passes made of `source`, its text now `edited` (if any edit was made), whose
/// check is `last` (if it was checked): balanced too if the order of its ids crashes the
/// reader.
fn finish<'f>(
    source: &'f SourceFile,
    edited: Option<&'f SourceFile>,
    last: Option<Checked<'f>>,
    passes: Passes,
    choice: &Choice,
) -> Fixes<'f> {
    let mut counts = passes.counts;
    let text = edited.unwrap_or(source);
    let balance = passes.crashes_reader && choice.rules.is_enabled(&COMPAT_READER_CRASH);
    // A file the layout cannot write keeps its order.
    let balanced = balance
        .then(|| Document::parse_balanced(text.text()).ok())
        .flatten();
    let outcome = match (balanced, edited) {
        (Some(document), _) => {
            *counts.entry(COMPAT_READER_CRASH.name).or_insert(0) += 1;
            Outcome::Balanced {
                file: text,
                document,
            }
        }
        (None, Some(edited)) => Outcome::Edited(edited),
        (None, None) => Outcome::Unchanged,
    };
    Fixes {
        outcome,
        counts,
        last_check: last,
    }
}

/// `bytes` with every byte that is not part of a UTF-8 sequence read as Windows-1252 (the
/// Latin-1 of Windows editors), or `None` if they hold a NUL (UTF-16 or UTF-32, more likely)
/// or a byte Windows-1252 leaves undefined. Valid UTF-8 is kept as it is.
pub fn from_latin1(bytes: &[u8]) -> Option<String> {
    /// Windows-1252's characters for 0x80..=0x9F (`None`: undefined).
    const HIGH: [Option<char>; 32] = [
        Some('€'),
        None,
        Some('‚'),
        Some('ƒ'),
        Some('„'),
        Some('…'),
        Some('†'),
        Some('‡'),
        Some('ˆ'),
        Some('‰'),
        Some('Š'),
        Some('‹'),
        Some('Œ'),
        None,
        Some('Ž'),
        None,
        None,
        Some('‘'),
        Some('’'),
        Some('“'),
        Some('”'),
        Some('•'),
        Some('–'),
        Some('—'),
        Some('˜'),
        Some('™'),
        Some('š'),
        Some('›'),
        Some('œ'),
        None,
        Some('ž'),
        Some('Ÿ'),
    ];
    if bytes.contains(&0) {
        return None;
    }
    let mut out = String::with_capacity(bytes.len() + bytes.len() / 8);
    for chunk in bytes.utf8_chunks() {
        out.push_str(chunk.valid());
        for &byte in chunk.invalid() {
            out.push(match byte {
                0x80..=0x9F => HIGH[usize::from(byte - 0x80)]?,
                _ => char::from(byte),
            });
        }
    }
    Some(out)
}

/// Applies the fixes of `diagnostics` to `text`, each whole or not at all, skipping a fix
/// whose edits clash with those of one taken before it. Returns the new text and how many
/// fixes of each rule it applied, or `None` if there was none to apply.
pub fn apply(text: &str, diagnostics: &[Diagnostic]) -> Option<(String, Counts)> {
    let mut fixes = FixList::default();
    for diagnostic in diagnostics {
        if let Some(fix) = &diagnostic.fix {
            fixes.push(
                diagnostic.rule,
                diagnostic.span,
                fix.is_safe(),
                fix.edits.clone(),
            );
        }
    }
    apply_where(text, &fixes, |_| true)
}

/// How many fixes of each rule were applied, by rule name.
pub type Counts = BTreeMap<&'static str, usize>;

/// [`apply`], to the fixes of `fixes` that are `allowed`, in their order.
fn apply_where(
    text: &str,
    fixes: &FixList,
    allowed: impl Fn(&ListedFix<'_>) -> bool,
) -> Option<(String, Counts)> {
    let chosen = choose(text, fixes, allowed)?;
    Some((chosen.write(text, fixes, |_| {}), chosen.counts))
}

/// The fixes of a [`FixList`] chosen to be applied.
struct Chosen {
    /// Whether each fix is applied.
    taken: Vec<bool>,
    /// Whether the edits of the fixes applied come in order of position.
    in_order: bool,
    counts: Counts,
}

/// The fixes of `fixes` that are `allowed` and whose edits clash with none of those taken
/// before, in their order; `None` if there is none. While each edit taken comes after the
/// last one (nearly always), the edits are only counted; after one that does not, every
/// edit taken is kept in a tree.
fn choose(text: &str, fixes: &FixList, allowed: impl Fn(&ListedFix<'_>) -> bool) -> Option<Chosen> {
    let mut accepted = Accepted::InOrder(None);
    let mut taken = vec![false; fixes.len()];
    let mut counts = Counts::new();
    let mut spans = Vec::new();
    for (index, fix) in fixes.iter().enumerate() {
        if !allowed(&fix) {
            continue;
        }
        spans.clear();
        spans.extend(
            fix.edits()
                .map(|(span, new)| keeping_id_column(text, span, new).0),
        );
        let fits = match &mut accepted {
            Accepted::InOrder(last) if follows(*last, &spans) => true,
            _ => {
                let taken_before =
                    || edits_taken(text, fixes, &taken[..index]).map(|(span, _)| span);
                let all = accepted.all(taken_before);
                spans.iter().all(|&span| !clashes(all, span)) && !clash_among(&spans)
            }
        };
        if fits {
            accepted.add(&spans);
            taken[index] = true;
            *counts.entry(fix.rule.name).or_insert(0) += 1;
        }
    }
    (!counts.is_empty()).then_some(Chosen {
        taken,
        in_order: matches!(accepted, Accepted::InOrder(_)),
        counts,
    })
}

impl Chosen {
    /// `text` with the edits of the fixes chosen of `fixes` made, written in one pass
    /// (the edits sorted first if they do not come in order); told to `copied` as in
    /// [`write_edits`].
    fn write(&self, text: &str, fixes: &FixList, copied: impl FnMut(usize)) -> String {
        let edits = edits_taken(text, fixes, &self.taken);
        if self.in_order {
            return write_edits(text, edits, copied);
        }
        let mut edits: Vec<(Span, Cow<'_, str>)> = edits.collect();
        edits.sort_by_key(|(span, _)| (span.start, span.end));
        write_edits(text, edits.into_iter(), copied)
    }
}

/// The edits of the fixes of `fixes` that were `taken` (one flag a fix, in order), in
/// order, each as it is made ([`keeping_id_column`]).
fn edits_taken<'a>(
    text: &'a str,
    fixes: &'a FixList,
    taken: &'a [bool],
) -> impl Iterator<Item = (Span, Cow<'a, str>)> + 'a {
    fixes
        .iter()
        .zip(taken)
        .filter(|&(_, &taken)| taken)
        .flat_map(|(fix, _)| fix.edits())
        .map(|(span, new)| keeping_id_column(text, span, new))
}

/// Applies `edits` to `text`; they must not overlap, and no two may insert at one offset
/// (for `ekb set` and `ekb import --po`, whose edits are one per line).
pub fn splice(text: &str, edits: &[Edit]) -> String {
    let mut sorted: Vec<&Edit> = edits.iter().collect();
    sorted.sort_by_key(|edit| (edit.span.start, edit.span.end));
    debug_assert!(!clash_among(
        &sorted.iter().map(|e| e.span).collect::<Vec<_>>()
    ));
    write_edits(
        text,
        sorted.iter().map(|e| (e.span, e.replacement.as_str())),
        |_| {},
    )
}

/// How much of the text [`write_edits`] copies between two calls of its `copied`.
const COPIED_STEP: usize = 4 << 20;

/// `text` with `edits` made, given in order of position, none overlapping another. Tells
/// `copied` how far into `text` it has read, every [`COPIED_STEP`] bytes or so.
fn write_edits(
    text: &str,
    edits: impl Iterator<Item = (Span, impl AsRef<str>)>,
    mut copied: impl FnMut(usize),
) -> String {
    let mut out = String::with_capacity(text.len());
    let mut at = 0;
    let mut told = 0;
    for (span, replacement) in edits {
        out.push_str(&text[at..span.start as usize]);
        out.push_str(replacement.as_ref());
        at = span.end as usize;
        if at - told >= COPIED_STEP {
            copied(at);
            told = at;
        }
    }
    out.push_str(&text[at..]);
    out
}

/// The edit of `span` to `new_key`, made to keep the column of the id when it renames the
/// key of a line whose key is padded with spaces up to the id (as `ekb fmt` writes):
/// `robotLocation` becoming `robotLocationPose` takes four of its spaces, and the reverse
/// gives them back. Any other edit is left as it is.
fn keeping_id_column<'e>(text: &str, span: Span, new_key: &'e str) -> (Span, Cow<'e, str>) {
    let (start, end) = (span.start as usize, span.end as usize);
    let old_key = &text[start..end];
    let at_line_start = start == 0 || text.as_bytes()[start - 1] == b'\n';
    let is_word = |word: &str| !word.is_empty() && !word.contains(char::is_whitespace);
    let padding = text[end..].bytes().take_while(|&b| b == b' ').count();
    let id_follows = text[end + padding..]
        .bytes()
        .next()
        .is_some_and(|b| !b.is_ascii_whitespace());
    let same_length = old_key.chars().count() == new_key.chars().count();
    // One space is a separator, not padding (and no layout to keep).
    if same_length
        || !at_line_start
        || !is_word(old_key)
        || !is_word(new_key)
        || padding < 2
        || !id_follows
    {
        return (span, Cow::Borrowed(new_key));
    }
    let column = old_key.chars().count() + padding;
    let new_padding = column.saturating_sub(new_key.chars().count()).max(1);
    (
        Span::new(start, end + padding),
        Cow::Owned(format!("{new_key}{}", " ".repeat(new_padding))),
    )
}

/// The spans of the edits taken, which do not overlap.
#[derive(Debug)]
enum Accepted {
    /// Each taken after the one before (or none taken): the last one.
    InOrder(Option<(u32, u32)>),
    /// Every one, by `(start, end)`.
    Any(BTreeSet<(u32, u32)>),
}

impl Accepted {
    /// Every edit taken, made from `taken` (the spans of the edits taken) the first time.
    fn all<I: Iterator<Item = Span>>(
        &mut self,
        taken: impl FnOnce() -> I,
    ) -> &BTreeSet<(u32, u32)> {
        if let Accepted::InOrder(_) = self {
            *self = Accepted::Any(taken().map(|span| (span.start, span.end)).collect());
        }
        match self {
            Accepted::Any(all) => all,
            Accepted::InOrder(_) => unreachable!("made above"),
        }
    }

    fn add(&mut self, spans: &[Span]) {
        match self {
            Accepted::InOrder(last) => *last = spans.last().map(|s| (s.start, s.end)).or(*last),
            Accepted::Any(all) => all.extend(spans.iter().map(|s| (s.start, s.end))),
        }
    }
}

/// Whether `spans` come each after the one before, the first after `last`: then they
/// clash with no edit taken (which all end before `last` does), nor among themselves.
fn follows(last: Option<(u32, u32)>, spans: &[Span]) -> bool {
    let mut last = last;
    spans.iter().all(|span| {
        let key = (span.start, span.end);
        let after = last.is_none_or(|last| key > last && span.start >= last.1);
        last = Some(key);
        after
    })
}

/// Whether `span` clashes with an edit of `taken`. Since none of those overlap, their ends
/// grow with their starts, so the one just before `span` is the only one that could reach
/// into it.
fn clashes(taken: &BTreeSet<(u32, u32)>, span: Span) -> bool {
    let before = taken.range(..(span.end, span.end)).next_back();
    let reaches_in = before.is_some_and(|&(_, end)| end > span.start);
    // Two insertions at one offset: which goes first is not defined.
    reaches_in || (span.is_empty() && taken.contains(&(span.start, span.end)))
}

/// Whether the edits of one fix clash among themselves (a rule's bug; the fix is skipped).
fn clash_among(spans: &[Span]) -> bool {
    let mut seen = BTreeSet::new();
    spans.iter().any(|&span| {
        let clash = clashes(&seen, span);
        !seen.insert((span.start, span.end)) || clash
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn fixed(text: &str) -> Fixed {
        fix(
            &SourceFile::from_bytes("t", text.into()),
            &Options::default(),
        )
    }

    #[test]
    fn fixes_only_the_broken_bytes() {
        let text = "postGestureMessageenglish 4 We use it  \r\ntourSpecification 1 4";
        let result = fixed(text);
        assert_eq!(
            result.text,
            "postGestureMessageEnglish 4 We use it\ntourSpecification 1 4\n"
        );
        let counts: Vec<(&str, usize)> = result.counts.into_iter().collect();
        assert_eq!(
            counts,
            [
                ("compat-crlf", 1),
                ("compat-no-final-newline", 1),
                ("key-case", 1),
                ("trailing-whitespace", 1)
            ]
        );
    }

    #[test]
    fn a_second_pass_finishes_what_the_first_started() {
        let options = Options {
            reader: Some(crate::robot::Reader::V2025_06),
            ..Options::default()
        };
        let source = SourceFile::from_bytes("t", b"RobotLocation 1 1 2 3\n".to_vec());
        let result = fix(&source, &options);
        assert_eq!(result.text, "robotLocationPose 1 1 2 3\n");
        assert_eq!(result.counts.get("key-case"), Some(&1));
        assert_eq!(result.counts.get("legacy-key"), Some(&1));
    }

    #[test]
    fn more_findings_of_a_rule_than_check_keeps_are_all_fixed_in_one_run() {
        use crate::source::MAX_KEPT_PER_RULE;
        // One more finding than MAX_PASSES passes of MAX_KEPT_PER_RULE could fix.
        let lines = MAX_PASSES * MAX_KEPT_PER_RULE + 1;
        let result = fixed(&" \n".repeat(lines));
        assert_eq!(result.text, "\n".repeat(lines));
        assert_eq!(result.counts.get("trailing-whitespace"), Some(&lines));
    }

    #[test]
    fn a_renamed_key_keeps_the_id_in_its_column() {
        let migrate = |text: &str, dialect| {
            let options = Options {
                dialect: Some(dialect),
                reader: Some(crate::robot::Reader::default_for(Some(dialect))),
                ..Options::default()
            };
            fix(&SourceFile::from_bytes("t", text.into()), &options).text
        };
        let seed = "robotLocation                 1 2.6 8.1 -90\n";
        let current = "robotLocationPose             1 2.6 8.1 -90\n";
        assert_eq!(migrate(seed, crate::model::Dialect::Current), current);
        assert_eq!(migrate(current, crate::model::Dialect::Seed), seed);
        // A key followed by one space, or a tab, is not padded: only the key changes.
        assert_eq!(
            migrate("robotLocation 1 2 3 4\n", crate::model::Dialect::Current),
            "robotLocationPose 1 2 3 4\n"
        );
        assert_eq!(
            migrate("robotLocationPose\t1 2 3 4\n", crate::model::Dialect::Seed),
            "robotLocation\t1 2 3 4\n"
        );
        // Padding too short for the longer key leaves one space.
        assert_eq!(
            migrate("robotLocation  1 2 3 4\n", crate::model::Dialect::Current),
            "robotLocationPose 1 2 3 4\n"
        );
    }

    #[test]
    fn clashing_edits_wait_for_the_next_pass() {
        let mut taken = BTreeSet::new();
        taken.insert((3, 3));
        assert!(clashes(&taken, Span::new(3, 3)));
        assert!(
            !clashes(&taken, Span::new(3, 5)),
            "delete after an insertion"
        );
        assert!(
            !clashes(&taken, Span::new(1, 3)),
            "delete before an insertion"
        );
        taken.insert((5, 9));
        assert!(clashes(&taken, Span::new(8, 10)));
        assert!(clashes(&taken, Span::new(6, 6)));
        assert!(clashes(&taken, Span::new(4, 6)));
        assert!(!clashes(&taken, Span::new(9, 9)));
        // Edits in order need no tree.
        assert!(follows(Some((3, 3)), &[Span::new(3, 5), Span::new(5, 5)]));
        assert!(!follows(Some((3, 3)), &[Span::new(3, 3)]));
        assert!(!follows(Some((3, 5)), &[Span::new(4, 6)]));
        assert!(!follows(None, &[Span::new(4, 6), Span::new(0, 1)]));
    }

    #[test]
    fn fixes_whose_edits_come_before_those_taken_are_written_in_place() {
        let text = "aaa bbb ccc\n";
        let at = |start: usize, new: &str| {
            Diagnostic::new(&COMPAT_READER_CRASH, Span::new(start, start + 3), "")
                .with_fix("", vec![Edit::replace(Span::new(start, start + 3), new)])
        };
        let (fixed, counts) = apply(text, &[at(8, "C"), at(0, "A"), at(4, "B")]).unwrap();
        assert_eq!(fixed, "A B C\n");
        assert_eq!(counts.get(COMPAT_READER_CRASH.name), Some(&3));
    }

    #[test]
    fn the_text_read_is_told_copied_as_the_new_one_is_written() {
        let text = "k 1 v\n".repeat(3 * COPIED_STEP / 6);
        let edits = (0..text.len())
            .step_by(6)
            .map(|at| (Span::new(at, at + 1), "K"));
        let mut told = Vec::new();
        let written = write_edits(&text, edits, |end| told.push(end));
        assert_eq!(written, text.replace("k 1", "K 1"));
        assert_eq!(told.len(), 2, "{told:?}");
        assert!(told[0] >= COPIED_STEP && told[1] - told[0] >= COPIED_STEP);
    }
}
