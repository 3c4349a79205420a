//! `ekb map [FILE] [-o tour.svg|tour.png]`: the tour on the lab map (SPEC §10), and the
//! map options that `check` and `report` share.

use std::io::{IsTerminal, Write};
use std::path::{Path, PathBuf};

use super::{CommandError, CommandResult, Context, Exit};
use crate::check::{check_on_map, Checked};
use crate::draw::{self, svg::MapImage, Scene};
use crate::map::LabMap;
use crate::model::build::Options;
use crate::present;
use crate::reader::{self, Loaded};
use crate::render::escape::escape;
use crate::rules::selection::{Choice, RuleSet};
use crate::source::SourceFile;
use crate::stderr_line;

/// Where the lab map comes from: `check`, `map` and `report` take these.
#[derive(Debug, Clone, Default, clap::Args)]
pub struct MapArgs {
    /// The robot's mapGenerationConfiguration.ini: check poses against its map and draw on it
    #[arg(long, value_name = "PATH", conflicts_with = "map_image")]
    pub map_config: Option<PathBuf>,

    /// A map image instead (PNG: white free, black occupied), with --map-size; the robot's
    /// radius is taken as 0.3 m
    #[arg(long, value_name = "PNG", requires = "map_size")]
    pub map_image: Option<PathBuf>,

    /// The map image's width and height, in metres
    #[arg(long, num_args = 2, value_names = ["W", "H"], requires = "map_image", allow_negative_numbers = true)]
    pub map_size: Option<Vec<f64>>,
}

impl MapArgs {
    /// The map: the command line's, else the `mapGenerationConfiguration.ini` that
    /// `settings_map_config` names (`[map] config` of `ekb.toml`, resolved by the caller),
    /// else none.
    pub fn load(
        &self,
        settings_map_config: Option<PathBuf>,
    ) -> Result<Option<LabMap>, CommandError> {
        let failed = |error: crate::map::MapError| CommandError::Failed(error.to_string());
        if let (Some(image), Some(size)) = (&self.map_image, &self.map_size) {
            let (width, height) = (size.first().copied(), size.get(1).copied());
            let (Some(width), Some(height)) = (width, height) else {
                return Err(CommandError::Failed(
                    "--map-size takes two numbers: the width and the height in metres".to_string(),
                ));
            };
            return LabMap::from_image(image, width, height)
                .map(Some)
                .map_err(failed);
        }
        let Some(config) = self.map_config.clone().or(settings_map_config) else {
            return Ok(None);
        };
        let map = LabMap::from_config(&config).map_err(failed)?;
        for warning in &map.warnings {
            stderr_line!("ekb: warning: {}", crate::render::escape::escape(warning));
        }
        Ok(Some(map))
    }
}

#[derive(Debug, clap::Args)]
pub struct Args {
    /// Knowledge-base file (`-` for standard input) [default: the configured knowledgeBase]
    #[arg(value_name = "FILE")]
    pub file: Option<PathBuf>,

    /// Write the drawing to this file: SVG, or PNG if it ends in `.png` [default: SVG on
    /// standard output]
    #[arg(short, long, value_name = "OUT")]
    pub output: Option<PathBuf>,

    /// The drawing's format [default: from OUT's extension, else svg]
    #[arg(long, value_enum, value_name = "FORMAT")]
    pub format: Option<PictureFormat>,

    #[command(flatten)]
    pub map: MapArgs,
}

/// `ekb map --format`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum PictureFormat {
    /// Scalable, self-contained, with selectable text
    Svg,
    /// A raster image, rendered with resvg
    Png,
}

impl PictureFormat {
    /// The format `output`'s extension names: PNG for `.png`, else SVG.
    fn of(output: Option<&Path>) -> PictureFormat {
        let png = output
            .and_then(Path::extension)
            .is_some_and(|extension| extension.eq_ignore_ascii_case("png"));
        if png {
            PictureFormat::Png
        } else {
            PictureFormat::Svg
        }
    }
}

pub fn run(args: &Args, context: &Context) -> CommandResult {
    let format = args
        .format
        .unwrap_or(PictureFormat::of(args.output.as_deref()));
    let output = args
        .output
        .as_deref()
        .filter(|path| *path != Path::new("-"));
    if output.is_none() && format == PictureFormat::Png && std::io::stdout().is_terminal() {
        return Err(CommandError::Failed(
            "a PNG is no text for a terminal: give -o tour.png, or redirect standard output"
                .to_string(),
        ));
    }
    let input = MapInput::read(args.file.as_deref(), &args.map, context)?;
    let (checked, loaded) = input.check(context.quiet);
    let scene = Scene::new(&checked, &loaded, input.map.as_ref());
    let bytes = match format {
        PictureFormat::Svg => draw::svg::draw(&scene, MapImage::Embedded).svg.into_bytes(),
        PictureFormat::Png => {
            let rendered = draw::png::render(&scene).map_err(CommandError::Failed)?;
            for warning in &rendered.warnings {
                stderr_line!("ekb: warning: {warning}");
            }
            rendered.png
        }
    };
    write_result(output, &bytes, context)?;
    Ok(Exit::Clean)
}

/// What `map` and `report` work on: a knowledge base, how to read it, the rules its
/// settings choose (as `ekb check` runs them), and the map.
pub struct MapInput {
    pub source: SourceFile,
    pub options: Options,
    pub rules: RuleSet,
    pub map: Option<LabMap>,
}

impl MapInput {
    /// Reads `file` (else the configured knowledge base) and the map of `map_args`.
    pub fn read(
        file: Option<&Path>,
        map_args: &MapArgs,
        context: &Context,
    ) -> Result<MapInput, CommandError> {
        let path = context.input(file)?;
        let options = context.read_options(&path)?;
        let rules = context.rules_for(&path, &Choice::default())?;
        let map_config = context.settings_for(&path)?.map.config;
        let map = map_args.load(map_config.map(|config| config.value))?;
        let source = context.read_to_report(&path)?;
        Ok(MapInput {
            source,
            options,
            rules,
            map,
        })
    }

    /// The file checked (with the map rules), and loaded as its reader loads it; unless
    /// `quiet`, a note on standard error if it has errors.
    pub fn check(&self, quiet: bool) -> (Checked<'_>, Loaded<'_>) {
        let map = self.map.as_ref();
        let checked = check_on_map(&self.source, &self.options, &self.rules, map);
        let loaded = reader::load(self.source.text().as_bytes(), checked.reader);
        present::note_errors(&checked, quiet);
        (checked, loaded)
    }
}

/// Writes `bytes` to `output` or standard output, and says where unless `--quiet`.
pub fn write_result(
    output: Option<&Path>,
    bytes: &[u8],
    context: &Context,
) -> Result<(), CommandError> {
    write_output(output, bytes)?;
    if let (Some(path), false) = (output, context.quiet) {
        stderr_line!("ekb: wrote {}", escape(&path.display().to_string()));
    }
    Ok(())
}

/// Writes `bytes` to `output` (atomically: a temporary file, then a rename), or to standard
/// output.
pub fn write_output(output: Option<&Path>, bytes: &[u8]) -> Result<(), CommandError> {
    match output {
        Some(path) => Ok(crate::write::write_atomically(path, bytes)?),
        None => {
            let mut stdout = std::io::stdout().lock();
            stdout.write_all(bytes)?;
            Ok(stdout.flush()?)
        }
    }
}
