//! `ekb settings [FILE]`: the settings in force for a file, in `ekb.toml`'s own form, each
//! with where it comes from (the settings file's line, a flag, the environment, the robot's
//! configuration, or the default), then the rules that run.

use std::io::Write;
use std::path::{Path, PathBuf};

use super::check::RuleArgs;
use super::{CommandError, CommandResult, Context, Exit};
use crate::model::Language;
use crate::render::escape::escape_lines;
use crate::rules::selection::RuleSelector;
use crate::rules::{categories, ALL};
use crate::settings::{Lookup, Settings, Sourced};

#[derive(Debug, clap::Args)]
pub struct Args {
    /// The knowledge-base file whose settings to show [default: the configured knowledgeBase, else a file in the current folder]
    #[arg(value_name = "FILE")]
    pub file: Option<PathBuf>,

    #[command(flatten)]
    pub rules: RuleArgs,
}

pub fn run(args: &Args, context: &Context) -> CommandResult {
    let configured = || context.config().ok()?.knowledge_base.clone();
    let file = args
        .file
        .clone()
        .or_else(configured)
        .unwrap_or_else(|| PathBuf::from("-"));
    let settings = context.settings_for(&file)?;
    let name = if file == Path::new("-") {
        "a file in the current folder".to_string()
    } else {
        file.display().to_string()
    };
    let mut out = String::new();
    out.push_str(&format!("# the settings for {name}\n"));
    out.push_str(&format!("# {}\n", where_from(&context.settings, &settings)));
    let at = |line: Option<u32>| -> String {
        match (line, &settings.path) {
            (Some(line), Some(path)) => format!("{}:{line}", path.display()),
            _ => "default".to_string(),
        }
    };
    let (reader, origin) = reader(context, &settings, &file)?;
    entry(&mut out, "reader", &reader, &origin);
    out.push_str("\n[check]\n");
    let check = &settings.check;
    let choice = args.rules.choice();
    let list = |value: Option<&Sourced<Vec<RuleSelector>>>, flag: Option<&Vec<RuleSelector>>| {
        let mut names: Vec<&str> =
            value.map_or(Vec::new(), |s| s.value.iter().map(|s| s.name()).collect());
        let mut origin = at(value.map(|s| s.line));
        if let Some(flag) = flag.filter(|flag| !flag.is_empty()) {
            names.extend(flag.iter().map(|s| s.name()));
            origin = format!("{origin}, then the command line");
        }
        (quoted_list(&names), origin)
    };
    let (select, select_from) = match &choice.select {
        Some(flag) => (
            quoted_list(&flag.iter().map(|s| s.name()).collect::<Vec<_>>()),
            "--select".to_string(),
        ),
        None => match &check.select {
            Some(_) => list(check.select.as_ref(), None),
            None => {
                let every: Vec<&str> = categories().into_iter().map(|c| c.name()).collect();
                (quoted_list(&every), "default: every rule".to_string())
            }
        },
    };
    entry(&mut out, "select", &select, &select_from);
    let (value, origin) = list(check.extend_select.as_ref(), Some(&choice.extend_select));
    entry(&mut out, "extend-select", &value, &origin);
    let (value, origin) = list(check.ignore.as_ref(), Some(&choice.ignore));
    entry(&mut out, "ignore", &value, &origin);
    for severity in &check.severity {
        let (selector, level) = severity.value;
        let value = format!("{{ {selector} = \"{}\" }}", level.name());
        entry(&mut out, "severity", &value, &at(Some(severity.line)));
    }
    for ignore in &check.per_file_ignores {
        let names: Vec<&str> = ignore.value.rules.iter().map(|s| s.name()).collect();
        let applies = if ignore.value.matches(&file) {
            "applies to this file"
        } else {
            "not this file"
        };
        let value = format!(
            "{{ \"{}\" = {} }}",
            ignore.value.pattern,
            quoted_list(&names)
        );
        let origin = format!("{}, {applies}", at(Some(ignore.line)));
        entry(&mut out, "per-file-ignores", &value, &origin);
    }
    out.push_str("\n[translations]\n");
    let languages = settings.translations.languages.as_ref();
    let names: Vec<&str> = match languages {
        Some(languages) => languages.value.iter().map(|l| l.name()).collect(),
        None => Language::ALL.map(Language::name).to_vec(),
    };
    entry(
        &mut out,
        "languages",
        &quoted_list(&names),
        &at(languages.map(|l| l.line)),
    );
    out.push_str("\n[map]\n");
    path_entry(&mut out, "config", settings.map.config.as_ref(), &at);
    out.push_str("\n[mission]\n");
    path_entry(
        &mut out,
        "config-dir",
        settings.mission.config_dir.as_ref(),
        &at,
    );
    out.push_str("\n[robot]\n");
    let robot = &settings.robot;
    let profile = robot.profile();
    let speaks: Vec<&str> = profile.speaks.iter().map(|l| l.name()).collect();
    let speaks_line = robot.speaks.as_ref().map(|s| s.line);
    entry(&mut out, "speaks", &quoted_list(&speaks), &at(speaks_line));
    for (key, value, set) in [
        ("speed", profile.speed, &robot.speed),
        ("turn-speed", profile.turn_speed, &robot.turn_speed),
        (
            "syllables-per-second",
            profile.syllables_per_second,
            &robot.syllables_per_second,
        ),
    ] {
        let line = set.as_ref().map(|s| s.line);
        entry(&mut out, key, &number(value), &at(line));
    }
    out.push_str(&rules_in_force(&settings, &file, &args.rules));
    std::io::stdout()
        .lock()
        .write_all(escape_lines(&out).as_bytes())?;
    Ok(Exit::Clean)
}

