//! `ekb export [FILE] [-o OUT]`: the typed model as JSON (SPEC §5), or its JSON Schema.

use std::io::Write;
use std::path::{Path, PathBuf};

use super::{CommandError, CommandResult, Context, Exit};
use crate::check::{check, Checked};
use crate::model::export::{ExportView, ExportedKnowledgeBase};
use crate::model::{Dialect, Key, Language};
use crate::reader::{self, export::LoadedExport};
use crate::render::safe_json as json;
use crate::render::{self, escape::escape, Format, RenderOptions};
use crate::streams;
use crate::syntax::Body;
use crate::translations::{po, Catalog};
use crate::write;
use crate::write::write_atomically;

#[derive(Debug, clap::Args)]
pub struct Args {
    /// Knowledge-base file (`-` for standard input) [default: the configured knowledgeBase]
    #[arg(value_name = "FILE", conflicts_with = "schema")]
    pub file: Option<PathBuf>,

    /// Output format
    #[arg(long, value_enum, default_value_t = ExportFormat::Json)]
    pub format: ExportFormat,

    /// With --format po: the language to translate into: isizulu (zulu), kinyarwanda, or zu/zul, rw/kin (any case)
    #[arg(long, value_name = "L", ignore_case = true, value_parser = crate::present::language::parser())]
    pub lang: Option<Language>,

    /// Write to this file instead of standard output (`-` is standard output)
    #[arg(short, long, value_name = "OUT")]
    pub output: Option<PathBuf>,

    /// Export even if the file has errors (what the robot would load of it)
    #[arg(long)]
    pub allow_errors: bool,

    /// Print the JSON Schema of the export instead
    #[arg(long, conflicts_with = "as_loaded")]
    pub schema: bool,

    /// Export what the chosen reader loads (`--reader`), field by field, instead of what the
    /// file says; exit 1 if that reader would crash on the file
    #[arg(long)]
    pub as_loaded: bool,
}

/// `ekb export --format`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum ExportFormat {
    /// The JSON of SPEC §5
    Json,
    /// gettext PO of one language (--lang), for translators' tools (SPEC §8)
    Po,
    /// gettext PO template: every English message, no translation
    Pot,
}

pub fn run(args: &Args, context: &Context) -> CommandResult {
    if args.schema {
        let schema = schemars::schema_for!(ExportedKnowledgeBase);
        write_output(args.output.as_deref(), &schema)?;
        return Ok(Exit::Clean);
    }
    let path = context.input(args.file.as_deref())?;
    let options = context.read_options(&path)?;
    let source = match args.as_loaded {
        true => context.read_to_report(&path)?,
        false => context.read(&path)?,
    };
    let checked = check(&source, &options);
    if matches!(args.format, ExportFormat::Po | ExportFormat::Pot) {
        return export_po(args, context, &checked);
    }
    if args.as_loaded {
        return export_as_loaded(args, context, checked);
    }
    if checked.has_errors() && !args.allow_errors {
        let summary = checked.summary();
        let why = format!(
            "ekb: not exported: {} has {} (fix them, or give --allow-errors to export what the robot would load)",
            escape(source.name()),
            plural(summary.errors, "error")
        );
        // Only the errors stop the export; the warnings would bury them.
        return report_to_stderr(checked.errors_only(), &why, context);
    }
    write_output(args.output.as_deref(), &ExportView::new(&checked.kb))?;
    if !context.quiet {
        if let Some(what) = left_out(checked.source.text()) {
            crate::stderr_line!(
                "ekb: warning: {}: {what} not in the JSON, which holds what the robot loads: \
                 `ekb import` of it writes none of them (docs/fixing-and-formatting.md says \
                 what the round trip keeps)",
                escape(source.name())
            );
        }
    }
    if checked.has_errors() {
        // What the robot would not load is not in the export, and `import` of it would not
        // write it back (a line whose key is in the wrong case, say): it is said, by line.
        let why = format!(
            "ekb: exported with {}: the export holds what the robot would load, and leaves \
             out what the lines above say that the robot would not read; `ekb import` of it \
             would not write them back (correct them first: `ekb fix` mends a key in the \
             wrong case)",
            plural(checked.summary().errors, "error")
        );
        write_errors(checked.errors_only(), &why, context)?;
    }
    Ok(Exit::Clean)
}

