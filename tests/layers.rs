//! The layers point one way: a module uses (`crate::…`, in a `use` or inline) only items of
//! its own entry of the code map of ARCHITECTURE.md, of another entry of its layer, or of
//! the layers below it, and the entries of one layer import no circle. The table is read
//! from ARCHITECTURE.md itself, so the document and the test cannot drift apart. Unit tests
//! (`#[cfg(test)]` items) may use anything: they are no part of the library.
//!
//! Two crates share the map: the core (`crates/ekb-core/src/`), whose `crate::` is its own,
//! and the command line's (`src/`), whose `crate::` also reaches the core's modules that it
//! re-exports at the same paths (`crate::model` is `ekb_core::model`). The core depends on
//! no crate of a face.

use std::collections::{BTreeMap, BTreeSet};
use std::path::Path;

/// The core's sources, from the repository's root.
const CORE: &str = "crates/ekb-core/src/";

/// One row of the code map: a path under `src/` or [`CORE`] (a folder ends in `/`) and
/// its layer.
#[derive(Debug, Clone, PartialEq, Eq)]
struct Entry {
    path: String,
    layer: u32,
}

/// The rows of the table of section "Code map" of ARCHITECTURE.md: `| `src/…` | N | … |`
/// (or `crates/ekb-core/src/…`).
fn code_map(architecture: &str) -> Vec<Entry> {
    let section = architecture
        .split("\n## ")
        .find(|section| section.starts_with("Code map"))
        .expect("ARCHITECTURE.md has a section \"Code map\"");
    section
        .lines()
        .filter_map(|line| {
            let mut cells = line.split('|').map(str::trim).skip(1);
            let path = cells.next()?.strip_prefix('`')?.strip_suffix('`')?;
            let layer = cells.next()?.parse().ok()?;
            (path.starts_with("src/") || path.starts_with(CORE)).then(|| Entry {
                path: path.to_string(),
                layer,
            })
        })
        .collect()
}

/// The entry of the code map that owns `path` (a file, or a module path made into one):
/// the longest entry that is the path or a folder holding it.
fn owner<'m>(map: &'m [Entry], path: &str) -> Option<&'m Entry> {
    map.iter()
        .filter(|entry| match entry.path.ends_with('/') {
            true => path.starts_with(&entry.path),
            false => path == entry.path,
        })
        .max_by_key(|entry| entry.path.len())
}

/// Items the crate's root re-exports, and the module each comes from.
const ROOT_ITEMS: &[(&str, &str)] = &[
    ("Checked", "check"),
    ("Diagnostic", "diagnostic"),
    ("Severity", "diagnostic"),
    ("KnowledgeBase", "model"),
    ("SourceFile", "source"),
    ("stderr_line", "streams"),
];

/// The entry a path of a `use crate::` tree (`["render", "escape", "escape"]`) in the file
/// `file` imports from: its longest leading part that names a file of its crate or, for a
/// file of the command line's crate, of the core's (`exists` tells which files there are).
fn imported<'m>(
    map: &'m [Entry],
    file: &str,
    segments: &[&str],
    exists: &dyn Fn(&str) -> bool,
) -> Option<&'m Entry> {
    let first = ROOT_ITEMS
        .iter()
        .find(|(item, _)| *item == segments[0])
        .map_or(segments[0], |(_, module)| module);
    let mut segments: Vec<&str> = segments.to_vec();
    segments[0] = first;
    let roots: &[&str] = match file.starts_with(CORE) {
        true => &[CORE],
        false => &["src/", CORE],
    };
    // The deepest module the path names, wherever it is: the command line's `render`
    // holds the core's `render::escape` by a re-export.
    (1..=segments.len()).rev().find_map(|length| {
        let module = segments[..length].join("/");
        roots
            .iter()
            .flat_map(|root| {
                [
                    format!("{root}{module}.rs"),
                    format!("{root}{module}/mod.rs"),
                ]
            })
            .find(|file| exists(file))
            .and_then(|file| owner(map, &file))
    })
}

/// The paths of a use tree (`{a, b::{c, d}}` gives `a`, `b::c`, `b::d`), each as its
/// segments; `self` and globs end a path where they stand.
fn use_paths(tree: &str) -> Vec<Vec<String>> {
    // `a as b` keeps `a`: marked before the blanks go.
    let tree: String = tree
        .replace(" as ", "@")
        .chars()
        .filter(|c| !c.is_whitespace())
        .collect();
    let mut paths = Vec::new();
    expand(&tree, &mut Vec::new(), &mut paths);
    paths
}

