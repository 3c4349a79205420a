//! `ekb serve [FILE] [--port N] [--open]`: the knowledge base in a local web page (see
//! [`crate::serve`]).

use std::io::Write;
use std::path::{Path, PathBuf};

use super::map::MapArgs;
use super::rewrite;
use super::{CommandError, CommandResult, Context, Exit};
use crate::rules::selection::Choice;
use crate::serve::{self, Served};

#[derive(Debug, clap::Args)]
pub struct Args {
    /// Knowledge-base file [default: the configured knowledgeBase]
    #[arg(value_name = "FILE")]
    pub file: Option<PathBuf>,

    /// The port on 127.0.0.1 (0: a free one, chosen by the system)
    #[arg(long, default_value_t = 0, value_name = "N")]
    pub port: u16,

    /// Say to open the page in a browser (this version prints the address on standard
    /// error too; it starts no browser)
    #[arg(long)]
    pub open: bool,

    #[command(flatten)]
    pub map: MapArgs,
}

/// Serves until stopped (Ctrl-C).
pub fn run(args: &Args, context: &Context) -> CommandResult {
    if args.file.as_deref() == Some(Path::new("-")) {
        return Err(CommandError::Failed(
            "ekb serve edits a file in place: name a file, not standard input".to_string(),
        ));
    }
    let path = context.file_to_rewrite(args.file.as_deref())?;
    let options = context.read_options(&path)?;
    let rules = context.rules_for(&path, &Choice::default())?;
    let map_config = context.settings_for(&path)?.map.config;
    let map = args.map.load(map_config.map(|config| config.value))?;
    let source = context.read(&path)?;
    rewrite::ensure_rewritable(&source)?;
    drop(source);
    let served = Served {
        path,
        options,
        rules,
        map,
        context,
    };
    let open = args.open;
    serve::run(served, args.port, |address| {
        let mut stdout = std::io::stdout().lock();
        writeln!(stdout, "{address}")?;
        stdout.flush()?;
        if open {
            crate::stderr_line!("ekb: open {address} in your browser");
        }
        Ok(())
    })?;
    Ok(Exit::Clean)
}