/// Which settings file is used, and why.
fn where_from(lookup: &Lookup, settings: &Settings) -> String {
    match (lookup, &settings.path) {
        (Lookup::Isolated, _) => "no settings file: --isolated".to_string(),
        (Lookup::Explicit(path), _) => format!("settings file {} (--settings)", path.display()),
        (Lookup::Discover, Some(path)) => format!(
            "settings file {} (the nearest to the file's folder)",
            path.display()
        ),
        (Lookup::Discover, None) => {
            "no settings file (no ekb.toml or .ekb.toml in the file's folder or above)".to_string()
        }
    }
}

/// The reader and where it comes from, as [`Context::read_options`] chooses it.
fn reader(
    context: &Context,
    settings: &Settings,
    file: &Path,
) -> Result<(String, String), CommandError> {
    let quoted = |reader: crate::robot::Reader| format!("\"{}\"", reader.name());
    if let Some(reader) = context.reader {
        let flag = if context.reader_from_env {
            "EKB_READER"
        } else {
            "--reader"
        };
        return Ok((quoted(reader), flag.to_string()));
    }
    if let (Some(reader), Some(path)) = (&settings.reader, &settings.path) {
        let origin = format!("{}:{}", path.display(), reader.line);
        return Ok((quoted(reader.value), origin));
    }
    let config = context.config()?;
    if let (Some(reader), Some(path)) = (config.reader, &config.path) {
        return Ok((quoted(reader), format!("configuration {}", path.display())));
    }
    let by_dialect = "by the file's dialect: d5.4.2 for a seed-dialect file, 2025-06 for any other";
    if file == Path::new("-") || !file.is_file() {
        return Ok(("(not set)".to_string(), format!("default, {by_dialect}")));
    }
    let source = context.read(file)?;
    let checked = crate::check::check(&source, &context.read_options(file)?);
    Ok((quoted(checked.reader), format!("default, {by_dialect}")))
}

/// The rules that run on `file`, and those whose severity the settings change.
fn rules_in_force(settings: &Settings, file: &Path, args: &RuleArgs) -> String {
    let rules = settings.rules_for(file, &args.choice());
    let enabled = rules.enabled().count();
    let mut out = format!("\n# {enabled} of {} rules run on this file", ALL.len());
    let off: Vec<&str> = ALL
        .iter()
        .filter(|rule| !rules.is_enabled(rule))
        .map(|rule| rule.name)
        .collect();
    if !off.is_empty() {
        out.push_str(&format!("; not: {}", off.join(", ")));
    }
    out.push('\n');
    for rule in rules.enabled() {
        if let Some(severity) = rules.severity_override(rule) {
            out.push_str(&format!(
                "# {} is {} here (its own severity: {})\n",
                rule.name,
                severity.name(),
                rule.severity.name()
            ));
        }
    }
    out
}

/// `key = value  # origin`.
fn entry(out: &mut String, key: &str, value: &str, origin: &str) {
    out.push_str(&format!("{key} = {value}  # {origin}\n"));
}

fn path_entry(
    out: &mut String,
    key: &str,
    value: Option<&Sourced<PathBuf>>,
    at: &dyn Fn(Option<u32>) -> String,
) {
    match value {
        Some(path) => entry(
            out,
            key,
            &format!("\"{}\"", path.value.display()),
            &at(Some(path.line)),
        ),
        None => out.push_str(&format!("# {key} is not set\n")),
    }
}

/// A number as TOML writes a float: `0.27`, `5.0`.
fn number(value: f64) -> String {
    let text = value.to_string();
    match text.contains(['.', 'e', 'i', 'N']) {
        true => text,
        false => format!("{text}.0"),
    }
}

/// `["a", "b"]`.
fn quoted_list(names: &[&str]) -> String {
    let quoted: Vec<String> = names.iter().map(|name| format!("\"{name}\"")).collect();
    format!("[{}]", quoted.join(", "))
}
