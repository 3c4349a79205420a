//! The drawing as SVG: self-contained (the map image is embedded), its text selectable
//! `<text>`, with a legend and a scale bar.
//!
//! Marks carry their data for tools and tests: each pose is a `<g class="pose">` with
//! `data-location` and `transform="translate(px py) rotate(deg)"` (SVG turns clockwise,
//! so the rotation is −theta); the plot's `<g id="plot">` says where the map's origin is
//! (`data-origin`) and its pixels per metre (`data-scale`).

use std::fmt::Write;

use base64::Engine;

use super::frame::Frame;
use super::layout::{Placer, Rect};
use super::{Scene, Spot, MAX_DRAWN_LOCATIONS, MAX_DRAWN_STOPS};
use crate::present::Gesture;
use crate::render::markup::markup;
use crate::rules::excerpt;

/// The arrow of a location on the tour.
pub const POSE_COLOUR: &str = "#1f5fbf";
/// The arrow of a location no stop visits.
pub const UNVISITED_COLOUR: &str = "#8a8a8a";
const PATH_COLOUR: &str = "#e07b00";
const TARGET_COLOUR: &str = "#7b3fa0";
pub const FINDING_COLOUR: &str = "#c8102e";
const START_COLOUR: &str = "#1a8f3a";
const TEXT_COLOUR: &str = "#222222";
const FONT: &str = "DejaVu Sans, Verdana, Arial, sans-serif";

/// Room around the plot, in pixels: for the title, the axes' labels, and labels that
/// spill off the plot to its right.
const LEFT: f64 = 64.0;
const TOP: f64 = 84.0;
const BOTTOM: f64 = 56.0;
const GAP: f64 = 150.0;
const LEGEND_WIDTH: f64 = 320.0;
const MARGIN: f64 = 16.0;

/// Label text.
const FONT_SIZE: f64 = 12.0;
const LINE_HEIGHT: f64 = 16.0;
const PADDING: f64 = 4.0;
/// A stop number's disc.
const BADGE_RADIUS: f64 = 7.5;
/// A pose's arrow: its shaft's length and its tip's.
const SHAFT: f64 = 30.0;
const TIP: f64 = 40.0;

/// How far from its mark a label's leader line starts.
const LEADER_GAP: f64 = 10.0;

/// The most locations labelled; on a larger file the tour's are labelled first.
pub const MAX_LABELLED: usize = 400;

/// Whether the SVG embeds the map's image, or leaves it (and the white background) to
/// whoever paints beneath it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MapImage {
    Embedded,
    PaintedBeneath,
}

/// An SVG document and its size in pixels.
#[derive(Debug, Clone)]
pub struct Drawing {
    pub svg: String,
    pub width: f64,
    pub height: f64,
    pub frame: Frame,
}

/// Draws `scene`.
pub fn draw(scene: &Scene<'_>, map_image: MapImage) -> Drawing {
    let frame = Frame::fit(scene, LEFT, TOP);
    let legend = legend_lines(scene);
    let legend_x = frame.left + frame.width_px() + GAP;
    let legend_height = LEGEND_ROWS.len() as f64 * 24.0 + 80.0 + legend.len() as f64 * LINE_HEIGHT;
    let title_width = LEFT + text_width(&title(scene), 18.0, true) + MARGIN;
    let width = (legend_x + LEGEND_WIDTH + MARGIN).max(title_width).ceil();
    let height = (frame.top + frame.height_px() + BOTTOM)
        .max(TOP + legend_height + MARGIN)
        .ceil();
    let positions: Vec<Option<Placed>> = scene
        .spots
        .iter()
        .map(|spot| Placed::of(spot, &frame))
        .collect();
    let mut svg = String::with_capacity(16_384 + scene.spots.len() * 400);
    let (origin_x, origin_y) = frame.px(0.0, 0.0);
    let _ = write!(
        svg,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" viewBox="0 0 {width} {height}" role="img" aria-labelledby="ekb-title ekb-desc" font-family="{FONT}" font-size="{FONT_SIZE}">"#
    );
    let _ = write!(
        svg,
        r#"<title id="ekb-title">{}</title><desc id="ekb-desc">{}</desc>"#,
        markup(&title(scene)),
        markup(&description(scene))
    );
    if map_image == MapImage::Embedded {
        let _ = write!(
            svg,
            r#"<rect width="{width}" height="{height}" fill="white"/>"#
        );
    }
    heading(&mut svg, scene);
    let _ = write!(
        svg,
        r#"<g id="plot" data-origin="{origin_x:.1} {origin_y:.1}" data-scale="{}">"#,
        frame.scale
    );
    map_layer(&mut svg, scene, &frame, map_image);
    grid(&mut svg, &frame);
    footprints(&mut svg, scene, &frame, &positions);
    tour_path(&mut svg, scene, &frame, &positions);
    gestures(&mut svg, scene, &positions);
    rings(&mut svg, scene, &positions);
    arrows(&mut svg, scene, &positions);
    let bounds = Rect::new(4.0, TOP - 8.0, legend_x - 16.0, height - TOP + 4.0);
    labels(&mut svg, scene, &frame, &positions, bounds);
    svg.push_str("</g>");
    legend_panel(&mut svg, scene, &frame, legend_x, &legend);
    svg.push_str("</svg>\n");
    Drawing {
        svg,
        width,
        height,
        frame,
    }
}

