//! `ekb._ekb`: the native part of the Python module `ekb`, a thin face over
//! [`ekb_core::loader`] (SPEC §12, §13).
//!
//! A knowledge base loads exactly as `ekb export` shows it, and a file that `ekb check`
//! finds an error in is refused with the same findings, as a `RefusedError`:
//!
//! ```python
//! import ekb
//! try:
//!     kb = ekb.load("data/environmentKnowledgeBaseInput.dat")
//!     print(kb.location(4).message("pre", "zu"))
//! except ekb.RefusedError as error:
//!     for finding in error.findings:
//!         print(finding)
//! ```
//!
//! The files are read with Python's lock released, so threads may load in parallel.

use std::path::PathBuf;

use ekb_core::settings::Lookup;

use ekb_core::loader::{self, Language, Options, Phase};
use ekb_core::model::export::ExportedLocation;
use ekb_core::present::language;
use ekb_core::robot::Reader;
use pyo3::create_exception;
use pyo3::exceptions::{PyException, PyKeyError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyTuple;

create_exception!(
    ekb,
    LoadError,
    PyException,
    "A knowledge base was not loaded; `findings` tells why (empty when the file could not be read)."
);
create_exception!(
    ekb,
    RefusedError,
    LoadError,
    "The file has an error: the robot would load something other than it says. `findings` has every finding of the check."
);
create_exception!(
    ekb,
    UnreadableError,
    LoadError,
    "The file, or the project settings named by `settings`, could not be read."
);

/// One finding of `ekb check`: 1-based lines and columns (columns count characters), the
/// end exclusive.
#[pyclass(module = "ekb", frozen, eq, get_all)]
#[derive(Clone, PartialEq)]
struct Finding {
    file: String,
    rule: String,
    /// `"error"`, `"warning"` or `"info"`.
    severity: String,
    message: String,
    line: u32,
    column: u32,
    end_line: u32,
    end_column: u32,
    location_id: Option<u32>,
    help: Option<String>,
}

impl From<&loader::Finding> for Finding {
    fn from(finding: &loader::Finding) -> Finding {
        Finding {
            file: finding.file.clone(),
            rule: finding.rule.to_string(),
            severity: finding.severity.name().to_string(),
            message: finding.message.clone(),
            line: finding.line,
            column: finding.column,
            end_line: finding.end_line,
            end_column: finding.end_column,
            location_id: finding.location_id,
            help: finding.help.clone(),
        }
    }
}

#[pymethods]
impl Finding {
    /// Every field, in the order of the class: what `pickle` rebuilds a finding from.
    #[new]
    #[pyo3(signature = (file, rule, severity, message, line, column, end_line, end_column, location_id, help))]
    #[allow(clippy::too_many_arguments)]
    fn new(
        file: String,
        rule: String,
        severity: String,
        message: String,
        line: u32,
        column: u32,
        end_line: u32,
        end_column: u32,
        location_id: Option<u32>,
        help: Option<String>,
    ) -> Finding {
        Finding {
            file,
            rule,
            severity,
            message,
            line,
            column,
            end_line,
            end_column,
            location_id,
            help,
        }
    }

    /// Pickles as its fields (a finding crosses to another process with its exception).
    fn __reduce__<'py>(
        slf: &Bound<'py, Self>,
    ) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyTuple>)> {
        let this = slf.get();
        let fields = (
            this.file.clone(),
            this.rule.clone(),
            this.severity.clone(),
            this.message.clone(),
            this.line,
            this.column,
            this.end_line,
            this.end_column,
            this.location_id,
            this.help.clone(),
        )
            .into_pyobject(slf.py())?;
        Ok((slf.get_type().into_any(), fields))
    }

    /// `file:line:column: severity[rule] message`, as `ekb check --format concise`.
    fn __str__(&self) -> String {
        format!(
            "{}:{}:{}: {}[{}] {}",
            self.file, self.line, self.column, self.severity, self.rule, self.message
        )
    }

    fn __repr__(&self) -> String {
        format!(
            "Finding(rule={:?}, severity={:?}, line={}, column={}, message={:?})",
            self.rule, self.severity, self.line, self.column, self.message
        )
    }
}

/// Where the robot stands, in metres, and the way it faces, in degrees.
#[pyclass(module = "ekb", frozen, eq, get_all)]
#[derive(Clone, PartialEq)]
struct Pose {
    x: f64,
    y: f64,
    theta: f64,
}

#[pymethods]
impl Pose {
    fn __repr__(&self) -> String {
        format!("Pose(x={}, y={}, theta={})", self.x, self.y, self.theta)
    }
}

/// The point the robot gestures at, in metres (`0 0 0`: no gesture).
#[pyclass(module = "ekb", frozen, eq, get_all)]
#[derive(Clone, PartialEq)]
struct Point {
    x: f64,
    y: f64,
    z: f64,
}

