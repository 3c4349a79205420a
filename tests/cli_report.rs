//! `ekb report`: one self-contained page, read as markup and rendered in headless Chromium
//! (Debian's `chromium`), with no console error, every location and every finding in its
//! text, and a screenshot.

use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};
use std::time::{Duration, Instant};

const SEED: &str = "data/environmentKnowledgeBaseInput.dat";
const LAB_MAP: &str = "tests/fixtures/map/mapGenerationConfiguration.ini";

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// `ekb report FILE -o DIR/report.html ARGS`: the page.
fn report(dir: &Path, file: &str, args: &[&str]) -> (PathBuf, String) {
    let out = dir.join("report.html");
    let output = assert_cmd::cargo::cargo_bin_cmd!("ekb")
        .current_dir(root())
        .env_remove("EKB_CONFIG")
        .env_remove("EKB_READER")
        .args(["report", file, "-o", out.to_str().unwrap()])
        .args(args)
        .output()
        .unwrap();
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(0), "{stderr}");
    let page = std::fs::read_to_string(&out).unwrap();
    (out, page)
}

/// The JSON findings of `ekb check FILE` (with the map), as (line, rule, message).
fn findings(file: &str) -> Vec<(u64, String, String)> {
    let output = assert_cmd::cargo::cargo_bin_cmd!("ekb")
        .current_dir(root())
        .env_remove("EKB_CONFIG")
        .env_remove("EKB_READER")
        .args(["check", file, "--format", "json", "--map-config", LAB_MAP])
        .output()
        .unwrap();
    let json: serde_json::Value = serde_json::from_slice(&output.stdout).unwrap();
    json["diagnostics"]
        .as_array()
        .unwrap()
        .iter()
        .map(|d| {
            (
                d["line"].as_u64().unwrap(),
                d["rule"].as_str().unwrap().to_string(),
                d["message"].as_str().unwrap().to_string(),
            )
        })
        .collect()
}

