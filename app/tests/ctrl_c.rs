//! Ctrl+C during a long `sim` or `bench` stops it between two ticks with what it has
//! (docs/scripts.md, "Long runs"): the results so far, a trace file that ends at the last
//! tick run, exit 130.
#![cfg(unix)]

use std::io::Read;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

fn fixture(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../tests/il/valid")
        .join(name)
}

/// Waits until `ready` holds (the run is under way), then sends SIGINT.
fn interrupt_when(child: &mut Child, ready: impl Fn() -> bool) {
    let start = Instant::now();
    while !ready() {
        assert!(
            child.try_wait().unwrap().is_none(),
            "the run ended before it was interrupted"
        );
        assert!(
            start.elapsed() < Duration::from_secs(120),
            "the run never started"
        );
        std::thread::sleep(Duration::from_millis(50));
    }
    let sent = Command::new("kill")
        .args(["-INT", &child.id().to_string()])
        .status()
        .unwrap();
    assert!(sent.success());
}

fn finish(mut child: Child) -> (i32, String, String) {
    let status = child.wait().unwrap();
    let (mut out, mut err) = (String::new(), String::new());
    child
        .stdout
        .take()
        .unwrap()
        .read_to_string(&mut out)
        .unwrap();
    child
        .stderr
        .take()
        .unwrap()
        .read_to_string(&mut err)
        .unwrap();
    (status.code().expect("ended by its own exit"), out, err)
}

#[test]
fn ctrl_c_stops_a_long_sim_with_the_results_and_the_trace_so_far() {
    let dir = tempfile::tempdir().unwrap();
    let script = dir.path().join("long.script");
    let trace = dir.path().join("trace.csv");
    let mut text: String = (0..40).map(|i| format!("watch R{i:04}\n")).collect();
    text.push_str("scan 2\nexpect R0000 0\nscan 100000000\nexpect R0000 1\n");
    std::fs::write(&script, text).unwrap();
    let mut child = Command::new(env!("CARGO_BIN_EXE_ladder-studio"))
        .args(["--lang", "en", "sim"])
        .arg(fixture("functions.il"))
        .arg("--script")
        .arg(&script)
        .arg("--trace")
        .arg(&trace)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    // Rows reach the file as the ticks run: once some have, the run is in its long line.
    interrupt_when(&mut child, || {
        std::fs::metadata(&trace).is_ok_and(|m| m.len() > 64 * 1024)
    });
    let (code, out, err) = finish(child);
    assert_eq!(code, 130, "{err}");
    assert!(out.ends_with("1 passed, 0 failed\n"), "{out}");
    assert!(err.contains(":43: stopped by Ctrl+C after"), "{err}");
    let csv = std::fs::read_to_string(&trace).unwrap();
    assert!(csv.starts_with("tick,ms,R0000,"), "{}", &csv[..80]);
    let rows = csv.lines().count() - 1;
    assert!(rows > 2, "the long line's ticks are in the trace");
    let last = csv.lines().last().unwrap();
    assert!(
        last.starts_with(&format!("{rows},")),
        "the trace ends with a whole row for the last tick: {last}"
    );
}

#[test]
fn ctrl_c_stops_a_long_bench_with_the_figures_so_far() {
    let mut child = Command::new(env!("CARGO_BIN_EXE_ladder-studio"))
        .args(["--lang", "en", "bench"])
        .arg(fixture("functions.il"))
        .args(["--scans", "100000000"])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    // The handler is in place before the timing starts; the first progress line (after two
    // seconds of timing) shows the timing is running.
    let err_pipe = child.stderr.take().unwrap();
    let (tx, rx) = std::sync::mpsc::channel();
    let reader = std::thread::Builder::new()
        .name("bench stderr".into())
        .spawn(move || {
            let mut err_pipe = err_pipe;
            let mut all = Vec::new();
            let mut buf = [0u8; 256];
            loop {
                match err_pipe.read(&mut buf) {
                    Ok(0) | Err(_) => break,
                    Ok(n) => {
                        all.extend_from_slice(&buf[..n]);
                        if all.windows(5).any(|w| w == b"scans") {
                            let _ = tx.send(());
                        }
                    }
                }
            }
            String::from_utf8(all).unwrap()
        })
        .unwrap();
    let started = rx.recv_timeout(Duration::from_secs(120)).is_ok();
    assert!(started, "no progress line");
    Command::new("kill")
        .args(["-INT", &child.id().to_string()])
        .status()
        .unwrap();
    let status = child.wait().unwrap();
    let mut out = String::new();
    child
        .stdout
        .take()
        .unwrap()
        .read_to_string(&mut out)
        .unwrap();
    let err = reader.join().unwrap();
    assert_eq!(status.code(), Some(130), "{err}");
    assert!(err.contains(" of 100000000 scans ("), "{err}");
    assert!(err.contains("stopped by Ctrl+C after"), "{err}");
    let last = out.lines().last().unwrap_or_default();
    assert!(
        last.starts_with("steps=") && last.contains(" ns_per_scan="),
        "{out}"
    );
    assert!(
        !last.contains("scans=100000000 "),
        "the figures cover the scans timed: {last}"
    );
}
