//! `ekb check [FILE...]`: validate knowledge bases.

use std::io::Write;
use std::path::{Path, PathBuf};

use super::{CommandError, CommandResult, Context, Exit};
use crate::check::{check_with, Checked};
use crate::diagnostic::{Hidden, Severity, Summary};
use crate::render::{self, escape::escape, statistics, Format, RenderOptions};
use crate::rewrite::{self, DiffStyle, Mode};
use crate::rules::selection::{Choice, RuleSelector};
use crate::source::SourceFile;
use crate::suppression;

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
    pub rules: RuleArgs,

    /// Show only findings at or above this severity (the summary still counts them all)
    #[arg(long, value_enum, value_name = "SEVERITY")]
    pub level: Option<Severity>,

    /// Instead of the findings, one line per rule: its count, and whether `ekb fix` can fix
    /// it, the most frequent first
    #[arg(long, conflicts_with = "add_ignore")]
    pub statistics: bool,

    /// Exit 0 even when there are findings (2 still means ekb could not do its job)
    #[arg(long)]
    pub exit_zero: bool,

    /// Write the report to this file instead of standard output
    #[arg(long, value_name = "PATH", conflicts_with = "add_ignore")]
    pub output_file: Option<PathBuf>,

    /// Write a `# ekb: ignore[RULE]` comment above every line with findings, so that the files
    /// check clean (to adopt ekb on an existing file); run again, it adds nothing
    #[arg(long)]
    pub add_ignore: bool,
}

/// `--select`, `--extend-select` and `--ignore`: which rules run, over `ekb.toml`'s choice.
#[derive(Debug, Clone, Default, clap::Args)]
pub struct RuleArgs {
    /// Run only these rules or categories (comma-separated), instead of those ekb.toml selects
    #[arg(long, value_delimiter = ',', value_name = "RULE", value_parser = RuleSelector::parse)]
    pub select: Option<Vec<RuleSelector>>,

    /// Run these rules or categories as well
    #[arg(long, value_delimiter = ',', value_name = "RULE", value_parser = RuleSelector::parse)]
    pub extend_select: Vec<RuleSelector>,

    /// Do not run these rules or categories
    #[arg(long, value_delimiter = ',', value_name = "RULE", value_parser = RuleSelector::parse)]
    pub ignore: Vec<RuleSelector>,
}

impl RuleArgs {
    /// The command line's layer of choices.
    pub fn choice(&self) -> Choice {
        Choice {
            select: self.select.clone(),
            extend_select: self.extend_select.clone(),
            ignore: self.ignore.clone(),
        }
    }
}

pub fn run(args: &Args, context: &Context) -> CommandResult {
    let paths = context.inputs(&args.files)?;
    let choice = args.rules.choice();
    let mut plans = Vec::with_capacity(paths.len());
    for path in &paths {
        plans.push((
            context.read_options(path)?,
            context.rules_for(path, &choice)?,
        ));
    }
    let sources = paths
        .iter()
        .map(|path| context.read(path))
        .collect::<Result<Vec<SourceFile>, _>>()?;
    let mut checked: Vec<Checked> = sources
        .iter()
        .zip(&plans)
        .map(|(source, (options, rules))| check_with(source, options, rules))
        .collect();
    if args.add_ignore {
        return add_ignores(&paths, &checked, context);
    }
    // Checked::summary also counts the findings past the cap of each rule (check.rs).
    let mut summary = Summary::default();
    for file in &checked {
        summary.merge(&file.summary());
    }
    let failed = summary.errors > 0 || (args.deny_warnings && summary.warnings > 0);
    let exit = if failed && !args.exit_zero {
        Exit::Findings
    } else {
        Exit::Clean
    };
    if let Some(level) = args.level {
        let shown = |severity: Severity| severity <= level;
        for file in &mut checked {
            file.diagnostics.retain(|d| shown(d.severity()));
            file.omitted.retain(|d| shown(d.severity()));
        }
        let below = summary.by_rule.iter().filter(|c| !shown(c.severity));
        summary.hidden = Some(Hidden {
            count: below.map(|c| c.count).sum(),
            level,
        });
    }
    let to_file = args.output_file.as_deref().filter(|p| *p != Path::new("-"));
    let render_options = RenderOptions {
        color: to_file.is_none() && context.color_stdout(),
        quiet: context.quiet,
    };
    let report = |out: &mut dyn Write| {
        if args.statistics {
            let level = args.level.unwrap_or(Severity::Info);
            statistics::render(args.format, &summary, level, out, &render_options)
        } else {
            render::render(args.format, &checked, &summary, out, &render_options)
        }
    };
    if let Some(path) = to_file {
        let mut bytes = Vec::new();
        report(&mut bytes)?;
        crate::write::write_atomically(path, &bytes)?;
        return Ok(exit);
    }
    // Buffered: a large file can have hundreds of thousands of findings, one line each.
    let mut stdout = std::io::BufWriter::new(std::io::stdout().lock());
    let written = report(&mut stdout).and_then(|()| stdout.flush());
    match written {
        // A reader that stops early (`ekb check | head`) is not a failure of the check.
        Err(error) if error.kind() == std::io::ErrorKind::BrokenPipe => Ok(exit),
        Err(error) => Err(CommandError::Failed(format!(
            "cannot write the report: {error}"
        ))),
        Ok(()) => Ok(exit),
    }
}

/// `--add-ignore`: writes a suppression above each line with findings, file by file, and
/// says how many on standard error.
fn add_ignores(paths: &[PathBuf], checked: &[Checked<'_>], context: &Context) -> CommandResult {
    let style = DiffStyle {
        color: context.color_stdout(),
    };
    let mut files = checked.iter();
    Ok(rewrite::for_each_file(paths, |path| {
        let checked = files.next().expect("one check per path");
        let source = checked.source;
        rewrite::ensure_rewritable(source)?;
        let (text, added) = suppression::add_ignores(source.text(), &checked.diagnostics);
        rewrite::deliver(path, source, &text, Mode::Write, style)?;
        if !context.quiet {
            let s = if added == 1 { "" } else { "s" };
            eprintln!(
                "{}: added {added} suppression comment{s}",
                escape(source.name())
            );
        }
        Ok(Exit::Clean)
    }))
}
