//! Hostile input: mutated corpus files never make the loader (or the queries) panic.

use crate::common;

use proptest::prelude::*;

fn base_text() -> Option<String> {
    let dir = common::shared_dir()?;
    std::fs::read_to_string(dir.join("corpus/esmini/xodr/fabriksgatan.xodr")).ok()
}

#[derive(Debug, Clone)]
enum Mutation {
    Delete(usize, usize),
    Insert(usize, String),
    Replace(usize, String),
    Duplicate(usize, usize),
}

fn mutation() -> impl Strategy<Value = Mutation> {
    let junk = prop_oneof![
        Just("<".to_string()),
        Just("\"".to_string()),
        Just("NaN".to_string()),
        Just("-1e308".to_string()),
        Just("1e400".to_string()),
        Just("</lane>".to_string()),
        Just("<road id=\"x\" length=\"-5\">".to_string()),
        Just("<geometry s=\"0\" x=\"0\" y=\"0\" hdg=\"0\" length=\"1e12\"><spiral curvStart=\"1e9\" curvEnd=\"-1e9\"/></geometry>".to_string()),
        "[ -~]{0,12}",
    ];
    prop_oneof![
        (0usize..1_000_000, 0usize..200).prop_map(|(a, n)| Mutation::Delete(a, n)),
        (0usize..1_000_000, junk.clone()).prop_map(|(a, s)| Mutation::Insert(a, s)),
        (0usize..1_000_000, junk).prop_map(|(a, s)| Mutation::Replace(a, s)),
        (0usize..1_000_000, 1usize..2000).prop_map(|(a, n)| Mutation::Duplicate(a, n)),
    ]
}

fn apply(text: &str, muts: &[Mutation]) -> String {
    let mut b = text.as_bytes().to_vec();
    for m in muts {
        let len = b.len().max(1);
        match m {
            Mutation::Delete(a, n) => {
                let a = a % len;
                let e = (a + n).min(b.len());
                b.drain(a.min(b.len())..e);
            }
            Mutation::Insert(a, s) => {
                let a = (a % len).min(b.len());
                b.splice(a..a, s.bytes());
            }
            Mutation::Replace(a, s) => {
                let a = (a % len).min(b.len());
                let e = (a + s.len()).min(b.len());
                b.splice(a..e, s.bytes());
            }
            Mutation::Duplicate(a, n) => {
                let a = (a % len).min(b.len());
                let e = (a + n).min(b.len());
                let piece: Vec<u8> = b[a..e].to_vec();
                b.splice(e..e, piece);
            }
        }
    }
    String::from_utf8_lossy(&b).into_owned()
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 200, ..ProptestConfig::default() })]
    #[test]
    fn mutated_corpus_file_never_panics(muts in proptest::collection::vec(mutation(), 1..4)) {
        let Some(text) = base_text() else { return Ok(()) };
        let mutated = apply(&text, &muts);
        if let Ok(loaded) = opendrive::parse_str(&mutated, std::path::Path::new("mutated.xodr")) {
            let n = &loaded.network;
            for (i, r) in n.roads.iter().enumerate() {
                let p = n.lane_to_world(i, -1, r.length * 0.5, 0.0);
                if let Some(p) = p {
                    let _ = n.world_to_lane(p.x, p.y, Some(i));
                    let _ = n.lanes_containing(p.x, p.y);
                }
                for sec in 0..r.lane_sections.len() {
                    let _ = n.lane_successors(opendrive::LaneRef { road: i, section: sec, lane: -1 });
                    let _ = n.lane_predecessors(opendrive::LaneRef { road: i, section: sec, lane: 1 });
                }
            }
            let _ = n.world_to_lane(1e12, -1e12, None);
        }
    }
}
