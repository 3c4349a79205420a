//! `ekb mission tree`: the mission's trees as an outline — each node with its parameter
//! and, for `SayText`, the phrase it says in the mission's language.

use serde::Serialize;

use super::culture::PhraseBook;
use super::tree::{self, Mission};
use super::xml::Element;
use crate::source::LineIndex;

/// One `<BehaviorTree>`.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct TreeOutline {
    pub id: Option<String>,
    /// The tree the robot runs.
    pub main: bool,
    /// Run by the main tree (itself included).
    pub reachable: bool,
    pub line: u32,
    pub nodes: Vec<NodeOutline>,
}

/// One node.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct NodeOutline {
    /// The node's ID (`SayText`), or the element's name if it has none.
    pub node: String,
    /// The `name` attribute: a robot node's parameter.
    pub name: Option<String>,
    /// The other attributes that are not notes: ports, a `SubTree`'s `ID`.
    pub ports: Vec<(String, String)>,
    /// What a `SayText` says: `Ok(text)`, or `Err(why it says nothing)`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub says: Option<Said>,
    pub line: u32,
    pub column: u32,
    pub children: Vec<NodeOutline>,
}

/// A `SayText`'s phrase.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Said {
    /// The culture key it looks up.
    pub key: String,
    /// The text the robot holds for it, if any.
    pub text: Option<String>,
    /// Why there is none.
    pub problem: Option<String>,
}

/// The mission's trees, the main one first, then the others in file order.
pub fn outline(mission: &Mission, text: &str, phrases: &PhraseBook<'_>) -> Vec<TreeOutline> {
    let index = LineIndex::new(text);
    let main = mission.main_tree();
    let reachable = mission.reachable();
    let is = |a: &Element, b: &Element| std::ptr::eq(a, b);
    let mut trees: Vec<&Element> = main.into_iter().collect();
    trees.extend(mission.trees().filter(|t| !main.is_some_and(|m| is(m, t))));
    trees
        .into_iter()
        .map(|tree| TreeOutline {
            id: tree.value("ID").map(str::to_string),
            main: main.is_some_and(|m| is(m, tree)),
            reachable: reachable.iter().any(|r| is(r, tree)),
            line: index.position(text, tree.name_span.start).line,
            nodes: tree
                .children
                .iter()
                .map(|node| node_outline(node, text, &index, phrases))
                .collect(),
        })
        .collect()
}

fn node_outline(
    node: &Element,
    text: &str,
    index: &LineIndex,
    phrases: &PhraseBook<'_>,
) -> NodeOutline {
    let position = index.position(text, node.name_span.start);
    let id = tree::node_id(node).unwrap_or(&node.name);
    let says = (id == "SayText")
        .then(|| node.value("name"))
        .flatten()
        .zip(phrases.language)
        .map(|(number, language)| {
            let key = super::phrase_key(number, language);
            let (text, problem) = match phrases.phrase(&key) {
                Ok(text) => (Some(text), None),
                Err(problem) => (None, Some(problem)),
            };
            Said { key, text, problem }
        });
    let explicit = id != node.name;
    NodeOutline {
        node: id.to_string(),
        name: node.value("name").map(str::to_string),
        ports: node
            .attributes
            .iter()
            .filter(|a| a.name != "name" && !a.name.starts_with('_'))
            .filter(|a| !(explicit && a.name == "ID"))
            .map(|a| (a.name.clone(), a.value.clone()))
            .collect(),
        says,
        line: position.line,
        column: position.column,
        children: node
            .children
            .iter()
            .map(|child| node_outline(child, text, index, phrases))
            .collect(),
    }
}

/// The outline as indented text, two spaces a level:
/// `SayText "4" says "Hello! …"`.
pub fn render_text(trees: &[TreeOutline]) -> String {
    let mut out = String::new();
    for tree in trees {
        let role = match (tree.main, tree.reachable) {
            (true, _) => "main tree, ",
            (false, true) => "",
            (false, false) => "never run, ",
        };
        out.push_str(&format!(
            "{} ({role}line {})\n",
            tree.id.as_deref().unwrap_or("<BehaviorTree without an ID>"),
            tree.line
        ));
        let mut stack: Vec<(usize, &NodeOutline)> =
            tree.nodes.iter().rev().map(|node| (1, node)).collect();
        while let Some((depth, node)) = stack.pop() {
            out.push_str(&"  ".repeat(depth));
            out.push_str(&node_line(node));
            out.push('\n');
            stack.extend(node.children.iter().rev().map(|child| (depth + 1, child)));
        }
    }
    out
}

fn node_line(node: &NodeOutline) -> String {
    let mut line = node.node.clone();
    if let Some(name) = &node.name {
        line.push_str(&format!(" \"{name}\""));
    }
    for (port, value) in &node.ports {
        line.push_str(&format!(" {port}=\"{value}\""));
    }
    match &node.says {
        Some(Said {
            text: Some(text), ..
        }) => line.push_str(&format!(" says \"{text}\"")),
        Some(Said {
            key,
            problem: Some(problem),
            ..
        }) => line.push_str(&format!(" says nothing: {key} {problem}")),
        _ => {}
    }
    line
}
