//! The short paragraphs of `--format human`, which keep a file's errors in a terminal's
//! sight: a rule's many warnings as one paragraph (how many, on which lines, the first
//! one's message, and the command that shows them all: `--show-all`), since twenty placeholders
//! of untranslated messages would otherwise push two errors out of view; and a finding that
//! follows from the one drawn just before it, under it, without drawing the file again.

use super::escape::escape;
use super::{FileReport, LocatedDiagnostic};
use crate::diagnostic::Severity;

/// A rule with more warnings (or infos) than this in a file is shown as a group.
pub const GROUPED_ABOVE: usize = 3;

/// The line numbers a group lists before `and N more`.
const LINES_LISTED: usize = 10;

/// The findings of one rule in one file, shown as one paragraph.
#[derive(Debug)]
pub struct Group<'a> {
    pub rule: &'static str,
    severity: Severity,
    /// Every finding of the rule in the file, shown or not.
    count: usize,
    /// The lines of the first findings shown (at most [`LINES_LISTED`]).
    lines: Vec<u32>,
    first_message: &'a str,
    file: &'a str,
}

/// The groups of `findings` (of `report`, in reading order): each rule with more than
/// [`GROUPED_ABOVE`] warnings or infos, in the order of its first finding. Errors are
/// never grouped: each is drawn.
pub fn groups<'a>(report: &FileReport<'a>, findings: &[&LocatedDiagnostic<'a>]) -> Vec<Group<'a>> {
    let mut groups: Vec<Group<'a>> = Vec::new();
    let mut shown: Vec<usize> = Vec::new();
    for finding in findings.iter().filter(|d| d.severity != Severity::Error) {
        match groups.iter().position(|group| group.rule == finding.rule) {
            Some(index) => {
                shown[index] += 1;
                let group = &mut groups[index];
                if group.lines.len() < LINES_LISTED {
                    group.lines.push(finding.region.line);
                }
            }
            None => {
                shown.push(1);
                groups.push(Group {
                    rule: finding.rule,
                    severity: finding.severity,
                    count: 0,
                    lines: vec![finding.region.line],
                    first_message: finding.message,
                    file: finding.file,
                });
            }
        }
    }
    // The count of each rule is the file's, those beyond what is kept included.
    let summary = report.checked.summary();
    let mut many: Vec<Group<'a>> = Vec::new();
    for (mut group, shown) in groups.into_iter().zip(shown) {
        if shown <= GROUPED_ABOVE {
            continue;
        }
        let counted: usize = summary
            .by_rule
            .iter()
            .filter(|count| count.rule.name == group.rule)
            .map(|count| count.count)
            .sum();
        group.count = counted.max(shown);
        many.push(group);
    }
    many
}

impl Group<'_> {
    /// The paragraph, wrapped at `width`:
    ///
    /// ```text
    /// warning[untranslated-message]: 20 findings, on lines 5, 6, 8, … and 10 more
    ///   the first: the isiZulu message before the gesture at location 1 is a placeholder: …
    ///   see all: ekb check --show-all --select untranslated-message kb.dat
    /// ```
    pub fn paragraph(&self, width: usize) -> String {
        let listed: Vec<String> = self.lines.iter().map(u32::to_string).collect();
        let lines = match self.count - self.lines.len() {
            0 => listed.join(", "),
            more => format!("{} and {more} more", listed.join(", ")),
        };
        let head = format!(
            "{}[{}]: {} findings, on lines {lines}",
            self.severity.name(),
            self.rule,
            self.count,
        );
        let first = format!("the first: {}", escape(self.first_message));
        // One line of it: the command below shows them all.
        let first = match wrapped(&first, width.saturating_sub(1), "  ").split_once('\n') {
            Some((line, _)) => format!("{line}…"),
            None => wrapped(&first, width, "  "),
        };
        let command = format!(
            "see all: ekb check --show-all --select {} {}",
            self.rule,
            shell_word(self.file)
        );
        [
            wrapped(&head, width, ""),
            first,
            wrapped(&command, width, "  "),
        ]
        .join("\n")
    }
}

/// Whether `finding` follows from `before` ([`Diagnostic::follows_from`]), the finding
/// drawn just before it.
///
/// [`Diagnostic::follows_from`]: crate::diagnostic::Diagnostic::follows_from
pub fn follows(finding: &LocatedDiagnostic<'_>, before: &LocatedDiagnostic<'_>) -> bool {
    finding
        .diagnostic
        .follows_from
        .is_some_and(|cause| cause.name == before.rule && finding.location_id == before.location_id)
}

/// A finding that [`follows`] the one drawn before it, as a paragraph under it:
///
/// ```text
/// error[missing-field]: location 4 has no `postGestureMessageEnglish`: …
///   at kb.dat:28:1, because of the key-case error above
///   help: …
/// ```
pub fn consequence(finding: &LocatedDiagnostic<'_>, width: usize) -> String {
    let cause = finding.diagnostic.follows_from.map_or("", |rule| rule.name);
    let head = format!(
        "{}[{}]: {}",
        finding.severity.name(),
        finding.rule,
        escape(finding.message)
    );
    let place = format!(
        "at {}:{}:{}, because of the {cause} {} above",
        escape(finding.file),
        finding.region.line,
        finding.region.column,
        finding.severity.name(),
    );
    let mut paragraph = vec![wrapped(&head, width, ""), wrapped(&place, width, "  ")];
    if let Some(help) = finding.help {
        paragraph.push(wrapped(&format!("help: {}", escape(help)), width, "  "));
    }
    paragraph.join("\n")
}

/// `text` wrapped at `width` between words (a summary never cut mid-word by the
/// terminal), each line after `indent`, those after the first a further two columns in.
pub fn wrapped(text: &str, width: usize, indent: &str) -> String {
    let rest = format!("{indent}  ");
    let options = textwrap::Options::new(width)
        .initial_indent(indent)
        .subsequent_indent(&rest)
        .break_words(false)
        .word_separator(textwrap::WordSeparator::AsciiSpace)
        .word_splitter(textwrap::WordSplitter::NoHyphenation);
    textwrap::fill(text, options)
}

/// A file name as one word of a shell command: as it is if it needs no quotes, else in
/// single quotes; escaped for the terminal either way.
fn shell_word(name: &str) -> String {
    let plain = |c: char| c.is_ascii_alphanumeric() || "._-/+=:,@%".contains(c);
    match !name.is_empty() && name.chars().all(plain) {
        true => name.to_string(),
        false => format!("'{}'", escape(&name.replace('\'', "'\\''"))),
    }
}
