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
    /// Where the robot reads its configuration otherwise than a reader of INI files
    /// would: each a sentence for a warning.
    pub warnings: Vec<String>,
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
        if let Some(text) = read(&dir.join(BEHAVIOR_CONTROLLER_INI))? {
            let robot = RobotIni::BehaviorController;
            let values = robot.values(&text);
            let get = |key| robot.value(&values, key);
            paths.mission = get("scenarioSpecification")
                .map(|scenario| in_data_or_beside(dir, &data, &format!("{scenario}.xml")));
            paths.asr_enabled = get("asrEnabled").map(|v| v == "true");
            paths
                .warnings
                .extend(robot.warnings(&text, BEHAVIOR_CONTROLLER_INI));
        }
        if let Some(text) = read(&dir.join(CULTURE_INI))? {
            let robot = RobotIni::Culture;
            let values = robot.values(&text);
            let get = |key| robot.value(&values, key);
            paths.culture_kb = get("knowledgeBase").map(|name| in_data_or_beside(dir, &data, name));
            paths.culture_types = get("valueTypes").map(|name| in_data_or_beside(dir, &data, name));
            paths.warnings.extend(robot.warnings(&text, CULTURE_INI));
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
            warnings: [self.warnings, fallback.warnings].concat(),
        }
    }

    /// What to add to the error of a file these paths name that cannot be read: where it
    /// was looked for, and the flag that names it instead (`None` if it was not found
    /// through a configuration folder).
    pub fn not_found_hint(&self, flag: &str) -> Option<String> {
        let dir = self.config_dir.as_ref()?;
        Some(format!(
            "the configuration in {} names it, and ekb looked for it in the robot's data \
             folder beside that folder and in the folder itself; if the files are laid out \
             otherwise, name them: --mission, --culture-kb, --culture-types, --kb (here {flag})",
            dir.display()
        ))
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

/// A file a configuration in `dir` names: in the robot's `data` folder beside `dir`, or,
/// if it is not there but in `dir` itself (a copy of the files in one folder), there.
fn in_data_or_beside(dir: &Path, data: &Path, name: &str) -> PathBuf {
    let in_data = data.join(name);
    let beside = dir.join(name);
    match !in_data.exists() && beside.is_file() {
        true => beside,
        false => in_data,
    }
}

/// The `key value` (or `key = value`) lines of a configuration file of the robot's; `None`
/// if there is no such file.
fn read(path: &Path) -> Result<Option<String>, String> {
    if !path.is_file() {
        return Ok(None);
    }
    let fail = |e: &dyn std::fmt::Display| format!("cannot read {}: {e}", path.display());
    let bytes = crate::open::read_regular(path).map_err(|e| fail(&e))?;
    String::from_utf8(bytes).map(Some).map_err(|e| fail(&e))
}

/// How the robot reads one of its two configuration files: the first word of a line is
/// its key, in both.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum RobotIni {
    /// `behaviorControllerConfiguration.ini` (`getValueFromConfig`): the value is the rest
    /// of the line, trimmed; the first line with the key wins; every key is required.
    BehaviorController,
    /// `cultureKnowledgeBaseConfiguration.ini` (`readConfigurationData`): the value is the
    /// second word (`sscanf("%s %s")`); the last line with the key wins.
    Culture,
}

impl RobotIni {
    fn values(self, text: &str) -> Vec<(String, String)> {
        text.lines()
            .filter_map(|line| {
                let line = line.trim_start();
                let key = line.split_whitespace().next()?;
                let rest = &line[key.len()..];
                let value = match self {
                    RobotIni::BehaviorController => rest.trim(),
                    RobotIni::Culture => rest.split_whitespace().next().unwrap_or(""),
                };
                Some((key.to_string(), value.to_string()))
            })
            .collect()
    }

