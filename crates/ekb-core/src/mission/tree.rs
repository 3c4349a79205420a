//! The behaviour trees of a mission file: which `BehaviorTree` runs first, which ones it
//! calls, and what each node element is.

use std::collections::HashMap;

use super::catalogue::{self, NodeModel, EXPLICIT_FORMS};
use super::xml::Element;

/// A mission: its `<root>` element, well-formed XML.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Mission {
    root: Element,
    /// The IDs of the trees its `<include>`d files register, each with its file
    /// ([`super::include`]; empty until they are read).
    pub included: Vec<(String, std::path::PathBuf)>,
    /// Where the first tree of each ID is among the root's children: a tree is looked up
    /// at every `SubTree`, and a mission of 30,000 trees is not searched each time.
    trees_by_id: HashMap<String, usize>,
}

impl Mission {
    /// The mission of the `<root>` element `root`.
    pub fn new(root: Element) -> Mission {
        let mut trees_by_id = HashMap::new();
        for (index, child) in root.children.iter().enumerate() {
            if let Some(id) = child.value("ID").filter(|_| child.name == "BehaviorTree") {
                trees_by_id.entry(id.to_string()).or_insert(index);
            }
        }
        Mission {
            root,
            included: Vec::new(),
            trees_by_id,
        }
    }

    /// The `<root>` element.
    pub fn root(&self) -> &Element {
        &self.root
    }

    /// The `<BehaviorTree>` elements, in file order.
    pub fn trees(&self) -> impl Iterator<Item = &Element> {
        self.root
            .children
            .iter()
            .filter(|child| child.name == "BehaviorTree")
    }

    /// The tree with this `ID`.
    pub fn tree(&self, id: &str) -> Option<&Element> {
        self.trees_by_id
            .get(id)
            .map(|&index| &self.root.children[index])
    }

    /// The included file that registers the tree `id`, if this file does not have it
    /// (the last registered wins, as BehaviorTree.CPP's map of trees keeps it).
    pub fn included_tree(&self, id: &str) -> Option<&std::path::Path> {
        self.included
            .iter()
            .rev()
            .find(|(included, _)| included == id)
            .map(|(_, file)| file.as_path())
    }

    /// Whether BehaviorTree.CPP registers a tree `id`: this file's, or an included one.
    pub fn knows_tree(&self, id: &str) -> bool {
        self.tree(id).is_some() || self.included_tree(id).is_some()
    }

    /// How many trees BehaviorTree.CPP registers, included ones too.
    pub fn tree_count(&self) -> usize {
        self.trees().count() + self.included.len()
    }

    /// The ID of the tree that runs: `main_tree_to_execute`, else the only tree's.
    pub fn main_tree_id(&self) -> Option<&str> {
        match self.root.value("main_tree_to_execute") {
            Some(id) => Some(id),
            None if self.tree_count() == 1 => self
                .trees()
                .next()
                .and_then(|only| only.value("ID"))
                .or_else(|| self.included.first().map(|(id, _)| id.as_str())),
            None => None,
        }
    }

    /// The tree that runs, if there is one.
    pub fn main_tree(&self) -> Option<&Element> {
        self.tree(self.main_tree_id()?)
    }

    /// The trees the main tree runs, itself included, in file order; every tree if there is
    /// no main tree (nothing can be said to be unreachable then).
    pub fn reachable(&self) -> Vec<&Element> {
        let main = self.main_tree_id().and_then(|id| self.trees_by_id.get(id));
        let Some(&main) = main else {
            return self.trees().collect();
        };
        // The trees reached, by their place among the root's children.
        let mut reached = vec![false; self.root.children.len()];
        reached[main] = true;
        let mut waiting = vec![main];
        while let Some(tree) = waiting.pop() {
            for node in nodes(&self.root.children[tree]) {
                let called = (node.name == "SubTree")
                    .then(|| node.value("ID").and_then(|id| self.trees_by_id.get(id)))
                    .flatten();
                if let Some(&called) = called {
                    if !reached[called] {
                        reached[called] = true;
                        waiting.push(called);
                    }
                }
            }
        }
        self.root
            .children
            .iter()
            .zip(reached)
            .filter(|(_, reached)| *reached)
            .map(|(tree, _)| tree)
            .collect()
    }

    /// The nodes of the trees the main tree runs.
    pub fn reachable_nodes(&self) -> impl Iterator<Item = &Element> {
        self.reachable().into_iter().flat_map(nodes)
    }
}

/// The node elements of a `<BehaviorTree>` (not the tree element itself), depth first.
pub fn nodes(tree: &Element) -> impl Iterator<Item = &Element> {
    tree.children.iter().flat_map(Element::descendants)
}

/// The ID a node element names: `<SayText/>` is `SayText`, `<Action ID="SayText"/>` too.
/// `None` for an explicit form without an `ID`.
pub fn node_id(element: &Element) -> Option<&str> {
    if EXPLICIT_FORMS.contains(&element.name.as_str()) {
        element.value("ID")
    } else {
        Some(&element.name)
    }
}

/// The model of a node element, if it names a known node.
pub fn model(element: &Element) -> Option<&'static NodeModel> {
    node_id(element).and_then(catalogue::lookup)
}

/// The node's `name` as the robot sees it: the attribute, else the node's ID (what
/// BehaviorTree.CPP names a node that has none).
pub fn robot_name(element: &Element) -> Option<&str> {
    element.value("name").or_else(|| node_id(element))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn mission(text: &str) -> Mission {
        Mission::new(super::super::xml::parse(text).unwrap())
    }

    #[test]
    fn trees_reached_through_subtrees() {
        let m = mission(
            r#"<root main_tree_to_execute="A">
                 <BehaviorTree ID="C"><AlwaysSuccess/></BehaviorTree>
                 <BehaviorTree ID="A"><Sequence><SubTree ID="B"/></Sequence></BehaviorTree>
                 <BehaviorTree ID="B"><SubTree ID="A"/></BehaviorTree>
               </root>"#,
        );
        let ids: Vec<&str> = m.reachable().iter().filter_map(|t| t.value("ID")).collect();
        assert_eq!(ids, ["A", "B"]);
        assert_eq!(m.reachable_nodes().count(), 3);
    }

    #[test]
    fn the_only_tree_is_the_main_tree() {
        let m = mission(
            r#"<root><BehaviorTree ID="X"><Action ID="SayText" name="1"/></BehaviorTree></root>"#,
        );
        assert_eq!(m.main_tree_id(), Some("X"));
        let say = nodes(m.main_tree().unwrap()).next().unwrap();
        assert_eq!(node_id(say), Some("SayText"));
        assert_eq!(robot_name(say), Some("1"));
        assert_eq!(model(say).map(|m| m.id), Some("SayText"));
    }
}
