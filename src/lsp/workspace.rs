//! How the server reads each document: the robot's configuration and `ekb.toml`, found as
//! the command line finds them, with the workspace's folder in place of the current one.

use std::cell::RefCell;
use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::rc::Rc;

use lsp_types::{InitializeParams, Uri};

use crate::config::{self, Config};
use crate::context::Context;
use crate::map::LabMap;
use crate::mission::culture::{self, ValueTypes};
use crate::mission::setup::{self, MissionPaths};
use crate::model::build::Options;
use crate::rules::selection::{Choice, RuleSet};
use crate::source::SourceFile;

/// The configuration in force, and what went wrong finding it (to tell the user once).
#[derive(Debug)]
pub struct Workspace {
    context: Context,
    /// The lab maps `[map] config` names, read once each (`None`: it cannot be read).
    maps: RefCell<HashMap<PathBuf, Option<Rc<LabMap>>>>,
}

impl Workspace {
    /// The workspace of `cli` (whose `--config`, `EKB_CONFIG` and `--reader` rule), rooted
    /// where the client says: the configuration is `--config`, else `EKB_CONFIG`, else
    /// `config/environmentKnowledgeBaseConfiguration.ini` in the current folder, else in the
    /// workspace's folder. Returns the problems met, for the user.
    pub fn new(cli: &Context, root: Option<&Path>) -> (Workspace, Vec<String>) {
        let mut problems = Vec::new();
        let found = cli.config().cloned().unwrap_or_else(|error| {
            problems.push(format!("{error}; checking with the default configuration"));
            Config::default()
        });
        let in_root = root
            .map(|root| root.join(config::DEFAULT_PATH))
            .filter(|path| found.path.is_none() && problems.is_empty() && path.is_file());
        let config = match in_root {
            Some(path) => Config::load(&path).unwrap_or_else(|error| {
                problems.push(format!("{error}; checking with the default configuration"));
                Config::default()
            }),
            None => found,
        };
        problems.extend(config.warnings.iter().cloned());
        let mut context = Context::with_config(config);
        context.reader = cli.reader;
        let maps = RefCell::default();
        (Workspace { context, maps }, problems)
    }

    /// How to read the document at `path` (`None`: not a file; the current folder's
    /// `ekb.toml` applies), or why the settings cannot be used.
    /// The lab map the document's `ekb.toml` names (`[map] config`), for the map rules;
    /// `None` without one, or when it cannot be read (`ekb check` tells why).
    pub fn map(&self, path: Option<&Path>) -> Option<Rc<LabMap>> {
        let settings = self
            .context
            .settings_for(path.unwrap_or(Path::new("-")))
            .ok()?;
        let config = settings.map.config?.value;
        self.maps
            .borrow_mut()
            .entry(config.clone())
            .or_insert_with(|| LabMap::from_config(&config).ok().map(Rc::new))
            .clone()
    }

    pub fn options(&self, path: Option<&Path>) -> Result<(Options, RuleSet), String> {
        let path = path.unwrap_or(Path::new("-"));
        let mut options = self
            .context
            .read_options(path)
            .map_err(|error| error.to_string())?;
        // `verboseMode` prints the file as it is read, on every keystroke: not in an editor.
        options.verbose = false;
        let rules = self
            .context
            .rules_for(path, &Choice::default())
            .map_err(|error| error.to_string())?;
        Ok((options, rules))
    }

    /// The culture knowledge base's keys, which `culturalKnowledge` words name: declared in the
    /// types file of the robot's configuration folder — `[mission] config-dir` of the
    /// document's `ekb.toml`, else the folder of the environment configuration when it holds
    /// the culture configuration too (the robot keeps them side by side). Read at each ask,
    /// so that an edit of the culture files shows at once; none when there is no such folder
    /// or its files cannot be read.
    pub fn culture_keys(&self, document: Option<&Path>) -> Vec<String> {
        let from_settings = self
            .context
            .settings_for(document.unwrap_or(Path::new("-")))
            .ok()
            .and_then(|settings| settings.mission.config_dir)
            .map(|dir| dir.value);
        let beside_config = || {
            let config = self.context.config().ok()?;
            let folder = config.path.as_deref()?.parent()?;
            folder
                .join(setup::CULTURE_INI)
                .is_file()
                .then(|| folder.to_path_buf())
        };
        let types = from_settings
            .or_else(beside_config)
            .and_then(|dir| MissionPaths::from_config_dir(&dir).ok())
            .and_then(|paths| paths.culture_types)
            .and_then(|path| SourceFile::read(&path).ok());
        types.map_or_else(Vec::new, |types| {
            ValueTypes::parse(types.text(), culture::LINE_BUFFER)
                .keys()
                .map(str::to_string)
                .collect()
        })
    }

    /// How to read a document with broken settings: as the command line's `--reader` says,
    /// the rest by default.
    pub fn fallback_options(&self) -> (Options, RuleSet) {
        let options = Options {
            reader: self.context.reader,
            ..Options::default()
        };
        (options, RuleSet::default())
    }
}

/// The workspace's folder: the first workspace folder, else the root URI, else the root path.
pub fn root(params: &InitializeParams) -> Option<PathBuf> {
    #[allow(deprecated)] // `root_uri` and `root_path`: older clients send only these.
    let uri = params
        .workspace_folders
        .as_ref()
        .and_then(|folders| folders.first())
        .map(|folder| &folder.uri)
        .or(params.root_uri.as_ref());
    #[allow(deprecated)]
    uri.and_then(file_path)
        .or_else(|| params.root_path.as_ref().map(PathBuf::from))
}

