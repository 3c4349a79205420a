//! `ekb check [FILE...]`: validate knowledge bases.

use std::io::Write;
use std::path::PathBuf;

use super::map::{on_map, MapArgs};
use super::{CommandError, CommandResult, Context, Exit};
use crate::check::Checked;
use crate::diagnostic::Summary;
use crate::mission::check::check_file;
use crate::render::escape::escape;
use crate::render::{self, Format, RenderOptions};
use crate::stderr_line;

#[derive(Debug, clap::Args)]
pub struct Args {
    /// Knowledge-base files (`-` for standard input) [default: the configured knowledgeBase]
    #[arg(value_name = "FILE")]
    pub files: Vec<PathBuf>,

    /// Output format
    #[arg(long, value_enum, default_value_t = Format::Human)]
    pub format: Format,

    /// Exit 1 on warnings too
    #[arg(long)]
    pub deny_warnings: bool,

    #[command(flatten)]
    pub map: MapArgs,
}

pub fn run(args: &Args, context: &Context) -> CommandResult {
    let paths = context.inputs(&args.files)?;
    // A bad configuration fails every file alike: once, here.
    context.config()?;
    // No `[map] config` from ekb.toml here yet: `MapArgs::load` takes it as its argument.
    let map = args.map.load(None)?;
    // A file that cannot be read is told at once and the others are checked all the same;
    // the exit is 2 then. If none can be read, there is no report.
    let mut unreadable = false;
    let mut sources = Vec::with_capacity(paths.len());
    let mut options = Vec::with_capacity(paths.len());
    for path in &paths {
        match context
            .read_options(path)
            .and_then(|read_options| Ok((read_options, context.read(path)?)))
        {
            Ok((read_options, source)) => {
                options.push(read_options);
                sources.push(source);
            }
            Err(error) => {
                stderr_line!("ekb: error: {}", escape(&error.to_string()));
                unreadable = true;
            }
        }
    }
    if sources.is_empty() {
        return Ok(Exit::Failure);
    }
    // A mission or a culture file is recognised by its content and checked alone.
    let checked: Vec<Checked> = sources
        .iter()
        .zip(&options)
        .map(|(source, options)| {
            let checked = check_file(source, options);
            match &map {
                Some(map) => on_map(checked, Some(map)).0,
                None => checked,
            }
        })
        .collect();
    let exit = report(&checked, args.format, args.deny_warnings, context)?;
    Ok(if unreadable { Exit::Failure } else { exit })
}

/// Renders the findings of `checked` in `format` on standard output, and gives the exit
/// code of SPEC §5.
pub fn report(
    checked: &[Checked<'_>],
    format: Format,
    deny_warnings: bool,
    context: &Context,
) -> CommandResult {
    // Checked::summary also counts the findings past the cap of each rule (check.rs).
    let mut summary = Summary::default();
    for file in checked {
        let one = file.summary();
        summary.files += one.files;
        summary.errors += one.errors;
        summary.warnings += one.warnings;
        summary.infos += one.infos;
        summary.fixable += one.fixable;
    }
    let render_options = RenderOptions {
        color: context.color_stdout(),
        quiet: context.quiet,
    };
    let failed = summary.errors > 0 || (deny_warnings && summary.warnings > 0);
    let exit = if failed { Exit::Findings } else { Exit::Clean };
    // Buffered: a large file can have hundreds of thousands of findings, one line each.
    let mut stdout = std::io::BufWriter::new(std::io::stdout().lock());
    let written = render::render(format, checked, &summary, &mut stdout, &render_options)
        .and_then(|()| stdout.flush());
    match written {
        Err(error) if error.kind() == std::io::ErrorKind::BrokenPipe => {
            Err(CommandError::OutputClosed)
        }
        Err(error) => Err(CommandError::Failed(format!(
            "cannot write the report: {error}"
        ))),
        Ok(()) => Ok(exit),
    }
}
