//! The layers point one way: a module imports (`use crate::…`) only from its own layer or
//! the layers below it, as the code map of ARCHITECTURE.md numbers them. The table is read
//! from ARCHITECTURE.md itself, so the document and the test cannot drift apart. The
//! imports that still point up are listed in [`KNOWN_DEBTS`]; any other fails.

use std::collections::BTreeSet;
use std::path::Path;

/// Upward imports that are known debts, each a pair (importing entry of the code map,
/// imported entry): they pass, and so does any import between the same two entries. Each
/// is to be paid by moving the item to the layer it belongs to; then the pair goes from
/// this list (the test fails on a pair that no longer imports upward, to keep it short).
const KNOWN_DEBTS: &[(&str, &str)] = &[
    // The model's reading options name the version of the robot's reader, and its line
    // facts the reader's key buffer: `Reader` (a version and its limits) belongs below.
    ("src/model/", "src/reader/"),
    // A finding names its rule (`&'static Rule`), and suppressions and fixes select rules:
    // the type `Rule` and its selection live with the catalogue, and belong below.
    ("src/diagnostic.rs", "src/rules/"),
    ("src/fix_list.rs", "src/rules/"),
    ("src/suppression.rs", "src/rules/"),
    // The rules fill the check's `Diagnostics`, which belongs with `diagnostic.rs`.
    ("src/rules/", "src/check.rs"),
];

/// One row of the code map: a path under `src/` (a folder ends in `/`) and its layer.
#[derive(Debug, Clone, PartialEq, Eq)]
struct Entry {
    path: String,
    layer: u32,
}

