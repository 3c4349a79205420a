//! `ekb locations [FILE]`: every location in id order, as a table, JSON, or the layout of
//! the robot's own `printToScreen()`.

use std::io::{self, BufWriter, Write};
use std::path::PathBuf;

use serde::Serialize;

use super::{CommandResult, Context, Exit};
use crate::check::{check, Checked};
use crate::model::export::LocationView;
use crate::model::{Dialect, Key, KnowledgeBase, Language, Location, Phase};
use crate::present::field::Field;
use crate::present::{
    self, language, robot, table, AllTourPositions, Gesture, Message, PositionsOf, TourPositions,
    MESSAGE_LEGEND,
};
use crate::reader::line::LoadedValue;
use crate::reader::{self, view, Loaded};
use crate::render::escape::escape;
use crate::render::safe_json as json;

#[derive(Debug, clap::Args)]
pub struct Args {
    /// Knowledge-base file (`-` for standard input) [default: the configured knowledgeBase]
    #[arg(value_name = "FILE")]
    pub file: Option<PathBuf>,

    /// Output format
    #[arg(long, value_enum, default_value_t = LocationsFormat::Table)]
    pub format: LocationsFormat,
}

/// `ekb locations --format`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum LocationsFormat {
    /// A table that fits the terminal
    Table,
    /// One JSON object: the export's locations, with message status and tour positions
    Json,
    /// The layout of the robot's printToScreen() (the document's Figure 3), to compare with its log
    Classic,
}

pub fn run(args: &Args, context: &Context) -> CommandResult {
    let path = context.input(args.file.as_deref())?;
    let options = context.read_options(&path)?;
    let source = context.read(&path)?;
    let checked = check(&source, &options);
    present::note_errors(&checked, context.quiet);
    // The JSON shows the file as written: only the other formats load it as the reader does.
    let text = checked.source.text().as_bytes();
    let mut stdout = BufWriter::new(std::io::stdout().lock());
    match args.format {
        LocationsFormat::Table => {
            let loaded = reader::load_fields(text, checked.reader, &TABLE_KEYS);
            write_table(&checked, loaded, &mut stdout)?;
        }
        LocationsFormat::Json => write_json(&checked, &mut stdout)?,
        LocationsFormat::Classic => {
            let loaded = reader::load(text, checked.reader);
            stdout.write_all(render_classic(&loaded).as_bytes())?;
        }
    }
    stdout.flush()?;
    Ok(Exit::Clean)
}

/// The keys whose values the table shows as the reader loads them.
const TABLE_KEYS: [Key; 3] = [
    Key::RobotLocationDescription,
    Key::RobotLocationPose,
    Key::GestureArm,
];

/// The table of locations, each value as the chosen reader loads it, marked where the file
/// says otherwise.
fn write_table(checked: &Checked<'_>, loaded: Loaded<'_>, out: &mut impl Write) -> io::Result<()> {
    let kb = &checked.kb;
    let text = checked.source.text().as_bytes();
    let as_loaded = |location: &Location<'_>, field: Field, key: Key| {
        let held = view::held(&loaded, text, location.id, key);
        field
            .get(location)
            .map(|(value, _)| robot::as_loaded(field, &value, &held, checked.reader))
    };
    let with_arm = kb.locations().iter().any(|l| l.gesture_arm.is_some());
    let mut header = vec!["id", "description", "pose (x, y, θ)", "gesture target"];
    if with_arm {
        header.push("arm");
    }
    header.extend(["messages", "tour stop"]);
    let positions = TourPositions::first(kb, present::MAX_LISTED);
    let row = |location: &Location<'_>| {
        // Made as long as the header at once: a row that grew to it took a copy of each.
        let mut row = Vec::with_capacity(header.len());
        row.push(location.id.to_string());
        row.push(
            as_loaded(location, Field::Description, Key::RobotLocationDescription)
                .unwrap_or_else(|| "—".to_string()),
        );
        row.push(
            as_loaded(location, Field::Pose, Key::RobotLocationPose)
                .unwrap_or_else(|| "—".to_string()),
        );
        row.push(
            location
                .gesture_target
                .map_or_else(|| "—".to_string(), |t| Gesture::of(&t.value).short()),
        );
        if with_arm {
            row.push(
                as_loaded(location, Field::GestureArm, Key::GestureArm)
                    .unwrap_or_else(|| "—".to_string()),
            );
        }
        row.push(message_marks(location));
        row.push(tour_cell(&positions, location.id));
        row
    };
    let locations = kb.locations();
    let mut table = table::Rows::with_capacity(&header, locations.len());
    for location in locations {
        table.add_row(row(location));
    }
    // A narrow table wraps other columns, never the marks (`RW` on one line, `~` below).
    table.keep_unbroken(header.len() - 2);
    // The rows hold what the table shows: what the reader holds goes before it is drawn.
    drop(loaded);
    table.write(out)?;
    let count = kb.locations().len();
    let plural = if count == 1 { "" } else { "s" };
    writeln!(
        out,
        "\n{count} location{plural}, as reader {} loads them. {MESSAGE_LEGEND}",
        checked.reader
    )
}