fn expand(tree: &str, prefix: &mut Vec<String>, out: &mut Vec<Vec<String>>) {
    for branch in split_top(tree) {
        let depth = prefix.len();
        let (head, group) = match branch.find('{') {
            Some(open) => (&branch[..open], Some(&branch[open + 1..branch.len() - 1])),
            None => (branch, None),
        };
        for segment in head.split("::").filter(|s| !s.is_empty()) {
            let name = segment.split('@').next().unwrap_or(segment);
            if name != "self" && name != "*" {
                prefix.push(name.to_string());
            }
        }
        match group {
            Some(group) => expand(group, prefix, out),
            None if !prefix.is_empty() => out.push(prefix.clone()),
            None => {}
        }
        prefix.truncate(depth);
    }
}

/// `tree` split at its commas outside braces.
fn split_top(tree: &str) -> Vec<&str> {
    let (mut parts, mut depth, mut start) = (Vec::new(), 0, 0);
    for (at, ch) in tree.char_indices() {
        match ch {
            '{' => depth += 1,
            '}' => depth -= 1,
            ',' if depth == 0 => {
                parts.push(&tree[start..at]);
                start = at + 1;
            }
            _ => {}
        }
    }
    parts.push(&tree[start..]);
    parts.retain(|part| !part.is_empty());
    parts
}

/// The lines of `source` that are library code, numbered from 1: without the items under
/// `#[cfg(test)]` (a test module is skipped to its closing brace) and without comments.
fn library_lines(source: &str) -> Vec<(usize, &str)> {
    let mut lines = Vec::new();
    let mut numbered = (1..).zip(source.lines());
    while let Some((number, line)) = numbered.next() {
        let code = line.trim();
        if code == "#[cfg(test)]" {
            skip_item(&mut numbered);
            continue;
        }
        let code = without_comment(code);
        if !code.is_empty() {
            lines.push((number, code));
        }
    }
    lines
}

/// Skips the item that follows an attribute: its block, to the brace that closes it, or
/// its one line.
fn skip_item<'s>(lines: &mut impl Iterator<Item = (usize, &'s str)>) {
    let mut depth = 0usize;
    for (_, line) in lines.by_ref() {
        let code = without_comment(line.trim());
        if code.starts_with("#[") {
            continue;
        }
        for ch in code.chars() {
            match ch {
                '{' => depth += 1,
                '}' => depth = depth.saturating_sub(1),
                _ => {}
            }
        }
        if depth == 0 && (code.ends_with('}') || code.ends_with(';')) {
            return;
        }
    }
}

/// `code` without a `//` comment (one inside a string, as in `"http://"`, stays).
fn without_comment(code: &str) -> &str {
    let mut in_string = false;
    let bytes = code.as_bytes();
    for (at, &byte) in bytes.iter().enumerate() {
        match byte {
            b'"' if at == 0 || bytes[at - 1] != b'\\' => in_string = !in_string,
            b'/' if !in_string && bytes.get(at + 1) == Some(&b'/') => return code[..at].trim(),
            _ => {}
        }
    }
    code
}

/// Every path into the crate that the library code of `source` names, with its line: the
/// paths of each `use crate::…;` (one may span lines), and each `crate::a::b` written
/// inline (not `$crate::`, a macro's).
fn crate_paths(source: &str) -> Vec<(usize, Vec<String>)> {
    let mut paths = Vec::new();
    let mut open: Option<(usize, String)> = None;
    for (number, code) in library_lines(source) {
        if let Some((_, text)) = open.as_mut() {
            text.push_str(code);
        } else {
            let statement = code
                .strip_prefix("pub(crate) ")
                .or_else(|| code.strip_prefix("pub(super) "))
                .or_else(|| code.strip_prefix("pub "))
                .unwrap_or(code);
            match statement.strip_prefix("use crate::") {
                Some(tree) => open = Some((number, tree.to_string())),
                None => paths.extend(inline_paths(code).into_iter().map(|p| (number, p))),
            }
        }
        if let Some((start, text)) = open.take() {
            match text.find(';') {
                Some(end) => paths.extend(use_paths(&text[..end]).into_iter().map(|p| (start, p))),
                None => open = Some((start, text)),
            }
        }
    }
    paths
}

