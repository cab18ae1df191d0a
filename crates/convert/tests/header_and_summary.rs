//! Benchmark ids, dates, and the summary table.

use convert::{benchmark_id, check_country, date_prefix, parse_date, render_summary, summarise};
use convert::{Facts, ScenarioReport, Status, Timings};
use std::path::PathBuf;

#[test]
fn benchmark_ids_keep_only_letters_and_digits() {
    let id = |name: &str, k| benchmark_id("ZAM", name, k).expect("valid").to_string();
    assert_eq!(id("cut-in_01", 1), "ZAM_cutin01-1_1_T-1");
    assert_eq!(id("Pedestrian Collision", 1), "ZAM_PedestrianCollision-1_1_T-1");
    assert_eq!(id("ÄÖ-ü", 1), "ZAM_Scenario-1_1_T-1", "nothing ASCII left");
    assert_eq!(id("x", 7), "ZAM_x-1_7_T-1", "variation = configuration id");
    assert_eq!(id("x", 0), "ZAM_x-1_1_T-1");
    assert_eq!(benchmark_id("DEU", "a_b", 1).expect("valid").to_string(), "DEU_ab-1_1_T-1");
    assert!(check_country("DEU").is_ok());
    assert!(check_country("de").is_err() && check_country("DEUT").is_err());
    // Shaped right but not a country: commonroad-io would refuse the file.
    assert!(check_country("XYZ").is_err() && check_country("GER").is_err());
    assert!(check_country("ZAM").is_ok() && check_country("SWE").is_ok());
}

#[test]
fn dates_come_from_the_file_header_or_the_option() {
    assert_eq!(date_prefix("2020-03-20T12:00:00").map(|d| d.to_string()), Some("2020-03-20".into()));
    assert_eq!(date_prefix("2021-12-01").map(|d| d.to_string()), Some("2021-12-01".into()));
    assert_eq!(date_prefix("2020-02-30T00:00:00"), None);
    assert_eq!(date_prefix("20-03-2020"), None);
    assert_eq!(date_prefix(""), None);
    assert_eq!(parse_date("2026-01-15").map(|d| d.to_string()), Ok("2026-01-15".into()));
    assert!(parse_date("2026-01-15T00:00").is_err());
    assert!(parse_date("today").is_err());
}

fn report(folder: &str, ok: bool, ms: f64, dur: f64) -> ScenarioReport {
    ScenarioReport {
        input: PathBuf::from("x.xosc"),
        folder: folder.into(),
        output: None,
        dynamic: None,
        map: None,
        variation: None,
        status: if ok { Status::Converted } else { Status::Failed },
        failure: None,
        warnings: Vec::new(),
        timings: Timings { total_ms: ms, ..Timings::default() },
        facts: Facts { duration_s: Some(dur), ..Facts::default() },
        picture: None,
    }
}

#[test]
fn summary_per_folder() {
    let rows = summarise(&[report("b", true, 10.0, 20.0), report("a", true, 4.0, 8.0), report("b", false, 1000.0, 1000.0), report("b", true, 20.0, 10.0)]);
    assert_eq!(rows.len(), 3);
    assert_eq!((rows[0].folder.as_str(), rows[0].scenarios, rows[0].converted), ("a", 1, 1));
    let b = &rows[1];
    assert_eq!((b.scenarios, b.converted), (3, 2));
    assert!((b.success_rate - 2.0 / 3.0).abs() < 1e-12);
    assert_eq!(b.mean_conversion_ms, Some(15.0), "failures do not count");
    assert_eq!(b.mean_duration_s, Some(15.0));
    let all = &rows[2];
    assert_eq!((all.folder.as_str(), all.scenarios, all.converted), ("all", 4, 3));
    let text = render_summary(&rows);
    assert!(text.contains("66.7 %") && text.contains("15.0 ms"), "{text}");
}

#[test]
fn a_conversion_complete_from_an_earlier_run_counts_as_converted_without_a_time() {
    let mut complete = report("a", true, 500.0, 500.0);
    complete.status = Status::Complete;
    let rows = summarise(&[report("a", true, 10.0, 20.0), complete, report("a", false, 1.0, 1.0)]);
    assert_eq!((rows[0].scenarios, rows[0].converted), (3, 2));
    assert_eq!(rows[0].mean_conversion_ms, Some(10.0), "only this run's conversions are timed");
    assert_eq!(rows[0].mean_duration_s, Some(20.0));
}
