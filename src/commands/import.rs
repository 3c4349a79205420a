//! `ekb import JSON [-o OUT]`: the JSON of `ekb export` back to a knowledge base, in the
//! canonical layout of `ekb fmt` (both are written by [`crate::canonical::Document`]).
//!
//! `ekb import --po PO [FILE]`: a translator's PO file back into the knowledge base, in
//! place (SPEC §8): only that language's messages change ([`crate::translations::import`]
//! decides which, [`crate::edit`] makes the edits).
//!
//! JSON can hold what the robot cannot read (a 300-byte message, a negative first number):
//! the file is written all the same, for a person to correct, and its errors are told.

use std::io::Write;
use std::path::{Path, PathBuf};

use super::rewrite::{self, DiffStyle, Mode};
use super::{errors_to_stderr, CommandError, CommandResult, Context, Exit};
use crate::canonical::Document;
use crate::check::check;
use crate::edit::{self, ValueEdit};
use crate::model::build::Options;
use crate::model::export::ExportedKnowledgeBase;
use crate::model::Language;
use crate::render::escape::escape;
use crate::source::SourceFile;
use crate::stderr_line;
use crate::translations::{import, po, Catalog};
use crate::write::write_atomically;

#[derive(Debug, clap::Args)]
pub struct Args {
    /// The JSON of `ekb export` (`-` for standard input); with --po, the knowledge base to import into [default: the configured knowledgeBase]
    #[arg(value_name = "JSON|FILE", required_unless_present = "po")]
    pub input: Option<PathBuf>,

    /// Write the knowledge base here (replaced atomically) instead of standard output
    #[arg(short, long, value_name = "OUT", conflicts_with = "po")]
    pub output: Option<PathBuf>,

    /// Import the translations of this PO file into FILE, in place: only those messages change
    #[arg(long, value_name = "PO")]
    pub po: Option<PathBuf>,

    /// With --po: the PO file's language, if its header has no `Language:` (zu, rw, …)
    #[arg(long, value_name = "L", ignore_case = true, value_parser = crate::present::language::parser(), requires = "po")]
    pub lang: Option<Language>,

    /// With --po: import entries made for an English text that has changed since
    #[arg(long, requires = "po")]
    pub accept_stale: bool,

    /// With --po: import translations the robot's reader would misread, too
    #[arg(long, requires = "po")]
    pub force: bool,

    /// With --po: write nothing; print the changes as a diff
    #[arg(long, requires = "po")]
    pub diff: bool,
}

pub fn run(args: &Args, context: &Context) -> CommandResult {
    if let Some(po) = &args.po {
        return import_po(args, po, context);
    }
    let Some(input) = &args.input else {
        return Err(CommandError::Failed(
            "name the JSON of `ekb export` to import (or give --po)".to_string(),
        ));
    };
    let json = SourceFile::read(input)?;
    let name = escape(json.name()).into_owned();
    if !json.invalid_utf8().is_empty() {
        return Err(CommandError::Failed(format!("{name} is not valid UTF-8")));
    }
    let kb = parse(json.text())
        .map_err(|reason| CommandError::Failed(format!("{name}: {}", escape(&reason))))?;
    let document = Document::from_export(&kb)
        .map_err(|error| CommandError::Failed(format!("{name}: {}", escape(&error.to_string()))))?;
    let text = document.render();
    let (name, options) = match &args.output {
        Some(out) if out != Path::new("-") => {
            write_atomically(out, text.as_bytes())?;
            (out.display().to_string(), context.read_options(out)?)
        }
        _ => {
            std::io::stdout().lock().write_all(text.as_bytes())?;
            let options = context.read_options(Path::new("-"))?;
            ("<stdout>".to_string(), options)
        }
    };
    report_errors(
        &SourceFile::from_bytes(name, text.into_bytes()),
        &options,
        context,
    )
}

/// A translator's PO file, read, and the language it is in.
pub struct TranslatorsFile {
    /// Its name, escaped for the terminal.
    pub name: String,
    pub po: po::PoFile,
    pub language: Language,
}