/// The `crate::a::b…` paths written in one line of code, each as its segments.
fn inline_paths(code: &str) -> Vec<Vec<String>> {
    let is_name = |ch: char| ch.is_ascii_alphanumeric() || ch == '_';
    code.match_indices("crate::")
        .filter(|(at, _)| {
            code[..*at]
                .chars()
                .next_back()
                .is_none_or(|ch| !is_name(ch) && ch != '$')
        })
        .map(|(at, _)| {
            let mut segments = Vec::new();
            let mut rest = &code[at + "crate::".len()..];
            loop {
                let length = rest.find(|ch: char| !is_name(ch)).unwrap_or(rest.len());
                if length == 0 {
                    break;
                }
                segments.push(rest[..length].to_string());
                match rest[length..].strip_prefix("::") {
                    Some(next) => rest = next,
                    None => break,
                }
            }
            segments
        })
        .filter(|segments| !segments.is_empty())
        .collect()
}

/// One use of an item of another entry of the code map.
#[derive(Debug, Clone)]
struct Import {
    file: String,
    line: usize,
    from: Entry,
    to: Entry,
    path: String,
}

impl std::fmt::Display for Import {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "{}:{}: `crate::{}`: {} (layer {}) uses {} (layer {})",
            self.file,
            self.line,
            self.path,
            self.from.path,
            self.from.layer,
            self.to.path,
            self.to.layer
        )
    }
}

/// The uses, in the library code of the file `file` (a path from the repository's root)
/// whose text is `source`, of items of other entries of the code map.
fn imports(map: &[Entry], file: &str, source: &str, exists: &dyn Fn(&str) -> bool) -> Vec<Import> {
    let from = owner(map, file)
        .unwrap_or_else(|| panic!("{file} is in no entry of the code map of ARCHITECTURE.md"));
    let mut found = Vec::new();
    for (line, path) in crate_paths(source) {
        let segments: Vec<&str> = path.iter().map(String::as_str).collect();
        let to = imported(map, file, &segments, exists).unwrap_or_else(|| {
            panic!(
                "{file}:{line}: `crate::{}` is in no entry of the code map",
                path.join("::")
            )
        });
        if to != from {
            found.push(Import {
                file: file.to_string(),
                line,
                from: from.clone(),
                to: to.clone(),
                path: path.join("::"),
            });
        }
    }
    found
}

/// The imports that point to a higher layer.
fn upward(imports: &[Import]) -> Vec<&Import> {
    imports
        .iter()
        .filter(|import| import.to.layer > import.from.layer)
        .collect()
}

/// The circles of imports between entries: each a set of two or more entries that all
/// reach each other, with one import of each of its edges as evidence.
fn circles(imports: &[Import]) -> Vec<Vec<&Import>> {
    let mut edges: BTreeMap<&str, BTreeMap<&str, &Import>> = BTreeMap::new();
    for import in imports {
        edges
            .entry(import.from.path.as_str())
            .or_default()
            .entry(import.to.path.as_str())
            .or_insert(import);
    }
    let reach = |start: &str| {
        let mut seen = BTreeSet::new();
        let mut stack = vec![start.to_string()];
        while let Some(at) = stack.pop() {
            for &next in edges.get(at.as_str()).into_iter().flat_map(BTreeMap::keys) {
                if seen.insert(next.to_string()) {
                    stack.push(next.to_string());
                }
            }
        }
        seen
    };
    let reached: BTreeMap<&str, BTreeSet<String>> =
        edges.keys().map(|&entry| (entry, reach(entry))).collect();
    let mut circles = Vec::new();
    let mut placed = BTreeSet::new();
    for &entry in edges.keys() {
        if placed.contains(entry) || !reached[entry].contains(entry) {
            continue;
        }
        let members: BTreeSet<&str> = reached[entry]
            .iter()
            .map(String::as_str)
            .filter(|other| reached.get(other).is_some_and(|r| r.contains(entry)))
            .collect();
        placed.extend(members.iter().copied());
        let evidence = members
            .iter()
            .flat_map(|from| edges[from].iter())
            .filter(|(to, _)| members.contains(*to))
            .map(|(_, &import)| import)
            .collect();
        circles.push(evidence);
    }
    circles
}