#[pymethods]
impl Point {
    fn __repr__(&self) -> String {
        format!("Point(x={}, y={}, z={})", self.x, self.y, self.z)
    }
}

/// One location, as `ekb export` shows it: a field absent from the file is `None`.
#[pyclass(module = "ekb", frozen, eq)]
#[derive(Clone, PartialEq)]
struct Location(ExportedLocation);

#[pymethods]
impl Location {
    #[getter]
    fn id(&self) -> u32 {
        self.0.id
    }

    #[getter]
    fn description(&self) -> Option<&str> {
        self.0.description.as_deref()
    }

    #[getter]
    fn pose(&self) -> Option<Pose> {
        self.0.pose.map(|pose| Pose {
            x: pose.x,
            y: pose.y,
            theta: pose.theta,
        })
    }

    #[getter]
    fn gesture_target(&self) -> Option<Point> {
        self.0.gesture_target.map(|point| Point {
            x: point.x,
            y: point.y,
            z: point.z,
        })
    }

    /// `"left"` or `"right"`; `None` when the file does not say.
    #[getter]
    fn gesture_arm(&self) -> Option<&'static str> {
        self.0.gesture_arm.map(|arm| arm.name())
    }

    #[getter]
    fn cultural_knowledge(&self) -> Vec<String> {
        self.0.cultural_knowledge.clone()
    }

    /// What the robot says before (`phase="pre"`) or after (`"post"`) the gesture, in a
    /// language given as `ekb tour --lang` takes it (`"english"`, `"isizulu"`,
    /// `"kinyarwanda"`, or `"en"`, `"zu"`, `"rw"`); `None` when the file has no such
    /// message.
    fn message(&self, phase: &str, language: &str) -> PyResult<Option<&str>> {
        let messages = match parse_phase(phase)? {
            Phase::Pre => &self.0.pre_gesture_message,
            Phase::Post => &self.0.post_gesture_message,
        };
        let text = match parse_language(language)? {
            Language::English => &messages.english,
            Language::IsiZulu => &messages.isi_zulu,
            Language::Kinyarwanda => &messages.kinyarwanda,
        };
        Ok(text.as_deref())
    }

    fn __repr__(&self) -> String {
        format!(
            "Location(id={}, description={:?})",
            self.0.id,
            self.0.description.as_deref().unwrap_or_default()
        )
    }
}

fn parse_phase(phase: &str) -> PyResult<Phase> {
    match phase.to_ascii_lowercase().as_str() {
        "pre" | "before" => Ok(Phase::Pre),
        "post" | "after" => Ok(Phase::Post),
        _ => Err(PyValueError::new_err(format!(
            "unknown phase {phase:?}: use \"pre\" (before the gesture) or \"post\" (after it)"
        ))),
    }
}

fn parse_language(name: &str) -> PyResult<Language> {
    language::parse(name).ok_or_else(|| {
        PyValueError::new_err(format!(
            "unknown language {name:?}: use \"english\", \"isizulu\" or \"kinyarwanda\" (or \"en\", \"zu\", \"rw\")"
        ))
    })
}

/// A knowledge base that `ekb check` finds no error in, as the robot loads it.
#[pyclass(module = "ekb", frozen)]
struct KnowledgeBase(loader::KnowledgeBase);

#[pymethods]
impl KnowledgeBase {
    /// The file's name, as given.
    #[getter]
    fn file(&self) -> &str {
        self.0.file()
    }

    /// The version of the robot's reader the file was checked against, e.g. `"2025-06"`.
    #[getter]
    fn reader(&self) -> &'static str {
        self.0.reader().name()
    }

    /// `"seed"` or `"current"`; `None` when the file has no dialect-specific key.
    #[getter]
    fn dialect(&self) -> Option<&'static str> {
        self.0.dialect().map(|dialect| dialect.name())
    }

    /// Every location, in ascending id order.
    #[getter]
    fn locations(&self) -> Vec<Location> {
        self.0
            .locations()
            .map(|location| Location(location.to_export()))
            .collect()
    }

    /// The ids of the tour's stops, in the order visited.
    #[getter]
    fn tour(&self) -> Vec<u32> {
        self.0.tour().to_vec()
    }

    /// The warnings and notes of the check (a loaded file has no error).
    #[getter]
    fn findings(&self) -> Vec<Finding> {
        self.0.findings().iter().map(Finding::from).collect()
    }

    /// The location with this id; `KeyError` for anything that is not the id of one (as a
    /// `dict` keyed by id: `-1`, `2**40` and `"x"` too).
    fn location(&self, id: &Bound<'_, PyAny>) -> PyResult<Location> {
        self.find(id)
            .map(|location| Location(location.to_export()))
            .ok_or_else(|| PyKeyError::new_err((id.clone().unbind(),)))
    }

    /// The whole knowledge base as a `dict` in the shape of `ekb export` (SPEC §5).
    fn export<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let json = serde_json::to_string(&self.0.export())
            .map_err(|error| PyValueError::new_err(error.to_string()))?;
        py.import("json")?.call_method1("loads", (json,))
    }

    fn __getitem__(&self, id: &Bound<'_, PyAny>) -> PyResult<Location> {
        self.location(id)
    }

    /// Whether `id` is the id of a location: `False` for anything else.
    fn __contains__(&self, id: &Bound<'_, PyAny>) -> bool {
        self.find(id).is_some()
    }

    fn __len__(&self) -> usize {
        self.0.len()
    }

    fn __repr__(&self) -> String {
        format!(
            "KnowledgeBase(file={:?}, locations={}, tour={:?})",
            self.0.file(),
            self.0.len(),
            self.0.tour()
        )
    }
}

