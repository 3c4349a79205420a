//! The map's occupancy image (`environmentMap.png`): white is free floor, black is occupied.
//!
//! The lab's image also carries a drawn "Origin" legend in its bottom-left corner (two axes,
//! "X (forward)", "Y (left)", "Origin"), which is not an obstacle. The map generator writes
//! occupied cells black (0) and free cells white (255); the legend is drawn in greys (76 and
//! 150) and white. So a pixel is occupied only when it is near black, darker than
//! [`OCCUPIED_BELOW`]: where the legend crosses the floor (its grey "t)" of "Y (left)" at
//! x 0.81–0.85 m) it is free, as the floor under it is. Where the legend is drawn on a wall,
//! it leaves grey and white holes in the wall; the black around them, and the wall's
//! rectangle in `obstacles.dat`, still keep every pose there within the robot's radius of
//! an obstacle.

use std::path::{Path, PathBuf};

use super::MapError;

/// A pixel darker than this (0 black, 255 white) is occupied: black, not the legend's greys.
pub const OCCUPIED_BELOW: u8 = 64;

/// The most bytes decoding an image may use (a 680 × 993 map needs under 1 MB).
const DECODE_LIMIT_BYTES: usize = 256 << 20;

/// The most pixels a map image may have: 4096 × 4096, 24 times the lab's 680 × 993 (a
/// 200 × 200 m floor at 5 cm a pixel). Checked from the header, before anything is
/// allocated: a small PNG can declare 40,000 × 40,000 pixels (1.6 GB once decoded).
pub const MAX_PIXELS: u64 = 4096 * 4096;

/// An occupancy image, as grey levels (composited on white where it is transparent).
#[derive(Debug, Clone, PartialEq)]
pub struct Occupancy {
    pub path: PathBuf,
    /// Pixels.
    pub width: usize,
    pub height: usize,
    /// Row by row from the top, one grey level per pixel.
    pub grey: Vec<u8>,
    /// The file's bytes, to embed in a drawing as they are.
    pub png: Vec<u8>,
}

/// An occupied pixel, by column and row from the top-left corner.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Pixel {
    pub column: usize,
    pub row: usize,
}

impl Occupancy {
    /// Reads and decodes the PNG at `path`; `named_by` says which file and line named it.
    pub fn read(path: &Path, named_by: Option<&str>) -> Result<Occupancy, MapError> {
        let png = crate::open::read_regular(path)
            .map_err(|e| MapError::cannot_read(path, &e, named_by))?;
        let (width, height, grey) = decode(&png).map_err(|refusal| match refusal {
            Refusal::Unreadable(reason) => MapError(format!(
                "{}: not a PNG image that ekb can read ({reason}); the map must be a PNG (white free, black occupied)",
                path.display()
            )),
            Refusal::TooLarge { width, height } => MapError(format!(
                "{}: the image declares {width} × {height} pixels, past ekb's cap of {MAX_PIXELS} \
                 pixels (4096 × 4096) for a map image; nothing was decoded: scale the map down \
                 (the lab's is 680 × 993)",
                path.display()
            )),
        })?;
        Ok(Occupancy {
            path: path.to_path_buf(),
            width,
            height,
            grey,
            png,
        })
    }

    pub fn is_occupied(&self, pixel: Pixel) -> bool {
        self.grey[pixel.row * self.width + pixel.column] < OCCUPIED_BELOW
    }

    /// The occupied pixel nearest to (`x`, `y`) within `radius`, all in pixels, measured to
    /// the nearest point of each pixel's square; `y` counts from the top.
    pub fn occupied_within(&self, x: f64, y: f64, radius: f64) -> Option<Pixel> {
        let rows = pixel_range(y - radius, y + radius, self.height)?;
        let mut nearest: Option<(f64, Pixel)> = None;
        for row in rows {
            let dy = axis_distance(y, row);
            if dy > radius {
                continue;
            }
            let half_width = (radius * radius - dy * dy).sqrt();
            let Some(columns) = pixel_range(x - half_width, x + half_width, self.width) else {
                continue;
            };
            let line = &self.grey[row * self.width..][columns.clone()];
            // Most rows are free: look for an occupied pixel first, then for the nearest.
            if !line.iter().any(|&grey| grey < OCCUPIED_BELOW) {
                continue;
            }
            for column in columns {
                let pixel = Pixel { column, row };
                let distance = axis_distance(x, column).hypot(dy);
                if self.is_occupied(pixel) && nearest.is_none_or(|(d, _)| distance < d) {
                    nearest = Some((distance, pixel));
                }
            }
        }
        nearest.map(|(_, pixel)| pixel)
    }
}

/// The pixels (of `0..count`) whose extent meets `from..=to`, if any.
fn pixel_range(from: f64, to: f64, count: usize) -> Option<std::ops::Range<usize>> {
    if !(to >= 0.0 && from <= count as f64) {
        return None;
    }
    let first = from.max(0.0).floor() as usize;
    let end = (to.min(count as f64).ceil() as usize)
        .max(first + 1)
        .min(count);
    (first < end).then_some(first..end)
}

