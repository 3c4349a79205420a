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
fn the_table_lists_errors_first_each_cause_before_what_it_causes() {
    let dir = tempfile::tempdir().unwrap();
    let (_, page) = report(dir.path(), SEED, &[]);
    let table = &page[page.find("<table class=\"findings\">").unwrap()..];
    let rules: Vec<&str> = table
        .split("<td><code>")
        .skip(1)
        .map(|row| &row[..row.find("</code>").unwrap()])
        .collect();
    assert_eq!(
        rules[..3],
        ["key-case", "missing-field", "repeated-word"],
        "{rules:?}"
    );
    assert!(
        table.contains("<caption>Every finding: errors first, each after what causes it</caption>")
    );
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
    assert!(page.contains("<td class=\"failing\" lang=\"zu\"><span class=\"badge fails\" title=\"double-space: two or more spaces in a row inside a message, in any language\">fails: double-space</span> Siyakwamukela  elebhu yamarobhothi <span class=\"line\">"));
    // The status counts them as the translations command does.
    assert!(page.contains("<tr><th scope=\"row\">isiZulu</th>"));
}

const STALE_AND_FAILING: &str = "tests/fixtures/report/stale-and-failing.dat";
const STALE_PO: &str = "tests/fixtures/report/stale-and-failing.zu.po";

/// One message cell of the tour: where it is, its classes, and its badges as (text, title).
#[derive(Debug)]
struct Cell {
    location: u32,
    phase: String,
    lang: String,
    classes: Vec<String>,
    badges: Vec<(String, String)>,
}

/// The message cells of the page's tour, each `<td>` parsed as XML (what the page writes
/// inside a cell is well-formed).
fn message_cells(page: &str) -> Vec<Cell> {
    let mut cells = Vec::new();
    for article in page.split("<article class=\"stop\" id=\"location-").skip(1) {
        let location = article[..article.find('"').unwrap()].parse().unwrap();
        let article = &article[..article.find("</article>").unwrap()];
        for row in article.split("<tr><th scope=\"row\">").skip(1) {
            let phase = row[..row.find(" pointing</th>").unwrap()].to_string();
            for td in row.split("<td").skip(1) {
                let td = format!("<td{}</td>", &td[..td.find("</td>").unwrap()]);
                let doc = roxmltree::Document::parse(&td).unwrap_or_else(|e| panic!("{e}: {td}"));
                let cell = doc.root_element();
                let badges = cell
                    .children()
                    .filter(|n| {
                        n.attribute("class")
                            .is_some_and(|c| c.starts_with("badge "))
                    })
                    .map(|n| {
                        let title = n.attribute("title").expect("a badge has a title");
                        (n.text().unwrap().to_string(), title.to_string())
                    })
                    .collect();
                cells.push(Cell {
                    location,
                    phase: phase.clone(),
                    lang: cell.attribute("lang").unwrap_or("").to_string(),
                    classes: cell
                        .attribute("class")
                        .unwrap_or("")
                        .split_whitespace()
                        .map(str::to_string)
                        .collect(),
                    badges,
                });
            }
        }
    }
    cells
}