impl TranslatorsFile {
    /// Reads the PO file at `path`, in `lang` (else the language its header says); an
    /// error names its line.
    pub fn read(path: &Path, lang: Option<Language>) -> Result<TranslatorsFile, CommandError> {
        let source = SourceFile::read(path)?;
        let name = escape(source.name()).into_owned();
        if let Some(bad) = source.invalid_utf8().first() {
            let line = crate::source::LineIndex::new(source.text()).line(bad.start);
            return Err(CommandError::Failed(format!(
                "{name}:{line}: not UTF-8: save the PO file as UTF-8 (its header should say charset=UTF-8)"
            )));
        }
        let fail_at = |line: u32, message: &str| {
            CommandError::Failed(format!("{name}:{line}: {}", escape(message)))
        };
        let po = po::parse(source.text()).map_err(|e| fail_at(e.line, &e.message))?;
        let language = import::language_of(&po, lang).map_err(|e| fail_at(e.line, &e.message))?;
        Ok(TranslatorsFile { name, po, language })
    }
}

/// `ekb import --po`: exit 1 when an entry was not imported (stale, refused), when the file
/// written still has errors, or with `--diff` when something would change (as `ekb fix`); 2
/// when the PO file cannot be read or belongs to another knowledge base (nothing is written).
fn import_po(args: &Args, po_path: &Path, context: &Context) -> CommandResult {
    let TranslatorsFile {
        name: po_name,
        po,
        language,
    } = TranslatorsFile::read(po_path, args.lang)?;
    let fail_at = |line: u32, message: &str| {
        CommandError::Failed(format!("{po_name}:{line}: {}", escape(message)))
    };
    let path = context.file_to_rewrite(args.input.as_deref())?;
    let mode = if args.diff { Mode::Diff } else { Mode::Write };
    let _lock = rewrite::lock(&path, mode)?;
    let options = context.read_options(&path)?;
    let source = context.read(&path)?;
    rewrite::ensure_rewritable(&source)?;
    let name = escape(source.name()).into_owned();
    let checked = check(&source, &options);
    let catalog = Catalog::new(&checked);
    let mut plan = import::plan(&po, &catalog, language, args.accept_stale)
        .map_err(|e| fail_at(e.line, &format!("{} (nothing was imported)", e.message)))?;
    // The edits check the file again: one check held at a time.
    drop(catalog);
    drop(checked);
    let (mut entries, mut edits): (Vec<_>, Vec<ValueEdit>) =
        std::mem::take(&mut plan.changes).into_iter().unzip();
    let mut misread = Vec::new();
    let edited = loop {
        let edited = edit::apply_checked(&source, &options, &edits)
            .map_err(|error| CommandError::Failed(format!("{name}: {error}")))?;
        if args.force || edited.edits.iter().all(|e| e.errors.is_empty()) {
            break edited;
        }
        // Leave out what the reader would misread, and make the rest again.
        let (mut kept_entries, mut kept_edits) = (Vec::new(), Vec::new());
        for ((entry, edit), done) in entries.into_iter().zip(edits).zip(edited.edits) {
            match done.errors.is_empty() {
                true => {
                    kept_entries.push(entry);
                    kept_edits.push(edit);
                }
                false => misread.push((entry, done.errors)),
            }
        }
        (entries, edits) = (kept_entries, kept_edits);
    };
    drop(edits);
    let style = DiffStyle {
        color: context.color_stdout(),
    };
    let changed = rewrite::deliver(&path, &source, &edited.text, mode, style)?;
    let mut stderr = std::io::stderr().lock();
    for (entry, english) in &plan.stale {
        let now = match english {
            Some(english) => format!("its English is now {}", crate::present::quoted(english)),
            None => "the message has no English now".to_string(),
        };
        writeln!(
            stderr,
            "{po_name}:{}: stale, not imported: `{}` was translated from {}; {now}",
            entry.line,
            escape(entry.msgctxt.as_deref().unwrap_or_default()),
            crate::present::quoted(&entry.msgid)
        )?;
    }
    for (entry, why) in &plan.refused {
        writeln!(stderr, "{po_name}:{}: not imported: {why}", entry.line)?;
    }
    for (entry, errors) in &misread {
        for error in errors {
            writeln!(
                stderr,
                "{po_name}:{}: not imported: error[{}] {} (--force imports it)",
                entry.line,
                error.rule.name,
                escape(&error.message)
            )?;
        }
    }
    if !context.quiet {
        let verb = match mode {
            Mode::Diff => "would import",
            Mode::Write => "imported",
        };
        let lines: Vec<String> = edited.edits.iter().map(|e| e.line.to_string()).collect();
        let at = match lines.is_empty() {
            true => String::new(),
            false => format!(
                " (line{} {})",
                if lines.len() == 1 { "" } else { "s" },
                lines.join(", ")
            ),
        };
        let mut parts = vec![format!(
            "{verb} {} {} message{}{at}",
            edited.edits.len(),
            language.name(),
            if edited.edits.len() == 1 { "" } else { "s" }
        )];
        for (count, what) in [
            (plan.unchanged, "already in the file"),
            (plan.empty, "untranslated (empty msgstr)"),
            (plan.fuzzy, "fuzzy, not imported"),
            (
                plan.stale.len(),
                "stale, not imported (--accept-stale imports them)",
            ),
            (plan.refused.len() + misread.len(), "refused"),
        ] {
            if count > 0 {
                parts.push(format!("{count} {what}"));
            }
        }
        writeln!(stderr, "{name}: {}", parts.join("; "))?;
    }
    drop(stderr);
    let left_out = plan.stale.len() + plan.refused.len() + misread.len();
    // As `ekb fix`: a diff that shows a change, or a written file that still has errors, is 1.
    let errors_left = mode == Mode::Write && edited.errors > 0;
    if errors_left && !context.quiet {
        let s = if edited.errors == 1 { "" } else { "s" };
        stderr_line!(
            "{name}: written with {} error{s} to correct (`ekb check` lists them)",
            edited.errors
        );
    }
    Ok(
        if left_out > 0 || errors_left || (mode == Mode::Diff && changed) {
            Exit::Findings
        } else {
            Exit::Clean
        },
    )
}

