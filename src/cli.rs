//! The `ekb` command line: global options and the subcommands (SPEC §5).
//!
//! This module only declares the interface and dispatches; each command lives in its own
//! module under [`crate::commands`].

use std::path::PathBuf;
use std::process::ExitCode;

use clap::parser::ValueSource;
use clap::{CommandFactory, FromArgMatches, Parser, Subcommand};

use crate::commands;
use crate::context::{ColorChoice, Context, Exit};
use crate::settings::Lookup;
use crate::stderr_line;
use crate::streams;

/// Author and validate the environment knowledge base of a tour-guide robot.
#[derive(Debug, Parser)]
// The version, and in a release build the commit (build.rs).
#[command(name = "ekb", version = env!("EKB_VERSION"), about, long_about = None, propagate_version = true)]
pub struct Cli {
    /// Configuration file [default: $EKB_CONFIG, else config/environmentKnowledgeBaseConfiguration.ini]
    #[arg(long, global = true, value_name = "PATH")]
    pub config: Option<PathBuf>,

    /// When to use colour (NO_COLOR in the environment means never, unless `always`)
    #[arg(long, global = true, value_enum, default_value_t = ColorChoice::Auto, value_name = "WHEN")]
    pub color: ColorChoice,

    /// Print what is read, as it is read, on standard error
    #[arg(short, long, global = true)]
    pub verbose: bool,

    /// The version of the robot's reader to check against [default: `reader` in ekb.toml, else d5.4.2 for a seed-dialect file, 2025-06 for any other]
    #[arg(
        long,
        global = true,
        value_parser = crate::commands::named_values::reader(),
        env = "EKB_READER",
        value_name = "VERSION"
    )]
    pub reader: Option<crate::robot::Reader>,

    /// Print only findings and errors, no summary
    #[arg(short, long, global = true)]
    pub quiet: bool,

    /// Use this settings file instead of the nearest ekb.toml (or .ekb.toml) in the file's folder or above
    #[arg(long, global = true, value_name = "PATH", conflicts_with = "isolated")]
    pub settings: Option<PathBuf>,

    /// Use no settings file: every rule, at its own severity
    #[arg(long, global = true)]
    pub isolated: bool,

    #[command(subcommand)]
    pub command: Command,
}

#[derive(Debug, Subcommand)]
pub enum Command {
    /// Validate knowledge-base files against every rule
    Check(commands::check::Args),
    /// A table of all locations
    Locations(commands::locations::Args),
    /// One location in full
    Show(commands::show::Args),
    /// The tour in order, as the robot will say it in one language
    Tour(commands::tour::Args),
    /// What changed between two knowledge bases, location by location
    Diff(commands::diff::Args),
    /// The typed model as JSON
    Export(commands::export::Args),
    /// JSON back to a canonical knowledge-base file
    Import(commands::import::Args),
    /// Rewrite files in the canonical layout
    Fmt(commands::fmt::Args),
    /// Apply the machine-applicable fixes
    Fix(commands::fix::Args),
    /// List the rule catalogue
    Rules(commands::rules::Args),
    /// Show one rule's documentation
    Explain(commands::explain::Args),
    /// Print a shell completion script
    Completions(commands::completions::Args),
    /// Print the man page
    Man(commands::man::Args),
    /// Draw the tour on the lab map, as SVG or PNG
    Map(commands::map::Args),
    /// Write one HTML page to review: the map, the tour's messages, the findings
    Report(commands::report::Args),
    /// The behaviour-tree mission with both knowledge bases: check, tree, walk
    Mission(commands::mission::Args),
    /// How far each language is translated, message by message
    Translations(commands::translations::Args),
    /// Edit one value in place, losslessly
    Set(commands::set::Args),
    /// Run the language server (LSP, on standard input and output) for editors
    Lsp(commands::lsp::Args),
    /// Edit the knowledge base in a local web page, checked as you type
    Serve(commands::serve::Args),
    /// Print the settings in force for a file, and where each comes from
    Settings(commands::settings::Args),
}

/// The context of the global options of `cli`; `reader_from_env`: whether its reader came
/// from `EKB_READER` rather than `--reader`.
fn context(cli: &Cli, reader_from_env: bool) -> Context {
    let mut context = Context::new(cli.config.clone());
    context.color = cli.color;
    context.verbose = cli.verbose;
    context.quiet = cli.quiet;
    context.reader = cli.reader;
    context.reader_from_env = reader_from_env;
    context.settings = match (&cli.settings, cli.isolated) {
        (Some(path), _) => Lookup::Explicit(path.clone()),
        (None, true) => Lookup::Isolated,
        (None, false) => Lookup::Discover,
    };
    context
}

/// Parses the command line, runs the command and turns the outcome into an exit code.
pub fn main() -> ExitCode {
    let mut matches = Cli::command().get_matches();
    // Asked before the values are taken out of `matches` (not cloned: a copy of every
    // argument was 2% of the check of a real file).
    let reader_from_env = matches.value_source("reader") == Some(ValueSource::EnvVariable);
    let cli = Cli::from_arg_matches_mut(&mut matches).unwrap_or_else(|error| error.exit());
    let context = context(&cli, reader_from_env);
    let outcome = match &cli.command {
        Command::Check(args) => commands::check::run(args, &context),
        Command::Locations(args) => commands::locations::run(args, &context),
        Command::Show(args) => commands::show::run(args, &context),
        Command::Tour(args) => commands::tour::run(args, &context),
        Command::Diff(args) => commands::diff::run(args, &context),
        Command::Export(args) => commands::export::run(args, &context),
        Command::Import(args) => commands::import::run(args, &context),
        Command::Fmt(args) => commands::fmt::run(args, &context),
        Command::Fix(args) => commands::fix::run(args, &context),
        Command::Rules(args) => commands::rules::run(args, &context),
        Command::Explain(args) => commands::explain::run(args, &context),
        Command::Completions(args) => commands::completions::run(args, Cli::command()),
        Command::Man(args) => commands::man::run(args, Cli::command()),
        Command::Map(args) => commands::map::run(args, &context),
        Command::Report(args) => commands::report::run(args, &context),
        Command::Mission(args) => commands::mission::run(args, &context),
        Command::Translations(args) => commands::translations::run(args, &context),
        Command::Set(args) => commands::set::run(args, &context),
        Command::Lsp(args) => commands::lsp::run(args, &context),
        Command::Serve(args) => commands::serve::run(args, &context),
        Command::Settings(args) => commands::settings::run(args, &context),
    };
    let exit = outcome.unwrap_or_else(|error| {
        error.report();
        Exit::Failure
    });
    // A stream that could not be written (`ekb export | head -c1`): what it should have
    // carried is lost, so the command failed, whatever else it did.
    match streams::failure() {
        Some(stream) => {
            stderr_line!(
                "ekb: error: cannot write to {stream}: it was closed before ekb finished \
                 (whoever read it stopped reading)"
            );
            Exit::Failure.into()
        }
        None => exit.into(),
    }
}
