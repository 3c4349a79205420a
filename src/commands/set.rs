//! `ekb set ID KEY TEXT [FILE]`: edit one value from the command line, in place and
//! losslessly ([`crate::edit`]): only the value's bytes change, or, when the location has no
//! line of that key, one line is added to its lines, aligned. A value the chosen reader would
//! misread is refused unless `--force`.

use std::path::{Path, PathBuf};

use super::rewrite::{self, DiffStyle, Mode};
use super::{CommandError, CommandResult, Context, Exit};
use crate::edit::{self, ValueEdit};
use crate::model::Key;
use crate::render::escape::escape;

#[derive(Debug, clap::Args)]
pub struct Args {
    /// The location's id
    #[arg(value_name = "ID")]
    pub id: String,

    /// The key, e.g. preGestureMessageIsiZulu (any case)
    #[arg(value_name = "KEY")]
    pub key: String,

    /// The new value, one line (blanks at either end are dropped)
    #[arg(value_name = "TEXT", allow_hyphen_values = true)]
    pub text: String,

    /// Knowledge-base file (`-`: read standard input, write standard output) [default: the configured knowledgeBase]
    #[arg(value_name = "FILE")]
    pub file: Option<PathBuf>,

    /// Write the value even if the robot's reader would misread it
    #[arg(long)]
    pub force: bool,

    /// Write nothing; print the change as a diff
    #[arg(long)]
    pub diff: bool,
}

pub fn run(args: &Args, context: &Context) -> CommandResult {
    let edit = parse(args)?;
    let path = context.file_to_rewrite(args.file.as_deref())?;
    let mode = if args.diff { Mode::Diff } else { Mode::Write };
    let _lock = rewrite::lock(&path, mode)?;
    let options = context.read_options(&path)?;
    let source = context.read(&path)?;
    rewrite::ensure_rewritable(&source)?;
    let name = escape(source.name()).into_owned();
    let edited = edit::apply_checked(&source, &options, std::slice::from_ref(&edit))
        .map_err(|error| CommandError::Failed(format!("{name}: {error}")))?;
    let done = &edited.edits[0];
    if !done.errors.is_empty() && !args.force {
        for error in &done.errors {
            crate::stderr_line!(
                "{name}:{}: error[{}] {}",
                done.line,
                error.rule.name,
                escape(&error.message)
            );
        }
        crate::stderr_line!(
            "ekb: not written: the robot's reader would not load `{}` of location {} as given \
             (see above); give --force to write it anyway",
            edit.key.name(),
            edit.id
        );
        return Ok(Exit::Findings);
    }
    let style = DiffStyle {
        color: context.color_stdout(),
    };
    let changed = rewrite::deliver(&path, &source, &edited.text, mode, style)?;
    if !context.quiet && path != Path::new("-") {
        let what = match (changed, mode) {
            (false, _) => "already has this value",
            (true, Mode::Diff) => "would be set",
            (true, Mode::Write) => "set",
        };
        crate::stderr_line!(
            "{name}:{}: `{}` of location {} {what}",
            done.line,
            edit.key.name(),
            edit.id
        );
    }
    Ok(Exit::Clean)
}

/// The edit the arguments ask for, or why it is no edit ekb can make.
fn parse(args: &Args) -> Result<ValueEdit, CommandError> {
    let fail = |message: String| Err(CommandError::Failed(message));
    let Some(id) = crate::model::build::parse_id(&args.id) else {
        return fail(format!(
            "`{}` is no location id: an id is a whole number from 1 to 2147483647",
            escape(&args.id)
        ));
    };
    let key = match Key::from_name_ignoring_case(&args.key) {
        Some(Key::TourSpecification) => {
            return fail(
                "`tourSpecification` belongs to no location; edit the tour line in the file"
                    .to_string(),
            )
        }
        Some(key) => key,
        None => {
            let hint = match Key::nearest_to(&args.key) {
                Some(near) => format!("did you mean `{}`?", near.name()),
                None => "`ekb explain unknown-key` lists the keys".to_string(),
            };
            return fail(format!("`{}` is no key; {hint}", escape(&args.key)));
        }
    };
    if args.text.contains(['\n', '\r']) {
        return fail(
            "the value has a line break: a value is one line of the knowledge base".to_string(),
        );
    }
    Ok(ValueEdit {
        id,
        key,
        value: args.text.trim_matches([' ', '\t']).to_string(),
    })
}