/// `.rs` files under `dir`, as paths relative to `root`.
fn rust_files(root: &Path, dir: &Path, out: &mut Vec<String>) {
    for entry in std::fs::read_dir(dir).expect("a readable folder") {
        let path = entry.expect("an entry").path();
        if path.is_dir() {
            rust_files(root, &path, out);
        } else if path.extension().is_some_and(|ext| ext == "rs") {
            let relative = path.strip_prefix(root).expect("under the root");
            out.push(relative.to_string_lossy().replace('\\', "/"));
        }
    }
}

/// Every import of the crate's library code between entries of ARCHITECTURE.md's code map.
fn crate_imports() -> Vec<Import> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let architecture =
        std::fs::read_to_string(root.join("ARCHITECTURE.md")).expect("ARCHITECTURE.md");
    let map = code_map(&architecture);
    assert!(map.len() >= 10, "the code map has {} rows", map.len());
    let mut files = Vec::new();
    rust_files(root, &root.join("src"), &mut files);
    let command_line = files.len();
    rust_files(root, &root.join(CORE), &mut files);
    assert!(command_line > 50, "found {command_line} files in src/");
    assert!(
        files.len() - command_line > 100,
        "found {} in {CORE}",
        files.len() - command_line
    );
    let exists = |file: &str| root.join(file).is_file();
    files
        .iter()
        .flat_map(|file| {
            let source = std::fs::read_to_string(root.join(file)).expect("a source file");
            imports(&map, file, &source, &exists)
        })
        .collect()
}

#[test]
fn no_module_imports_from_a_layer_above_it() {
    let imports = crate_imports();
    assert!(imports.len() > 100, "found {} imports", imports.len());
    let report: Vec<String> = upward(&imports).iter().map(|up| up.to_string()).collect();
    assert!(
        report.is_empty(),
        "imports from a layer above (move the item down, or the importer up; see \
         ARCHITECTURE.md, \"Code map\"):\n{}",
        report.join("\n")
    );
}

#[test]
fn no_entries_import_each_other_in_a_circle() {
    let imports = crate_imports();
    let report: Vec<String> = circles(&imports)
        .iter()
        .map(|circle| {
            let lines: Vec<String> = circle.iter().map(|import| format!("  {import}")).collect();
            lines.join("\n")
        })
        .collect();
    assert!(
        report.is_empty(),
        "entries of the code map that import each other (one of them, or the item they \
         share, belongs elsewhere):\n{}",
        report.join("\n\n")
    );
}

/// A made-up code map and sources: the checker itself finds an upward import, in a `use`
/// (with groups, over lines, through a root re-export) or inline, passes a downward one,
/// a comment and a unit test, and finds a circle.
#[test]
fn an_added_upward_import_or_circle_is_found() {
    let map = code_map(
        "# A\n\n## Code map\n\n| Path | Layer |\n|---|---|\n| `src/syntax/` | 0 |\n\
         | `src/render/escape.rs` | 0 |\n| `src/render/` | 7 |\n| `src/rules/` | 5 |\n\
         | `src/diagnostic.rs` | 4 |\n| `src/check.rs` | 6 |\n| `src/fixing.rs` | 6 |\n\n\
         ## Invariants\n\n| `src/x/` | 9 |\n",
    );
    assert_eq!(map.len(), 7, "{map:?}");
    let files = [
        "src/syntax/mod.rs",
        "src/syntax/span.rs",
        "src/syntax/line.rs",
        "src/render/mod.rs",
        "src/render/escape.rs",
        "src/render/human.rs",
        "src/rules/mod.rs",
        "src/diagnostic.rs",
        "src/check.rs",
        "src/fixing.rs",
    ];
    let exists = |file: &str| files.contains(&file);
    let found = |file: &str, source: &str| imports(&map, file, source, &exists);
    let upward_in = |file: &str, source: &str| {
        upward(&found(file, source))
            .iter()
            .map(|up| format!("{}:{} {}", up.file, up.line, up.path))
            .collect::<Vec<_>>()
    };
    assert_eq!(
        upward_in("src/syntax/span.rs", "//! x\nuse crate::rules::ALL;\n"),
        ["src/syntax/span.rs:2 rules::ALL"]
    );
    assert_eq!(
        upward_in(
            "src/syntax/line.rs",
            "pub(crate) use crate::{\n    render::{escape::escape, human},\n    syntax::Span,\n};\n"
        ),
        ["src/syntax/line.rs:1 render::human"]
    );
    assert_eq!(
        upward_in("src/diagnostic.rs", "use crate::{Checked, Severity};\n"),
        ["src/diagnostic.rs:1 Checked"]
    );
    assert_eq!(
        upward_in(
            "src/diagnostic.rs",
            "fn f() {\n    let n = crate::rules::index_of(r); // crate::check\n}\n"
        ),
        ["src/diagnostic.rs:2 rules::index_of"]
    );
    assert!(upward_in(
        "src/check.rs",
        "use crate::rules::{self, Rule};\nuse crate::render::escape::escape as e;\n\
         // crate::render::human\nmacro_rules! m { () => { $crate::render::human } }\n"
    )
    .is_empty());
    assert!(upward_in(
        "src/diagnostic.rs",
        "fn f() {}\n\n#[cfg(test)]\nmod tests {\n    use crate::check::check;\n    \
         fn g() {\n        crate::rules::ALL;\n    }\n}\n"
    )
    .is_empty());
    assert_eq!(
        upward_in(
            "src/diagnostic.rs",
            "#[cfg(test)]\nfn helper() {\n    crate::check::check();\n}\nuse crate::rules::ALL;\n"
        ),
        ["src/diagnostic.rs:5 rules::ALL"]
    );
    let mut both = found("src/check.rs", "use crate::fixing::apply;\n");
    assert!(circles(&both).is_empty());
    both.extend(found(
        "src/fixing.rs",
        "fn f() { crate::check::check(); }\n",
    ));
    let circle: Vec<String> = circles(&both)
        .iter()
        .flatten()
        .map(|import| format!("{}:{}", import.file, import.line))
        .collect();
    assert_eq!(circle, ["src/check.rs:1", "src/fixing.rs:1"]);
}

