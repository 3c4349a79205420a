//! How soon `ekb lsp` publishes the diagnostics of a change (BENCHMARKS.md, issue 15).
//!
//! `cargo bench --bench lsp` starts the release binary, opens a document, and then, edit
//! after edit, sends one incremental change (a letter typed into a message, or taken out)
//! and waits for the diagnostics of that version. Each round trip is timed at the client,
//! so it includes the pipe both ways and the client's JSON: an upper bound of the server's
//! own time. Two documents: the real 46-line file, and 100,000 generated locations
//! (`ekb-generate 100000`, ~62 MB). Prints the median, 95th percentile and worst, and the
//! server's processor time per change (user and system, all its threads, from
//! `/proc/PID/stat`): on a shared machine the round trips also count the time the server
//! waits for a core, the processor time does not.
//!
//! `EKB_BENCH_EDITS=N` sets the edits on the real file (default 500; a tenth of that on the
//! large one).

#[path = "../tests/lsp/client.rs"]
mod client;
#[path = "../tests/support/generate.rs"]
mod generate;

use std::time::{Duration, Instant};

use client::{position, Client};
use serde_json::json;

fn main() {
    let edits: usize = std::env::var("EKB_BENCH_EDITS")
        .ok()
        .and_then(|n| n.parse().ok())
        .unwrap_or(500);
    let real = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/fixtures/check/seed.dat"
    ))
    .unwrap();
    measure("the real file (46 lines)", &real, edits);
    let large = generate::generate(&generate::Spec::new(100_000));
    measure("100,000 locations (62 MB)", &large, (edits / 10).max(5));
}

fn measure(name: &str, text: &str, edits: usize) {
    let mut client = Client::start();
    client.initialize(json!({}));
    let uri = "untitled:bench";
    let opened = Instant::now();
    client.open(uri, text);
    client.diagnostics(uri);
    let open_time = opened.elapsed();
    let mut times = Vec::with_capacity(edits);
    let cpu_before = cpu_time(client.pid());
    for version in 2..edits as i32 + 2 {
        // On line 4 (a message): type a letter after column 35, or take it out again.
        let (end, letter) = if version % 2 == 0 {
            (35, "x")
        } else {
            (36, "")
        };
        let change = json!({
            "textDocument": {"uri": uri, "version": version},
            "contentChanges": [{"range": {"start": position(3, 35), "end": position(3, end)}, "text": letter}],
        });
        let sent = Instant::now();
        client.notify("textDocument/didChange", change);
        let published = client.take(|m| {
            m["method"] == "textDocument/publishDiagnostics" && m["params"]["version"] == version
        });
        times.push(sent.elapsed());
        assert!(!published["params"]["diagnostics"]
            .as_array()
            .unwrap()
            .is_empty());
    }
    let cpu = (cpu_time(client.pid()) - cpu_before) / edits as u32;
    times.sort();
    let at = |fraction: f64| times[((times.len() - 1) as f64 * fraction).round() as usize];
    println!(
        "{name}: open → diagnostics {}; change → diagnostics over {edits} edits: median {}, p95 {}, worst {}; server processor time per change {}",
        ms(open_time),
        ms(at(0.5)),
        ms(at(0.95)),
        ms(times[times.len() - 1]),
        ms(cpu)
    );
    assert!(client.shut_down().success());
}

fn ms(duration: Duration) -> String {
    format!("{:.2} ms", duration.as_secs_f64() * 1000.0)
}

/// The processor time a process has used, all its threads (Linux; ticks of 10 ms).
fn cpu_time(pid: u32) -> Duration {
    let stat = std::fs::read_to_string(format!("/proc/{pid}/stat")).unwrap();
    // Fields after the command name (which may hold spaces), from the third on.
    let fields: Vec<&str> = stat
        .rsplit(')')
        .next()
        .unwrap()
        .split_whitespace()
        .collect();
    let ticks: u64 = fields[11].parse::<u64>().unwrap() + fields[12].parse::<u64>().unwrap();
    Duration::from_millis(ticks * 10)
}