/// Text as an HTML serialiser writes it.
fn html_text(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

#[test]
fn the_page_is_self_contained_accessible_and_printable() {
    let dir = tempfile::tempdir().unwrap();
    let (_, page) = report(dir.path(), SEED, &["--map-config", LAB_MAP]);
    assert!(page.starts_with("<!DOCTYPE html>\n<html lang=\"en\">"));
    assert!(page.contains("Content-Security-Policy\" content=\"default-src 'none'; style-src 'unsafe-inline'; img-src data:\""));
    for forbidden in ["<script", "<link", "@import", "http://", "https://", "url("] {
        let outside_svg_namespace = page.replace("http://www.w3.org/2000/svg", "");
        assert!(
            !outside_svg_namespace.contains(forbidden),
            "{forbidden} in the page"
        );
    }
    for expected in [
        "<h1>",
        "<h2 id=\"map-heading\">",
        "<h2 id=\"tour-heading\">",
        "<h2 id=\"translations-heading\">",
        "<h2 id=\"findings-heading\">",
        "<th scope=\"col\">",
        "<th scope=\"row\">",
        "role=\"img\" aria-labelledby=\"ekb-title ekb-desc\"",
        "<figcaption>",
        "@media print",
        "lang=\"zu\"",
        "data:image/png;base64,",
    ] {
        assert!(page.contains(expected), "{expected} not in the page");
    }
    // Placeholders, missing messages and failing ones are marked, in words too.
    assert!(page.contains("<td class=\"placeholder\" lang=\"zu\"><span class=\"tag\">placeholder</span> No message in isiZulu"));
    assert!(page.contains(
        "<td class=\"missing\"><span class=\"tag\">missing</span> the robot says nothing (line 34 has its key in the wrong case)</td>"
    ));
    assert!(page.contains("<td class=\"failing\" lang=\"en\">Welcome the the robotics lab at Carnegie Mellon University Africa <span class=\"rule\">repeated-word</span>"));
    // The status per language.
    assert!(page.contains("<tr><th scope=\"row\">isiZulu</th><td>"));
    assert!(page.contains("0 of 10 (0%)"));
    assert!(
        page.contains("9 of 10 (90%)"),
        "English: location 4's message after pointing is missing"
    );
}

#[test]
fn the_page_lists_every_location_and_every_finding() {
    let dir = tempfile::tempdir().unwrap();
    let file = "tests/fixtures/rules/pose-in-obstacle/bad.dat";
    let (_, page) = report(dir.path(), file, &["--map-config", LAB_MAP]);
    let all = findings(file);
    assert!(all.iter().any(|(_, rule, _)| rule == "pose-in-obstacle"));
    for (line, rule, message) in &all {
        let row = format!("<td><code>{rule}</code></td>");
        assert!(page.contains(&row), "no row for {rule}");
        assert!(
            page.contains(
                &html_text(message)
                    .replace('"', "&quot;")
                    .replace('\'', "&#39;")
            ),
            "no {message}"
        );
        assert!(page.contains(&format!("<td>{line}:")), "no line {line}");
    }
    for description in ["Entrance", "Pepper robot", "Lynxmotion"] {
        assert!(page.contains(&format!(" · {description}")), "{description}");
    }
}

#[test]
fn copies_of_the_english_and_failing_translations_are_marked() {
    let dir = tempfile::tempdir().unwrap();
    let (_, page) = report(
        dir.path(),
        "tests/fixtures/rules/same-as-source/bad.dat",
        &[],
    );
    assert!(
        page.contains("<td class=\"same failing\" lang=\"zu\"><span class=\"tag\">same as English</span> Welcome to the robotics lab"),
        "{page}"
    );
    let (_, page) = report(dir.path(), "tests/fixtures/rules/double-space/bad.dat", &[]);
    assert!(page.contains("<td class=\"failing\" lang=\"zu\">Siyakwamukela  elebhu yamarobhothi <span class=\"rule\">double-space</span>"));
    // The status counts them as the translations command does.
    assert!(page.contains("<tr><th scope=\"row\">isiZulu</th>"));
}

// ---------------------------------------------------------------------------------------
// In a browser

/// Debian's `chromium`, if installed. In CI (`CI` set) it must be: `.ci/run` installs it.
fn chromium() -> Option<PathBuf> {
    let found = std::env::var_os("PATH").and_then(|path| {
        std::env::split_paths(&path)
            .flat_map(|dir| ["chromium", "chromium-browser"].map(|name| dir.join(name)))
            .find(|candidate| candidate.is_file())
    });
    if found.is_none() {
        assert!(
            std::env::var_os("CI").is_none(),
            "chromium is not installed, and CI must run the browser test: .ci/run installs it (apt-get install chromium)"
        );
        eprintln!("SKIPPED: chromium is not installed (Debian: apt-get install chromium); the report was not opened in a browser");
    }
    found
}

/// Runs headless Chromium on `page` with `args`, stopped after a minute if it hangs.
fn headless(chromium: &Path, page: &Path, args: &[&str]) -> Output {
    let profile = tempfile::tempdir().unwrap();
    let mut child = Command::new(chromium)
        .args([
            "--headless",
            "--no-sandbox",
            "--disable-gpu",
            "--disable-quic",
            "--no-first-run",
            "--disable-background-networking",
            "--disable-component-update",
            "--disable-sync",
            "--enable-logging=stderr",
            "--v=0",
        ])
        .arg(format!("--user-data-dir={}", profile.path().display()))
        .args(args)
        .arg(format!("file://{}", page.display()))
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("chromium starts");
    let deadline = Instant::now() + Duration::from_secs(60);
    while child.try_wait().unwrap().is_none() {
        if Instant::now() > deadline {
            child.kill().unwrap();
            panic!("chromium did not finish within a minute");
        }
        std::thread::sleep(Duration::from_millis(50));
    }
    child.wait_with_output().unwrap()
}

/// The console messages Chromium logged (`…:INFO:CONSOLE:…] "…"`): errors, blocked loads.
fn console_messages(output: &Output) -> Vec<String> {
    String::from_utf8_lossy(&output.stderr)
        .lines()
        .filter(|line| line.contains(":CONSOLE"))
        .map(str::to_string)
        .collect()
}

#[test]
fn the_console_check_sees_errors_and_blocked_loads() {
    let Some(chromium) = chromium() else { return };
    let dir = tempfile::tempdir().unwrap();
    let page = dir.path().join("broken.html");
    std::fs::write(
        &page,
        "<!DOCTYPE html><html><head><meta http-equiv=\"Content-Security-Policy\" content=\"default-src 'none'; style-src 'unsafe-inline'; img-src data:\"></head><body><img alt=\"\" src=\"https://example.invalid/x.png\"></body></html>",
    )
    .unwrap();
    let messages = console_messages(&headless(&chromium, &page, &["--dump-dom"]));
    assert!(
        messages.iter().any(|m| m.contains("example.invalid")),
        "{messages:?}"
    );
}

#[test]
fn the_report_renders_in_chromium_without_console_errors() {
    let Some(chromium) = chromium() else { return };
    let dir = tempfile::tempdir().unwrap();
    let (page, _) = report(dir.path(), SEED, &["--map-config", LAB_MAP]);
    let dump = headless(&chromium, &page, &["--dump-dom"]);
    assert!(
        dump.status.success(),
        "{}",
        String::from_utf8_lossy(&dump.stderr)
    );
    assert_eq!(console_messages(&dump), Vec::<String>::new());
    let dom = String::from_utf8(dump.stdout).unwrap();
    assert!(
        dom.contains("<h2 id=\"map-heading\">The tour on the map</h2>"),
        "the DOM was not dumped"
    );
    for description in [
        "Pepper's starting location",
        "The (other) Pepper robot",
        "Lynxmotion",
        "Roomba",
    ] {
        assert!(
            dom.contains(&html_text(description)),
            "{description} not rendered"
        );
    }
    for (line, rule, message) in findings(SEED) {
        assert!(
            dom.contains(&format!("<td>{line}:")) && dom.contains(&format!("<code>{rule}</code>"))
        );
        assert!(dom.contains(&html_text(&message)), "{message} not rendered");
    }
    // The screenshot: a PNG of the window's size, with the page drawn on it.
    let shot = dir.path().join("report.png");
    let run = headless(
        &chromium,
        &page,
        &[
            &format!("--screenshot={}", shot.display()),
            "--window-size=1280,2400",
            "--hide-scrollbars",
        ],
    );
    assert_eq!(console_messages(&run), Vec::<String>::new());
    let decoder = png::Decoder::new(std::io::Cursor::new(
        std::fs::read(&shot).expect("a screenshot"),
    ));
    let mut reader = decoder.read_info().unwrap();
    let mut pixels = vec![0; reader.output_buffer_size().unwrap()];
    let frame = reader.next_frame(&mut pixels).unwrap();
    assert_eq!((frame.width, frame.height), (1280, 2400));
    let dark = pixels
        .chunks(frame.color_type.samples())
        .filter(|p| p[0] < 80 && p[1] < 80)
        .count();
    assert!(
        dark > 10_000,
        "the screenshot is nearly blank ({dark} dark pixels)"
    );
    // The map's blue arrows are drawn.
    let blue = pixels
        .chunks(frame.color_type.samples())
        .filter(|p| (p[0], p[1], p[2]) == (0x1f, 0x5f, 0xbf))
        .count();
    assert!(blue > 50, "no arrow in the screenshot ({blue} blue pixels)");
}
