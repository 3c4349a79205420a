//! `ekb tour [FILE] --lang L`: the tour in order, as the robot will perform it in one
//! language — where it stands, where it points, what it says — with every message that is
//! missing or untranslated in that language shown as such.

use std::io::Write;
use std::path::PathBuf;

use serde::Serialize;

use super::map::MapArgs;
use super::{timeline, CommandError, CommandResult, Context, Exit};
use crate::check::{check, Checked};
use crate::model::{Arm, Key, Language, Location, Phase, Point, Pose};
use crate::present::field::{Field, FieldValue};
use crate::present::language::Languages;
use crate::present::{self, language, robot, Gesture, Lines, Message};
use crate::reader;
use crate::reader::view::{self, Held};
use crate::render::escape::escape;
use crate::render::safe_json as json;
use crate::robot::speech;
use crate::stderr_line;

#[derive(Debug, clap::Args)]
pub struct Args {
    /// Knowledge-base file (`-` for standard input) [default: the configured knowledgeBase]
    #[arg(value_name = "FILE")]
    pub file: Option<PathBuf>,

    /// The language the robot speaks: english, isizulu (zulu), kinyarwanda, or an ISO 639 code: en/eng, zu/zul, rw/kin (any case); with --timeline also `all`, side by side
    #[arg(long, value_name = "L", ignore_case = true, value_parser = language::parser_or_all(), default_value = "english")]
    pub lang: Languages,

    /// The tour in time: each leg driven (metres, seconds, the turn; with the map, as the
    /// robot's planner drives it) and the seconds each message takes to say, and the totals
    #[arg(long)]
    pub timeline: bool,

    /// Output format
    #[arg(long, value_enum, default_value_t = TourFormat::Text)]
    pub format: TourFormat,

    #[command(flatten)]
    pub map: MapArgs,
}

/// `ekb tour --format`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum TourFormat {
    /// The tour as a script to read
    Text,
    /// One JSON object
    Json,
}

pub fn run(args: &Args, context: &Context) -> CommandResult {
    if args.timeline {
        return timeline::run(args, context);
    }
    let Languages::One(lang) = args.lang else {
        return Err(CommandError::Failed(
            "`--lang all` shows the languages side by side in the timeline: give --timeline, \
             or one language"
                .to_string(),
        ));
    };
    let path = context.input(args.file.as_deref())?;
    let options = context.read_options(&path)?;
    let source = context.read(&path)?;
    let checked = check(&source, &options);
    present::note_errors(&checked, context.quiet);
    let file = escape(source.name());
    let Some(tour) = &checked.kb.tour else {
        stderr_line!("ekb: {file} has no tour: add a `tourSpecification` line");
        return Ok(Exit::Findings);
    };
    if tour.has_no_stops() {
        stderr_line!("ekb: the tour of {file} has no stops");
        return Ok(Exit::Findings);
    }
    // The text shows the first stops, as `check` shows the first findings of a rule; the
    // JSON has them all.
    let shown = match args.format {
        TourFormat::Text => MAX_STOPS_SHOWN,
        TourFormat::Json => usize::MAX,
    };
    let robot = context.settings_for(&path)?.robot.profile();
    let mut tour = Tour::new(&checked, lang, shown);
    tour.spoken = robot.speaks(lang);
    let mut stdout = std::io::stdout().lock();
    match args.format {
        TourFormat::Text => {
            let order = checked.kb.tour_stops();
            stdout.write_all(tour.text(&file, order).as_bytes())?
        }
        TourFormat::Json => json::write(&tour, &mut stdout)?,
    }
    stdout.flush()?;
    Ok(Exit::Clean)
}

/// The most stops `ekb tour` shows as text (the robot's reader holds 20).
const MAX_STOPS_SHOWN: usize = 1000;