    fn value<'v>(self, values: &'v [(String, String)], key: &str) -> Option<&'v str> {
        let mut with_key = values.iter().filter(|(k, _)| k == key);
        let found = match self {
            RobotIni::BehaviorController => with_key.next(),
            RobotIni::Culture => with_key.next_back(),
        };
        found.map(|(_, v)| v.as_str()).filter(|v| !v.is_empty())
    }

    /// The keys the robot needs from the file.
    fn keys(self) -> &'static [&'static str] {
        match self {
            RobotIni::BehaviorController => &[
                "scenarioSpecification",
                "verboseMode",
                "asrEnabled",
                "audioDebugMode",
            ],
            RobotIni::Culture => &["knowledgeBase", "valueTypes"],
        }
    }

    /// What the robot reads otherwise than meant: `key = value` lines, and (in the
    /// behaviour controller's file) a missing key, which stops it as it starts.
    fn warnings(self, text: &str, file: &str) -> Vec<String> {
        let values = self.values(text);
        let mut warnings = Vec::new();
        for line in text.lines().map(str::trim) {
            let Some((key, value)) = line.split_once('=') else {
                continue;
            };
            let key = key.trim();
            if self.keys().contains(&key) && !key.contains(char::is_whitespace) {
                let read = self.value(&values, key).unwrap_or("");
                warnings.push(format!(
                    "{file}: the robot reads `{line}` as the key `{}` with the value `{read}`, \
                     not `{}`: write `{key} {}`",
                    line.split_whitespace().next().unwrap_or(key),
                    value.trim(),
                    value.trim()
                ));
            }
        }
        if self == RobotIni::BehaviorController {
            for key in self.keys() {
                if self.value(&values, key).is_none() {
                    warnings.push(format!(
                        "{file}: no `{key}`: the robot stops as it starts (\"Failed to retrieve \
                         value for key: {key}\")"
                    ));
                }
            }
        }
        warnings
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn each_file_is_read_as_the_robot_reads_it() {
        let culture = RobotIni::Culture;
        let text =
            "verboseMode   false\nknowledgeBase = kb.dat\nvalueTypes t.dat\nvalueTypes u.dat\n";
        let values = culture.values(text);
        assert_eq!(culture.value(&values, "verboseMode"), Some("false"));
        assert_eq!(culture.value(&values, "knowledgeBase"), Some("="));
        assert_eq!(culture.value(&values, "valueTypes"), Some("u.dat"));
        let warnings = culture.warnings(text, CULTURE_INI);
        assert_eq!(warnings.len(), 1, "{warnings:?}");
        assert!(warnings[0].contains("the value `=`"), "{warnings:?}");
        let controller = RobotIni::BehaviorController;
        let text =
            "scenarioSpecification = labTour\nscenarioSpecification other\nasrEnabled true\n";
        let values = controller.values(text);
        assert_eq!(
            controller.value(&values, "scenarioSpecification"),
            Some("= labTour")
        );
        let warnings = controller.warnings(text, BEHAVIOR_CONTROLLER_INI);
        assert_eq!(warnings.len(), 3, "{warnings:?}");
        assert!(warnings[1].contains("no `verboseMode`"), "{warnings:?}");
        assert!(warnings[2].contains("no `audioDebugMode`"), "{warnings:?}");
    }

    #[test]
    fn a_configuration_folder_names_the_files_in_data() {
        let root = tempfile::tempdir().unwrap();
        let config = root.path().join("config");
        std::fs::create_dir(&config).unwrap();
        std::fs::write(
            config.join(BEHAVIOR_CONTROLLER_INI),
            "scenarioSpecification labTour\nasrEnabled false\nverboseMode false\n\
             audioDebugMode false\n",
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
        assert!(paths.warnings.is_empty(), "{:?}", paths.warnings);
        let error = paths.missing("environment knowledge base", "--kb", ENVIRONMENT_INI);
        assert!(
            error.contains("--kb") && error.contains("config"),
            "{error}"
        );
        assert!(MissionPaths::from_config_dir(&data).is_err());
        let hint = paths.not_found_hint("--mission").unwrap();
        assert!(
            hint.contains("name them: --mission, --culture-kb"),
            "{hint}"
        );
        // Files kept beside the configuration, with no data folder, are found there.
        std::fs::write(config.join("labTour.xml"), "<root/>").unwrap();
        let paths = MissionPaths::from_config_dir(&config).unwrap();
        assert_eq!(paths.mission, Some(config.join("labTour.xml")));
        assert_eq!(paths.culture_kb, Some(data.join("c.dat")));
    }
}
