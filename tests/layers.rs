//! The layers point one way (issue 11): the model is built with no knowledge of the rules
//! or of the check that runs them. The builder reports facts through
//! `ekb::model::build::LineFindings`, which the rules implement.

use std::path::Path;

#[test]
fn the_model_names_neither_the_rules_nor_the_check() {
    let model = Path::new(env!("CARGO_MANIFEST_DIR")).join("src/model");
    let mut read = 0;
    let mut stack = vec![model];
    while let Some(dir) = stack.pop() {
        for entry in std::fs::read_dir(&dir).expect("src/model is readable") {
            let path = entry.expect("an entry").path();
            if path.is_dir() {
                stack.push(path);
                continue;
            }
            if path.extension().is_none_or(|ext| ext != "rs") {
                continue;
            }
            let source = std::fs::read_to_string(&path).expect("a source file");
            read += 1;
            for (number, line) in (1..).zip(source.lines()) {
                for upper in ["crate::rules", "crate::check", "ekb::rules", "ekb::check"] {
                    assert!(
                        !line.contains(upper),
                        "{}:{number} names `{upper}`, a layer above the model: {line}",
                        path.display()
                    );
                }
                // `use crate::{check, rules}` and the like.
                let code = line.trim_start();
                if code.starts_with("use crate::{") || code.starts_with("pub use crate::{") {
                    for upper in ["check", "rules"] {
                        assert!(
                            !code
                                .split(['{', '}', ',', ' ', ':'])
                                .any(|name| name == upper),
                            "{}:{number} names `{upper}`: {line}",
                            path.display()
                        );
                    }
                }
            }
        }
    }
    assert!(read >= 5, "found only {read} source files under src/model");
}