/// Where a location's pose and gesture target are drawn.
#[derive(Debug, Clone, Copy)]
struct Placed {
    pose: (f64, f64),
    /// The pose is off the drawing, shown at its edge.
    pinned: bool,
    target: Option<(f64, f64)>,
}

impl Placed {
    /// `None` when the pose is not a finite number (it cannot be drawn).
    fn of(spot: &Spot<'_>, frame: &Frame) -> Option<Placed> {
        let (pose, pinned) = frame.pinned(spot.pose.x, spot.pose.y)?;
        let target = match spot.gesture {
            Gesture::At(t) | Gesture::Skipped(t) => frame.pinned(t.x, t.y).map(|(px, _)| px),
            Gesture::None => None,
        };
        Some(Placed {
            pose,
            pinned,
            target,
        })
    }
}

fn title(scene: &Scene<'_>) -> String {
    match scene.map {
        Some(map) => format!("The tour of {} on {}", excerpt(scene.file), map.name()),
        None => format!("The tour of {}", excerpt(scene.file)),
    }
}

/// One sentence for screen readers: the tour and the findings.
fn description(scene: &Scene<'_>) -> String {
    format!(
        "{} locations; the tour visits {}; as the {} reader loads the file. {}.",
        scene.spots.len() + scene.undrawn_locations,
        tour_ids(scene),
        scene.reader.name(),
        scene.summary.sentence()
    )
}

/// `1 → 4 → 3 → 2 → 5` (the first 20 stops).
fn tour_ids(scene: &Scene<'_>) -> String {
    if scene.tour.is_empty() {
        return "no location (no tour)".to_string();
    }
    let mut ids: Vec<String> = scene
        .tour
        .iter()
        .take(20)
        .map(|&index| scene.spots[index].id.to_string())
        .collect();
    if scene.tour.len() > 20 {
        ids.push(format!(
            "… ({} stops)",
            scene.tour.len() + scene.undrawn_stops
        ));
    }
    ids.join(" → ")
}

fn heading(svg: &mut String, scene: &Scene<'_>) {
    let map = match scene.map {
        Some(map) => format!("map {} m × {} m", map.width, map.height),
        None => "no map: a metre grid fitted to the poses".to_string(),
    };
    let _ = write!(
        svg,
        r##"<text x="{LEFT}" y="30" font-size="18" font-weight="bold" fill="{TEXT_COLOUR}">{}</text><text x="{LEFT}" y="52" font-size="13" fill="#555555">Tour: {} · as the {} reader loads the file · {}</text>"##,
        markup(&title(scene)),
        markup(&tour_ids(scene)),
        scene.reader.name(),
        markup(&map)
    );
}

/// The map's image (or its obstacles, if it has no image) and its edge.
fn map_layer(svg: &mut String, scene: &Scene<'_>, frame: &Frame, map_image: MapImage) {
    let Some(map) = scene.map else {
        return;
    };
    let (x, y) = frame.px(0.0, map.height);
    let (w, h) = (map.width * frame.scale, map.height * frame.scale);
    match &map.image {
        Some(image) if map_image == MapImage::Embedded => {
            let _ = write!(
                svg,
                r#"<image id="map-image" x="{x:.1}" y="{y:.1}" width="{w:.1}" height="{h:.1}" preserveAspectRatio="none" opacity="{MAP_OPACITY}" href="data:image/png;base64,{}"/>"#,
                base64::engine::general_purpose::STANDARD.encode(&image.png)
            );
        }
        Some(_) => {}
        None => {
            for obstacle in &map.obstacles {
                let (ox, oy) = frame.px(
                    obstacle.centre_x - obstacle.width / 2.0,
                    obstacle.centre_y + obstacle.height / 2.0,
                );
                let _ = write!(
                    svg,
                    r##"<rect x="{ox:.1}" y="{oy:.1}" width="{:.1}" height="{:.1}" fill="#000000" opacity="{MAP_OPACITY}"/>"##,
                    obstacle.width * frame.scale,
                    obstacle.height * frame.scale
                );
            }
        }
    }
    let _ = write!(
        svg,
        r##"<rect x="{x:.1}" y="{y:.1}" width="{w:.1}" height="{h:.1}" fill="none" stroke="#555555" stroke-width="1"/>"##
    );
}

/// How strongly the map is drawn: its black walls come out grey, so that marks stand out.
pub const MAP_OPACITY: f64 = 0.35;

