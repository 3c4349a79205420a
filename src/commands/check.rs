//! `ekb check [FILE...]`: validate knowledge bases.

use std::collections::HashSet;
use std::io::Write;
use std::path::{Path, PathBuf};

use super::map::MapArgs;
use super::rewrite::{self, DiffStyle, Mode};
use super::{CommandError, CommandResult, Context, Exit};
use crate::check::suppression;
use crate::check::Checked;
use crate::check::{Hidden, Summary};
use crate::diagnostic::Severity;
use crate::mission::check::check_file;
use crate::render::{self, escape::escape, statistics, Format, RenderOptions};
use crate::rules::selection::{Choice, RuleSelector};
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
    pub rules: RuleArgs,

    /// Show only findings at or above this severity (the summary still counts them all)
    #[arg(long, value_parser = super::named_values::severity(), value_name = "SEVERITY")]
    pub level: Option<Severity>,

    /// Instead of the findings, one line per rule: its count, and whether `ekb fix` can fix
    /// it, the most frequent first
    #[arg(long, conflicts_with = "add_ignore")]
    pub statistics: bool,

    /// Draw every finding in full: without it, a rule with more than three warnings in a
    /// file is one paragraph (its count, its lines, the first message)
    #[arg(long)]
    pub show_all: bool,

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

    #[command(flatten)]
    pub map: MapArgs,
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
    // A bad configuration fails every file alike: once, here.
    context.config()?;
    let choice = args.rules.choice();
    if args.add_ignore {
        return Ok(add_ignores(&paths, &choice, &args.map, context));
    }
    // A file that cannot be read is told at once and the others are checked all the same;
    // the exit is 2 then. If none can be read, there is no report.
    let mut unreadable = false;
    let mut read = Vec::with_capacity(paths.len());
    for path in &paths {
        let plan = context.read_options(path).and_then(|options| {
            let rules = context.rules_for(path, &choice)?;
            Ok((path.clone(), options, rules, context.read_to_report(path)?))
        });
        match plan {
            Ok(plan) => read.push(plan),
            Err(error) => {
                stderr_line!("ekb: error: {}", escape(&error.to_string()));
                unreadable = true;
            }
        }
    }
    let Some((first, ..)) = read.first() else {
        return Ok(Exit::Failure);
    };
    // One map for all the files: that of the first file's `ekb.toml`, unless given.
    let map_config = context.settings_for(first)?.map.config;
    let map = args.map.load(map_config.map(|config| config.value))?;
    // A mission or a culture file is recognised by its content and checked alone.
    let checked: Vec<Checked> = read
        .iter()
        .map(|(_, options, rules, source)| check_file(source, options, rules, map.as_ref()))
        .collect();
    let shown = Shown {
        format: args.format,
        deny_warnings: args.deny_warnings,
        exit_zero: args.exit_zero,
        level: args.level,
        statistics: args.statistics,
        show_all: args.show_all,
        output_file: args.output_file.as_deref(),
    };
    let exit = report(checked, &shown, context)?;
    Ok(if unreadable { Exit::Failure } else { exit })
}

/// How a report is shown, and what makes it fail.
#[derive(Debug, Default)]
pub struct Shown<'a> {
    pub format: Format,
    pub deny_warnings: bool,
    pub exit_zero: bool,
    pub level: Option<Severity>,
    pub statistics: bool,
    pub show_all: bool,
    pub output_file: Option<&'a Path>,
}

/// Renders the findings of `checked` as `shown` says, on standard output or in its file,
/// and gives the exit code of SPEC §5.
pub fn report(mut checked: Vec<Checked<'_>>, shown: &Shown, context: &Context) -> CommandResult {
    // Checked::summary also counts the findings past the cap of each rule (check.rs).
    let mut summary = Summary::default();
    for file in &checked {
        summary.merge(&file.summary());
    }
    let failed = summary.errors > 0 || (shown.deny_warnings && summary.warnings > 0);
    let exit = if failed && !shown.exit_zero {
        Exit::Findings
    } else {
        Exit::Clean
    };
    if let Some(level) = shown.level {
        let at_level = |severity: Severity| severity <= level;
        for file in &mut checked {
            file.diagnostics.retain(|d| at_level(d.severity()));
            file.omitted.retain(|d| at_level(d.severity()));
        }
        let below = summary.by_rule.iter().filter(|c| !at_level(c.severity));
        summary.hidden = Some(Hidden {
            count: below.map(|c| c.count).sum(),
            level,
        });
    }
    let to_file = shown.output_file.filter(|p| *p != Path::new("-"));
    let render_options = RenderOptions {
        color: to_file.is_none() && context.color_stdout(),
        quiet: context.quiet,
        width: render::stdout_width(),
        show_all: shown.show_all,
    };
    let render = |out: &mut dyn Write| {
        if shown.statistics {
            let level = shown.level.unwrap_or(Severity::Info);
            statistics::render(shown.format, &summary, level, out, &render_options)
        } else {
            render::render(shown.format, &checked, &summary, out, &render_options)
        }
    };
    if let Some(path) = to_file {
        crate::write::write_streamed(path, |out| render(out))?;
        return Ok(exit);
    }
    // Buffered: a large file can have hundreds of thousands of findings, one line each.
    let mut stdout = std::io::BufWriter::new(std::io::stdout().lock());
    let written = render(&mut stdout).and_then(|()| stdout.flush());
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

/// `--add-ignore`: writes a suppression above each line with findings, and says how many on
/// standard error. One file at a time, from its lock to its write (so one lock and one open
/// file at a time, and two ekb given the same files in another order never wait on each
/// other); a file named twice (by any of its names) is done once.
fn add_ignores(paths: &[PathBuf], choice: &Choice, map_args: &MapArgs, context: &Context) -> Exit {
    let style = DiffStyle {
        color: context.color_stdout(),
    };
    let mut done = HashSet::new();
    // One map for all the files, as for a report: that of the first file's `ekb.toml`.
    let mut map = None;
    rewrite::for_each_file(paths, |path| {
        let id = crate::write::FileId::of(path);
        if id.is_some_and(|id| done.contains(&id)) {
            return Ok(Exit::Clean);
        }
        let _lock = rewrite::lock(path, Mode::Write)?;
        let options = context.read_options(path)?;
        let rules = context.rules_for(path, choice)?;
        let source = context.read_to_report(path)?;
        if map.is_none() {
            let map_config = context.settings_for(path)?.map.config;
            map = Some(map_args.load(map_config.map(|config| config.value))?);
        }
        let checked = check_file(
            &source,
            &options,
            &rules,
            map.as_ref().and_then(Option::as_ref),
        );
        rewrite::ensure_rewritable(&source)?;
        let (text, added) = suppression::add_ignores(source.text(), &checked.diagnostics);
        rewrite::deliver(path, &source, &text, Mode::Write, style)?;
        // Replaced by a rename, the file has a new inode: its other names now lead there.
        done.extend(id.into_iter().chain(crate::write::FileId::of(path)));
        if !context.quiet {
            let s = if added == 1 { "" } else { "s" };
            stderr_line!(
                "{}: added {added} suppression comment{s}",
                escape(source.name())
            );
        }
        Ok(Exit::Clean)
    })
}
