//! `ekb report [FILE] -o report.html`: one self-contained page to review and share.

use std::path::{Path, PathBuf};

use super::map::{write_result, MapArgs, MapInput};
use super::{CommandResult, Context, Exit};

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
    let input = MapInput::read(args.file.as_deref(), &args.map, context)?;
    let (checked, loaded) = input.check(context.quiet);
    let page = crate::report::page(&checked, &loaded, input.map.as_ref());
    let output = Some(args.output.as_path()).filter(|path| *path != Path::new("-"));
    write_result(output, page.as_bytes(), context)?;
    Ok(Exit::Clean)
}