/// The metre grid, with the metres along the plot's bottom and left edges.
fn grid(svg: &mut String, frame: &Frame) {
    let step = frame.grid_step();
    let (left, top) = (frame.left, frame.top);
    let (right, bottom) = (left + frame.width_px(), top + frame.height_px());
    svg.push_str(r##"<g stroke="#b8b8b8" stroke-width="0.6" stroke-dasharray="2 3">"##);
    let lines = |from: f64, to: f64| {
        let first = (from / step).ceil() as i64;
        let last = (to / step).floor() as i64;
        (first..=last).map(move |k| k as f64 * step)
    };
    for x in lines(frame.x0, frame.x1) {
        let (px, _) = frame.px(x, 0.0);
        let _ = write!(
            svg,
            r#"<line x1="{px:.1}" y1="{top:.1}" x2="{px:.1}" y2="{bottom:.1}"/>"#
        );
    }
    for y in lines(frame.y0, frame.y1) {
        let (_, py) = frame.px(0.0, y);
        let _ = write!(
            svg,
            r#"<line x1="{left:.1}" y1="{py:.1}" x2="{right:.1}" y2="{py:.1}"/>"#
        );
    }
    svg.push_str("</g><g fill=\"#555555\" font-size=\"11\">");
    for x in lines(frame.x0, frame.x1) {
        let (px, _) = frame.px(x, 0.0);
        let _ = write!(
            svg,
            r#"<text x="{px:.1}" y="{:.1}" text-anchor="middle">{}</text>"#,
            bottom + 16.0,
            metres(x)
        );
    }
    for y in lines(frame.y0, frame.y1) {
        let (_, py) = frame.px(0.0, y);
        let _ = write!(
            svg,
            r#"<text x="{:.1}" y="{:.1}" text-anchor="end">{}</text>"#,
            left - 6.0,
            py + 4.0,
            metres(y)
        );
    }
    let _ = write!(
        svg,
        r#"<text x="{right:.1}" y="{:.1}" text-anchor="end">x (m)</text><text x="{:.1}" y="{:.1}">y (m)</text></g>"#,
        bottom + 34.0,
        left - 40.0,
        top - 10.0
    );
}

/// A number of metres without float noise: `0.6`, not `0.6000000000000001`.
fn metres(value: f64) -> String {
    let rounded = (value * 1e6).round() / 1e6;
    format!("{}", rounded + 0.0)
}

/// The robot's footprint (its radius on the map) at each pose.
fn footprints(svg: &mut String, scene: &Scene<'_>, frame: &Frame, positions: &[Option<Placed>]) {
    let Some(map) = scene.map else {
        return;
    };
    let radius = map.robot_radius * frame.scale;
    for (spot, placed) in scene.spots.iter().zip(positions) {
        let Some(placed) = placed else { continue };
        let (x, y) = placed.pose;
        let _ = write!(
            svg,
            r#"<circle class="footprint" cx="{x:.1}" cy="{y:.1}" r="{radius:.1}" fill="{0}" fill-opacity="0.12" stroke="{0}" stroke-opacity="0.45" stroke-width="1"/>"#,
            arrow_colour(spot)
        );
    }
}

fn arrow_colour(spot: &Spot<'_>) -> &'static str {
    if spot.stops.is_empty() {
        UNVISITED_COLOUR
    } else {
        POSE_COLOUR
    }
}

/// The tour's path, stop to stop, with an arrowhead halfway along each leg: with a map, as
/// the robot's planner drives it, a leg it cannot drive dashed in red from where it stands.
fn tour_path(svg: &mut String, scene: &Scene<'_>, frame: &Frame, positions: &[Option<Placed>]) {
    let stops: Vec<String> = scene
        .tour
        .iter()
        .map(|&i| scene.spots[i].id.to_string())
        .collect();
    let _ = write!(
        svg,
        r#"<g id="tour" data-locations="{}" stroke="{PATH_COLOUR}" fill="{PATH_COLOUR}" stroke-width="2.5" stroke-linecap="round">"#,
        stops.join(" ")
    );
    for (points, to) in drawn_legs(scene, frame, positions) {
        match to {
            None => planned_leg(svg, &points),
            Some(to) => unreachable_leg(svg, points[0], points[1], to),
        }
    }
    svg.push_str("</g>");
}

/// A leg as drawn: its points in pixels of the drawing, and the stop it cannot reach, if
/// the robot cannot drive it.
type DrawnLeg<'s> = (Vec<(f64, f64)>, Option<&'s Spot<'s>>);

/// Each leg of the tour as drawn: with a map, the path the robot's planner drives (or, to a
/// stop it cannot reach, the straight line); without one, the straight line stop to stop.
fn drawn_legs<'s>(
    scene: &'s Scene<'_>,
    frame: &Frame,
    positions: &[Option<Placed>],
) -> Vec<DrawnLeg<'s>> {
    if scene.map.is_none() {
        let points: Vec<(f64, f64)> = scene
            .tour
            .iter()
            .filter_map(|&index| positions[index].map(|placed| placed.pose))
            .collect();
        return points.windows(2).map(|leg| (leg.to_vec(), None)).collect();
    }
    scene
        .legs
        .iter()
        .filter_map(|leg| {
            let (from, to) = (positions[leg.from]?, positions[leg.to]?);
            Some(match &leg.path {
                Some(path) => (path.iter().map(|&(x, y)| frame.px(x, y)).collect(), None),
                None => (vec![from.pose, to.pose], Some(&scene.spots[leg.to])),
            })
        })
        .collect()
}

