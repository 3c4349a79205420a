//! `ekb report [FILE] -o report.html`: one self-contained page to review and share.

use std::path::{Path, PathBuf};

use super::map::{check_on_map, write_output, MapArgs};
use super::{CommandResult, Context, Exit};
use crate::present;
use crate::render::escape::escape;
use crate::stderr_line;

#[derive(Debug, clap::Args)]
pub struct Args {
    /// Knowledge-base file (`-` for standard input) [default: the configured knowledgeBase]
    #[arg(value_name = "FILE")]
    pub file: Option<PathBuf>,

    /// Write the page here (`-` is standard output)
    #[arg(short, long, value_name = "OUT", required = true)]
    pub output: PathBuf,

    #[command(flatten)]
    pub map: MapArgs,
}

pub fn run(args: &Args, context: &Context) -> CommandResult {
    let path = context.input(args.file.as_deref())?;
    let options = context.read_options(&path)?;
    // No `[map] config` from ekb.toml here yet: `MapArgs::load` takes it as its argument.
    let map = args.map.load(None)?;
    let source = context.read(&path)?;
    let (checked, loaded) = check_on_map(&source, &options, map.as_ref());
    present::note_errors(&checked, context.quiet);
    let page = crate::report::page(&checked, &loaded, map.as_ref());
    let output = Some(args.output.as_path()).filter(|path| *path != Path::new("-"));
    write_output(output, page.as_bytes())?;
    if let (Some(path), false) = (output, context.quiet) {
        stderr_line!("ekb: wrote {}", escape(&path.display().to_string()));
    }
    Ok(Exit::Clean)
}
