//! The version lives in one place, the workspace's Cargo.toml: the catkin manifests say the
//! same (CMake reads it from Cargo.toml itself).

use std::path::Path;

#[test]
fn the_catkin_packages_have_the_workspace_version() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let want = format!("<version>{}</version>", env!("CARGO_PKG_VERSION"));
    for manifest in [
        "crates/ekb-capi/package.xml",
        "integrations/ros/package.xml",
    ] {
        let text = std::fs::read_to_string(root.join(manifest)).unwrap();
        assert!(
            text.contains(&want),
            "{manifest} does not say {want}: give it the version of Cargo.toml"
        );
    }
}
