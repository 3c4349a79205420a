//! `ekb mission check|tree|walk`: the behaviour-tree mission with both knowledge bases
//! (SPEC §11).

use std::io::Write;
use std::path::{Path, PathBuf};

use super::map::MapArgs;
use super::{CommandError, CommandResult, Context, Exit};
use crate::mission::check::{check_together, read_mission, MissionSources};
use crate::mission::culture::{CultureKnowledgeBase, Held, PhraseBook, ValueTypes};
use crate::mission::setup::{self, MissionPaths};
use crate::mission::tree::Mission;
use crate::mission::{outline, robot_language, walk, LANGUAGE_KEY};
use crate::model::build::Options;
use crate::model::Language;
use crate::present::language;
use crate::render::escape::{escape, escape_lines};
use crate::render::{safe_json as json, Format};
use crate::robot::speech::RobotProfile;
use crate::robot::Reader;
use crate::rules::selection::RuleSet;
use crate::source::SourceFile;

#[derive(Debug, clap::Args)]
pub struct Args {
    #[command(subcommand)]
    pub command: MissionCommand,
}

#[derive(Debug, clap::Subcommand)]
pub enum MissionCommand {
    /// Check the mission, the culture knowledge base and the environment knowledge base together
    Check(CheckArgs),
    /// Print the mission's trees, with each node's parameter and the phrase each SayText says
    Tree(ShowArgs),
    /// A dry run of the mission on the happy path: the steps the robot takes, in order
    Walk(ShowArgs),
}

/// Where the mission's files are.
#[derive(Debug, Clone, Default, clap::Args)]
pub struct Files {
    /// The robot's configuration folder: its behaviorControllerConfiguration.ini,
    /// cultureKnowledgeBaseConfiguration.ini and environmentKnowledgeBaseConfiguration.ini
    /// name the files, in the sibling data/ folder [default: `[mission] config-dir` in ekb.toml]
    #[arg(long, value_name = "DIR")]
    pub config_dir: Option<PathBuf>,
    /// The mission (behaviour tree XML) [default: from the configuration folder]
    #[arg(long, value_name = "X.xml")]
    pub mission: Option<PathBuf>,
    /// The culture knowledge base [default: from the configuration folder]
    #[arg(long, value_name = "C.dat")]
    pub culture_kb: Option<PathBuf>,
    /// The culture knowledge base's types file [default: from the configuration folder]
    #[arg(long, value_name = "T.dat")]
    pub culture_types: Option<PathBuf>,
    /// The environment knowledge base [default: from the configuration folder]
    #[arg(long, value_name = "E.dat")]
    pub kb: Option<PathBuf>,
}

#[derive(Debug, clap::Args)]
pub struct CheckArgs {
    #[command(flatten)]
    pub files: Files,
    /// Output format
    #[arg(long, value_enum, default_value_t = Format::Human)]
    pub format: Format,
    /// Exit 1 on warnings too
    #[arg(long)]
    pub deny_warnings: bool,
}

/// The arguments of `tree` and `walk`, which show the mission in one language.
#[derive(Debug, clap::Args)]
pub struct ShowArgs {
    #[command(flatten)]
    pub files: Files,
    /// The language the robot speaks [default: the culture knowledge base's phraseLanguage]
    #[arg(long, value_name = "L", ignore_case = true, value_parser = language::parser())]
    pub lang: Option<Language>,
    /// Output format
    #[arg(long, value_enum, default_value_t = TextOrJson::Text)]
    pub format: TextOrJson,
    /// The lab map, for `walk`: a `Navigate` to a stop the robot cannot drive to fails
    #[command(flatten)]
    pub map: MapArgs,
}

/// `--format` of `tree` and `walk`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum TextOrJson {
    /// For people
    Text,
    /// One JSON object
    Json,
}

pub fn run(args: &Args, context: &Context) -> CommandResult {
    match &args.command {
        MissionCommand::Check(args) => run_check(args, context),
        MissionCommand::Tree(args) => run_tree(args, context),
        MissionCommand::Walk(args) => run_walk(args, context),
    }
}

/// The robot's configuration folder: `--config-dir`, else `from_settings`, the
/// `[mission] config-dir` of the current folder's `ekb.toml` (resolved against its folder).
pub fn config_dir(flag: Option<&Path>, from_settings: Option<PathBuf>) -> Option<PathBuf> {
    flag.map(Path::to_path_buf).or(from_settings)
}

