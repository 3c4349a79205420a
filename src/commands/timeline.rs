//! `ekb tour --timeline [--lang L|all] [--format text|json] [map options]`: the tour in time
//! (SPEC §15), as [`crate::present::timeline`] makes it.

use std::io::Write;

use super::map::MapInput;
use super::tour::{Args, TourFormat};
use super::{CommandResult, Context, Exit};
use crate::model::Phase;
use crate::present::language::Languages;
use crate::present::timeline::{StopTime, Timeline};
use crate::render::escape::escape;
use crate::render::safe_json as json;
use crate::robot::speech;

pub fn run(args: &Args, context: &Context) -> CommandResult {
    let input = MapInput::read(args.file.as_deref(), &args.map, context)?;
    let path = context.input(args.file.as_deref())?;
    let robot = context.settings_for(&path)?.robot.profile();
    let (checked, loaded) = input.check(context.quiet);
    let languages = args.lang.each();
    let timelines = Timeline::each(&checked, &loaded, input.map.as_ref(), &robot, &languages);
    let mut stdout = std::io::stdout().lock();
    match (args.format, args.lang) {
        (TourFormat::Json, Languages::One(_)) => json::write(&timelines[0], &mut stdout)?,
        (TourFormat::Json, Languages::All) => json::write(&timelines, &mut stdout)?,
        (TourFormat::Text, _) => {
            let file = escape(checked.source.name());
            let map = input
                .map
                .as_ref()
                .map(|map| escape(&map.name()).into_owned());
            stdout.write_all(text(&file, map.as_deref(), &timelines).as_bytes())?
        }
    }
    stdout.flush()?;
    Ok(Exit::Clean)
}

/// The timelines as a table to read: a column pair (before, after pointing) per language.
fn text(file: &str, map: Option<&str>, timelines: &[Timeline]) -> String {
    let Some(first) = timelines.first() else {
        return String::new();
    };
    let names: Vec<&str> = timelines.iter().map(|t| t.language.name()).collect();
    let mut out = format!("Timeline of {file}'s tour in {}", names.join(", "));
    match map {
        Some(map) => out += &format!(", each leg as the robot plans it on {map}\n"),
        None => {
            out += ": legs as straight lines (give --map-config for the paths the robot drives)\n"
        }
    }
    for timeline in timelines.iter().filter(|t| !t.spoken) {
        out += &speech::silence_notice(timeline.language);
        out.push('\n');
    }
    let mut header = format!(
        "{:>4}  {:>8}  {:<14}  {:>5}",
        "stop", "location", "leg", "turn"
    );
    for name in &names {
        header += &format!("  {:>17}", format!("{name} before/after"));
    }
    out += &format!("{}\n", header.trim_end());
    for (index, stop) in first.stops.iter().enumerate() {
        let mut line = format!(
            "{:>4}  {:>8}  {:<14}  {:>5}",
            stop.stop,
            stop.id,
            leg(stop),
            stop.leg
                .turn_deg
                .map_or_else(|| "-".to_string(), |turn| format!("{turn:.0}°"))
        );
        for timeline in timelines {
            let speech = &timeline.stops[index].speech;
            line += &format!(
                "  {:>17}",
                format!("{} / {}", seconds(speech.pre_s), seconds(speech.post_s))
            );
        }
        out += &format!("{}\n", line.trim_end());
    }
    out += &format!(
        "Driven: {:.2} m in {} ({} leg{} the robot cannot drive)\n",
        first.distance_m(),
        seconds(Some(first.drive_s())),
        first.stops.iter().filter(|s| !s.leg.reachable).count(),
        if first.stops.iter().filter(|s| !s.leg.reachable).count() == 1 {
            ""
        } else {
            "s"
        },
    );
    for timeline in timelines {
        let longest = timeline
            .longest_message()
            .map_or_else(String::new, |(stop, phase, s)| {
                let when = match phase {
                    Phase::Pre => "before",
                    Phase::Post => "after",
                };
                format!(
                    "; the longest wait is location {}'s message {when} pointing, {}",
                    stop.id,
                    seconds(Some(s))
                )
            });
        match timeline.spoken {
            true => {
                out += &format!(
                    "{}: {} of speech, {} in all{longest}\n",
                    timeline.language.name(),
                    seconds(Some(timeline.speech_s())),
                    seconds(Some(timeline.total_s)),
                )
            }
            false => {
                out += &format!(
                    "{}: silent, {} in all (the driving)\n",
                    timeline.language.name(),
                    seconds(Some(timeline.total_s))
                )
            }
        }
    }
    out
}

/// `3.57 m 14 s`, or where the robot cannot drive, `unreachable`.
fn leg(stop: &StopTime) -> String {
    match (stop.leg.distance_m, stop.leg.drive_s) {
        (Some(metres), Some(drive)) => format!("{metres:.2} m {}", seconds(Some(drive))),
        _ => "unreachable".to_string(),
    }
}

/// `4.3 s`, `1 min 2 s`, or `-` for silence.
fn seconds(seconds: Option<f64>) -> String {
    match seconds {
        None => "-".to_string(),
        Some(s) if s < 60.0 => format!("{s:.1} s"),
        Some(s) => format!("{} min {:.0} s", (s / 60.0).floor(), s % 60.0),
    }
}