/// In a made-up map of both crates, the command line's `crate::model` is the core's model
/// (it has none of its own), and its `crate::render::human` its own renderer, while
/// `crate::render::escape` is the core's, which the command line's `render` re-exports.
#[test]
fn a_path_of_the_command_line_reaches_the_core_it_re_exports() {
    let map = code_map(
        "# A\n\n## Code map\n\n| `crates/ekb-core/src/model/` | 2 |\n\
         | `crates/ekb-core/src/render/` | 0 |\n| `src/render/` | 7 |\n| `src/lsp/` | 9 |\n",
    );
    let files = [
        "crates/ekb-core/src/model/mod.rs",
        "crates/ekb-core/src/render/escape.rs",
        "src/render/human.rs",
    ];
    let exists = |file: &str| files.contains(&file);
    let layers = |file: &str, source: &str| {
        imports(&map, file, source, &exists)
            .iter()
            .map(|import| format!("{} {}", import.path, import.to.layer))
            .collect::<Vec<_>>()
    };
    assert_eq!(
        layers(
            "src/lsp/server.rs",
            "use crate::model::Location;\nuse crate::render::{escape::escape, human};\n"
        ),
        [
            "model::Location 2",
            "render::escape::escape 0",
            "render::human 7"
        ]
    );
    assert_eq!(
        layers(
            "crates/ekb-core/src/render/escape.rs",
            "use crate::model::Location;\n"
        ),
        ["model::Location 2"]
    );
}

/// The crates the faces bring in: the core, which the C ABI and the Python module link
/// alone, depends on none of them.
const FACES_ONLY: &[&str] = &[
    "clap",
    "clap_complete",
    "clap_mangen",
    "miette",
    "comfy-table",
    "anstream",
    "terminal_size",
    "similar",
    "resvg",
    "base64",
    "lsp-server",
    "lsp-types",
    "crossbeam-channel",
    "self_cell",
    "serde_path_to_error",
];

#[test]
fn the_core_depends_on_no_crate_of_a_face() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let manifest = std::fs::read_to_string(root.join("crates/ekb-core/Cargo.toml")).unwrap();
    let dependencies = manifest
        .split("\n[dependencies]\n")
        .nth(1)
        .expect("crates/ekb-core/Cargo.toml has [dependencies]");
    let dependencies = dependencies.split("\n[").next().unwrap_or(dependencies);
    let names: Vec<&str> = dependencies
        .lines()
        .filter_map(|line| line.split_once('=').map(|(name, _)| name.trim()))
        .filter(|name| !name.starts_with('#'))
        .collect();
    assert!(names.contains(&"serde"), "read no dependency: {names:?}");
    let faces: Vec<&&str> = names
        .iter()
        .filter(|name| FACES_ONLY.contains(name))
        .collect();
    assert!(
        faces.is_empty(),
        "the core depends on {faces:?}: move what needs it to a face"
    );
}
