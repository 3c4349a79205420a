//! `ekb fix [FILE...] [--diff] [--dialect D]`: apply the machine-applicable fixes of the rule
//! catalogue ([`crate::fixing`]), and migrate a file from one dialect to the other.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use super::check::RuleArgs;
use super::rewrite::{self, DiffStyle, Mode};
use super::{errors_to_stderr, CommandError, CommandResult, Context, Exit};
use crate::canonical::Document;
use crate::check::{check_with, Checked};
use crate::fixing::{self, Fixes, Outcome};
use crate::model::build::Options;
use crate::model::{Dialect, Key, KnowledgeBase};
use crate::render::escape::escape;
use crate::robot::Reader;
use crate::rules::compat::compat_reader_crash::COMPAT_READER_CRASH;
use crate::rules::compat::compat_slow_load::COMPAT_SLOW_LOAD;
use crate::rules::selection::{RuleSelector, RuleSet};
use crate::rules::structure::invalid_utf8::INVALID_UTF8;
use crate::source::SourceFile;
use crate::stderr_line;
use crate::syntax::{self, Body};

#[derive(Debug, clap::Args)]
pub struct Args {
    /// Knowledge-base files (`-`: read standard input, write standard output) [default: the configured knowledgeBase]
    #[arg(value_name = "FILE")]
    pub files: Vec<PathBuf>,

    /// Write nothing; print a diff and exit 1 if anything would change
    #[arg(long)]
    pub diff: bool,

    /// Migrate to this dialect (`current`: robotLocation becomes robotLocationPose; `seed`: the reverse)
    #[arg(long, value_parser = super::named_values::dialect(), value_name = "DIALECT")]
    pub dialect: Option<Dialect>,

    /// Apply the unsafe fixes too, which guess what was meant: a dash before a number becomes a
    /// minus, a decimal comma a point, a file that is not UTF-8 is read as Latin-1
    #[arg(long)]
    pub unsafe_fixes: bool,

    #[command(flatten)]
    pub rules: RuleArgs,
}

pub fn run(args: &Args, context: &Context) -> CommandResult {
    let paths = context.files_to_rewrite(&args.files)?;
    let rules = args.rules.choice();
    Ok(rewrite::for_each_file(&paths, |path| {
        let choice = fixing::Choice {
            rules: context.rules_for(path, &rules)?,
            unsafe_fixes: args.unsafe_fixes,
        };
        let mut options = context.read_options(path)?;
        if let Some(target) = args.dialect {
            // Migrating is fixing `legacy-key` against the target dialect's reader.
            options.dialect = Some(target);
            options.reader = Some(Reader::default_for(Some(target)));
        }
        fix_file(path, args, context, &options, &choice)
    }))
}

fn fix_file(
    path: &Path,
    args: &Args,
    context: &Context,
    options: &Options,
    choice: &fixing::Choice,
) -> Result<Exit, CommandError> {
    let mode = if args.diff { Mode::Diff } else { Mode::Write };
    let _lock = rewrite::lock(path, mode)?;
    let read = context.read(path)?;
    // Read as Latin-1, the file is UTF-8 text to fix further; `read` is what is replaced.
    let converted = match args.unsafe_fixes && !read.invalid_utf8().is_empty() {
        true => Some(from_latin1(path, &read)?),
        false => None,
    };
    let source = converted.as_ref().unwrap_or(&read);
    rewrite::ensure_rewritable(source)?;
    if let Some(target) = args.dialect {
        refuse_inexpressible(source, target)?;
    }
    let style = DiffStyle {
        color: context.color_stdout(),
    };
    let converted_lines = converted.is_some().then(|| read.invalid_utf8_lines());
    let after = |fixes: Fixes<'_>| -> Result<(bool, bool), CommandError> {
        let Fixes {
            outcome,
            mut counts,
            last_check,
        } = fixes;
        if let Some(lines) = converted_lines {
            counts.insert(INVALID_UTF8.name, lines);
        }
        let report = |after: &SourceFile, checked, rules: &RuleSet| {
            report(after, checked, &counts, options, rules, context, mode)
        };
        match (outcome, mode) {
            (Outcome::Balanced { file, document }, Mode::Diff) => {
                // What is left to correct is what the text before the balance has but for
                // the order of its ids, which the balanced order mends (its tree is log2(n)
                // deep): checked without the rules of that order, the balanced text is
                // never made.
                let order = [
                    RuleSelector::Rule(&COMPAT_READER_CRASH),
                    RuleSelector::Rule(&COMPAT_SLOW_LOAD),
                ];
                let mut rules = choice.rules.clone();
                rules.ignore(&order);
                // Its findings tell it; the model of the file is let go before the diff.
                let checked =
                    last_check
                        .and_then(|checked| checked.ignoring(&order))
                        .map(|mut checked| {
                            checked.kb = KnowledgeBase::default();
                            checked
                        });
                let changed = print_balanced(&read, &document, style)?;
                Ok((changed, report(file, checked, &rules)?))
            }
            (Outcome::Balanced { document, .. }, Mode::Write) => {
                let text = document.render();
                let changed = rewrite::deliver(path, &read, &text, mode, style)?;
                drop(document);
                let balanced = SourceFile::from_bytes(source.name(), text.into_bytes());
                Ok((changed, report(&balanced, None, &choice.rules)?))
            }
            (Outcome::Edited(file), mode) => {
                let changed = rewrite::deliver(path, &read, file.text(), mode, style)?;
                Ok((changed, report(file, last_check, &choice.rules)?))
            }
            (Outcome::Unchanged, mode) => {
                let changed = rewrite::deliver(path, &read, source.text(), mode, style)?;
                Ok((changed, report(source, last_check, &choice.rules)?))
            }
        }
    };
    let (changed, errors_left) = fixing::fixes(source, options, choice, after)?;
    Ok(match mode {
        Mode::Diff if changed => Exit::Findings,
        Mode::Write if errors_left => Exit::Findings,
        _ => Exit::Clean,
    })
}