/// A leg along `points` (pixels of the drawing), its arrowhead halfway along it.
fn planned_leg(svg: &mut String, points: &[(f64, f64)]) {
    let length: f64 = points
        .windows(2)
        .map(|pair| (pair[1].0 - pair[0].0).hypot(pair[1].1 - pair[0].1))
        .sum();
    if length < 1.0 {
        return;
    }
    let list: Vec<String> = points
        .iter()
        .map(|(x, y)| format!("{x:.1},{y:.1}"))
        .collect();
    let _ = write!(
        svg,
        r#"<polyline class="leg" points="{}" fill="none" stroke-opacity="0.8" stroke-linejoin="round"/>"#,
        list.join(" ")
    );
    // The arrowhead where half the length is behind.
    let mut left = length / 2.0;
    for pair in points.windows(2) {
        let ((x1, y1), (x2, y2)) = (pair[0], pair[1]);
        let step = (x2 - x1).hypot(y2 - y1);
        if step >= left && step > 0.0 {
            let (x, y) = (x1 + (x2 - x1) * left / step, y1 + (y2 - y1) * left / step);
            let angle = (y2 - y1).atan2(x2 - x1).to_degrees();
            let _ = write!(
                svg,
                r#"<path d="M-7 -6 L7 0 L-7 6 Z" stroke="none" transform="translate({x:.1} {y:.1}) rotate({angle:.1})"/>"#
            );
            return;
        }
        left -= step;
    }
}

/// A leg the robot cannot drive: dashed in red from where it stands to the stop, crossed
/// out halfway.
fn unreachable_leg(svg: &mut String, (x1, y1): (f64, f64), (x2, y2): (f64, f64), to: &Spot<'_>) {
    let (x, y) = ((x1 + x2) / 2.0, (y1 + y2) / 2.0);
    let _ = write!(
        svg,
        r#"<g class="leg unreachable" data-location="{}" stroke="{FINDING_COLOUR}"><title>The robot cannot drive to location {}: it gives the talk where it stands</title><line x1="{x1:.1}" y1="{y1:.1}" x2="{x2:.1}" y2="{y2:.1}" stroke-dasharray="6 5"/><path d="M{:.1} {:.1} L{:.1} {:.1} M{:.1} {:.1} L{:.1} {:.1}" stroke-width="3"/></g>"#,
        to.id,
        to.id,
        x - 7.0,
        y - 7.0,
        x + 7.0,
        y + 7.0,
        x - 7.0,
        y + 7.0,
        x + 7.0,
        y - 7.0,
    );
}

/// A dashed line from each pose to its gesture target, and the target's marker.
fn gestures(svg: &mut String, scene: &Scene<'_>, positions: &[Option<Placed>]) {
    for (spot, placed) in scene.spots.iter().zip(positions) {
        let Some(Placed {
            pose: (x1, y1),
            target: Some((x2, y2)),
            ..
        }) = placed
        else {
            continue;
        };
        let colour = gesture_colour(spot);
        let _ = write!(
            svg,
            r#"<g class="gesture" data-location="{}" stroke="{colour}"><line x1="{x1:.1}" y1="{y1:.1}" x2="{x2:.1}" y2="{y2:.1}" stroke-width="1.5" stroke-dasharray="5 4"/><circle cx="{x2:.1}" cy="{y2:.1}" r="6" fill="white" stroke-width="2"/><path d="M{:.1} {y2:.1} H{:.1} M{x2:.1} {:.1} V{:.1}" stroke-width="1.5"/></g>"#,
            spot.id,
            x2 - 3.5,
            x2 + 3.5,
            y2 - 3.5,
            y2 + 3.5
        );
    }
}

