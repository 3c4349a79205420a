//! Sets `EKB_VERSION`, what `ekb --version` prints after the name: the version of
//! Cargo.toml and, in a release build, the commit it was built from: `0.1.0 (1a2b3c4)`.
//!
//! The commit is `EKB_COMMIT` if set (for a build from a tarball or an sdist), else
//! `git rev-parse --short HEAD`; with neither (no git, not a clone) the version stands
//! alone. Debug builds leave the commit out, so that a commit does not rebuild every test.

use std::path::PathBuf;
use std::process::Command;

fn main() {
    println!("cargo:rerun-if-changed=build.rs");
    println!("cargo:rerun-if-env-changed=EKB_COMMIT");
    let version = std::env::var("CARGO_PKG_VERSION").expect("cargo sets CARGO_PKG_VERSION");
    let release = std::env::var("PROFILE").is_ok_and(|profile| profile == "release");
    let commit = if release { commit() } else { None };
    match commit {
        Some(commit) => println!("cargo:rustc-env=EKB_VERSION={version} ({commit})"),
        None => println!("cargo:rustc-env=EKB_VERSION={version}"),
    }
}

fn commit() -> Option<String> {
    if let Ok(commit) = std::env::var("EKB_COMMIT") {
        return Some(commit).filter(|commit| !commit.is_empty());
    }
    let commit = git(&["rev-parse", "--short", "HEAD"])?;
    // Built again when HEAD moves: HEAD itself, the branch it names, and packed-refs.
    let mut watched = vec![git(&["rev-parse", "--git-path", "HEAD"])?];
    if let Some(branch) = git(&["rev-parse", "--symbolic-full-name", "HEAD"]) {
        watched.extend(git(&["rev-parse", "--git-path", &branch]));
    }
    watched.extend(git(&["rev-parse", "--git-path", "packed-refs"]));
    for path in watched.into_iter().map(PathBuf::from) {
        if path.exists() {
            println!("cargo:rerun-if-changed={}", path.display());
        }
    }
    Some(commit)
}

/// The output of a git command, trimmed; `None` if git is missing or fails.
fn git(args: &[&str]) -> Option<String> {
    let output = Command::new("git").args(args).output().ok()?;
    let text = String::from_utf8(output.stdout).ok()?;
    let text = text.trim();
    (output.status.success() && !text.is_empty()).then(|| text.to_string())
}
