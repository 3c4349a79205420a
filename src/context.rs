//! What the command line and the language server share: the global options, the
//! configuration (read once, and only by what needs it), the exit codes of SPEC §5 and why a
//! command stopped.

use std::cell::OnceCell;
use std::io::IsTerminal;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use clap::ValueEnum;

use crate::config::Config;
use crate::model::build::Options;
use crate::render::escape::escape;
use crate::robot::Reader;
use crate::rules::selection::{Choice, RuleSet};
use crate::settings::{Lookup, Settings};
use crate::source::SourceFile;
use crate::stderr_line;

/// Whether output is coloured.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum ColorChoice {
    Auto,
    Always,
    Never,
}

/// The exit codes of SPEC §5.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Exit {
    /// No errors, no differences, nothing to change.
    Clean = 0,
    /// Errors found, differences found, or something would change.
    Findings = 1,
    /// The tool could not do its job.
    Failure = 2,
}

impl From<Exit> for ExitCode {
    fn from(exit: Exit) -> ExitCode {
        ExitCode::from(exit as u8)
    }
}

/// Why a command stopped before the end of its job.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum CommandError {
    /// It could not do its job: one line for standard error, exit code 2.
    Failed(String),
    /// Whoever read its output went away (`ekb … | head`): not a failure of `ekb`.
    OutputClosed,
}

impl std::fmt::Display for CommandError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            CommandError::Failed(message) => f.write_str(message),
            CommandError::OutputClosed => f.write_str("the output was closed"),
        }
    }
}

impl<E: std::error::Error + 'static> From<E> for CommandError {
    fn from(error: E) -> CommandError {
        let io_error = (&error as &dyn std::error::Error).downcast_ref::<std::io::Error>();
        if io_error.is_some_and(|e| e.kind() == std::io::ErrorKind::BrokenPipe) {
            return CommandError::OutputClosed;
        }
        CommandError::Failed(error.to_string())
    }
}

impl CommandError {
    /// Tells on standard error why the command failed, `ekb: error: …` on one line, escaped:
    /// errors quote file names and file text. A closed standard output is only remembered,
    /// to be told once, at the end ([`crate::streams::failure`]).
    pub fn report(&self) {
        match self {
            CommandError::OutputClosed => crate::streams::stdout_failed(),
            CommandError::Failed(message) => {
                crate::stderr_line!("ekb: error: {}", escape(message));
            }
        }
    }
}

pub type CommandResult = Result<Exit, CommandError>;

/// What every command may need: the global options and the configuration (read once, and
/// only by commands that need it).
#[derive(Debug)]
pub struct Context {
    config_path: Option<PathBuf>,
    pub color: ColorChoice,
    pub verbose: bool,
    pub quiet: bool,
    /// `--reader` (or `EKB_READER`), which overrides `ekb.toml`.
    pub reader: Option<Reader>,
    /// Whether `reader` came from `EKB_READER` rather than `--reader`.
    pub reader_from_env: bool,
    /// Where the settings come from: `--settings`, `--isolated`, or each file's folder.
    pub settings: Lookup,
    config: OnceCell<Config>,
}

impl Context {
    /// A context that reads the configuration at `config_path` (`None`: where
    /// [`Config::discover`] looks), with the default options, to be set by the command line.
    pub fn new(config_path: Option<PathBuf>) -> Context {
        Context {
            config_path,
            color: ColorChoice::Auto,
            verbose: false,
            quiet: false,
            reader: None,
            reader_from_env: false,
            settings: Lookup::Discover,
            config: OnceCell::new(),
        }
    }

    /// A context with default options, for tests and embedding.
    pub fn with_config(config: Config) -> Context {
        Context {
            config_path: None,
            color: ColorChoice::Never,
            verbose: false,
            quiet: false,
            reader: None,
            reader_from_env: false,
            settings: Lookup::Discover,
            config: OnceCell::from(config),
        }
    }

    /// The configuration (see [`Config::discover`]); what it ignores is told on standard
    /// error, once.
    pub fn config(&self) -> Result<&Config, CommandError> {
        if let Some(config) = self.config.get() {
            return Ok(config);
        }
        let config = Config::discover(self.config_path.as_deref())?;
        for warning in &config.warnings {
            stderr_line!("ekb: warning: {}", escape(warning));
        }
        Ok(self.config.get_or_init(|| config))
    }

    /// The settings for the file at `path` (see [`Lookup`]).
    pub fn settings_for(&self, path: &Path) -> Result<Settings, CommandError> {
        self.settings
            .settings_for(path)
            .map_err(CommandError::Failed)
    }

    /// The rules to run on the file at `path`: its settings' choice, then `command_line`'s.
    pub fn rules_for(&self, path: &Path, command_line: &Choice) -> Result<RuleSet, CommandError> {
        Ok(self.settings_for(path)?.rules_for(path, command_line))
    }

    /// How to read the knowledge base at `path`: the configuration's dialect and verbosity
    /// (or `-v`), and the reader of `--reader` (or `EKB_READER`), else of the file's
    /// `ekb.toml`, else of the configuration.
    pub fn read_options(&self, path: &Path) -> Result<Options, CommandError> {
        let config = self.config()?;
        let reader = match self.reader {
            Some(reader) => Some(reader),
            None => self
                .settings_for(path)?
                .reader
                .map(|reader| reader.value)
                .or(config.reader),
        };
        Ok(Options {
            dialect: config.dialect,
            reader,
            verbose: self.verbose || config.verbose,
        })
    }