/// Whether `ekb fix --unsafe-fixes` fixes `finding`: its fix guesses what was meant, or the
/// file is read as Latin-1.
fn fixed_by_guessing(finding: &crate::Diagnostic) -> bool {
    finding.fix.as_ref().is_some_and(|fix| !fix.is_safe()) || finding.rule.name == INVALID_UTF8.name
}

/// Prints the diff of `read` and its blocks put in a balanced order (`document`, laid out
/// from `read`'s text or from the text the fixes made of it). Returns whether they differ.
fn print_balanced(
    read: &SourceFile,
    document: &Document<'_>,
    style: DiffStyle,
) -> Result<bool, CommandError> {
    Ok(rewrite::print_diff_streamed(
        read.name(),
        read.text(),
        style,
        |mut out| document.write_to(&mut out),
    )?)
}

/// The file at `path`, not UTF-8, read as Latin-1 (Windows-1252): `--unsafe-fixes` guesses
/// that this is what a file saved by an older editor is.
fn from_latin1(path: &Path, read: &SourceFile) -> Result<SourceFile, CommandError> {
    let name = escape(read.name());
    if path == Path::new("-") {
        return Err(CommandError::Failed(format!(
            "{name} is not UTF-8, and standard input cannot be read again to convert it from \
             Latin-1; give the file's path"
        )));
    }
    let bytes = crate::open::read_regular(path).map_err(|e| {
        CommandError::Failed(format!("cannot read {name} again to convert it: {e}"))
    })?;
    let text = fixing::from_latin1(&bytes).ok_or_else(|| {
        CommandError::Failed(format!(
            "{name} is neither UTF-8 nor Latin-1 text (it has NUL bytes or bytes Windows-1252 \
             leaves undefined; UTF-16?): save it as UTF-8 and run again"
        ))
    })?;
    Ok(SourceFile::from_bytes(read.name(), text.into_bytes()))
}

/// Refuses to migrate a file with lines the target dialect has no key for: dropping them
/// would lose content, keeping them would not be a migration.
fn refuse_inexpressible(source: &SourceFile, target: Dialect) -> Result<(), CommandError> {
    let text = source.text();
    let other = target.other();
    let lines: Vec<(u32, String)> = syntax::lines(text)
        .filter_map(|line| match line.body {
            Body::Entry { key, .. } => Key::from_name_ignoring_case(key.text(text))
                .filter(|key| key.dialect() == Some(other) && *key != other.pose_key())
                .map(|key| (line.number, key.name().to_string())),
            _ => None,
        })
        .collect();
    if lines.is_empty() {
        return Ok(());
    }
    Err(CommandError::Failed(format!(
        "cannot migrate {} to the {} dialect: {} {} no equivalent in it; remove {} by hand \
         first if the robot can do without {}",
        escape(source.name()),
        target.name(),
        crate::canonical::name_lines(&lines),
        if lines.len() == 1 { "has" } else { "have" },
        if lines.len() == 1 { "it" } else { "them" },
        if lines.len() == 1 { "it" } else { "them" },
    )))
}

/// Tells, on standard error, what was fixed (`counts`) and which errors are left in
/// `after`, the text the fixes made, given its check if the fixes made one that tells.
/// Returns whether errors are left.
fn report(
    after: &SourceFile,
    checked: Option<Checked<'_>>,
    counts: &BTreeMap<&'static str, usize>,
    options: &Options,
    rules: &RuleSet,
    context: &Context,
    mode: Mode,
) -> Result<bool, CommandError> {
    let name = escape(after.name());
    let mut checked = checked.unwrap_or_else(|| {
        let options = Options {
            verbose: false,
            ..*options
        };
        check_with(after, &options, rules)
    });
    let summary = checked.summary();
    let guessable = checked
        .diagnostics
        .iter()
        .filter(|d| d.severity() == crate::Severity::Error && fixed_by_guessing(d))
        .count();
    if !context.quiet && !counts.is_empty() {
        let fixed: Vec<String> = counts
            .iter()
            .map(|(rule, count)| format!("{count} {rule}"))
            .collect();
        let verb = if mode == Mode::Diff {
            "would fix"
        } else {
            "fixed"
        };
        stderr_line!("{name}: {verb} {}", fixed.join(", "));
    }
    errors_to_stderr(&mut checked);
    if !context.quiet {
        let by_hand = summary.errors - guessable;
        if guessable > 0 {
            let s = if guessable == 1 { "" } else { "s" };
            stderr_line!(
                "{name}: {guessable} error{s} left that `ekb fix --unsafe-fixes` fixes by a guess \
                 (`ekb fix --unsafe-fixes --diff` shows it first)"
            );
        }
        if by_hand > 0 {
            let s = if by_hand == 1 { "" } else { "s" };
            let more = if guessable > 0 { " more" } else { "" };
            stderr_line!("{name}: {by_hand}{more} error{s} left to correct by hand");
        } else if summary.errors == 0 && counts.is_empty() {
            stderr_line!("{name}: nothing to fix");
        }
        if summary.warnings > 0 {
            let s = if summary.warnings == 1 { "" } else { "s" };
            stderr_line!(
                "{name}: {} warning{s} left (`ekb check` lists them)",
                summary.warnings
            );
        }
    }
    Ok(summary.errors > 0)
}