/// The tour as the robot will perform it in one language.
#[derive(Serialize)]
struct Tour<'a> {
    #[serde(serialize_with = "language::serialize_name")]
    language: Language,
    /// Whether the robot profile (`[robot] speaks`) speaks the language: if not, the robot
    /// says nothing at any stop.
    spoken: bool,
    /// The version of the robot's reader whose view this is.
    reader: &'static str,
    /// The stops the reader loads, where they are not the file's (`null`: undefined).
    #[serde(rename = "robotTour", skip_serializing_if = "Option::is_none")]
    robot_tour: Option<Vec<Option<i32>>>,
    stops: Stops<'a>,
    /// Messages written in the language (placeholders and missing ones are not).
    translated: usize,
    /// Messages the tour says: two per stop.
    messages: usize,
    /// How many of the messages are placeholders, and how many missing.
    #[serde(skip)]
    placeholders: usize,
    #[serde(skip)]
    missing: usize,
    /// How many stops the tour has (`stops` may make only the first).
    #[serde(skip)]
    total: usize,
}

/// The tour's first `shown` stops, each made when it is shown or written, and let go of
/// after: a tour may have a million, and the JSON lists them all.
struct Stops<'a> {
    checked: &'a Checked<'a>,
    language: Language,
    lines: Lines,
    loaded: reader::Loaded<'a>,
    shown: usize,
}

impl Serialize for Stops<'_> {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.collect_seq(self.iter())
    }
}

#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
struct Stop<'a> {
    /// 1-based.
    stop: usize,
    id: u32,
    /// The first stop: its pose is the robot's initial pose and its home.
    start: bool,
    /// Whether the file has a location with this id.
    found: bool,
    description: Option<&'a str>,
    pose: Option<Pose>,
    gesture_target: Option<Point>,
    /// Whether the robot points: the target is not `0 0 0` and does not sum to 0.
    points: bool,
    gesture_arm: Option<Arm>,
    before: Said<'a>,
    after: Said<'a>,
    /// Where the robot stands, as the reader loads it (marked where the file differs).
    #[serde(skip)]
    stands: String,
    /// Where the reader's gesture target is not the file's, what it loads.
    #[serde(skip)]
    target_as_loaded: Option<String>,
}

/// One message of a stop in the tour's language.
#[derive(Serialize)]
struct Said<'a> {
    /// `written`, `placeholder` or `missing`.
    status: &'static str,
    /// The text in the file (a placeholder too); null when missing.
    text: Option<&'a str>,
    line: Option<u32>,
    /// The English message, what a translator should translate (null for English itself).
    english: Option<&'a str>,
    /// What the robot says, as its reader loads the message (null: undefined).
    #[serde(rename = "robotSays")]
    robot_says: Option<String>,
    #[serde(skip)]
    message: Message<'a>,
    /// Where the robot says something else than the file: what, shown.
    #[serde(skip)]
    differs: Option<String>,
}

