//! The README as a newcomer follows it: every ```sh block is run as written, in a fresh folder
//! holding the repository's `examples/` and the binary this test suite built at
//! `target/release/osc2cr` — but for the blocks marked `<!-- not run by the README test: why -->`
//! (they need `../shared`, minutes of work, or a fixed port; the test named in the reason runs
//! each) and the `cargo build` line, whose work is this suite's own. And what a newcomer relies
//! on: one way to call the binary in every command, no placeholder, `dist/` ignored. (The
//! README's Python blocks run in `python_package/`.)

use crate::common::*;

use std::path::Path;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

const SKIP: &str = "<!-- not run by the README test:";

/// A ```sh block: its first line's number in the README, its lines, and why it is not run.
struct Block {
    line: usize,
    lines: Vec<String>,
    skipped: Option<String>,
}

fn blocks(readme: &str) -> Vec<Block> {
    let lines: Vec<&str> = readme.lines().collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < lines.len() {
        if lines[i].trim_end() == "```sh" {
            let before = lines[..i].iter().rev().find(|l| !l.trim().is_empty()).copied().unwrap_or("");
            let skipped = before.strip_prefix(SKIP).map(|r| r.trim_end_matches("-->").trim().to_string());
            let body: Vec<String> = lines[i + 1..].iter().take_while(|l| l.trim_end() != "```").map(|l| l.to_string()).collect();
            i += body.len() + 2;
            out.push(Block { line: i - body.len() - 1, lines: body, skipped });
        } else {
            i += 1;
        }
    }
    out
}

fn readme() -> String {
    std::fs::read_to_string(testkit::workspace_root().join("README.md")).expect("README.md")
}

/// Runs `script` with `sh -e` in `dir`, at most `limit`; (success, what it said).
fn sh(script: &str, dir: &Path, limit: Duration) -> (bool, String) {
    let log = dir.join(".readme-test.log");
    let file = std::fs::File::create(&log).expect("log");
    let mut child = Command::new("sh")
        .args(["-e", "-c", script])
        .current_dir(dir)
        .stdout(file.try_clone().expect("log"))
        .stderr(file)
        .stdin(Stdio::null())
        .spawn()
        .expect("sh runs");
    let start = Instant::now();
    let status = loop {
        if let Some(s) = child.try_wait().expect("wait") {
            break s;
        }
        if start.elapsed() > limit {
            let _ = child.kill();
            let _ = child.wait();
            panic!("still running after {limit:?}:\n{script}");
        }
        std::thread::sleep(Duration::from_millis(50));
    };
    (status.success(), std::fs::read_to_string(&log).unwrap_or_default())
}

#[test]
fn the_readme_commands_run_as_written() {
    let work = tmp("readme", "work");
    #[cfg(unix)]
    {
        std::os::unix::fs::symlink(testkit::workspace_root().join("examples"), work.join("examples")).expect("examples");
        std::fs::create_dir_all(work.join("target/release")).expect("target");
        std::os::unix::fs::symlink(env!("CARGO_BIN_EXE_osc2cr"), work.join("target/release/osc2cr")).expect("binary");
    }
    let all = blocks(&readme());
    let mut ran = 0;
    for b in &all {
        if let Some(why) = &b.skipped {
            assert!(!why.is_empty(), "README line {}: say why the block is not run", b.line);
            continue;
        }
        let script: Vec<&str> = b.lines.iter().map(String::as_str).filter(|l| !l.trim_start().starts_with("cargo build")).collect();
        let script = script.join("\n");
        assert!(!script.contains("../shared"), "README line {}: a block that needs ../shared is marked not run:\n{script}", b.line);
        let (ok, said) = sh(&script, &work, Duration::from_secs(180));
        assert!(ok, "README line {}:\n{script}\nsaid:\n{said}", b.line);
        ran += 1;
    }
    // the quick start, the pictures: four blocks
    assert!(ran >= 3, "{ran} blocks run");
    let written = |p: &str| work.join(p).is_file();
    for f in ["out/cut_in.xml", "out/cut_in.png", "out/cut_in.gif", "out/story.png"] {
        assert!(written(f), "{f} was not written");
    }
    // what the commands write goes into out/ (ignored by git), nothing beside the examples
    let mut top: Vec<String> = std::fs::read_dir(&work).expect("work").flatten().map(|e| e.file_name().to_string_lossy().into_owned()).collect();
    top.sort();
    assert_eq!(top, [".readme-test.log", "examples", "out", "target"]);
}

#[test]
fn the_readme_calls_the_binary_one_way_and_has_no_placeholder() {
    let text = readme();
    for b in blocks(&text) {
        for l in &b.lines {
            let first = l.split_whitespace().next().unwrap_or("");
            assert!(first != "osc2cr" && !l.contains("cargo run --release --"), "README line {}: call the binary as target/release/osc2cr: {l}", b.line);
        }
    }
    assert!(text.contains("target/release/osc2cr convert examples/cut_in.xosc -o out/"), "the quick start");
    assert!(!text.contains("<repository URL>") && !text.contains("<URL>"), "a placeholder in the README");
    // what ../shared is, and that tests skip without it
    assert!(text.contains("## The test data: `../shared`") && text.contains("skip"), "../shared is not explained");
    let ignored = std::fs::read_to_string(testkit::workspace_root().join(".gitignore")).expect(".gitignore");
    for pattern in ["/out/", "/dist/", "target/"] {
        assert!(ignored.lines().any(|l| l.trim() == pattern), "{pattern} is not in .gitignore");
    }
}
