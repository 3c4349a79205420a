//! Where labels go: each in the first place around its point that covers nothing drawn
//! or labelled before it, and stays on the drawing.

/// A rectangle in pixels.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rect {
    pub x: f64,
    pub y: f64,
    pub width: f64,
    pub height: f64,
}

impl Rect {
    pub fn new(x: f64, y: f64, width: f64, height: f64) -> Rect {
        Rect {
            x,
            y,
            width,
            height,
        }
    }

    /// A square of side `2 × half` around (`x`, `y`).
    pub fn around((x, y): (f64, f64), half: f64) -> Rect {
        Rect::new(x - half, y - half, 2.0 * half, 2.0 * half)
    }

    /// The smallest rectangle holding the segment from `a` to `b`, grown by `pad`.
    pub fn of_segment(a: (f64, f64), b: (f64, f64), pad: f64) -> Rect {
        let (x0, y0) = (a.0.min(b.0), a.1.min(b.1));
        Rect::new(
            x0 - pad,
            y0 - pad,
            (a.0 - b.0).abs() + 2.0 * pad,
            (a.1 - b.1).abs() + 2.0 * pad,
        )
    }

    pub fn right(&self) -> f64 {
        self.x + self.width
    }

    pub fn bottom(&self) -> f64 {
        self.y + self.height
    }

    /// The area the two share.
    pub fn overlap(&self, other: &Rect) -> f64 {
        let width = self.right().min(other.right()) - self.x.max(other.x);
        let height = self.bottom().min(other.bottom()) - self.y.max(other.y);
        width.max(0.0) * height.max(0.0)
    }

    /// Whether `other` lies wholly inside this rectangle.
    pub fn holds(&self, other: &Rect) -> bool {
        other.x >= self.x
            && other.y >= self.y
            && other.right() <= self.right()
            && other.bottom() <= self.bottom()
    }

    /// The point of this rectangle nearest to `point`.
    pub fn nearest_to(&self, (x, y): (f64, f64)) -> (f64, f64) {
        (
            x.clamp(self.x, self.right()),
            y.clamp(self.y, self.bottom()),
        )
    }
}

/// Places labels among what is drawn already.
#[derive(Debug)]
pub struct Placer {
    /// Where labels may go.
    bounds: Rect,
    taken: Vec<Rect>,
}

/// How far from its point a label is tried, in pixels, nearest first.
const DISTANCES: [f64; 6] = [10.0, 24.0, 48.0, 80.0, 120.0, 170.0];

impl Placer {
    pub fn new(bounds: Rect) -> Placer {
        Placer {
            bounds,
            taken: Vec::new(),
        }
    }

    /// Marks `rect` as drawn on: labels avoid it.
    pub fn take(&mut self, rect: Rect) {
        self.taken.push(rect);
    }

    /// The place for a label of `width` × `height` about `point`: to its right, left,
    /// below, above or on a diagonal, nearest first; the first that covers nothing and stays
    /// in bounds, else the one that covers least. The place is then taken.
    pub fn place(&mut self, point: (f64, f64), width: f64, height: f64) -> Rect {
        let (x, y) = point;
        let mut best: Option<(f64, Rect)> = None;
        'search: for distance in DISTANCES {
            let d = distance;
            for (cx, cy) in [
                (x + d, y - height / 2.0),
                (x - d - width, y - height / 2.0),
                (x + d, y + d),
                (x + d, y - d - height),
                (x - d - width, y + d),
                (x - d - width, y - d - height),
                (x - width / 2.0, y + d),
                (x - width / 2.0, y - d - height),
            ] {
                let candidate = Rect::new(cx, cy, width, height);
                let cost = self.cost(&candidate);
                if best.is_none_or(|(least, _)| cost < least) {
                    best = Some((cost, candidate));
                }
                if cost == 0.0 {
                    break 'search;
                }
            }
        }
        let (_, place) = best.unwrap_or((0.0, Rect::new(x, y, width, height)));
        self.taken.push(place);
        place
    }

    /// What placing `rect` would cover: the area of what is drawn under it, and (dearer)
    /// the area off the drawing.
    fn cost(&self, rect: &Rect) -> f64 {
        let covered: f64 = self.taken.iter().map(|taken| rect.overlap(taken)).sum();
        let off_bounds = if self.bounds.holds(rect) {
            0.0
        } else {
            rect.width * rect.height - rect.overlap(&self.bounds)
        };
        covered + 4.0 * off_bounds
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn labels_go_where_nothing_is() {
        let mut placer = Placer::new(Rect::new(0.0, 0.0, 400.0, 400.0));
        let first = placer.place((200.0, 200.0), 100.0, 20.0);
        assert_eq!(first, Rect::new(210.0, 190.0, 100.0, 20.0), "to the right");
        let second = placer.place((200.0, 200.0), 100.0, 20.0);
        assert_eq!(
            second,
            Rect::new(90.0, 190.0, 100.0, 20.0),
            "then to the left"
        );
        let edge = placer.place((395.0, 50.0), 100.0, 20.0);
        assert!(edge.right() <= 400.0, "kept on the drawing: {edge:?}");
        assert_eq!(first.overlap(&edge) + second.overlap(&edge), 0.0);
    }
}
