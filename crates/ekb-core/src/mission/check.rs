//! The mission's files checked together (`ekb mission check`), and each alone
//! (`ekb check FILE`, which recognises a mission or a culture file by its content).

use crate::check::{self as env, Checked, FileKind};

use crate::diagnostic::Diagnostics;
use crate::map::LabMap;
use crate::model::build::Options;
use crate::model::{KnowledgeBase, Language};
use crate::robot::speech::RobotProfile;
use crate::robot::Reader;
use crate::rules::culture::culture_duplicate_key::Wins;
use crate::rules::culture::*;
use crate::rules::mission::*;
use crate::rules::selection::RuleSet;
use crate::rules::structure::{invalid_utf8, not_a_knowledge_base};
use crate::source::SourceFile;

use super::culture::{self, CultureKnowledgeBase, ValueType, ValueTypes};
use super::include::{self, IncludeProblem};
use super::tree::Mission;

/// The files of a mission, each if given; the environment knowledge base with the options
/// `ekb check` would read it with.
#[derive(Debug, Clone, Copy, Default)]
pub struct MissionSources<'s> {
    pub mission: Option<&'s SourceFile>,
    pub culture_kb: Option<&'s SourceFile>,
    pub culture_types: Option<&'s SourceFile>,
    pub kb: Option<(&'s SourceFile, &'s Options)>,
    /// The robot's reader that the settings name, if any: its culture reader's line buffer
    /// ([`Reader::culture_line_buffer`]; `2025-06`'s when none is named).
    pub reader: Option<Reader>,
    /// The robot profile that the settings give (`[robot]`), if any; the default's when none.
    pub robot: Option<&'s RobotProfile>,
}

impl MissionSources<'_> {
    /// The line buffer that the robot's culture reader reads both culture files with.
    pub fn culture_line_buffer(&self) -> usize {
        self.reader
            .unwrap_or(Reader::V2025_06)
            .culture_line_buffer()
    }
}

/// Checks the files given, each alone and against the others: one checked file each.
pub fn check_together<'s>(sources: &MissionSources<'s>, rules: &RuleSet) -> Vec<Checked<'s>> {
    let line_buffer = sources.culture_line_buffer();
    let mut mission_out = Diagnostics::default();
    let mission = sources.mission.and_then(|source| {
        invalid_utf8::check(source, &mut mission_out);
        match with_includes(source) {
            Ok((mission, problems)) => {
                mission_bad_include::check(problems, &mut mission_out);
                check_tree(&mission, sources.reader, &mut mission_out);
                Some(mission)
            }
            Err(finding) => {
                mission_out.push(*finding);
                None
            }
        }
    });

    let mut types_out = Diagnostics::default();
    let types = sources.culture_types.map(|source| {
        invalid_utf8::check(source, &mut types_out);
        let types = ValueTypes::parse(source.text(), line_buffer);
        culture_unknown_type::check(&types, &mut types_out);
        culture_duplicate_key::check(&types.entries, Wins::Earlier, &mut types_out);
        culture_line_too_long::check(source.text(), line_buffer, &mut types_out);
        culture_word_too_long::check(&types.entries, &mut types_out);
        types
    });

    let mut culture_out = Diagnostics::default();
    let culture = sources
        .culture_kb
        .map(|source| CultureKnowledgeBase::parse(source.text(), line_buffer));
    let mut language = None;
    if let (Some(source), Some(culture)) = (sources.culture_kb, &culture) {
        invalid_utf8::check(source, &mut culture_out);
        culture_duplicate_key::check(&culture.entries, Wins::Later, &mut culture_out);
        culture_line_too_long::check(source.text(), line_buffer, &mut culture_out);
        culture_crlf::check(source.text(), &mut culture_out);
        culture_word_too_long::check(&culture.entries, &mut culture_out);
        if let Some(types) = &types {
            culture_unknown_key::check(culture, types, &mut culture_out);
            culture_type_mismatch::check(culture, types, &mut culture_out);
            language = mission_language_invalid::check(culture, types, &mut culture_out);
            if let Some(language) = language {
                let default = RobotProfile::default();
                let robot = sources.robot.unwrap_or(&default);
                mission_language_not_spoken::check(
                    culture,
                    types,
                    language,
                    robot,
                    &mut culture_out,
                );
            }
        }
        let said = match (&mission, language) {
            (Some(mission), Some(language)) => super::said_phrases(mission, language)
                .into_iter()
                .map(|said| said.key)
                .collect(),
            _ => Vec::new(),
        };
        culture_no_final_newline::check(culture, types.as_ref(), &said, &mut culture_out);
        if let (Some(mission), Some(types), Some(language)) = (&mission, &types, language) {
            mission_missing_phrase::check(mission, culture, types, language, &mut mission_out);
        }
    }

    let mut checked = Vec::new();
    let no_reader = Reader::default_for(None);
    if let Some(source) = sources.mission {
        let kind = FileKind::Mission;
        checked.push(env::finish(
            source,
            kind,
            KnowledgeBase::default(),
            no_reader,
            mission_out,
            rules,
        ));
    }
    if let Some(source) = sources.culture_kb {
        let kind = FileKind::CultureKnowledgeBase;
        checked.push(env::finish(
            source,
            kind,
            KnowledgeBase::default(),
            no_reader,
            culture_out,
            rules,
        ));
    }
    if let Some(source) = sources.culture_types {
        let kind = FileKind::CultureValueTypes;
        checked.push(env::finish(
            source,
            kind,
            KnowledgeBase::default(),
            no_reader,
            types_out,
            rules,
        ));
    }
    if let Some((source, options)) = sources.kb {
        let mut kb = env::check_with(source, options, rules);
        let keys: Option<Vec<&str>> = match (&types, &culture) {
            (Some(types), _) => Some(types.keys().collect()),
            (None, Some(culture)) => Some(culture.entries.iter().map(|e| e.key).collect()),
            (None, None) => None,
        };
        kb.extend(against_the_tour(&kb, language, keys.as_deref()));
        checked.push(kb);
    }
    checked
}