/// The PO file of `--lang`, or the template: the file's errors do not stop it (a translator
/// can work while an engineer fixes a pose), but they are noted.
fn export_po(args: &Args, context: &Context, checked: &Checked<'_>) -> CommandResult {
    let language = match (args.format, args.lang) {
        (ExportFormat::Pot, _) => None,
        (_, Some(Language::English)) => {
            return Err(CommandError::Failed(
                "English is the language translations are made from: export isiZulu or \
                 Kinyarwanda (`--lang zu` or `--lang rw`), or the template (`--format pot`)"
                    .to_string(),
            ))
        }
        (_, Some(language)) => Some(language),
        (_, None) => {
            return Err(CommandError::Failed(
                "--format po needs the language to translate into: `--lang zu` or `--lang rw` \
                 (or `--format pot` for the template)"
                    .to_string(),
            ))
        }
    };
    crate::present::note_errors(checked, context.quiet);
    let catalog = Catalog::new(checked);
    // The translations were last revised when the knowledge base was.
    let revised = std::fs::metadata(checked.source.name())
        .and_then(|metadata| metadata.modified())
        .unwrap_or_else(|_| std::time::SystemTime::now());
    let po = po::write(&catalog, checked.source.name(), language, revised);
    match args
        .output
        .as_deref()
        .filter(|path| *path != Path::new("-"))
    {
        Some(path) => write_atomically(path, po.as_bytes())?,
        None => {
            let mut stdout = std::io::stdout().lock();
            stdout.write_all(po.as_bytes())?;
            stdout.flush()?;
        }
    }
    Ok(Exit::Clean)
}

/// What the reader loads, errors or not: that is the point. A reader that crashes loads
/// nothing, and its crash is the finding to show.
fn export_as_loaded(args: &Args, context: &Context, mut checked: Checked<'_>) -> CommandResult {
    let crashes = checked.reader_crashes();
    if !crashes.is_empty() {
        let why = format!(
            "ekb: not exported: reader {} crashes on {}",
            checked.reader,
            escape(checked.source.name())
        );
        checked.diagnostics = crashes;
        checked.omitted.clear();
        return report_to_stderr(checked, &why, context);
    }
    let text = checked.source.text().as_bytes();
    let loaded = reader::load(text, checked.reader);
    write_output(args.output.as_deref(), &LoadedExport::new(&loaded))?;
    Ok(Exit::Clean)
}

/// Shows `checked`'s findings on standard error, concisely, then `why`: exit 1.
fn report_to_stderr(checked: Checked<'_>, why: &str, context: &Context) -> CommandResult {
    write_errors(checked, why, context)?;
    Ok(Exit::Findings)
}

/// Writes the findings of `checked`, then `why`, to standard error.
fn write_errors(checked: Checked<'_>, why: &str, context: &Context) -> Result<(), CommandError> {
    let summary = checked.summary();
    let mut stderr = streams::stderr();
    let render_options = RenderOptions {
        color: context.color_stderr(),
        quiet: true,
        ..RenderOptions::default()
    };
    render::render(
        Format::Concise,
        std::slice::from_ref(&checked),
        &summary,
        &mut stderr,
        &render_options,
    )?;
    writeln!(stderr, "{why}")?;
    Ok(())
}

fn plural(count: usize, word: &str) -> String {
    if count == 1 {
        format!("1 {word}")
    } else {
        format!("{count} {word}s")
    }
}

/// What of `text` the export has no place for, in words (`None`: nothing): its comments
/// (suppressions named: without them, `ekb check` of the imported file finds what they
/// silenced) and the lines of keys the robot does not read. A dialect's declaration is not
/// one: the JSON says the dialect.
fn left_out(text: &str) -> Option<String> {
    let (mut comments, mut suppressions, mut unread) = (0, 0, 0);
    for line in crate::syntax::lines(text) {
        match line.body {
            Body::Comment(comment) => {
                let comment = comment.text(text);
                if Dialect::declared_in(comment).is_some() {
                    continue;
                }
                comments += 1;
                let directive = comment[1..].trim_start().strip_prefix("ekb:");
                if directive.is_some_and(|rest| rest.trim_start().starts_with("ignore")) {
                    suppressions += 1;
                }
            }
            Body::Entry { key, .. } if Key::from_name(key.text(text)).is_none() => unread += 1,
            _ => {}
        }
    }
    let mut parts = Vec::new();
    if comments > 0 {
        let mut part = plural(comments, "comment line");
        if suppressions > 0 {
            part += &format!(" ({suppressions} `# ekb: ignore`)");
        }
        parts.push(part);
    }
    if unread > 0 {
        parts.push(format!(
            "{} of a key the robot does not read",
            plural(unread, "line")
        ));
    }
    let verb = if comments + unread == 1 { "is" } else { "are" };
    (!parts.is_empty()).then(|| format!("{} {verb}", parts.join(" and ")))
}

/// Writes JSON to `output` (through [`crate::write`]) or standard output.
fn write_output(output: Option<&Path>, value: &impl serde::Serialize) -> Result<(), CommandError> {
    let Some(path) = output.filter(|path| *path != Path::new("-")) else {
        let mut stdout = std::io::stdout().lock();
        json::write(value, &mut stdout)?;
        stdout.flush()?;
        return Ok(());
    };
    write::write_streamed(path, |out| json::write(value, out))?;
    Ok(())
}
