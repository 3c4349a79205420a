//! `<include path="…"/>`: the other mission files whose trees BehaviorTree.CPP registers
//! before a file's own (`XMLParser::loadDocImpl`). A relative path is taken from the
//! including file's folder (the current folder for standard input); each included file is
//! read the same way, its own includes first. A file that cannot be read, is no `<root>`
//! document, or includes itself again stops the load.
//!
//! `ekb` reads the included files for the IDs of their trees, so that a `<SubTree>` may
//! call them; their trees themselves are checked when the included file is checked.

use std::path::{Path, PathBuf};

use super::tree::Mission;
use super::xml::{self, Element};
use crate::source::SourceFile;
use crate::syntax::Span;

/// Why an `<include>` stops BehaviorTree.CPP from loading the mission.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Problem {
    /// No `path` attribute.
    NoPath,
    /// A `path` attribute with nothing in it (or only blanks).
    EmptyPath,
    /// A `ros_pkg` attribute with a relative path: only a BehaviorTree.CPP built for ROS 2
    /// resolves it, and the robot runs ROS 1.
    RosPackage { package: String },
    /// The file cannot be read.
    Unreadable { path: PathBuf, reason: String },
    /// The file is not a `<root>` document.
    NotAMission { path: PathBuf, reason: String },
    /// The file includes itself, directly or through others.
    Cycle { path: PathBuf },
}

/// A problem with an `<include>` of the file checked, at the include (`chain`: the files
/// included on the way, when the problem is in one of them).
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct IncludeProblem {
    pub at: Span,
    pub chain: Vec<PathBuf>,
    pub problem: Problem,
}

/// What the `<include>`s of a mission bring: the IDs of the trees registered from other
/// files, each with the file that holds it, and the problems met.
#[derive(Debug, Default)]
pub struct Included {
    pub trees: Vec<(String, PathBuf)>,
    pub problems: Vec<IncludeProblem>,
}

/// Reads the files that `mission` includes, and theirs, from `file` (the mission's own path;
/// `None` for standard input).
pub fn load(mission: &Mission, file: Option<&Path>) -> Included {
    let folder = folder_of(file);
    let mut included = Included::default();
    let this: Vec<PathBuf> = file.map(canonical).into_iter().collect();
    for include in includes(mission.root()) {
        let at = include
            .attribute("path")
            .map_or(include.name_span, |a| a.value_span);
        let (mut open, mut chain) = (this.clone(), Vec::new());
        if let Err(problem) = follow(include, &folder, &mut open, &mut chain, &mut included) {
            included
                .problems
                .push(IncludeProblem { at, chain, problem });
        }
    }
    included
}

/// The `<include>` elements of a document's `<root>`.
fn includes(root: &Element) -> impl Iterator<Item = &Element> {
    root.children.iter().filter(|child| child.name == "include")
}

/// Reads the file that `include` names (from `folder`), its own includes first, and adds its
/// trees; `open` holds the files being read, `chain` the files on the way to a problem.
fn follow(
    include: &Element,
    folder: &Path,
    open: &mut Vec<PathBuf>,
    chain: &mut Vec<PathBuf>,
    included: &mut Included,
) -> Result<(), Problem> {
    let path = include.value("path").ok_or(Problem::NoPath)?;
    if path.trim().is_empty() {
        return Err(Problem::EmptyPath);
    }
    let path = Path::new(path);
    if let Some(package) = include.value("ros_pkg").filter(|_| path.is_relative()) {
        return Err(Problem::RosPackage {
            package: package.to_string(),
        });
    }
    let path = folder.join(path);
    let identity = canonical(&path);
    if open.contains(&identity) {
        return Err(Problem::Cycle { path });
    }
    let source = SourceFile::read(&path).map_err(|error| Problem::Unreadable {
        path: path.clone(),
        reason: error.reason,
    })?;
    let root = xml::parse(source.text())
        .map_err(|error| error.message)
        .and_then(|root| match root.name.as_str() {
            "root" => Ok(root),
            other => Err(format!("its root element is <{other}>, not <root>")),
        })
        .map_err(|reason| Problem::NotAMission {
            path: path.clone(),
            reason,
        })?;
    open.push(identity);
    chain.push(path.clone());
    let inner = folder_of(Some(&path));
    for nested in includes(&root) {
        follow(nested, &inner, open, chain, included)?;
    }
    chain.pop();
    open.pop();
    let trees = root
        .children
        .iter()
        .filter(|child| child.name == "BehaviorTree");
    for id in trees.filter_map(|tree| tree.value("ID")) {
        included.trees.push((id.to_string(), path.clone()));
    }
    Ok(())
}

/// The folder a relative include is taken from: the file's, or the current one.
fn folder_of(file: Option<&Path>) -> PathBuf {
    file.and_then(Path::parent)
        .map(Path::to_path_buf)
        .unwrap_or_default()
}

/// A path that names one file whichever way it is written (as it is, if it cannot be
/// resolved: then it is not read either).
fn canonical(path: &Path) -> PathBuf {
    path.canonicalize().unwrap_or_else(|_| path.to_path_buf())
}
