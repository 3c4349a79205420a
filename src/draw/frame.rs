//! Where the world (metres, y up) goes on the drawing (pixels, y down).

use super::Scene;
use crate::present::Gesture;

/// The largest side of the plot, in pixels.
const MAX_PLOT_PIXELS: f64 = 1000.0;

/// How far past a map's edge the drawing reaches to show a point off the map; points
/// farther away are drawn pinned to the drawing's edge.
const SHOWN_OFF_MAP: f64 = 3.0;

/// Without a map, how far from the origin the drawing reaches (metres).
const SHOWN_WITHOUT_MAP: f64 = 1.0e6;

/// The metres drawn, and how they map to pixels.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Frame {
    pub x0: f64,
    pub x1: f64,
    pub y0: f64,
    pub y1: f64,
    /// Pixels per metre.
    pub scale: f64,
    /// The pixel position of the plot's top-left corner, (`x0`, `y1`).
    pub left: f64,
    pub top: f64,
}

impl Frame {
    /// The frame that shows the map (if any) and every pose and gesture target of `scene`,
    /// with its top-left corner at (`left`, `top`) pixels.
    pub fn fit(scene: &Scene<'_>, left: f64, top: f64) -> Frame {
        let points = scene.spots.iter().flat_map(|spot| {
            let target = match spot.gesture {
                Gesture::At(t) | Gesture::Skipped(t) => Some((t.x, t.y)),
                Gesture::None => None,
            };
            [Some((spot.pose.x, spot.pose.y)), target]
                .into_iter()
                .flatten()
        });
        let points: Vec<(f64, f64)> = points
            .filter(|(x, y)| x.is_finite() && y.is_finite())
            .collect();
        let (x0, x1, y0, y1) = match scene.map {
            Some(map) => {
                let limits = (
                    -SHOWN_OFF_MAP,
                    map.width + SHOWN_OFF_MAP,
                    -SHOWN_OFF_MAP,
                    map.height + SHOWN_OFF_MAP,
                );
                let (bx0, bx1, by0, by1) = bounds(&points, limits);
                // A point off the map gets some room around it; the map keeps its edges.
                let pad = |inner: f64, outer: f64, beyond: bool| if beyond { outer } else { inner };
                (
                    pad(0.0, (bx0 - 0.5).max(limits.0), bx0 < 0.0),
                    pad(map.width, (bx1 + 0.5).min(limits.1), bx1 > map.width),
                    pad(0.0, (by0 - 0.5).max(limits.2), by0 < 0.0),
                    pad(map.height, (by1 + 0.5).min(limits.3), by1 > map.height),
                )
            }
            None => {
                let far = SHOWN_WITHOUT_MAP;
                let (bx0, bx1, by0, by1) = if points.is_empty() {
                    (0.0, 0.0, 0.0, 0.0)
                } else {
                    bounds(&points, (-far, far, -far, far))
                };
                let (x0, x1) = widen((bx0 - 1.0).floor(), (bx1 + 1.0).ceil());
                let (y0, y1) = widen((by0 - 1.0).floor(), (by1 + 1.0).ceil());
                (x0, x1, y0, y1)
            }
        };
        let scale = nice_at_most(MAX_PLOT_PIXELS / (x1 - x0).max(y1 - y0));
        Frame {
            x0,
            x1,
            y0,
            y1,
            scale,
            left,
            top,
        }
    }

    /// The pixel of (`x`, `y`), wherever it is.
    pub fn px(&self, x: f64, y: f64) -> (f64, f64) {
        (
            self.left + (x - self.x0) * self.scale,
            self.top + (self.y1 - y) * self.scale,
        )
    }

    /// The pixel of (`x`, `y`) pinned to the plot's edge if it is off the plot, and whether
    /// it was; `None` if a coordinate is not a finite number.
    pub fn pinned(&self, x: f64, y: f64) -> Option<((f64, f64), bool)> {
        if !(x.is_finite() && y.is_finite()) {
            return None;
        }
        let (cx, cy) = (x.clamp(self.x0, self.x1), y.clamp(self.y0, self.y1));
        Some((self.px(cx, cy), (cx, cy) != (x, y)))
    }

    pub fn width_px(&self) -> f64 {
        (self.x1 - self.x0) * self.scale
    }

    pub fn height_px(&self) -> f64 {
        (self.y1 - self.y0) * self.scale
    }

    /// Metres between grid lines: at least 60 pixels apart.
    pub fn grid_step(&self) -> f64 {
        nice_at_least(60.0 / self.scale)
    }

    /// A scale bar's length in metres: 80 to 200 pixels long.
    pub fn scale_bar(&self) -> f64 {
        nice_at_least(80.0 / self.scale)
    }
}

/// The bounds of `points` (each clamped to `limits`), or `limits`' inner corner if none.
fn bounds(
    points: &[(f64, f64)],
    (lx0, lx1, ly0, ly1): (f64, f64, f64, f64),
) -> (f64, f64, f64, f64) {
    points.iter().fold(
        (
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::INFINITY,
            f64::NEG_INFINITY,
        ),
        |(x0, x1, y0, y1), &(x, y)| {
            let (x, y) = (x.clamp(lx0, lx1), y.clamp(ly0, ly1));
            (x0.min(x), x1.max(x), y0.min(y), y1.max(y))
        },
    )
}

/// `from..to` made at least 4 metres long, around its middle.
fn widen(from: f64, to: f64) -> (f64, f64) {
    let missing = (4.0 - (to - from)).max(0.0);
    (from - (missing / 2.0).ceil(), to + (missing / 2.0).ceil())
}

/// Pixels per metre are one of these × 10ⁿ: finer steps than 1, 2, 5, so that a plot is
/// never much smaller than it can be.
const SCALES: [f64; 10] = [1.0, 1.2, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0, 8.0];

/// Grid steps and scale bars are one of these × 10ⁿ metres.
const STEPS: [f64; 3] = [1.0, 2.0, 5.0];

/// The largest of `SCALES` × 10ⁿ at most `value` (`value` positive).
fn nice_at_most(value: f64) -> f64 {
    let power = 10f64.powi(value.log10().floor() as i32);
    SCALES
        .iter()
        .rev()
        .map(|mantissa| mantissa * power)
        .find(|&n| n <= value)
        .unwrap_or(power)
}

/// The smallest of `STEPS` × 10ⁿ at least `value` (`value` positive).
fn nice_at_least(value: f64) -> f64 {
    let power = 10f64.powi(value.log10().floor() as i32);
    STEPS
        .iter()
        .map(|mantissa| mantissa * power)
        .find(|&n| n >= value)
        .unwrap_or(10.0 * power)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nice_numbers() {
        assert_eq!(nice_at_most(100.7), 100.0);
        assert_eq!(nice_at_most(91.5), 80.0);
        assert_eq!(nice_at_most(0.45), 0.4);
        assert_eq!(nice_at_most(5.0), 5.0);
        assert_eq!(nice_at_least(0.6), 1.0);
        assert_eq!(nice_at_least(1.5), 2.0);
        assert_eq!(nice_at_least(3.0), 5.0);
        assert_eq!(nice_at_least(7.0), 10.0);
    }

    #[test]
    fn short_ranges_are_widened_to_four_metres() {
        assert_eq!(widen(1.0, 2.0), (-1.0, 4.0));
        assert_eq!(widen(-3.0, 9.0), (-3.0, 9.0));
    }
}