impl KnowledgeBase {
    /// The location whose id `id` is: none for an int out of the ids' range or a non-int.
    fn find(&self, id: &Bound<'_, PyAny>) -> Option<loader::Location<'_>> {
        let id: u32 = id.extract().ok()?;
        self.0.location(id)
    }
}

/// The options of `ekb check --reader` and `--settings`: the project settings (`ekb.toml`)
/// at `settings`, if given; none otherwise (an `ekb.toml` above the file is not read).
fn options(reader: Option<&str>, settings: Option<PathBuf>) -> PyResult<Options> {
    let reader = match reader {
        None => None,
        Some(name) => Some(Reader::from_name(name).ok_or_else(|| {
            let names: Vec<&str> = Reader::ALL.iter().map(|reader| reader.name()).collect();
            PyValueError::new_err(format!(
                "unknown reader {name:?}: use one of {}",
                names.join(", ")
            ))
        })?),
    };
    Ok(Options {
        reader,
        settings: settings.map_or(Lookup::Isolated, Lookup::Explicit),
        ..Options::default()
    })
}

/// The Python exception for a knowledge base that was not loaded, its findings attached.
fn raised(py: Python<'_>, error: loader::LoadError) -> PyErr {
    let exception = match &error {
        loader::LoadError::Unreadable { .. } => UnreadableError::new_err(error.to_string()),
        loader::LoadError::Refused { .. } => RefusedError::new_err(error.to_string()),
    };
    let findings: Vec<Finding> = error.findings().iter().map(Finding::from).collect();
    let file = match &error {
        loader::LoadError::Unreadable { file, .. } => Some(file.clone()),
        loader::LoadError::Refused { findings } => findings.first().map(|f| f.file.clone()),
    };
    let value = exception.value(py);
    if let Err(failed) = value
        .setattr("findings", findings)
        .and_then(|()| value.setattr("file", file))
    {
        return failed;
    }
    exception
}

/// Loads the knowledge base at `path`, as the robot should: refused with a
/// `RefusedError` carrying every finding if `ekb check` finds an error in it.
#[pyfunction]
#[pyo3(signature = (path, *, reader = None, settings = None))]
fn load(
    py: Python<'_>,
    path: PathBuf,
    reader: Option<&str>,
    settings: Option<PathBuf>,
) -> PyResult<KnowledgeBase> {
    let options = options(reader, settings)?;
    py.detach(|| loader::load_path(&path, &options))
        .map(KnowledgeBase)
        .map_err(|error| raised(py, error))
}

/// Checks the knowledge base at `path` as `ekb check --isolated` does (or with
/// `settings`, as `--settings`): its findings, in the order of the file (an empty list
/// for a clean file). `UnreadableError` if it cannot be read.
#[pyfunction]
#[pyo3(signature = (path, *, reader = None, settings = None))]
fn check(
    py: Python<'_>,
    path: PathBuf,
    reader: Option<&str>,
    settings: Option<PathBuf>,
) -> PyResult<Vec<Finding>> {
    let options = options(reader, settings)?;
    let findings = py
        .detach(|| loader::check_path(&path, &options))
        .map_err(|error| raised(py, error))?;
    Ok(findings.iter().map(Finding::from).collect())
}

#[pymodule]
fn _ekb(module: &Bound<'_, PyModule>) -> PyResult<()> {
    let py = module.py();
    module.add("__version__", env!("CARGO_PKG_VERSION"))?;
    module.add_function(wrap_pyfunction!(load, module)?)?;
    module.add_function(wrap_pyfunction!(check, module)?)?;
    module.add_class::<KnowledgeBase>()?;
    module.add_class::<Location>()?;
    module.add_class::<Pose>()?;
    module.add_class::<Point>()?;
    module.add_class::<Finding>()?;
    module.add("LoadError", py.get_type::<LoadError>())?;
    module.add("RefusedError", py.get_type::<RefusedError>())?;
    module.add("UnreadableError", py.get_type::<UnreadableError>())?;
    Ok(())
}
