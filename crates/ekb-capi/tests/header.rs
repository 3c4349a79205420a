//! The committed header `include/ekb.h` is what cbindgen makes of `src/lib.rs`.
//!
//! `EKB_BLESS=1 cargo test -p ekb-capi --test header` (scripts/generate-ekb-header.sh)
//! writes it anew.

use std::path::Path;

#[test]
fn the_committed_header_is_up_to_date() {
    let crate_dir = Path::new(env!("CARGO_MANIFEST_DIR"));
    let config = cbindgen::Config::from_file(crate_dir.join("cbindgen.toml")).unwrap();
    let mut generated = Vec::new();
    cbindgen::Builder::new()
        .with_crate(crate_dir)
        .with_config(config)
        .generate()
        .expect("cbindgen reads src/lib.rs")
        .write(&mut generated);
    let generated = String::from_utf8(generated).unwrap();
    let committed_path = crate_dir.join("include/ekb.h");
    if std::env::var_os("EKB_BLESS").is_some() {
        std::fs::write(&committed_path, &generated).unwrap();
    }
    let committed = std::fs::read_to_string(&committed_path).unwrap_or_default();
    assert!(
        committed == generated,
        "include/ekb.h is out of date: run scripts/generate-ekb-header.sh and commit it"
    );
}