#[test]
fn stale_and_failing_translations_are_marked_on_exactly_their_cells() {
    let dir = tempfile::tempdir().unwrap();
    let (_, page) = report(dir.path(), STALE_AND_FAILING, &["--po", STALE_PO]);
    let cells = message_cells(&page);
    assert_eq!(
        cells.len(),
        2 * 2 * 3,
        "two locations, two messages, three languages"
    );
    for cell in &cells {
        let at = (cell.location, cell.phase.as_str(), cell.lang.as_str());
        let texts: Vec<&str> = cell.badges.iter().map(|(text, _)| text.as_str()).collect();
        match at {
            // The PO file says it was made for "Welcome to the lab".
            (1, "Before", "zu") => {
                assert_eq!(texts, ["stale"], "{cell:?}");
                assert!(cell.classes.contains(&"stale".to_string()), "{cell:?}");
                assert!(!cell.classes.contains(&"failing".to_string()), "{cell:?}");
                assert_eq!(
                    cell.badges[0].1,
                    format!("stale: translated from \"Welcome to the lab\", an English text that has since changed ({STALE_PO}:7)")
                );
            }
            // The English asks, the isiZulu does not.
            (2, "After", "zu") => {
                assert_eq!(texts, ["fails: end-punctuation-mismatch"], "{cell:?}");
                assert_eq!(cell.classes, ["failing"], "{cell:?}");
                assert!(cell.badges[0]
                    .1
                    .starts_with("end-punctuation-mismatch: `.` `?`"));
            }
            // Everything else is clean: the PO file's current entry (location 1 after) and
            // its stale entry whose translation the file no longer has (location 2 before)
            // mark nothing.
            _ => {
                assert!(texts.is_empty(), "{cell:?}");
                assert_eq!(cell.classes, [""; 0], "{cell:?}");
            }
        }
    }
    // The same facts as `ekb translations`: one isiZulu message fails a check.
    assert!(page.contains("<tr><th scope=\"row\">isiZulu</th>"));
    // The legend says what each mark means, in words.
    for legend in [
        "<span class=\"badge stale\">stale</span> translated from an English text that has since changed, as the translators' PO files given say",
        "<span class=\"badge fails\">fails: RULE</span> the message fails that translation rule",
    ] {
        assert!(page.contains(legend), "{legend}");
    }
    // Print styles are intact, and the marks are styled.
    let style = &page[page.find("<style>").unwrap()..page.find("</style>").unwrap()];
    for rule in ["@media print", ".badge.stale", ".badge.fails", "td.stale"] {
        assert!(style.contains(rule), "{rule}");
    }
}

#[test]
fn without_a_po_file_nothing_is_stale_and_the_legend_says_how_to_tell() {
    let dir = tempfile::tempdir().unwrap();
    let (_, page) = report(dir.path(), STALE_AND_FAILING, &[]);
    let marked: Vec<Cell> = message_cells(&page)
        .into_iter()
        .filter(|cell| !cell.badges.is_empty())
        .collect();
    assert_eq!(marked.len(), 1, "{marked:?}");
    let (cell, badge) = (&marked[0], &marked[0].badges[0].0);
    assert_eq!(
        (cell.location, cell.lang.as_str(), badge.as_str()),
        (2, "zu", "fails: end-punctuation-mismatch")
    );
    assert!(page.contains("(no PO file was given: <code>ekb report --po zu.po</code> tells)"));
}

