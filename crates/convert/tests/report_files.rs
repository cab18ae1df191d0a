//! The batch's report files: `--report` to a pipe or device (`/dev/null`) is written in place,
//! never renamed over — a rename would leave a regular file where the pipe was.

use convert::JsonReport;

#[test]
fn a_json_report_into_a_pipe_goes_through_it() {
    let dir = testkit::ScratchDir::new("convert-report-fifo");
    let path = dir.join("report.json");
    let Some(fifo) = testkit::Fifo::new(&path) else { return };
    let report = JsonReport::create(&path).expect("created");
    report.finish(&[], &[], 0).expect("finished");
    let text = String::from_utf8(fifo.received()).expect("utf-8");
    assert!(text.starts_with("{\n\"scenarios\": [") && text.contains("\"planned\": 0"), "{text}");
    let names: Vec<_> = std::fs::read_dir(&dir).expect("dir").flatten().map(|e| e.file_name()).collect();
    assert_eq!(names, ["report.json"], "a temporary file was left beside the pipe");
}