/// The files: those named by flags, the others from the configuration folder.
fn paths(files: &Files, context: &Context) -> Result<MissionPaths, CommandError> {
    let from_settings = context.settings_for(Path::new("-"))?.mission.config_dir;
    let named = MissionPaths {
        mission: files.mission.clone(),
        culture_kb: files.culture_kb.clone(),
        culture_types: files.culture_types.clone(),
        kb: files.kb.clone(),
        ..MissionPaths::default()
    };
    match config_dir(
        files.config_dir.as_deref(),
        from_settings.map(|dir| dir.value),
    ) {
        Some(dir) => {
            Ok(named.or(MissionPaths::from_config_dir(&dir).map_err(CommandError::Failed)?))
        }
        None => Ok(named),
    }
}

/// The files read: each one known, read (or exit 2).
struct Read {
    paths: MissionPaths,
    mission: Option<SourceFile>,
    culture_kb: Option<SourceFile>,
    culture_types: Option<SourceFile>,
    kb: Option<(SourceFile, Options)>,
    /// The robot's reader that the settings name for the knowledge bases, if any.
    reader: Option<Reader>,
    /// The robot profile (`[robot]`) of the same settings.
    robot: RobotProfile,
    /// The lab map (`[map] config`) of the same settings, resolved, if any.
    map_config: Option<PathBuf>,
}

impl Read {
    fn all(files: &Files, context: &Context) -> Result<Read, CommandError> {
        let paths = paths(files, context)?;
        if !context.quiet {
            for warning in &paths.warnings {
                crate::stderr_line!("ekb: warning: {}", escape(warning));
            }
        }
        // A file found through the configuration folder that cannot be read: where it was
        // looked for, and the flag that names it instead.
        let read_one = |path: &Path, named: bool, flag: &str| {
            context.read(path).map_err(|error| {
                match paths.not_found_hint(flag).filter(|_| !named) {
                    Some(hint) => CommandError::Failed(format!("{error}; {hint}")),
                    None => error,
                }
            })
        };
        let read = |path: &Option<PathBuf>, named: &Option<PathBuf>, flag: &str| {
            path.as_deref()
                .map(|p| read_one(p, named.is_some(), flag))
                .transpose()
        };
        let kb = match &paths.kb {
            Some(path) => Some((
                read_one(path, files.kb.is_some(), "--kb")?,
                context.read_options(path)?,
            )),
            None => None,
        };
        // The culture reader is the environment reader's robot's: named by the settings
        // that apply to the environment knowledge base, else to the culture knowledge base.
        let reader = match (&kb, &paths.culture_kb) {
            (Some((_, options)), _) => options.reader,
            (None, Some(path)) => context.read_options(path)?.reader,
            (None, None) => None,
        };
        // The robot profile of the same settings: the environment knowledge base's, else the
        // culture knowledge base's, else the current folder's.
        let settings_of = paths
            .kb
            .as_deref()
            .or(paths.culture_kb.as_deref())
            .unwrap_or(Path::new("-"));
        let settings = context.settings_for(settings_of)?;
        Ok(Read {
            reader,
            robot: settings.robot.profile(),
            map_config: settings.map.config.map(|config| config.value),
            mission: read(&paths.mission, &files.mission, "--mission")?,
            culture_kb: read(&paths.culture_kb, &files.culture_kb, "--culture-kb")?,
            culture_types: read(
                &paths.culture_types,
                &files.culture_types,
                "--culture-types",
            )?,
            kb,
            paths,
        })
    }

    fn sources(&self) -> MissionSources<'_> {
        MissionSources {
            mission: self.mission.as_ref(),
            culture_kb: self.culture_kb.as_ref(),
            culture_types: self.culture_types.as_ref(),
            kb: self.kb.as_ref().map(|(source, options)| (source, options)),
            reader: self.reader,
            robot: Some(&self.robot),
        }
    }

    /// The mission, which `tree` and `walk` need, parsed.
    fn mission(&self) -> Result<Mission, CommandError> {
        let source = self.mission.as_ref().ok_or_else(|| {
            let why = self
                .paths
                .missing("mission", "--mission", setup::BEHAVIOR_CONTROLLER_INI);
            CommandError::Failed(why)
        })?;
        read_mission(source).map_err(|finding| {
            CommandError::Failed(format!(
                "{} cannot be read: {} (run `ekb mission check`)",
                source.name(),
                finding.message
            ))
        })
    }
}