/// The target's colour: grey where the robot does not point (its coordinates sum to 0).
fn gesture_colour(spot: &Spot<'_>) -> &'static str {
    match spot.gesture {
        Gesture::At(_) => TARGET_COLOUR,
        _ => UNVISITED_COLOUR,
    }
}

/// A green ring around the start, a red one around each location with an error or a
/// warning.
fn rings(svg: &mut String, scene: &Scene<'_>, positions: &[Option<Placed>]) {
    for (spot, placed) in scene.spots.iter().zip(positions) {
        let Some(placed) = placed else { continue };
        let (x, y) = placed.pose;
        if spot.is_start() {
            let _ = write!(
                svg,
                r#"<circle class="start" cx="{x:.1}" cy="{y:.1}" r="14" fill="none" stroke="{START_COLOUR}" stroke-width="3"/>"#
            );
        }
        if spot.is_flagged() {
            let _ = write!(
                svg,
                r#"<circle class="finding" cx="{x:.1}" cy="{y:.1}" r="9" fill="none" stroke="{FINDING_COLOUR}" stroke-width="2"/>"#
            );
        }
    }
}

/// Each pose's arrow, pointing along theta; those on the tour drawn last, on top.
fn arrows(svg: &mut String, scene: &Scene<'_>, positions: &[Option<Placed>]) {
    let unvisited_first = scene
        .spots
        .iter()
        .zip(positions)
        .filter(|(spot, _)| spot.stops.is_empty())
        .chain(
            scene
                .spots
                .iter()
                .zip(positions)
                .filter(|(spot, _)| !spot.stops.is_empty()),
        );
    for (spot, placed) in unvisited_first {
        let Some(placed) = placed else { continue };
        let (x, y) = placed.pose;
        let rotation = (-spot.pose.theta).rem_euclid(360.0);
        let rotation = if rotation.is_finite() { rotation } else { 0.0 };
        let _ = write!(
            svg,
            r#"<g class="pose" data-location="{id}" transform="translate({x:.1} {y:.1}) rotate({rotation:.1})" fill="{colour}" stroke="{colour}"><circle r="4.5" stroke="none"/><path d="M0 0 H{SHAFT}" stroke-width="3" fill="none"/><path d="M{base} -6.5 L{TIP} 0 L{base} 6.5 Z" stroke="none"/></g>"#,
            id = spot.id,
            colour = arrow_colour(spot),
            base = SHAFT - 2.0,
        );
    }
}

/// One line of a label.
struct LabelLine {
    /// Stop numbers, drawn as discs before the text; the first is the start if `start`.
    stops: Vec<usize>,
    text: String,
    colour: &'static str,
    bold: bool,
    indent: bool,
}

impl LabelLine {
    fn plain(text: String, colour: &'static str) -> LabelLine {
        LabelLine {
            stops: Vec::new(),
            text,
            colour,
            bold: false,
            indent: true,
        }
    }

    fn width(&self) -> f64 {
        let badges = self.stops.len() as f64 * (2.0 * BADGE_RADIUS + 3.0);
        let indent = if self.indent { 12.0 } else { 0.0 };
        badges + indent + text_width(&self.text, FONT_SIZE, self.bold)
    }
}

/// About how wide `text` is in DejaVu Sans (the widest of the usual fonts).
fn text_width(text: &str, size: f64, bold: bool) -> f64 {
    let per_char = if bold { 0.62 } else { 0.57 };
    text.chars().count() as f64 * size * per_char
}

/// The lines of one location's label.
fn spot_lines(spot: &Spot<'_>, placed: &Placed) -> Vec<LabelLine> {
    let description = spot.description.map_or_else(
        || "(no description)".to_string(),
        |d| excerpt(d).into_owned(),
    );
    let mut text = format!("{} · {description}", spot.id);
    if spot.is_start() {
        text.push_str(" — start / home");
    } else if spot.stops.is_empty() {
        text.push_str(" — not on the tour");
    }
    let mut lines = vec![LabelLine {
        stops: spot.stops.iter().copied().take(6).collect(),
        text,
        colour: if spot.stops.is_empty() {
            UNVISITED_COLOUR
        } else {
            TEXT_COLOUR
        },
        bold: false,
        indent: false,
    }];
    if !spot.pose_loaded {
        lines.push(LabelLine::plain(
            "no pose loaded: the robot stands at 0, 0, 0°".to_string(),
            FINDING_COLOUR,
        ));
    }
    if placed.pinned {
        lines.push(LabelLine::plain(
            format!("off the drawing, at ({:?}, {:?})", spot.pose.x, spot.pose.y),
            FINDING_COLOUR,
        ));
    }
    const MAX_RULES: usize = 6;
    for finding in spot.findings.iter().take(MAX_RULES) {
        let times = if finding.count > 1 {
            format!(" ×{}", finding.count)
        } else {
            String::new()
        };
        let mut line = LabelLine::plain(format!("{}{times}", finding.rule.name), FINDING_COLOUR);
        line.bold = finding.severity == crate::Severity::Error;
        lines.push(line);
    }
    if spot.findings.len() > MAX_RULES {
        lines.push(LabelLine::plain(
            format!("… and {} more rules", spot.findings.len() - MAX_RULES),
            FINDING_COLOUR,
        ));
    }
    lines
}

/// The label of a gesture target.
fn target_line(spot: &Spot<'_>) -> Option<LabelLine> {
    let text = match spot.gesture {
        Gesture::At(target) => {
            let arm = spot
                .arm
                .map(|arm| format!(", {} arm", arm.name()))
                .unwrap_or_default();
            format!("{}: {:?} m high{arm}", spot.id, target.z)
        }
        Gesture::Skipped(_) => format!("{}: sums to 0, not pointed at", spot.id),
        Gesture::None => return None,
    };
    let mut line = LabelLine::plain(text, gesture_colour(spot));
    line.indent = false;
    Some(line)
}

/// The labels: one per place where poses stand (listing each location there, its stops
/// and findings), and one per gesture target, each placed where it covers nothing.
fn labels(
    svg: &mut String,
    scene: &Scene<'_>,
    frame: &Frame,
    positions: &[Option<Placed>],
    bounds: Rect,
) {
    let mut placer = Placer::new(bounds);
    // Labels stay off the tour's lines: each line is taken in short pieces (a diagonal's
    // bounding box would take the whole square it crosses).
    for (points, _) in drawn_legs(scene, frame, positions)
        .iter()
        .take(MAX_LABELLED)
    {
        for pair in points.windows(2) {
            let ((x1, y1), (x2, y2)) = (pair[0], pair[1]);
            let pieces = ((x2 - x1).hypot(y2 - y1) / 16.0).ceil().clamp(1.0, 1000.0) as usize;
            for piece in 0..pieces {
                let at = |k: usize| {
                    let t = k as f64 / pieces as f64;
                    (x1 + (x2 - x1) * t, y1 + (y2 - y1) * t)
                };
                placer.take(Rect::of_segment(at(piece), at(piece + 1), 3.0));
            }
        }
    }
    let labelled = labelled(scene, positions);
    for &index in &labelled {
        let Some(placed) = positions[index] else {
            continue;
        };
        let rotation = scene.spots[index].pose.theta.to_radians();
        let tip = (
            placed.pose.0 + TIP * rotation.cos(),
            placed.pose.1 - TIP * rotation.sin(),
        );
        let tip = if tip.0.is_finite() && tip.1.is_finite() {
            tip
        } else {
            placed.pose
        };
        placer.take(Rect::of_segment(placed.pose, tip, 8.0));
        placer.take(Rect::around(placed.pose, 10.0));
        if let Some(target) = placed.target {
            placer.take(Rect::around(target, 8.0));
        }
    }
    let pose_groups = group(&labelled, |index| positions[index].map(|p| p.pose));
    for (anchor, members) in pose_groups {
        let mut members = members;
        members.sort_by_key(|&i| {
            (
                scene.spots[i].stops.first().copied().unwrap_or(usize::MAX),
                scene.spots[i].id,
            )
        });
        let lines: Vec<LabelLine> = members
            .iter()
            .filter_map(|&i| positions[i].map(|placed| spot_lines(&scene.spots[i], &placed)))
            .flatten()
            .collect();
        label(svg, &mut placer, anchor, &lines, "location");
    }
    let target_groups = group(&labelled, |index| positions[index].and_then(|p| p.target));
    for (anchor, members) in target_groups {
        let lines: Vec<LabelLine> = members
            .iter()
            .filter_map(|&i| target_line(&scene.spots[i]))
            .collect();
        label(svg, &mut placer, anchor, &lines, "target");
    }
}

/// The locations to label: all, or on a large file the first [`MAX_LABELLED`], those on
/// the tour first.
fn labelled(scene: &Scene<'_>, positions: &[Option<Placed>]) -> Vec<usize> {
    let drawn = |&i: &usize| positions[i].is_some();
    let visited = (0..scene.spots.len()).filter(|&i| !scene.spots[i].stops.is_empty());
    let unvisited = (0..scene.spots.len()).filter(|&i| scene.spots[i].stops.is_empty());
    visited
        .chain(unvisited)
        .filter(drawn)
        .take(MAX_LABELLED)
        .collect()
}

/// `indexes` grouped by the point `at` gives each (points within 3 pixels are one).
fn group(
    indexes: &[usize],
    at: impl Fn(usize) -> Option<(f64, f64)>,
) -> Vec<((f64, f64), Vec<usize>)> {
    let mut groups: Vec<((f64, f64), Vec<usize>)> = Vec::new();
    for &index in indexes {
        let Some(point) = at(index) else { continue };
        let near = |(x, y): (f64, f64)| (x - point.0).hypot(y - point.1) < 3.0;
        match groups.iter_mut().find(|(anchor, _)| near(*anchor)) {
            Some((_, members)) => members.push(index),
            None => groups.push((point, vec![index])),
        }
    }
    // Large labels first: they have the fewest places to go.
    groups.sort_by_key(|(_, members)| std::cmp::Reverse(members.len()));
    groups
}

/// Writes a label of `lines` near `anchor`, with a leader line when it stands off.
fn label(
    svg: &mut String,
    placer: &mut Placer,
    anchor: (f64, f64),
    lines: &[LabelLine],
    class: &str,
) {
    if lines.is_empty() {
        return;
    }
    let width = lines.iter().map(LabelLine::width).fold(0.0, f64::max) + 2.0 * PADDING;
    let height = lines.len() as f64 * LINE_HEIGHT + 2.0 * PADDING;
    let place = placer.place(anchor, width, height);
    let near = place.nearest_to(anchor);
    let _ = write!(svg, r#"<g class="label {class}">"#);
    let distance = (near.0 - anchor.0).hypot(near.1 - anchor.1);
    if distance > 2.0 * LEADER_GAP {
        // From outside the mark, so that the mark's own pixels stay its colour.
        let along = LEADER_GAP / distance;
        let start = (
            anchor.0 + (near.0 - anchor.0) * along,
            anchor.1 + (near.1 - anchor.1) * along,
        );
        let _ = write!(
            svg,
            r##"<line x1="{:.1}" y1="{:.1}" x2="{:.1}" y2="{:.1}" stroke="#777777" stroke-width="0.8"/>"##,
            start.0, start.1, near.0, near.1
        );
    }
    let _ = write!(
        svg,
        r##"<rect x="{:.1}" y="{:.1}" width="{width:.1}" height="{height:.1}" rx="3" fill="white" fill-opacity="0.94" stroke="#bbbbbb" stroke-width="0.6"/>"##,
        place.x, place.y
    );
    for (row, line) in lines.iter().enumerate() {
        let baseline = place.y + PADDING + row as f64 * LINE_HEIGHT + LINE_HEIGHT - 4.0;
        let mut x = place.x + PADDING + if line.indent { 12.0 } else { 0.0 };
        for &stop in &line.stops {
            let fill = if stop == 1 { START_COLOUR } else { PATH_COLOUR };
            let cy = baseline - 4.0;
            let _ = write!(
                svg,
                r#"<g class="stop" data-stop="{stop}"><circle cx="{:.1}" cy="{cy:.1}" r="{BADGE_RADIUS}" fill="{fill}"/><text x="{:.1}" y="{:.1}" text-anchor="middle" font-size="10" font-weight="bold" fill="white">{stop}</text></g>"#,
                x + BADGE_RADIUS,
                x + BADGE_RADIUS,
                cy + 3.5
            );
            x += 2.0 * BADGE_RADIUS + 3.0;
        }
        text_line(svg, x, baseline, line);
    }
    svg.push_str("</g>");
}

/// The text of `line` at (`x`, `baseline`), in its colour and weight.
fn text_line(svg: &mut String, x: f64, baseline: f64, line: &LabelLine) {
    let weight = if line.bold {
        r#" font-weight="bold""#
    } else {
        ""
    };
    let _ = write!(
        svg,
        r#"<text x="{x:.1}" y="{baseline:.1}" fill="{}"{weight}>{}</text>"#,
        line.colour,
        markup(&line.text)
    );
}

/// The legend's rows of marks: what each mark means.
const LEGEND_ROWS: [&str; 8] = [
    "pose and heading (on the tour)",
    "location no stop visits",
    "first stop: start and home",
    "stop number, in visit order",
    "the tour, stop to stop",
    "gesture target (height, arm)",
    "a finding here (its rule below)",
    "the robot's radius on the map",
];

/// The legend's lines of text after its marks: the map, the findings not at a location.
fn legend_lines(scene: &Scene<'_>) -> Vec<LabelLine> {
    let mut lines = Vec::new();
    match scene.map {
        Some(map) => {
            lines.push(LabelLine::plain(
                format!("Map: {}", excerpt(&map.name())),
                TEXT_COLOUR,
            ));
            lines.push(LabelLine::plain(
                format!(
                    "{} × {} m, robot radius {} m",
                    map.width, map.height, map.robot_radius
                ),
                TEXT_COLOUR,
            ));
        }
        None => lines.push(LabelLine::plain(
            "No map: a grid fitted to the poses".to_string(),
            TEXT_COLOUR,
        )),
    }
    lines.push(LabelLine::plain(scene.summary.sentence(), TEXT_COLOUR));
    if !scene.elsewhere.is_empty() {
        lines.push(LabelLine::plain(
            "Not at one location:".to_string(),
            TEXT_COLOUR,
        ));
        for finding in scene.elsewhere.iter().take(10) {
            let times = if finding.count > 1 {
                format!(" ×{}", finding.count)
            } else {
                String::new()
            };
            lines.push(LabelLine::plain(
                format!("{}{times}", finding.rule.name),
                FINDING_COLOUR,
            ));
        }
    }
    let undrawn = scene
        .spots
        .iter()
        .filter(|spot| !(spot.pose.x.is_finite() && spot.pose.y.is_finite()))
        .count();
    if undrawn > 0 {
        lines.push(LabelLine::plain(
            format!("{undrawn} locations not drawn: a pose is not a finite number"),
            FINDING_COLOUR,
        ));
    }
    if scene.legs.iter().any(|leg| leg.path.is_none()) {
        lines.push(LabelLine::plain(
            "Dashed, crossed: a leg it cannot drive".to_string(),
            FINDING_COLOUR,
        ));
    }
    for (undrawn, what, most) in [
        (scene.undrawn_locations, "locations", MAX_DRAWN_LOCATIONS),
        (scene.undrawn_stops, "stops", MAX_DRAWN_STOPS),
    ] {
        if undrawn > 0 {
            lines.push(LabelLine::plain(
                format!("{undrawn} more {what} not drawn (at most {most})"),
                FINDING_COLOUR,
            ));
        }
    }
    if scene.spots.len() > MAX_LABELLED {
        lines.push(LabelLine::plain(
            format!(
                "{} locations not labelled (the tour's first)",
                scene.spots.len() - MAX_LABELLED
            ),
            TEXT_COLOUR,
        ));
    }
    // A line wider than the legend is cut at its edge: each is wrapped at words instead.
    lines.into_iter().flat_map(wrapped).collect()
}

/// `line` as lines that each fit in the legend's width, broken at spaces.
fn wrapped(line: LabelLine) -> Vec<LabelLine> {
    let room = LEGEND_WIDTH - 12.0;
    if !line.stops.is_empty() || text_width(&line.text, FONT_SIZE, line.bold) <= room {
        return vec![line];
    }
    let mut pieces: Vec<String> = Vec::new();
    for word in line.text.split(' ') {
        match pieces.last_mut() {
            Some(last) if text_width(&format!("{last} {word}"), FONT_SIZE, line.bold) <= room => {
                last.push(' ');
                last.push_str(word);
            }
            _ => pieces.push(word.to_string()),
        }
    }
    pieces
        .into_iter()
        .map(|text| LabelLine {
            text,
            stops: Vec::new(),
            ..line
        })
        .collect()
}

/// The legend, the scale bar, and `lines`, in a panel right of the plot.
fn legend_panel(svg: &mut String, scene: &Scene<'_>, frame: &Frame, x: f64, lines: &[LabelLine]) {
    let _ = write!(
        svg,
        r#"<g id="legend"><text x="{x}" y="{TOP}" font-size="14" font-weight="bold" fill="{TEXT_COLOUR}">Legend</text>"#
    );
    let rows = if scene.map.is_some() {
        LEGEND_ROWS.len()
    } else {
        LEGEND_ROWS.len() - 1
    };
    for (row, text) in LEGEND_ROWS.iter().take(rows).enumerate() {
        let y = TOP + 24.0 + row as f64 * 24.0;
        let (cx, cy) = (x + 12.0, y - 4.0);
        let mark = match row {
            0 | 1 => {
                let colour = if row == 0 {
                    POSE_COLOUR
                } else {
                    UNVISITED_COLOUR
                };
                format!(
                    r#"<g transform="translate({:.1} {cy:.1})" fill="{colour}" stroke="{colour}"><circle r="4.5" stroke="none"/><path d="M0 0 H14" stroke-width="3"/><path d="M12 -6 L22 0 L12 6 Z" stroke="none"/></g>"#,
                    cx - 8.0
                )
            }
            2 => format!(
                r#"<circle cx="{cx:.1}" cy="{cy:.1}" r="8" fill="none" stroke="{START_COLOUR}" stroke-width="3"/>"#
            ),
            3 => format!(
                r#"<circle cx="{cx:.1}" cy="{cy:.1}" r="{BADGE_RADIUS}" fill="{PATH_COLOUR}"/><text x="{cx:.1}" y="{:.1}" text-anchor="middle" font-size="10" font-weight="bold" fill="white">2</text>"#,
                cy + 3.5
            ),
            4 => format!(
                r#"<g stroke="{PATH_COLOUR}" fill="{PATH_COLOUR}"><line x1="{:.1}" y1="{cy:.1}" x2="{:.1}" y2="{cy:.1}" stroke-width="2.5"/><path d="M-6 -5 L6 0 L-6 5 Z" stroke="none" transform="translate({cx:.1} {cy:.1})"/></g>"#,
                cx - 12.0,
                cx + 12.0
            ),
            5 => format!(
                r#"<g stroke="{TARGET_COLOUR}"><line x1="{:.1}" y1="{cy:.1}" x2="{:.1}" y2="{cy:.1}" stroke-width="1.5" stroke-dasharray="5 4"/><circle cx="{:.1}" cy="{cy:.1}" r="6" fill="white" stroke-width="2"/></g>"#,
                cx - 14.0,
                cx + 4.0,
                cx + 6.0
            ),
            6 => format!(
                r#"<circle cx="{cx:.1}" cy="{cy:.1}" r="8" fill="none" stroke="{FINDING_COLOUR}" stroke-width="2"/>"#
            ),
            _ => format!(
                r#"<circle cx="{cx:.1}" cy="{cy:.1}" r="9" fill="{POSE_COLOUR}" fill-opacity="0.12" stroke="{POSE_COLOUR}" stroke-opacity="0.45"/>"#
            ),
        };
        let _ = write!(
            svg,
            r#"{mark}<text x="{:.1}" y="{y:.1}" fill="{TEXT_COLOUR}">{text}</text>"#,
            x + 34.0
        );
    }
    let bar_y = TOP + 24.0 + rows as f64 * 24.0 + 8.0;
    scale_bar(svg, frame, x, bar_y);
    for (row, line) in lines.iter().enumerate() {
        text_line(svg, x, bar_y + 48.0 + row as f64 * LINE_HEIGHT, line);
    }
    svg.push_str("</g>");
}

/// A bar of a round number of metres, with 0, its middle and its end marked.
fn scale_bar(svg: &mut String, frame: &Frame, x: f64, y: f64) {
    let metres_long = frame.scale_bar();
    let length = metres_long * frame.scale;
    let _ = write!(
        svg,
        r##"<g id="scale-bar" data-metres="{}" data-pixels="{length:.1}"><rect x="{x:.1}" y="{y:.1}" width="{:.1}" height="6" fill="#222222"/><rect x="{:.1}" y="{y:.1}" width="{:.1}" height="6" fill="white" stroke="#222222"/><g fill="{TEXT_COLOUR}" font-size="11" text-anchor="middle"><text x="{x:.1}" y="{:.1}">0</text><text x="{:.1}" y="{:.1}">{}</text><text x="{:.1}" y="{:.1}">{} m</text></g></g>"##,
        metres(metres_long),
        length / 2.0,
        x + length / 2.0,
        length / 2.0,
        y + 20.0,
        x + length / 2.0,
        y + 20.0,
        metres(metres_long / 2.0),
        x + length,
        y + 20.0,
        metres(metres_long)
    );
}