/// The findings in the environment knowledge base that come from the culture side: the
/// tour in the mission's language, and the culturalKnowledge words.
fn against_the_tour(
    kb: &Checked<'_>,
    language: Option<Language>,
    culture_keys: Option<&[&str]>,
) -> Vec<crate::Diagnostic> {
    let mut out = Diagnostics::default();
    if let Some(language) = language {
        mission_untranslated_tour::check(&kb.kb, language, &mut out);
    }
    if let Some(keys) = culture_keys {
        cultural_knowledge_unknown_key::check(&kb.kb, keys, &mut out);
    }
    out.to_vec()
}

/// The kind of file `text` is, by its content: XML is a mission; a file of `key value`
/// lines with no key of the environment knowledge base is the culture knowledge base (it
/// has `phraseLanguage` or `utilityPhrase…` keys) or its types file (most values are
/// types); anything else is taken for an environment knowledge base.
pub fn recognise(text: &str) -> FileKind {
    let content = text.trim_start_matches('\u{feff}').trim_start();
    if content.starts_with('<') {
        return FileKind::Mission;
    }
    if not_a_knowledge_base::check(text).is_none() {
        return FileKind::EnvironmentKnowledgeBase;
    }
    let entries = culture::entries(text);
    let typed = entries
        .iter()
        .filter(|e| {
            e.first_word()
                .is_some_and(|(w, _)| ValueType::parse(w).is_some())
        })
        .count();
    if typed * 2 >= entries.len() {
        FileKind::CultureValueTypes
    } else if entries
        .iter()
        .any(|e| e.key == super::LANGUAGE_KEY || e.key.starts_with("utilityPhrase"))
    {
        FileKind::CultureKnowledgeBase
    } else {
        FileKind::EnvironmentKnowledgeBase
    }
}

/// `ekb check FILE`: the file checked as the kind its content says, alone (an environment
/// knowledge base with the map rules too when there is a `map`).
pub fn check_file<'s>(
    source: &'s SourceFile,
    options: &Options,
    rules: &RuleSet,
    map: Option<&LabMap>,
) -> Checked<'s> {
    let alone = match recognise(source.text()) {
        FileKind::EnvironmentKnowledgeBase => {
            return env::check_on_map(source, options, rules, map)
        }
        FileKind::Mission => MissionSources {
            mission: Some(source),
            reader: options.reader,
            ..MissionSources::default()
        },
        FileKind::CultureKnowledgeBase => MissionSources {
            culture_kb: Some(source),
            reader: options.reader,
            ..MissionSources::default()
        },
        FileKind::CultureValueTypes => MissionSources {
            culture_types: Some(source),
            reader: options.reader,
            ..MissionSources::default()
        },
    };
    let mut checked = check_together(&alone, rules);
    checked
        .pop()
        .unwrap_or_else(|| env::check_with(source, options, rules))
}

/// Parses a mission, with the trees of the files it includes, or gives the finding that says
/// why it cannot be read (`ekb mission check` reports what is wrong with its includes).
pub fn read_mission(source: &SourceFile) -> Result<Mission, Box<crate::Diagnostic>> {
    with_includes(source).map(|(mission, _)| mission)
}

/// The mission in `source` with the trees of the files it includes, and what stops its
/// includes; or the finding that says why it cannot be read.
fn with_includes(
    source: &SourceFile,
) -> Result<(Mission, Vec<IncludeProblem>), Box<crate::Diagnostic>> {
    let mut mission = mission_invalid_xml::check(source.text())?;
    let included = include::load(&mission, source.path());
    mission.included = included.trees;
    Ok((mission, included.problems))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn files_are_recognised_by_content() {
        assert_eq!(
            recognise("\u{feff}  <?xml version=\"1.0\"?><root/>"),
            FileKind::Mission
        );
        let culture = "passingDistance 100\nphraseLanguage English\nutilityPhraseEnglish1 Hi\n";
        assert_eq!(recognise(culture), FileKind::CultureKnowledgeBase);
        let types = "passingDistance NUMBER\nphraseLanguage WORD\nutilityPhraseEnglish1 PHRASE\n";
        assert_eq!(recognise(types), FileKind::CultureValueTypes);
        assert_eq!(
            recognise("robotLocationDescription 1 Hall\n"),
            FileKind::EnvironmentKnowledgeBase
        );
        let foreign = "colour red\nsize 4\nshape round\n";
        assert_eq!(recognise(foreign), FileKind::EnvironmentKnowledgeBase);
    }
}