fn run_check(args: &CheckArgs, context: &Context) -> CommandResult {
    let read = Read::all(&args.files, context)?;
    let sources = read.sources();
    if sources.mission.is_none()
        && sources.culture_kb.is_none()
        && sources.culture_types.is_none()
        && sources.kb.is_none()
    {
        return Err(CommandError::Failed(
            "no files to check: give --config-dir, or --mission, --culture-kb, \
             --culture-types and --kb"
                .to_string(),
        ));
    }
    let rules = RuleSet::default();
    let checked = check_together(&sources, &rules);
    let shown = super::check::Shown {
        format: args.format,
        deny_warnings: args.deny_warnings,
        ..Default::default()
    };
    super::check::report(checked, &shown, context)
}

/// The culture knowledge base and its types, parsed, if both are given.
struct Culture<'s> {
    kb: CultureKnowledgeBase<'s>,
    types: ValueTypes<'s>,
}

impl<'s> Culture<'s> {
    fn of(read: &'s Read) -> Option<Culture<'s>> {
        let line_buffer = read.sources().culture_line_buffer();
        Some(Culture {
            kb: CultureKnowledgeBase::parse(read.culture_kb.as_ref()?.text(), line_buffer),
            types: ValueTypes::parse(read.culture_types.as_ref()?.text(), line_buffer),
        })
    }

    /// The phrases in `--lang`, else in the culture knowledge base's language.
    fn phrases(culture: Option<&'s Culture<'s>>, lang: Option<Language>) -> PhraseBook<'s> {
        let configured = || {
            let culture = culture?;
            robot_language(culture.kb.held(&culture.types, LANGUAGE_KEY).text()?)
        };
        PhraseBook {
            culture: culture.map(|c| (&c.kb, &c.types)),
            language: lang.or_else(configured),
        }
    }
}

fn run_tree(args: &ShowArgs, context: &Context) -> CommandResult {
    let read = Read::all(&args.files, context)?;
    let mission = read.mission()?;
    let culture = Culture::of(&read);
    let phrases = Culture::phrases(culture.as_ref(), args.lang);
    let text = read.mission.as_ref().map_or("", |m| m.text());
    let trees = outline::outline(&mission, text, &phrases);
    let mut stdout = std::io::stdout().lock();
    match args.format {
        TextOrJson::Text => {
            stdout.write_all(escape_lines(&outline::render_text(&trees)).as_bytes())?
        }
        TextOrJson::Json => json::write(&serde_json::json!({ "trees": trees }), &mut stdout)?,
    }
    Ok(Exit::Clean)
}

fn run_walk(args: &ShowArgs, context: &Context) -> CommandResult {
    let read = Read::all(&args.files, context)?;
    let mission = read.mission()?;
    let paths = &read.paths;
    let (kb_source, options) = read.kb.as_ref().ok_or_else(|| {
        let why = paths.missing("environment knowledge base", "--kb", setup::ENVIRONMENT_INI);
        CommandError::Failed(why)
    })?;
    let culture = Culture::of(&read).ok_or_else(|| {
        let what = "culture knowledge base and types file";
        CommandError::Failed(paths.missing(
            what,
            "--culture-kb and --culture-types",
            setup::CULTURE_INI,
        ))
    })?;
    let phrases = Culture::phrases(Some(&culture), args.lang);
    let kb = crate::check::check(kb_source, options);
    crate::present::note_errors(&kb, context.quiet);
    if phrases.language.is_none() {
        if let Held::Text(word, _) = culture.kb.held(&culture.types, LANGUAGE_KEY) {
            crate::stderr_line!(
                "ekb: warning: the mission's language `{}` is not one the robot accepts; \
                 give --lang to walk it in another",
                escape(&word)
            );
        }
    }
    let map = args.map.load(read.map_config.clone())?;
    let world = walk::World {
        kb: &kb.kb,
        phrases,
        asr_enabled: paths.asr_enabled.unwrap_or(true),
        robot: &read.robot,
        map: map.as_ref(),
    };
    let text = read.mission.as_ref().map_or("", |m| m.text());
    let walked = walk::walk(&mission, text, &world);
    let mut stdout = std::io::stdout().lock();
    match args.format {
        TextOrJson::Text => {
            stdout.write_all(escape_lines(&walk::render_text(&walked)).as_bytes())?
        }
        TextOrJson::Json => json::write(&walked, &mut stdout)?,
    }
    Ok(match walked.outcome {
        walk::Outcome::Completed => Exit::Clean,
        walk::Outcome::Stopped { .. } => Exit::Failure,
        walk::Outcome::Failed | walk::Outcome::NeverEnds { .. } | walk::Outcome::Crashes { .. } => {
            Exit::Findings
        }
    })
}
