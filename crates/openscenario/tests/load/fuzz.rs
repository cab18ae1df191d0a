//! No panic on any input: random mutations of corpus files must load to Ok or Err.

use crate::common;

use openscenario::{load_str, LoadOptions};
use proptest::prelude::*;
use std::path::PathBuf;
use std::sync::OnceLock;

fn corpus() -> &'static Vec<(PathBuf, String)> {
    static FILES: OnceLock<Vec<(PathBuf, String)>> = OnceLock::new();
    FILES.get_or_init(|| {
        let Some(shared) = common::shared() else { return Vec::new() };
        common::xosc_files(&shared.join("corpus")).into_iter().filter_map(|p| std::fs::read_to_string(&p).ok().map(|t| (p, t))).collect()
    })
}

/// Byte ranges of attribute values (between the quotes).
fn value_spans(text: &str) -> Vec<(usize, usize)> {
    let b = text.as_bytes();
    let mut out = Vec::new();
    let mut i = 0;
    while i + 1 < b.len() {
        if b[i] == b'=' && b[i + 1] == b'"' {
            let start = i + 2;
            if let Some(len) = b[start..].iter().position(|&c| c == b'"') {
                out.push((start, start + len));
                i = start + len;
            }
        }
        i += 1;
    }
    out
}

const NASTY: &[&str] =
    &["", "$", "${", "${(}", "${1/0}", "$$x", "-1e400", "NaN", "inf", "99999999999999999999", "-", "${$x}", "true", "a&amp;b", "${((((((1))))))}", "1e-320"];

#[derive(Debug, Clone)]
enum Mutation {
    Flip { at: usize, byte: u8 },
    Truncate { at: usize },
    Swap { a: usize, b: usize },
    Nasty { at: usize, which: usize },
    Delete { at: usize, len: usize },
}

fn mutation() -> impl Strategy<Value = Mutation> {
    prop_oneof![
        (any::<usize>(), any::<u8>()).prop_map(|(at, byte)| Mutation::Flip { at, byte }),
        any::<usize>().prop_map(|at| Mutation::Truncate { at }),
        (any::<usize>(), any::<usize>()).prop_map(|(a, b)| Mutation::Swap { a, b }),
        (any::<usize>(), 0..NASTY.len()).prop_map(|(at, which)| Mutation::Nasty { at, which }),
        (any::<usize>(), 1usize..200).prop_map(|(at, len)| Mutation::Delete { at, len }),
    ]
}

fn apply(text: &str, m: &Mutation) -> Vec<u8> {
    let mut bytes = text.as_bytes().to_vec();
    let n = bytes.len().max(1);
    match *m {
        Mutation::Flip { at, byte } => {
            if let Some(b) = bytes.get_mut(at % n) {
                *b ^= byte | 1;
            }
        }
        Mutation::Truncate { at } => bytes.truncate(at % n),
        Mutation::Delete { at, len } => {
            let s = at % n;
            let e = (s + len).min(bytes.len());
            bytes.drain(s..e);
        }
        Mutation::Swap { a, b } => {
            let spans = value_spans(text);
            if spans.len() >= 2 {
                let (x, y) = (spans[a % spans.len()], spans[b % spans.len()]);
                let (first, second) = if x.0 <= y.0 { (x, y) } else { (y, x) };
                if first.1 <= second.0 {
                    let mut out = Vec::with_capacity(bytes.len());
                    out.extend_from_slice(&bytes[..first.0]);
                    out.extend_from_slice(&bytes[second.0..second.1]);
                    out.extend_from_slice(&bytes[first.1..second.0]);
                    out.extend_from_slice(&bytes[first.0..first.1]);
                    out.extend_from_slice(&bytes[second.1..]);
                    bytes = out;
                }
            }
        }
        Mutation::Nasty { at, which } => {
            let spans = value_spans(text);
            if !spans.is_empty() {
                let (s, e) = spans[at % spans.len()];
                bytes.splice(s..e, NASTY[which].bytes());
            }
        }
    }
    bytes
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 400, ..ProptestConfig::default() })]

    #[test]
    fn mutated_corpus_files_never_panic(file in any::<usize>(), muts in proptest::collection::vec(mutation(), 1..4)) {
        let files = corpus();
        if files.is_empty() {
            return Ok(());
        }
        let (path, text) = &files[file % files.len()];
        let mut current = text.clone();
        for m in &muts {
            current = String::from_utf8_lossy(&apply(&current, m)).into_owned();
        }
        // Ok or Err, both fine: only a panic fails the test.
        let _ = load_str(path, &current, &LoadOptions::default());
    }
}