impl<'a> Tour<'a> {
    /// The tour of `checked` in `language`, with the first `shown` stops in full.
    fn new(checked: &'a Checked<'a>, language: Language, shown: usize) -> Tour<'a> {
        let text = checked.source.text();
        let stops = Stops {
            checked,
            language,
            lines: Lines::new(text),
            loaded: reader::load(text.as_bytes(), checked.reader),
            shown,
        };
        // Every stop's messages counted, shown or not.
        let (mut translated, mut placeholders, mut missing, mut total) = (0, 0, 0, 0);
        for id in checked.kb.tour_stops() {
            total += 1;
            let location = checked.kb.location(id);
            for phase in Phase::ALL {
                match location.map_or(Message::Missing, |l| Message::of(l, phase, language)) {
                    Message::Written(_) => translated += 1,
                    Message::Placeholder(_) => placeholders += 1,
                    Message::Missing => missing += 1,
                }
            }
        }
        Tour {
            language,
            spoken: true,
            reader: checked.reader.name(),
            robot_tour: robot::other_tour(&checked.kb, &stops.loaded),
            messages: total * 2,
            stops,
            translated,
            placeholders,
            missing,
            total,
        }
    }

    fn text(&self, file: &str, order: impl Iterator<Item = u32>) -> String {
        let count = self.total;
        let mut out = String::new();
        if !self.spoken {
            out.push_str(&speech::silence_notice(self.language));
            out.push('\n');
        }
        out.push_str(&format!(
            "Tour of {file} in {}: {count} stop{} ({}), as reader {} loads it\n",
            self.language.name(),
            if count == 1 { "" } else { "s" },
            present::listed(order, " → "),
            self.reader
        ));
        if let Some(robot_tour) = &self.robot_tour {
            out.push_str(&format!(
                "The robot's reader loads another tour: {} (`ekb check` says why)\n",
                robot::tour_text(robot_tour)
            ));
        }
        for stop in self.stops.iter() {
            out.push('\n');
            out.push_str(&stop.text(self.language));
        }
        let shown = self.total.min(self.stops.shown);
        if self.total > shown {
            out.push_str(&format!(
                "\n… and {} more stops, not shown (ekb shows the first {shown}; `ekb tour --format json` lists them all)\n",
                self.total - shown,
            ));
        }
        out.push('\n');
        out.push_str(&self.closing());
        out
    }

    /// `isiZulu: 0 of 10 messages translated (10 placeholders)`.
    fn closing(&self) -> String {
        let verb = match self.language {
            Language::English => "written",
            _ => "translated",
        };
        let mut parts = Vec::new();
        for (n, word) in [
            (self.placeholders, "placeholder"),
            (self.missing, "missing"),
        ] {
            if n > 0 {
                let plural = if n > 1 && word == "placeholder" {
                    "s"
                } else {
                    ""
                };
                parts.push(format!("{n} {word}{plural}"));
            }
        }
        let detail = if parts.is_empty() {
            String::new()
        } else {
            format!(" ({})", parts.join(", "))
        };
        format!(
            "{}: {} of {} messages {verb}{detail}\n",
            self.language.name(),
            self.translated,
            self.messages
        )
    }
}

impl<'a> Stops<'a> {
    /// The stops, in order, each made as it is asked for.
    fn iter(&self) -> impl Iterator<Item = Stop<'a>> + '_ {
        let kb = &self.checked.kb;
        kb.tour_stops()
            .take(self.shown)
            .enumerate()
            .map(|(index, id)| self.stop(index, id))
    }

    /// Stop `index` (from 0), at location `id`.
    fn stop(&self, index: usize, id: u32) -> Stop<'a> {
        let checked = self.checked;
        let text = checked.source.text().as_bytes();
        let held = |key: Key| view::held(&self.loaded, text, id, key);
        let location = checked.kb.location(id);
        let said = |phase| {
            let key = Key::for_message(phase, self.language);
            Said::new(location, phase, self.language, &self.lines, held(key))
        };
        let pose = location.and_then(|l| l.pose).map(|p| p.value);
        let stands = match pose {
            Some(pose) => robot::as_loaded(
                Field::Pose,
                &FieldValue::Pose(pose),
                &held(Key::RobotLocationPose),
                checked.reader,
            ),
            // A pose line whose numbers the reader cannot read is lost as a missing one is.
            None if location.is_some_and(|l| l.has_line(Key::RobotLocation) || l.has_line(Key::RobotLocationPose)) => {
                "0, 0, 0°: the pose line's numbers are invalid, so the robot's reader does not read the pose (`ekb check` shows the line)".to_string()
            }
            None => "MISSING pose: the robot's reader leaves it at 0, 0, 0°".to_string(),
        };
        let target = location.and_then(|l| l.gesture_target).map(|t| t.value);
        let target_held = held(Key::GestureTarget);
        let target_as_loaded = target
            .filter(|target| {
                !robot::agrees(
                    Field::GestureTarget,
                    &FieldValue::Point(*target),
                    &target_held,
                )
            })
            .map(|_| robot::shown(Field::GestureTarget, &target_held));
        Stop {
            stands,
            target_as_loaded,
            stop: index + 1,
            id,
            start: index == 0,
            found: location.is_some(),
            description: location.and_then(|l| l.description()).map(|d| d.value),
            pose,
            gesture_target: target,
            points: target.is_some_and(|t| matches!(Gesture::of(&t), Gesture::At(_))),
            gesture_arm: location.and_then(|l| l.gesture_arm).map(|a| a.value),
            before: said(Phase::Pre),
            after: said(Phase::Post),
        }
    }
}