    /// The files to work on: those given, else the configured knowledge base. Standard input
    /// may be given once: a second read of it would find it empty, a file with no tour.
    pub fn inputs(&self, files: &[PathBuf]) -> Result<Vec<PathBuf>, CommandError> {
        let stdin_count = files.iter().filter(|f| f.as_os_str() == "-").count();
        if stdin_count > 1 {
            return Err(CommandError::Failed(format!(
                "standard input (`-`) is named {stdin_count} times, but it can be read only once; name it once"
            )));
        }
        if !files.is_empty() {
            return Ok(files.to_vec());
        }
        Ok(vec![self.configured_knowledge_base()?])
    }

    /// The one file to work on: the one given, else the configured knowledge base.
    pub fn input(&self, file: Option<&Path>) -> Result<PathBuf, CommandError> {
        match file {
            Some(file) => Ok(file.to_path_buf()),
            None => self.configured_knowledge_base(),
        }
    }

    /// The files a command may rewrite in place: [`Context::inputs`], but a configured
    /// knowledge base outside the configuration's project folder (`knowledgeBase
    /// /etc/passwd`, or `../../..`) is refused: such a file is rewritten only when named on
    /// the command line.
    pub fn files_to_rewrite(&self, files: &[PathBuf]) -> Result<Vec<PathBuf>, CommandError> {
        let paths = self.inputs(files)?;
        if !files.is_empty() {
            return Ok(paths);
        }
        let config = self.config()?;
        match config.locate_knowledge_base() {
            Some(location) if !location.inside => Err(CommandError::Failed(format!(
                "the knowledgeBase of configuration {} is {}, outside the configuration's \
                 project folder {}: ekb rewrites a file outside the project only when you \
                 name it on the command line",
                config.path.as_deref().unwrap_or(Path::new("")).display(),
                location.file.display(),
                location.project.display()
            ))),
            _ => Ok(paths),
        }
    }

    /// [`Context::files_to_rewrite`] for a command that rewrites one file (`set`,
    /// `import --po`).
    pub fn file_to_rewrite(&self, file: Option<&Path>) -> Result<PathBuf, CommandError> {
        let named: Vec<PathBuf> = file.map(Path::to_path_buf).into_iter().collect();
        let mut paths = self.files_to_rewrite(&named)?;
        Ok(paths.swap_remove(0))
    }

    /// The configured knowledge base; with `-v`, where it really points.
    fn configured_knowledge_base(&self) -> Result<PathBuf, CommandError> {
        let config = self.config()?;
        let path = config.knowledge_base()?.to_path_buf();
        if let (true, Some(location)) = (self.verbose(), config.locate_knowledge_base()) {
            let outside = if location.inside {
                String::new()
            } else {
                format!(
                    ", outside its project folder {}",
                    escape(&location.project.display().to_string())
                )
            };
            stderr_line!(
                "ekb: the knowledgeBase of configuration {} is {}{outside}",
                escape(
                    &config
                        .path
                        .as_deref()
                        .unwrap_or(Path::new(""))
                        .display()
                        .to_string()
                ),
                escape(&location.file.display().to_string())
            );
        }
        Ok(path)
    }

    /// Whether to tell what is read: `-v` or the configuration's `verboseMode`.
    fn verbose(&self) -> bool {
        self.verbose || self.config().is_ok_and(|config| config.verbose)
    }

    /// Reads a knowledge base (`-` is standard input), to rewrite it or show it as written:
    /// a file in UTF-16 or UTF-32 is refused. A file an ekb stopped while writing it in place
    /// left partly written is first restored ([`crate::write::restore_if_interrupted`]).
    pub fn read(&self, path: &Path) -> Result<SourceFile, CommandError> {
        self.say_reading(path);
        self.restore_if_interrupted(path)?;
        Ok(SourceFile::read(path)?)
    }

    /// Reads a knowledge base to report on it: a file in UTF-16 or UTF-32 is one the robot
    /// loads nothing from, a finding ([`SourceFile::read_even_wide`]). Restored first, as
    /// [`Context::read`] does.
    pub fn read_to_report(&self, path: &Path) -> Result<SourceFile, CommandError> {
        self.say_reading(path);
        self.restore_if_interrupted(path)?;
        Ok(SourceFile::read_even_wide(path)?)
    }

    fn restore_if_interrupted(&self, path: &Path) -> Result<(), CommandError> {
        crate::write::restore_if_interrupted(path).map_err(|reason| {
            let name = path.display().to_string();
            CommandError::Failed(format!("cannot read {}: {reason}", escape(&name)))
        })
    }

    fn say_reading(&self, path: &Path) {
        if self.verbose() {
            stderr_line!("ekb: reading {}", escape(&path.display().to_string()));
        }
    }

    /// Whether to colour what goes to standard output.
    pub fn color_stdout(&self) -> bool {
        self.use_color(std::io::stdout().is_terminal())
    }

    /// Whether to colour what goes to standard error.
    pub fn color_stderr(&self) -> bool {
        self.use_color(std::io::stderr().is_terminal())
    }

    fn use_color(&self, is_terminal: bool) -> bool {
        match self.color {
            ColorChoice::Always => true,
            ColorChoice::Never => false,
            ColorChoice::Auto => {
                is_terminal && std::env::var_os("NO_COLOR").is_none_or(|v| v.is_empty())
            }
        }
    }
}
