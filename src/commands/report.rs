//! `ekb report [FILE] -o report.html`: one self-contained page to review and share.

use std::path::{Path, PathBuf};

use super::import::TranslatorsFile;
use super::map::{write_result, MapArgs, MapInput};
use super::{CommandError, CommandResult, Context, Exit};
use crate::check::Checked;
use crate::render::escape::escape;
use crate::translations::import::{self, StaleTranslation};
use crate::translations::Catalog;

#[derive(Debug, clap::Args)]
pub struct Args {
    /// Knowledge-base file (`-` for standard input) [default: the configured knowledgeBase]
    #[arg(value_name = "FILE")]
    pub file: Option<PathBuf>,

    /// Write the page here (`-` is standard output)
    #[arg(short, long, value_name = "OUT", required = true)]
    pub output: PathBuf,

    /// Mark the translations these translators' PO files (of `ekb export --format po`) say
    /// were made for an English text that has since changed (stale)
    #[arg(long, value_name = "PO")]
    pub po: Vec<PathBuf>,

    #[command(flatten)]
    pub map: MapArgs,
}

pub fn run(args: &Args, context: &Context) -> CommandResult {
    let input = MapInput::read(args.file.as_deref(), &args.map, context)?;
    let (checked, loaded) = input.check(context.quiet);
    let stale = match args.po.is_empty() {
        true => None,
        false => Some(stale_translations(&args.po, &checked)?),
    };
    let path = context.input(args.file.as_deref())?;
    let robot = context.settings_for(&path)?.robot.profile();
    let page = crate::report::page(
        &checked,
        &loaded,
        input.map.as_ref(),
        stale.as_deref(),
        &robot,
    );
    let output = Some(args.output.as_path()).filter(|path| *path != Path::new("-"));
    write_result(output, page.as_bytes(), context)?;
    Ok(Exit::Clean)
}

/// The translations of `checked` that the PO files at `paths` say are stale. A PO file
/// that cannot be read, or that belongs to another knowledge base, is an error.
fn stale_translations(
    paths: &[PathBuf],
    checked: &Checked<'_>,
) -> Result<Vec<StaleTranslation>, CommandError> {
    let catalog = Catalog::new(checked);
    let mut stale = Vec::new();
    for path in paths {
        let po = TranslatorsFile::read(path, None)?;
        let found =
            import::stale_translations(&po.po, &po.name, &catalog, po.language).map_err(|e| {
                CommandError::Failed(format!("{}:{}: {}", po.name, e.line, escape(&e.message)))
            })?;
        stale.extend(found);
    }
    Ok(stale)
}