#[test]
fn a_po_file_of_another_knowledge_base_is_an_error() {
    let dir = tempfile::tempdir().unwrap();
    let po = dir.path().join("other.po");
    let text = std::fs::read_to_string(root().join(STALE_PO)).unwrap();
    std::fs::write(
        &po,
        text.replace(
            "location 2 preGestureMessage",
            "location 9 preGestureMessage",
        ),
    )
    .unwrap();
    let out = dir.path().join("report.html");
    let output = assert_cmd::cargo::cargo_bin_cmd!("ekb")
        .current_dir(root())
        .env_remove("EKB_CONFIG")
        .args([
            "report",
            STALE_AND_FAILING,
            "--po",
            po.to_str().unwrap(),
            "-o",
            out.to_str().unwrap(),
        ])
        .output()
        .unwrap();
    assert_eq!(output.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(
        stderr.contains("other.po:17: unknown `msgctxt \"location 9 preGestureMessage\"`: the file has no such location"),
        "{stderr}"
    );
    assert!(!out.exists(), "no page is written");
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
    // The stale and failing marks render too.
    let (marked, _) = report(dir.path(), STALE_AND_FAILING, &["--po", STALE_PO]);
    let dump = headless(&chromium, &marked, &["--dump-dom"]);
    assert_eq!(console_messages(&dump), Vec::<String>::new());
    let dom = String::from_utf8(dump.stdout).unwrap();
    assert!(
        dom.contains(">stale</span>") && dom.contains(">fails: end-punctuation-mismatch</span>")
    );
    let (page, _) = report(dir.path(), SEED, &["--map-config", LAB_MAP]);
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

#[test]
fn the_page_shows_at_most_500_stops_and_500_unvisited_locations() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("many.dat");
    let mut text: String = (1..=1_200)
        .map(|id| format!("robotLocationDescription {id} Place {id}\n"))
        .collect();
    let tour: Vec<String> = (0..700).map(|i| (i % 5 + 1).to_string()).collect();
    text += &format!("tourSpecification 700 {}\n", tour.join(" "));
    std::fs::write(&file, text).unwrap();
    let (_, page) = report(dir.path(), file.to_str().unwrap(), &[]);
    assert_eq!(page.matches("<article class=\"stop\"").count(), 1_000);
    assert!(page.contains("200 more stops are not shown: a page shows at most 500"));
    assert!(page.contains("695 more locations no stop visits are not shown"));
}

#[test]
fn a_language_the_robot_does_not_speak_is_marked_not_spoken_on_its_column() {
    let badge = "<th scope=\"col\" lang=\"zu\">isiZulu <span class=\"badge silent\" \
                 title=\"the robot does not speak isiZulu: it says nothing at these stops (its \
                 text-to-speech has no isiZulu engine; `[robot] speaks` in ekb.toml says \
                 otherwise if yours does)\">not spoken</span></th>";
    let dir = tempfile::tempdir().unwrap();
    let (_, page) = report(dir.path(), SEED, &[]);
    assert!(page.contains(badge), "no isiZulu badge");
    // One column header per stop's table, each marked; the spoken languages are not.
    let stops = page.matches("<table class=\"messages\">").count();
    assert_eq!(page.matches(badge).count(), stops);
    assert!(page.contains("<th scope=\"col\" lang=\"rw\">Kinyarwanda</th>"));
    assert!(page.contains("<th scope=\"col\" lang=\"en\">English</th>"));
    // Once ekb.toml says the robot speaks isiZulu, nothing is marked.
    let file = dir.path().join("kb.dat");
    std::fs::copy(root().join(SEED), &file).unwrap();
    std::fs::write(
        dir.path().join("ekb.toml"),
        "[robot]\nspeaks = [\"english\", \"isiZulu\", \"kinyarwanda\"]\n",
    )
    .unwrap();
    let (_, page) = report(dir.path(), file.to_str().unwrap(), &[]);
    assert!(!page.contains("not spoken"));
    assert!(page.contains("<th scope=\"col\" lang=\"zu\">isiZulu</th>"));
}

#[test]
fn the_page_charts_the_tour_in_time_for_each_language() {
    let dir = tempfile::tempdir().unwrap();
    let (_, page) = report(
        dir.path(),
        "tests/fixtures/corpus/upstream-2025-06-environmentKnowledgeBaseInput.dat",
        &[
            "--map-config",
            "tests/fixtures/map/mapGenerationConfiguration.ini",
        ],
    );
    let section = &page[page.find("<section id=\"time\"").expect("the section")..];
    let section = &section[..section.find("</section>").unwrap()];
    for language in ["English", "isiZulu", "Kinyarwanda"] {
        assert!(
            section.contains(&format!("<g data-language=\"{language}\">")),
            "{language}"
        );
    }
    // isiZulu is silent: its bar is the driving alone, and the table says why.
    assert!(section.contains("35 s (silent)"), "{section}");
    assert!(section.contains("silent: the robot does not speak it"));
    assert!(section.contains("each leg as the robot's planner drives it on the map"));
    // Each segment says what it is.
    assert!(
        section.contains("<title>Stop 2, location 4: driving, 13 s</title>"),
        "{section}"
    );
    assert!(!section.contains("cannot drive there"));
}