/// How far `at` is from the pixel `index` (which spans `index..index + 1`) along one axis.
fn axis_distance(at: f64, index: usize) -> f64 {
    let start = index as f64;
    (start - at).max(at - (start + 1.0)).max(0.0)
}

/// Why an image was not decoded.
#[derive(Debug)]
enum Refusal {
    Unreadable(String),
    /// More than [`MAX_PIXELS`], or more decoded bytes than [`DECODE_LIMIT_BYTES`].
    TooLarge {
        width: u32,
        height: u32,
    },
}

/// The width, height and grey levels of a PNG image.
fn decode(png: &[u8]) -> Result<(usize, usize, Vec<u8>), Refusal> {
    let unreadable = |e: png::DecodingError| Refusal::Unreadable(e.to_string());
    let limits = png::Limits {
        bytes: DECODE_LIMIT_BYTES,
    };
    let mut decoder = png::Decoder::new_with_limits(std::io::Cursor::new(png), limits);
    decoder.set_transformations(png::Transformations::normalize_to_color8());
    let mut reader = decoder.read_info().map_err(unreadable)?;
    let (width, height) = (reader.info().width, reader.info().height);
    let too_large = Refusal::TooLarge { width, height };
    if u64::from(width) * u64::from(height) > MAX_PIXELS {
        return Err(too_large);
    }
    let size = match reader.output_buffer_size() {
        Some(size) if size <= DECODE_LIMIT_BYTES => size,
        _ => return Err(too_large),
    };
    let mut buffer = vec![0; size];
    let frame = reader.next_frame(&mut buffer).map_err(unreadable)?;
    let (width, height) = (frame.width as usize, frame.height as usize);
    let channels = frame.color_type.samples();
    let bytes = &buffer[..frame.buffer_size()];
    let mut grey = Vec::with_capacity(width * height);
    for row in bytes.chunks(frame.line_size).take(height) {
        let row = &row[..width * channels];
        if channels == 1 {
            // The robot's maps are grey already: one copy per row.
            grey.extend_from_slice(row);
        } else {
            grey.extend(row.chunks_exact(channels).map(grey_on_white));
        }
    }
    Ok((width, height, grey))
}

/// The grey level of one pixel (grey, grey and alpha, RGB or RGBA), laid on white.
fn grey_on_white(pixel: &[u8]) -> u8 {
    let (grey, alpha) = match *pixel {
        [grey] => (u32::from(grey), 255),
        [grey, alpha] => (u32::from(grey), u32::from(alpha)),
        [r, g, b] => (luminance(r, g, b), 255),
        [r, g, b, alpha, ..] => (luminance(r, g, b), u32::from(alpha)),
        [] => (255, 255),
    };
    ((grey * alpha + 255 * (255 - alpha) + 127) / 255) as u8
}

/// Rec. 601 luma, in integers: 0.299 R + 0.587 G + 0.114 B.
fn luminance(r: u8, g: u8, b: u8) -> u32 {
    (299 * u32::from(r) + 587 * u32::from(g) + 114 * u32::from(b) + 500) / 1000
}

#[cfg(test)]
mod tests {
    use super::*;

    fn image(rows: &[&str]) -> Occupancy {
        let grey = rows
            .iter()
            .flat_map(|row| row.bytes().map(|b| if b == b'#' { 0 } else { 255 }))
            .collect();
        Occupancy {
            path: PathBuf::from("test.png"),
            width: rows[0].len(),
            height: rows.len(),
            grey,
            png: Vec::new(),
        }
    }

    #[test]
    fn the_nearest_occupied_pixel_within_a_radius() {
        let map = image(&["#.....", "......", "....#."]);
        // (2.7, 1.5) is 1.77 from pixel (0, 0) and 1.39 from pixel (4, 2).
        assert_eq!(map.occupied_within(2.7, 1.5, 1.3), None);
        assert_eq!(
            map.occupied_within(2.7, 1.5, 1.8),
            Some(Pixel { column: 4, row: 2 })
        );
        assert_eq!(
            map.occupied_within(0.5, 0.5, 0.0),
            Some(Pixel { column: 0, row: 0 })
        );
        assert_eq!(map.occupied_within(-10.0, 1.0, 2.0), None);
        assert_eq!(map.occupied_within(f64::NAN, 1.0, 2.0), None);
    }

    #[test]
    fn greys_are_free_and_transparency_is_white() {
        assert_eq!(grey_on_white(&[0]), 0);
        assert_eq!(grey_on_white(&[0, 0]), 255);
        assert_eq!(grey_on_white(&[255, 0, 0, 255]), 76);
        assert!(
            grey_on_white(&[76]) >= OCCUPIED_BELOW,
            "the legend's dark grey"
        );
    }
}
