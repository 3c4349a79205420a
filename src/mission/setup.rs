//! Where the robot's three files are: from its configuration folder (the
//! `behaviorController/config/` of the robot, with the data in the sibling `data/`), or
//! named one by one.

use std::path::{Path, PathBuf};

use crate::config::Config;

/// The behaviour controller's configuration: the mission is `data/<scenarioSpecification>.xml`.
pub const BEHAVIOR_CONTROLLER_INI: &str = "behaviorControllerConfiguration.ini";
/// The culture knowledge base's configuration: `knowledgeBase` and `valueTypes` in `data/`.
pub const CULTURE_INI: &str = "cultureKnowledgeBaseConfiguration.ini";
/// The environment knowledge base's configuration (SPEC §3).
pub const ENVIRONMENT_INI: &str = "environmentKnowledgeBaseConfiguration.ini";

/// The files of a mission, each if known.
#[derive(Debug, Clone, Default, PartialEq, Eq)]
pub struct MissionPaths {
    /// The behaviour tree (`labTour.xml`).
    pub mission: Option<PathBuf>,
    /// `cultureKnowledgeBaseInput.dat`.
    pub culture_kb: Option<PathBuf>,
    /// `cultureKnowledgeValueTypesInput.dat`.
    pub culture_types: Option<PathBuf>,
    /// The environment knowledge base.
    pub kb: Option<PathBuf>,
    /// `asrEnabled` of the behaviour controller: whether visitors answer by voice.
    pub asr_enabled: Option<bool>,
    /// The configuration folder they came from, if any (for messages).
    pub config_dir: Option<PathBuf>,
}

impl MissionPaths {
    /// The files named in the configuration folder `dir`. A configuration file that is
    /// missing leaves its files unknown; one that cannot be read is an error.
    pub fn from_config_dir(dir: &Path) -> Result<MissionPaths, String> {
        if !dir.is_dir() {
            return Err(format!(
                "the configuration folder {} does not exist or is not a folder",
                dir.display()
            ));
        }
        let data = dir
            .parent()
            .map_or_else(|| PathBuf::from("../data"), |p| p.join("data"));
        let mut paths = MissionPaths {
            config_dir: Some(dir.to_path_buf()),
            ..MissionPaths::default()
        };
        if let Some(values) = read_ini(&dir.join(BEHAVIOR_CONTROLLER_INI))? {
            paths.mission = value(&values, "scenarioSpecification")
                .map(|scenario| data.join(format!("{scenario}.xml")));
            paths.asr_enabled = value(&values, "asrEnabled").map(|v| v == "true");
        }
        if let Some(values) = read_ini(&dir.join(CULTURE_INI))? {
            paths.culture_kb = value(&values, "knowledgeBase").map(|name| data.join(name));
            paths.culture_types = value(&values, "valueTypes").map(|name| data.join(name));
        }
        let environment = dir.join(ENVIRONMENT_INI);
        if environment.is_file() {
            paths.kb = Config::load(&environment)
                .map_err(|e| e.to_string())?
                .knowledge_base;
        }
        Ok(paths)
    }

    /// These paths, with each one not known taken from `fallback`.
    pub fn or(self, fallback: MissionPaths) -> MissionPaths {
        MissionPaths {
            mission: self.mission.or(fallback.mission),
            culture_kb: self.culture_kb.or(fallback.culture_kb),
            culture_types: self.culture_types.or(fallback.culture_types),
            kb: self.kb.or(fallback.kb),
            asr_enabled: self.asr_enabled.or(fallback.asr_enabled),
            config_dir: self.config_dir.or(fallback.config_dir),
        }
    }

    /// Why a file a command needs is not known, and what to give for it.
    pub fn missing(&self, what: &str, flag: &str, ini: &str) -> String {
        match &self.config_dir {
            Some(dir) => format!(
                "no {what}: {} names none (is {ini} there?); give {flag}",
                dir.display()
            ),
            None => format!("no {what}: give {flag}, or --config-dir with the robot's {ini}"),
        }
    }
}

/// The `key value` (or `key = value`) lines of a configuration file of the robot's; `None`
/// if there is no such file.
fn read_ini(path: &Path) -> Result<Option<Vec<(String, String)>>, String> {
    if !path.is_file() {
        return Ok(None);
    }
    let text = std::fs::read_to_string(path)
        .map_err(|e| format!("cannot read {}: {e}", path.display()))?;
    Ok(Some(ini_values(&text)))
}

/// The robot's own INI form, `key   value`, and the standard `key = value`.
fn ini_values(text: &str) -> Vec<(String, String)> {
    text.lines()
        .map(str::trim)
        .filter(|line| !line.is_empty() && !line.starts_with(['#', ';', '[']))
        .filter_map(|line| {
            let (key, value) = line
                .split_once('=')
                .or_else(|| line.split_once(char::is_whitespace))?;
            Some((key.trim().to_string(), value.trim().to_string()))
        })
        .collect()
}

fn value<'v>(values: &'v [(String, String)], key: &str) -> Option<&'v str> {
    values
        .iter()
        .rev()
        .find(|(k, _)| k == key)
        .map(|(_, v)| v.as_str())
        .filter(|v| !v.is_empty())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn both_ini_forms() {
        let values = ini_values("verboseMode   false\nknowledgeBase = kb.dat\n# note\n[s]\n");
        assert_eq!(value(&values, "verboseMode"), Some("false"));
        assert_eq!(value(&values, "knowledgeBase"), Some("kb.dat"));
        assert_eq!(value(&values, "note"), None);
    }

    #[test]
    fn a_configuration_folder_names_the_files_in_data() {
        let root = tempfile::tempdir().unwrap();
        let config = root.path().join("config");
        std::fs::create_dir(&config).unwrap();
        std::fs::write(
            config.join(BEHAVIOR_CONTROLLER_INI),
            "scenarioSpecification labTour\nasrEnabled false\n",
        )
        .unwrap();
        std::fs::write(
            config.join(CULTURE_INI),
            "knowledgeBase c.dat\nvalueTypes t.dat\n",
        )
        .unwrap();
        let paths = MissionPaths::from_config_dir(&config).unwrap();
        let data = root.path().join("data");
        assert_eq!(paths.mission, Some(data.join("labTour.xml")));
        assert_eq!(paths.culture_kb, Some(data.join("c.dat")));
        assert_eq!(paths.culture_types, Some(data.join("t.dat")));
        assert_eq!(paths.kb, None);
        assert_eq!(paths.asr_enabled, Some(false));
        let error = paths.missing("environment knowledge base", "--kb", ENVIRONMENT_INI);
        assert!(
            error.contains("--kb") && error.contains("config"),
            "{error}"
        );
        assert!(MissionPaths::from_config_dir(&data).is_err());
    }
}