/// `before EN ✓ ZU ~ RW ~` and `after` on a second line.
fn message_marks(location: &Location<'_>) -> String {
    let mut marks = String::with_capacity(64);
    for (i, &phase) in Phase::ALL.iter().enumerate() {
        if i > 0 {
            marks.push('\n');
        }
        // Pieces pushed, not formatted (padding with `{:<6}` was a third of the cell): this
        // is two lines of every row of a table that may have 100,000 of them.
        let name = phase.name();
        marks.push_str(name);
        marks.push_str(&"      "[name.len().min(6)..]);
        for &lang in Language::ALL.iter() {
            marks.push(' ');
            marks.push_str(language::code(lang));
            marks.push(' ');
            marks.push_str(Message::of(location, phase, lang).mark());
        }
    }
    marks
}

/// `1 (start)`, `2, 5` or `—` (not on the tour); the first positions of a location that a
/// long tour visits over and over, then how many more.
fn tour_cell(positions: &TourPositions, id: u32) -> String {
    if positions.count(id) == 0 {
        return "—".to_string();
    }
    let first = positions.of(id).iter().map(|&position| match position {
        1 => "1 (start)".to_string(),
        n => n.to_string(),
    });
    present::listed_of(first, positions.count(id), ", ")
}

/// `ekb locations --format json`.
#[derive(Serialize)]
struct JsonLocations<'a> {
    /// The version of the robot's reader the file was checked against.
    reader: &'static str,
    dialect: Option<Dialect>,
    locations: EachLocation<'a>,
    /// The tour's stops, read from its line as they are written (a tour may have a million).
    #[serde(serialize_with = "stop_ids")]
    tour: Option<&'a KnowledgeBase<'a>>,
}

/// Writes the JSON of every location of `checked`.
fn write_json(checked: &Checked<'_>, out: &mut impl Write) -> io::Result<()> {
    let view = JsonLocations {
        reader: checked.reader.name(),
        dialect: checked.kb.dialect,
        locations: EachLocation {
            kb: &checked.kb,
            lines: present::Lines::new(checked.source.text()),
            positions: AllTourPositions::new(&checked.kb),
        },
        tour: checked.kb.tour.as_ref().map(|_| &checked.kb),
    };
    json::write(&view, out)
}

/// The list of [`JsonLocation`]s, each made as it is written: holding them all held a copy
/// of the file's text, and the positions of a location on a million-stop tour are long.
struct EachLocation<'a> {
    kb: &'a KnowledgeBase<'a>,
    lines: present::Lines,
    positions: AllTourPositions<'a>,
}

impl Serialize for EachLocation<'_> {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let locations = self.kb.locations().iter();
        s.collect_seq(locations.map(|location| JsonLocation::new(location, self)))
    }
}