/// Tells, on standard error, the errors of the knowledge base written: exit 1 if it has any.
fn report_errors(written: &SourceFile, options: &Options, context: &Context) -> CommandResult {
    let mut checked = check(written, options);
    let errors = checked.summary().errors;
    if errors == 0 {
        return Ok(Exit::Clean);
    }
    errors_to_stderr(&mut checked);
    if !context.quiet {
        let s = if errors == 1 { "" } else { "s" };
        stderr_line!(
            "{}: written with {errors} error{s} to correct by hand (`ekb check` lists every finding)",
            escape(written.name())
        );
    }
    Ok(Exit::Findings)
}

/// Deserializes an export; an error names the JSON path of the bad field.
pub fn parse(json: &str) -> Result<ExportedKnowledgeBase, String> {
    // serde would also take an array for the object, and then name puzzling paths.
    if !json.trim_start().starts_with('{') {
        return Err("expected a JSON object, as `ekb export` writes".into());
    }
    let mut deserializer = serde_json::Deserializer::from_str(json);
    let kb = serde_path_to_error::deserialize(&mut deserializer).map_err(|error| {
        let path = error.path().to_string();
        let inner = error.into_inner();
        let position = format!("line {}, column {}", inner.line(), inner.column());
        // serde_json's message ends with its own position; ours comes first.
        let message = inner.to_string();
        let message = message
            .rsplit_once(" at line ")
            .map_or(message.as_str(), |(message, _)| message);
        if path == "." || path == "?" {
            format!("{position}: {message}")
        } else {
            format!("{path} ({position}): {message}")
        }
    })?;
    deserializer
        .end()
        .map_err(|error| format!("after the JSON value: {error}"))?;
    Ok(kb)
}