impl Stop<'_> {
    fn text(&self, language: Language) -> String {
        let start = if self.start {
            "  [start: the robot's initial pose and home]"
        } else {
            ""
        };
        if !self.found {
            return format!(
                "Stop {}: location {} — NOT IN THE FILE: the robot has nothing to do or say here{start}\n",
                self.stop, self.id
            );
        }
        let description = self.description.map_or_else(
            || "(no description)".to_string(),
            |d| present::text(d).into_owned(),
        );
        let mut out = format!(
            "Stop {}: location {}, {description}{start}\n",
            self.stop, self.id
        );
        let mut gesture = self.gesture_target.map_or_else(
            || "MISSING gesture target: the robot does not point".to_string(),
            |target| Gesture::of(&target).sentence(self.gesture_arm),
        );
        if let Some(loaded) = &self.target_as_loaded {
            gesture.push_str(&format!(" (the robot's reader loads the target {loaded})"));
        }
        out.push_str(&format!("  {:<13}{}\n", "stands at", self.stands));
        out.push_str(&format!("  {:<13}{gesture}\n", "gesture"));
        for (said, label) in [(&self.before, "says before"), (&self.after, "says after")] {
            out.push_str(&said.text(label, language));
        }
        out
    }
}

impl<'a> Said<'a> {
    fn new(
        location: Option<&Location<'a>>,
        phase: Phase,
        language: Language,
        lines: &Lines,
        held: Held,
    ) -> Said<'a> {
        let message = location.map_or(Message::Missing, |l| Message::of(l, phase, language));
        let english = match language {
            Language::English => None,
            _ => location
                .and_then(|l| l.message(phase, Language::English))
                .map(|m| m.value),
        };
        let field = Field::Message(phase, language);
        let differs = message
            .value()
            .filter(|v| !robot::agrees(field, &FieldValue::Text(v.value), &held))
            .map(|_| robot::shown(field, &held));
        let robot_says = match &held {
            Held::Text(text) => Some(text.clone().into_owned()),
            Held::Nothing => Some(String::new()),
            _ => None,
        };
        Said {
            status: message.status(),
            text: message.value().map(|v| v.value),
            line: message.value().map(|v| lines.of(v.span)),
            english,
            robot_says,
            message,
            differs,
        }
    }

    fn text(&self, label: &str, language: Language) -> String {
        let line = self
            .line
            .map(|n| format!(" (line {n})"))
            .unwrap_or_default();
        let first = match self.message {
            Message::Written(value) => format!("{}{line}", present::quoted(value.value)),
            Message::Placeholder(value) => format!(
                "UNTRANSLATED: the file has the placeholder {}{line}",
                present::quoted(value.value)
            ),
            Message::Missing => format!(
                "MISSING: no {} message, the robot says nothing",
                language.name()
            ),
        };
        let mut out = format!("  {label:<13}{first}\n");
        if let Some(loaded) = &self.differs {
            out.push_str(&format!(
                "  {:<13}but the robot's reader loads {loaded}\n",
                ""
            ));
        }
        if !matches!(self.message, Message::Written(_)) && language != Language::English {
            let hint = match self.english {
                Some(english) => format!("translate from English: {}", present::quoted(english)),
                None => "no English message either".to_string(),
            };
            out.push_str(&format!("  {:<13}{hint}\n", ""));
        }
        out
    }
}