fn stop_ids<S: serde::Serializer>(
    kb: &Option<&KnowledgeBase<'_>>,
    s: S,
) -> Result<S::Ok, S::Error> {
    match kb {
        Some(kb) => s.collect_seq(kb.tour_stops()),
        None => s.serialize_none(),
    }
}

#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
struct JsonLocation<'a, 'p> {
    #[serde(flatten)]
    location: LocationView<'a>,
    /// `written`, `placeholder` or `missing`, per message.
    message_status: JsonMessageStatus,
    /// 1-based positions on the tour.
    tour_positions: PositionsOf<'p, 'p>,
    /// The first and last line of the location in the file.
    lines: [u32; 2],
}

#[derive(Serialize)]
#[serde(rename_all = "camelCase")]
struct JsonMessageStatus {
    pre_gesture_message: JsonStatuses,
    post_gesture_message: JsonStatuses,
}

#[derive(Serialize)]
struct JsonStatuses {
    english: &'static str,
    #[serde(rename = "isiZulu")]
    isi_zulu: &'static str,
    kinyarwanda: &'static str,
}

impl<'a, 'p> JsonLocation<'a, 'p> {
    fn new(location: &Location<'a>, all: &'p EachLocation<'p>) -> JsonLocation<'a, 'p> {
        let statuses = |phase| {
            let status = |lang| Message::of(location, phase, lang).status();
            JsonStatuses {
                english: status(Language::English),
                isi_zulu: status(Language::IsiZulu),
                kinyarwanda: status(Language::Kinyarwanda),
            }
        };
        let (first, last) = all.lines.range(location);
        JsonLocation {
            location: LocationView::new(location),
            message_status: JsonMessageStatus {
                pre_gesture_message: statuses(Phase::Pre),
                post_gesture_message: statuses(Phase::Post),
            },
            tour_positions: all.positions.of(location.id),
            lines: [first, last],
        }
    }
}

/// The labels of the robot's printout, each padded to the width of the longest.
const CLASSIC_WIDTH: usize = 33;

/// The layout of the robot's `printToScreen()` and of the document's example application
/// (section 6): one block per location, in id order, of what the chosen reader holds. As on
/// the robot, numbers are 32-bit floats printed with one decimal, and what no line set prints
/// as 0.0 or nothing.
fn render_classic(loaded: &Loaded<'_>) -> String {
    let mut out = String::new();
    let triple = |numbers: Option<LoadedValue>| {
        let [a, b, c] = match numbers {
            Some(LoadedValue::Numbers(numbers)) => numbers,
            _ => [0.0; 3],
        };
        format!("({a:.1}, {b:.1} {c:.1})")
    };
    for location in loaded.locations.values() {
        let label = |name: &str| format!("{name:<CLASSIC_WIDTH$}");
        let text = |key: Key| match loaded.field(location, key).map(|field| field.value) {
            Some(LoadedValue::Text(span)) => {
                escape(&String::from_utf8_lossy(&loaded.text()[span.range()])).into_owned()
            }
            _ => String::new(),
        };
        let numbers = |key: Key| loaded.field(location, key).map(|field| field.value);
        out.push_str(&format!("{}{:<4} \n", label("Key"), location.id));
        out.push_str(&format!(
            "{}{} \n",
            label("Location Description"),
            text(Key::RobotLocationDescription)
        ));
        out.push_str(&format!(
            "{}{}\n",
            label("Robot Location"),
            triple(numbers(loaded.reader.pose_key()))
        ));
        out.push_str(&format!(
            "{}{} \n",
            label("Gesture Target"),
            triple(numbers(Key::GestureTarget))
        ));
        for phase in Phase::ALL {
            let prefix = match phase {
                Phase::Pre => "Pre-Gesture Message",
                Phase::Post => "Post-Gesture Message",
            };
            for lang in Language::ALL {
                out.push_str(&format!(
                    "{}{} \n",
                    label(&format!("{prefix} {}", lang.name())),
                    text(Key::for_message(phase, lang))
                ));
            }
        }
        out.push('\n');
    }
    out
}
