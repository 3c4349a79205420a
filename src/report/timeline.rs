//! The report's "The tour in time": a bar per language, stop after stop — the leg driven,
//! then the message before pointing and the one after — and a table of the totals.

use std::fmt::Write;

use crate::present::timeline::Timeline;
use crate::render::markup::markup;

/// Pixels: the chart's width, the language names' column, a row's height.
const WIDTH: f64 = 760.0;
const LABELS: f64 = 110.0;
const TOTALS: f64 = 90.0;
const ROW: f64 = 30.0;

const DRIVE_COLOUR: &str = "#8fa9cf";
const BEFORE_COLOUR: &str = "#d9762b";
const AFTER_COLOUR: &str = "#f0b27a";
const UNREACHABLE_COLOUR: &str = "#c8102e";

/// The section, for the timelines of each language (one tour).
pub fn section(html: &mut String, timelines: &[Timeline]) {
    html.push_str("<section id=\"time\" aria-labelledby=\"time-heading\">\n<h2 id=\"time-heading\">The tour in time</h2>\n");
    let Some(first) = timelines.first() else {
        html.push_str("</section>\n");
        return;
    };
    let planned = match first.planned {
        true => "each leg as the robot's planner drives it on the map",
        false => "each leg as a straight line (no map was given)",
    };
    let _ = writeln!(
        html,
        "<p class=\"legend\"><span class=\"swatch\" style=\"background:{DRIVE_COLOUR}\"></span> driving and turning ({planned}) · <span class=\"swatch\" style=\"background:{BEFORE_COLOUR}\"></span> the message before pointing · <span class=\"swatch\" style=\"background:{AFTER_COLOUR}\"></span> the message after · <span class=\"swatch\" style=\"background:{UNREACHABLE_COLOUR}\"></span> a stop the robot cannot drive to. A language the robot does not speak is silent.</p>"
    );
    chart(html, timelines);
    html.push_str("<table class=\"status\">\n<caption>How long the tour takes in each language</caption>\n<thead><tr><th scope=\"col\">Language</th><th scope=\"col\">In all</th><th scope=\"col\">Speech</th><th scope=\"col\">Driving</th><th scope=\"col\">The longest wait</th></tr></thead>\n<tbody>\n");
    for timeline in timelines {
        let longest = match (timeline.spoken, timeline.longest_message()) {
            (false, _) => "silent: the robot does not speak it".to_string(),
            (true, Some((stop, phase, seconds))) => format!(
                "location {}, {} pointing: {}",
                stop.id,
                match phase {
                    crate::model::Phase::Pre => "before",
                    crate::model::Phase::Post => "after",
                },
                shown(seconds)
            ),
            (true, None) => "none".to_string(),
        };
        let _ = writeln!(
            html,
            "<tr><th scope=\"row\">{}</th><td>{}</td><td>{}</td><td>{}</td><td>{}</td></tr>",
            timeline.language.name(),
            shown(timeline.total_s),
            shown(timeline.speech_s()),
            shown(timeline.drive_s()),
            markup(&longest)
        );
    }
    html.push_str("</tbody>\n</table>\n</section>\n");
}

/// One bar per language, on one time scale.
fn chart(html: &mut String, timelines: &[Timeline]) {
    let longest = timelines
        .iter()
        .map(|timeline| timeline.total_s)
        .fold(0.0, f64::max)
        .max(1.0);
    let scale = (WIDTH - LABELS - TOTALS) / longest;
    let height = ROW * timelines.len() as f64 + 8.0;
    let summary: Vec<String> = timelines
        .iter()
        .map(|t| format!("{}: {}", t.language.name(), shown(t.total_s)))
        .collect();
    let _ = write!(
        html,
        r#"<svg class="timeline" xmlns="http://www.w3.org/2000/svg" width="{WIDTH}" height="{height}" viewBox="0 0 {WIDTH} {height}" role="img" aria-label="How long the tour takes: {}" font-family="DejaVu Sans, sans-serif" font-size="13">"#,
        markup(&summary.join("; "))
    );
    for (row, timeline) in timelines.iter().enumerate() {
        let y = 4.0 + row as f64 * ROW;
        let _ = write!(
            html,
            r#"<g data-language="{}"><text x="0" y="{:.1}">{}</text>"#,
            timeline.language.name(),
            y + 17.0,
            timeline.language.name()
        );
        let mut x = LABELS;
        for stop in &timeline.stops {
            let segments = [
                (stop.leg.drive_s, DRIVE_COLOUR, "driving"),
                (stop.speech.pre_s, BEFORE_COLOUR, "before pointing"),
                (stop.speech.post_s, AFTER_COLOUR, "after pointing"),
            ];
            if !stop.leg.reachable {
                let _ = write!(
                    html,
                    r#"<rect x="{x:.1}" y="{y:.1}" width="3" height="22" fill="{UNREACHABLE_COLOUR}"><title>Stop {}, location {}: the robot cannot drive there, and gives its talk where it stands</title></rect>"#,
                    stop.stop, stop.id
                );
            }
            for (seconds, colour, what) in segments {
                let Some(seconds) = seconds.filter(|s| *s > 0.0) else {
                    continue;
                };
                let width = seconds * scale;
                let _ = write!(
                    html,
                    r#"<rect x="{x:.1}" y="{y:.1}" width="{width:.1}" height="22" fill="{colour}" stroke="white" stroke-width="0.5"><title>Stop {}, location {}: {what}, {}</title></rect>"#,
                    stop.stop,
                    stop.id,
                    shown(seconds)
                );
                x += width;
            }
        }
        let total = match timeline.spoken {
            true => shown(timeline.total_s),
            false => format!("{} (silent)", shown(timeline.total_s)),
        };
        let _ = write!(
            html,
            r#"<text x="{:.1}" y="{:.1}">{}</text></g>"#,
            x + 6.0,
            y + 17.0,
            markup(&total)
        );
    }
    html.push_str("</svg>\n");
}

/// `59 s`, `1 min 14 s`.
fn shown(seconds: f64) -> String {
    match seconds {
        s if s < 60.0 => format!("{s:.0} s"),
        s => format!("{} min {:.0} s", (s / 60.0).floor(), s % 60.0),
    }
}
