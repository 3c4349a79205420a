//! The drawing as PNG, rendered by `resvg` from the SVG; the map's image is painted
//! beneath it directly, pixel for pixel, rather than embedded and decoded again.
//!
//! Text needs a font: the system's fonts are loaded (`fontdb`); DejaVu Sans, which the
//! SVG asks for first, is in Debian's `fonts-dejavu-core`.

use resvg::tiny_skia::{self, FilterQuality, Pixmap, PixmapPaint, Transform};
use resvg::usvg;

use super::svg::{self, MapImage, MAP_OPACITY};
use super::Scene;

/// A PNG, and what the user should know about it.
#[derive(Debug)]
pub struct Rendered {
    pub png: Vec<u8>,
    pub warnings: Vec<String>,
}

/// Renders `scene` as a PNG image.
pub fn render(scene: &Scene<'_>) -> Result<Rendered, String> {
    let drawing = svg::draw(scene, MapImage::PaintedBeneath);
    let mut options = usvg::Options::default();
    options.fontdb_mut().load_system_fonts();
    let mut warnings = Vec::new();
    if options.fontdb.is_empty() {
        warnings.push(
            "no fonts found: the PNG has no text; install one (Debian: apt-get install fonts-dejavu-core), or write SVG".to_string(),
        );
    }
    let tree = usvg::Tree::from_str(&drawing.svg, &options)
        .map_err(|e| format!("cannot render the drawing: {e}"))?;
    let (width, height) = (drawing.width as u32, drawing.height as u32);
    let mut pixmap = Pixmap::new(width, height)
        .ok_or_else(|| format!("cannot render a {width} × {height} image"))?;
    pixmap.fill(tiny_skia::Color::WHITE);
    if let (Some(map), Some(image)) = (scene.map, scene.map.and_then(|m| m.image.as_ref())) {
        let frame = drawing.frame;
        let (x, y) = frame.px(0.0, map.height);
        let scale_x = map.width * frame.scale / image.width as f64;
        let scale_y = map.height * frame.scale / image.height as f64;
        let faded = faded(image)?;
        let whole_pixels = x.fract() == 0.0 && y.fract() == 0.0 && x >= 0.0 && y >= 0.0;
        if scale_x == 1.0 && scale_y == 1.0 && whole_pixels {
            // The usual case (a pixel of the map per pixel of the drawing): copy the rows.
            copy(&faded, &mut pixmap, x as usize, y as usize);
        } else {
            let paint = PixmapPaint {
                quality: FilterQuality::Nearest,
                ..PixmapPaint::default()
            };
            let transform =
                Transform::from_row(scale_x as f32, 0.0, 0.0, scale_y as f32, x as f32, y as f32);
            pixmap.draw_pixmap(0, 0, faded.as_ref(), &paint, transform, None);
        }
    }
    resvg::render(&tree, Transform::identity(), &mut pixmap.as_mut());
    let png = encode(&pixmap).map_err(|e| format!("cannot encode the PNG: {e}"))?;
    Ok(Rendered { png, warnings })
}

/// `pixmap` (opaque: it starts white) as an RGB PNG, compressed fast: tiny-skia's own
/// encoder spends several times as long on RGBA at the default level, for a slightly
/// smaller file.
fn encode(pixmap: &Pixmap) -> Result<Vec<u8>, png::EncodingError> {
    let rgb: Vec<u8> = pixmap
        .pixels()
        .iter()
        .flat_map(|pixel| [pixel.red(), pixel.green(), pixel.blue()])
        .collect();
    let mut png = Vec::new();
    let mut encoder = png::Encoder::new(&mut png, pixmap.width(), pixmap.height());
    encoder.set_color(png::ColorType::Rgb);
    encoder.set_depth(png::BitDepth::Eight);
    encoder.set_compression(png::Compression::Fast);
    // Each row against the one above: the drawing is mostly flat colour, and trying every
    // filter on every row (the default) costs more than the compression it buys.
    encoder.set_filter(png::Filter::Up);
    let mut writer = encoder.write_header()?;
    writer.write_image_data(&rgb)?;
    writer.finish()?;
    Ok(png)
}

/// Copies `from` into `to` with its top-left corner at (`x`, `y`), as far as `to` reaches.
fn copy(from: &Pixmap, to: &mut Pixmap, x: usize, y: usize) {
    let (from_width, to_width) = (from.width() as usize, to.width() as usize);
    let width = from_width.min(to_width.saturating_sub(x));
    let rows = from.pixels().chunks(from_width);
    let to_rows = to.pixels_mut().chunks_mut(to_width).skip(y);
    for (from_row, to_row) in rows.zip(to_rows) {
        to_row[x..x + width].copy_from_slice(&from_row[..width]);
    }
}

/// The map's image as the SVG shows it: its grey levels laid on white at [`MAP_OPACITY`].
fn faded(image: &crate::map::Occupancy) -> Result<Pixmap, String> {
    let mut pixmap =
        Pixmap::new(image.width as u32, image.height as u32).ok_or("the map's image is empty")?;
    // 256 grey levels: each computed once, not once per pixel.
    let faded: Vec<tiny_skia::PremultipliedColorU8> = (0..=255u8)
        .map(|grey| {
            let level = (255.0 - (255.0 - f64::from(grey)) * MAP_OPACITY).round() as u8;
            tiny_skia::ColorU8::from_rgba(level, level, level, 255).premultiply()
        })
        .collect();
    for (pixel, &grey) in pixmap.pixels_mut().iter_mut().zip(&image.grey) {
        *pixel = faded[usize::from(grey)];
    }
    Ok(pixmap)
}