/// The file a `file:` URI names (percent-decoded), `None` for any other URI.
pub fn file_path(uri: &Uri) -> Option<PathBuf> {
    let rest = uri.as_str().strip_prefix("file://")?;
    // `file:///path` or `file://localhost/path`; another host is not a local file.
    let path = rest.strip_prefix("localhost").unwrap_or(rest);
    if !path.starts_with('/') {
        return None;
    }
    let path = path.split(['?', '#']).next().unwrap_or(path);
    let decoded = percent_decode(path)?;
    // `/C:/folder` on Windows.
    let windows_drive = decoded.len() > 2 && decoded.as_bytes()[2] == b':';
    Some(PathBuf::from(match windows_drive && cfg!(windows) {
        true => decoded[1..].to_string(),
        false => decoded,
    }))
}

fn percent_decode(text: &str) -> Option<String> {
    let bytes = text.as_bytes();
    let mut out = Vec::with_capacity(bytes.len());
    let mut at = 0;
    while at < bytes.len() {
        if bytes[at] == b'%' {
            let hex = text.get(at + 1..at + 3)?;
            out.push(u8::from_str_radix(hex, 16).ok()?);
            at += 3;
        } else {
            out.push(bytes[at]);
            at += 1;
        }
    }
    String::from_utf8(out).ok()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn uri(text: &str) -> Uri {
        text.parse().unwrap()
    }

    #[test]
    fn file_uris_are_paths() {
        assert_eq!(
            file_path(&uri("file:///work/my%20kb/data/kb.dat")),
            Some(PathBuf::from("/work/my kb/data/kb.dat"))
        );
        assert_eq!(
            file_path(&uri("file://localhost/kb.dat")),
            Some(PathBuf::from("/kb.dat"))
        );
        assert_eq!(file_path(&uri("untitled:Untitled-1")), None);
        assert_eq!(file_path(&uri("file://server/share/kb.dat")), None);
        assert_eq!(percent_decode("/bad%zz"), None);
        assert_eq!(percent_decode("/bad%ff"), None, "not UTF-8");
    }

    #[test]
    fn the_configuration_is_found_in_the_workspace_folder() {
        let root = tempfile::tempdir().unwrap();
        std::fs::create_dir(root.path().join("config")).unwrap();
        std::fs::write(
            root.path().join(config::DEFAULT_PATH),
            "knowledgeBase kb.dat\nreader 2026-02\nverbosemode true\n",
        )
        .unwrap();
        let cli = Context::with_config(Config::default());
        let (workspace, problems) = Workspace::new(&cli, Some(root.path()));
        assert_eq!(problems.len(), 1, "{problems:?}");
        assert!(problems[0].contains("did you mean `verboseMode`"));
        let options = workspace.options(Some(&root.path().join("data/kb.dat")));
        assert_eq!(
            options.unwrap().0.reader,
            Some(crate::robot::Reader::V2026_02)
        );
    }

    /// The robot's layout: `config/` with the three configurations, the files in `data/`.
    fn robot_folder(root: &Path) {
        let (config, data) = (root.join("config"), root.join("data"));
        std::fs::create_dir_all(&config).unwrap();
        std::fs::create_dir_all(&data).unwrap();
        std::fs::write(
            config.join(setup::ENVIRONMENT_INI),
            "knowledgeBase kb.dat\n",
        )
        .unwrap();
        std::fs::write(
            config.join(setup::CULTURE_INI),
            "knowledgeBase culture.dat\nvalueTypes types.dat\n",
        )
        .unwrap();
        std::fs::write(
            data.join("types.dat"),
            "deicticShape STRING\ngreeting PHRASE\n",
        )
        .unwrap();
    }

    #[test]
    fn culture_keys_come_from_the_folder_of_the_configuration() {
        let root = tempfile::tempdir().unwrap();
        robot_folder(root.path());
        let cli = Context::with_config(Config::default());
        let (workspace, _) = Workspace::new(&cli, Some(root.path()));
        let kb = root.path().join("data/kb.dat");
        assert_eq!(
            workspace.culture_keys(Some(&kb)),
            ["deicticShape", "greeting"]
        );
    }

    #[test]
    fn culture_keys_come_from_the_mission_setting() {
        let root = tempfile::tempdir().unwrap();
        robot_folder(&root.path().join("robot"));
        std::fs::write(
            root.path().join("ekb.toml"),
            "[mission]\nconfig-dir = \"robot/config\"\n",
        )
        .unwrap();
        let cli = Context::with_config(Config::default());
        let (workspace, _) = Workspace::new(&cli, None);
        let kb = root.path().join("kb.dat");
        assert_eq!(
            workspace.culture_keys(Some(&kb)),
            ["deicticShape", "greeting"]
        );
    }

    #[test]
    fn no_culture_keys_without_a_culture_configuration() {
        let root = tempfile::tempdir().unwrap();
        let cli = Context::with_config(Config::default());
        let (workspace, _) = Workspace::new(&cli, Some(root.path()));
        assert!(workspace
            .culture_keys(Some(&root.path().join("kb.dat")))
            .is_empty());
    }
}
