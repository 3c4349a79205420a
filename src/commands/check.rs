//! `ekb check [FILE...]`: validate knowledge bases.

use std::io::Write;
use std::path::PathBuf;

use super::map::{check_on_map, MapArgs};
use super::{CommandError, CommandResult, Context, Exit};
use crate::check::{check, Checked};
use crate::diagnostic::Summary;
use crate::model::build::Options;
use crate::render::{self, Format, RenderOptions};
use crate::source::SourceFile;

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
    let options = paths
        .iter()
        .map(|path| context.read_options(path))
        .collect::<Result<Vec<Options>, _>>()?;
    let sources = paths
        .iter()
        .map(|path| context.read(path))
        .collect::<Result<Vec<SourceFile>, _>>()?;
    let map = args.map.load(None)?;
    let checked: Vec<Checked> = sources
        .iter()
        .zip(&options)
        .map(|(source, options)| match &map {
            Some(map) => check_on_map(source, options, Some(map)).0,
            None => check(source, options),
        })
        .collect();
    // Checked::summary also counts the findings past the cap of each rule (check.rs).
    let mut summary = Summary::default();
    for file in &checked {
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
    let failed = summary.errors > 0 || (args.deny_warnings && summary.warnings > 0);
    let exit = if failed { Exit::Findings } else { Exit::Clean };
    // Buffered: a large file can have hundreds of thousands of findings, one line each.
    let mut stdout = std::io::BufWriter::new(std::io::stdout().lock());
    let written = render::render(
        args.format,
        &checked,
        &summary,
        &mut stdout,
        &render_options,
    )
    .and_then(|()| stdout.flush());
    match written {
        // A reader that stops early (`ekb check | head`) is not a failure of the check.
        Err(error) if error.kind() == std::io::ErrorKind::BrokenPipe => Ok(exit),
        Err(error) => Err(CommandError::Failed(format!(
            "cannot write the report: {error}"
        ))),
        Ok(()) => Ok(exit),
    }
}
