//! `ekb import JSON [-o OUT]`: the JSON of `ekb export` back to a knowledge base, in the
//! canonical layout of `ekb fmt` (both are written by [`crate::canonical::Document`]).
//!
//! JSON can hold what the robot cannot read (a 300-byte message, a negative first number):
//! the file is written all the same, for a person to correct, and its errors are told.

use std::io::Write;
use std::path::{Path, PathBuf};

use super::{errors_to_stderr, CommandError, CommandResult, Context, Exit};
use crate::canonical::Document;
use crate::check::check;
use crate::model::build::Options;
use crate::model::export::ExportedKnowledgeBase;
use crate::render::escape::escape;
use crate::source::SourceFile;
use crate::stderr_line;
use crate::write::write_atomically;

#[derive(Debug, clap::Args)]
pub struct Args {
    /// The JSON of `ekb export` (`-` for standard input)
    #[arg(value_name = "JSON")]
    pub input: PathBuf,

    /// Write the knowledge base here (replaced atomically) instead of standard output
    #[arg(short, long, value_name = "OUT")]
    pub output: Option<PathBuf>,
}

pub fn run(args: &Args, context: &Context) -> CommandResult {
    let json = SourceFile::read(&args.input)?;
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