/// The rows of the table of section "Code map" of ARCHITECTURE.md: `| `src/…` | N | … |`.
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
            path.starts_with("src/").then(|| Entry {
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

/// The entry a path of a `use crate::` tree (`["render", "escape", "escape"]`) imports
/// from: its longest leading part that names a file or folder of the map.
fn imported<'m>(map: &'m [Entry], segments: &[&str]) -> Option<&'m Entry> {
    let first = ROOT_ITEMS
        .iter()
        .find(|(item, _)| *item == segments[0])
        .map_or(segments[0], |(_, module)| module);
    let mut segments: Vec<&str> = segments.to_vec();
    segments[0] = first;
    (1..=segments.len())
        .flat_map(|length| {
            let module = segments[..length].join("/");
            [format!("src/{module}.rs"), format!("src/{module}/mod.rs")]
        })
        .filter_map(|file| owner(map, &file))
        .max_by_key(|entry| entry.path.len())
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

/// Every `use crate::…;` statement of `source` (one may span lines), with the line it
/// starts on, as the tree after `crate::`.
fn crate_uses(source: &str) -> Vec<(usize, String)> {
    let mut uses = Vec::new();
    let mut open: Option<(usize, String)> = None;
    for (number, line) in (1..).zip(source.lines()) {
        let code = line.trim();
        if open.is_none() {
            let statement = code
                .strip_prefix("pub(crate) ")
                .or_else(|| code.strip_prefix("pub(super) "))
                .or_else(|| code.strip_prefix("pub "))
                .unwrap_or(code);
            if let Some(tree) = statement.strip_prefix("use crate::") {
                open = Some((number, String::new()));
                let (_, text) = open.as_mut().expect("just opened");
                text.push_str(tree);
            }
        } else if let Some((_, text)) = open.as_mut() {
            text.push_str(code);
        }
        if let Some((start, text)) = open.take() {
            match text.find(';') {
                Some(end) => uses.push((start, text[..end].to_string())),
                None => open = Some((start, text)),
            }
        }
    }
    uses
}

/// An import that points up, not in [`KNOWN_DEBTS`].
#[derive(Debug)]
struct Upward {
    file: String,
    line: usize,
    from: Entry,
    to: Entry,
    path: String,
}

/// The upward imports of the file `file` (a path under `src/`) whose text is `source`, and
/// the pairs of [`KNOWN_DEBTS`] it uses.
fn upward_imports(
    map: &[Entry],
    file: &str,
    source: &str,
    used_debts: &mut BTreeSet<(String, String)>,
) -> Vec<Upward> {
    let from = owner(map, file)
        .unwrap_or_else(|| panic!("{file} is in no entry of the code map of ARCHITECTURE.md"));
    let mut found = Vec::new();
    for (line, tree) in crate_uses(source) {
        for path in use_paths(&tree) {
            let segments: Vec<&str> = path.iter().map(String::as_str).collect();
            let to = imported(map, &segments).unwrap_or_else(|| {
                panic!(
                    "{file}:{line}: `crate::{}` is in no entry of the code map",
                    path.join("::")
                )
            });
            if to.layer <= from.layer {
                continue;
            }
            let pair = (from.path.clone(), to.path.clone());
            if KNOWN_DEBTS.contains(&(pair.0.as_str(), pair.1.as_str())) {
                used_debts.insert(pair);
                continue;
            }
            found.push(Upward {
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

/// The `.rs` files under `dir`, as paths relative to `root`.
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

#[test]
fn no_module_imports_from_a_layer_above_it() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let architecture =
        std::fs::read_to_string(root.join("ARCHITECTURE.md")).expect("ARCHITECTURE.md");
    let map = code_map(&architecture);
    assert!(map.len() >= 10, "the code map has {} rows", map.len());
    let mut files = Vec::new();
    rust_files(root, &root.join("src"), &mut files);
    assert!(files.len() > 100, "found {} source files", files.len());
    let mut used_debts = BTreeSet::new();
    let mut upward = Vec::new();
    for file in &files {
        let source = std::fs::read_to_string(root.join(file)).expect("a source file");
        upward.extend(upward_imports(&map, file, &source, &mut used_debts));
    }
    let report: Vec<String> = upward
        .iter()
        .map(|up| {
            format!(
                "{}:{}: `crate::{}`: {} (layer {}) imports from {} (layer {})",
                up.file, up.line, up.path, up.from.path, up.from.layer, up.to.path, up.to.layer
            )
        })
        .collect();
    assert!(
        report.is_empty(),
        "imports from a layer above (move the item down, or the importer up; see \
         ARCHITECTURE.md, \"Code map\"):\n{}",
        report.join("\n")
    );
    let paid: Vec<_> = KNOWN_DEBTS
        .iter()
        .filter(|(from, to)| !used_debts.contains(&(from.to_string(), to.to_string())))
        .collect();
    assert!(
        paid.is_empty(),
        "debts paid, to take off KNOWN_DEBTS: {paid:?}"
    );
}

/// A made-up code map and import: the checker itself finds an upward import, follows
/// groups, multi-line statements and root re-exports, and passes a downward one.
#[test]
fn an_added_upward_import_is_found() {
    let map = code_map(
        "# A\n\n## Code map\n\n| Path | Layer |\n|---|---|\n| `src/syntax/` | 0 |\n\
         | `src/render/escape.rs` | 0 |\n| `src/render/` | 7 |\n| `src/rules/` | 5 |\n\
         | `src/diagnostic.rs` | 4 |\n| `src/check.rs` | 6 |\n\n## Invariants\n\n| `src/x/` | 9 |\n",
    );
    assert_eq!(map.len(), 6, "{map:?}");
    let upward = |file: &str, source: &str| {
        let found = upward_imports(&map, file, source, &mut BTreeSet::new());
        found
            .iter()
            .map(|up| format!("{}:{} {}", up.file, up.line, up.path))
            .collect::<Vec<_>>()
    };
    assert_eq!(
        upward("src/syntax/span.rs", "//! x\nuse crate::rules::ALL;\n"),
        ["src/syntax/span.rs:2 rules::ALL"]
    );
    assert_eq!(
        upward(
            "src/syntax/line.rs",
            "pub(crate) use crate::{\n    render::{escape::escape, human},\n    syntax::Span,\n};\n"
        ),
        ["src/syntax/line.rs:1 render::human"]
    );
    assert_eq!(
        upward("src/diagnostic.rs", "use crate::{Checked, Severity};\n"),
        ["src/diagnostic.rs:1 Checked"]
    );
    assert!(upward(
        "src/check.rs",
        "use crate::rules::{self, Rule};\nuse crate::render::escape::escape as e;\n"
    )
    .is_empty());
}
