//! End to end over the public corpus: `osc2cr convert <shared>/corpus -o OUT -j 2 --report`.
//! Every scenario converts or fails with a message that names what is not supported, and
//! every output passes `cr_check.py --on-road` (with the older commonroad-io as second
//! reader). Prints the number of outputs whose vehicles leave the lanelets (on-road fraction
//! < 0.99), and why, for the record.

use std::path::PathBuf;
use std::process::Command;

#[test]
fn the_whole_corpus_converts_and_every_output_passes_the_oracle() {
    let Some(shared) = testkit::shared_dir() else { return };
    let out = std::env::temp_dir().join(format!("osc2cr-corpus-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&out);
    let report = out.join("report.json");
    // a few variations per distribution keep the oracle's run short; all of them are
    // converted by the same code path
    let r = Command::new(env!("CARGO_BIN_EXE_osc2cr"))
        .arg("convert")
        .arg(shared.join("corpus"))
        .arg("-o")
        .arg(&out)
        .args(["-j", "2", "--max-variations", "5", "--report"])
        .arg(&report)
        .output()
        .expect("osc2cr runs");
    let stderr = String::from_utf8_lossy(&r.stderr);
    assert!(matches!(r.status.code(), Some(0 | 1)), "{stderr}");
    println!("{}", String::from_utf8_lossy(&r.stdout));

    let json: serde_json::Value = serde_json::from_slice(&std::fs::read(&report).expect("report")).expect("json");
    let scenarios = json["scenarios"].as_array().expect("scenarios");
    assert!(scenarios.len() >= 175, "{} scenarios", scenarios.len());
    let mut outputs = Vec::new();
    for sc in scenarios {
        let input = sc["input"].as_str().unwrap_or("?");
        match sc["status"].as_str() {
            Some("converted") => outputs.push(PathBuf::from(sc["output"].as_str().expect("output path"))),
            _ => {
                let msg = sc["failure"]["message"].as_str().unwrap_or("");
                println!("failed {input}: {msg}");
                // the message says where and what: a file position and an explanation
                assert!(msg.contains(".xosc") || msg.contains(".xodr"), "{input}: {msg}");
                assert!(msg.len() > 30, "{input}: {msg}");
            }
        }
    }
    let skipped = json["skipped"].as_array().expect("skipped");
    assert!(skipped.iter().all(|s| s["reason"].as_str().is_some_and(|r| !r.is_empty())));
    // the corpus: 175 scenarios, 6 distributions, 28 catalogs; two cannot be converted: car_walk's
    // catalogs are not shipped, and traffic_light_tests has no entity to be the ego
    assert_eq!(skipped.len(), 28, "catalogs");
    let converted_plain = scenarios.iter().filter(|s| s["variation"].is_null() && s["status"] == "converted").count();
    assert!(converted_plain >= 173, "{converted_plain} of 175 scenarios converted");
    for d in
        ["EndOfTrafficJamParameterSet", "SlowPrecedingVehicleDeterministicParameterSet", "SlowPrecedingVehicleStochasticParameterSet", "cut-in_parameter_set"]
    {
        assert!(outputs.iter().any(|p| p.to_string_lossy().contains(&format!("{d}_1.xml"))), "{d}");
    }

    let results = testkit::cr_check(&outputs, &["--on-road"]);
    let mut off_road = Vec::new();
    for res in &results {
        assert!(res.ok, "{}", res.summary());
        if let Some(min) = res.json["on_road"]["min_fraction"].as_f64() {
            if min < 0.99 {
                off_road.push(format!("{} ({min})", res.file.display()));
            }
        }
    }
    println!("{} outputs checked, {} with an on-road fraction < 0.99:", results.len(), off_road.len());
    for o in &off_road {
        println!("  {o}");
    }
    let _ = std::fs::remove_dir_all(&out);
}
