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
        let paint = PixmapPaint {
            quality: FilterQuality::Nearest,
            ..PixmapPaint::default()
        };
        let transform =
            Transform::from_row(scale_x as f32, 0.0, 0.0, scale_y as f32, x as f32, y as f32);
        pixmap.draw_pixmap(0, 0, faded(image)?.as_ref(), &paint, transform, None);
    }
    resvg::render(&tree, Transform::identity(), &mut pixmap.as_mut());
    let png = pixmap
        .encode_png()
        .map_err(|e| format!("cannot encode the PNG: {e}"))?;
    Ok(Rendered { png, warnings })
}

/// The map's image as the SVG shows it: its grey levels laid on white at [`MAP_OPACITY`].
fn faded(image: &crate::map::Occupancy) -> Result<Pixmap, String> {
    let mut pixmap =
        Pixmap::new(image.width as u32, image.height as u32).ok_or("the map's image is empty")?;
    for (pixel, &grey) in pixmap.pixels_mut().iter_mut().zip(&image.grey) {
        let level = (255.0 - (255.0 - f64::from(grey)) * MAP_OPACITY).round() as u8;
        *pixel = tiny_skia::ColorU8::from_rgba(level, level, level, 255).premultiply();
    }
    Ok(pixmap)
}
