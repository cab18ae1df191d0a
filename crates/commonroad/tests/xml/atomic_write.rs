//! `write_atomic`: the target holds the old or the new bytes, never a mix, and no temporary
//! file is left behind.

use std::path::PathBuf;

use commonroad::xml::write_atomic;
use commonroad::Error;

fn fresh_dir(name: &str) -> PathBuf {
    let d = PathBuf::from(env!("CARGO_TARGET_TMPDIR")).join("atomic").join(name);
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

fn entries(dir: &PathBuf) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(dir).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
    v.sort();
    v
}

/// `write_atomic` of `bytes` to `out.xml` in `d`: the file holds them and is all the folder holds.
fn writes_only(d: &PathBuf, bytes: &[u8]) {
    let p = d.join("out.xml");
    write_atomic(&p, bytes).unwrap();
    assert_eq!(std::fs::read(&p).unwrap(), bytes);
    assert_eq!(entries(d), vec!["out.xml"]);
}

#[test]
fn writes_new_file_and_leaves_nothing_else() {
    let d = fresh_dir("new");
    writes_only(&d, b"hello");
}

#[test]
fn replaces_an_existing_file_whole() {
    let d = fresh_dir("replace");
    let p = d.join("out.xml");
    std::fs::write(&p, vec![b'x'; 10_000]).unwrap();
    writes_only(&d, b"short");
}

#[test]
fn missing_directory_is_an_error_naming_a_path_and_creates_nothing() {
    let d = fresh_dir("missing");
    let p = d.join("no/such/dir/out.xml");
    match write_atomic(&p, b"x") {
        Err(Error::WriteFile { path, .. }) => assert!(path.starts_with(d.join("no/such/dir")), "{}", path.display()),
        other => panic!("expected Io error, got {other:?}"),
    }
    assert!(entries(&d).is_empty());
}

#[test]
fn target_that_is_a_directory_fails_and_the_temp_file_is_removed() {
    let d = fresh_dir("isdir");
    let p = d.join("taken");
    std::fs::create_dir(&p).unwrap();
    std::fs::write(p.join("inside"), b"keep").unwrap();
    let err = write_atomic(&p, b"x").unwrap_err();
    assert!(err.to_string().contains("taken"), "{err}");
    assert_eq!(entries(&d), vec!["taken"]);
    assert_eq!(std::fs::read(p.join("inside")).unwrap(), b"keep");
}

#[test]
fn concurrent_writers_leave_one_complete_version() {
    let d = fresh_dir("concurrent");
    let p = d.join("out.xml");
    let payloads: Vec<Vec<u8>> = (0..4u8).map(|i| vec![b'a' + i; 1 << 20]).collect();
    std::thread::scope(|s| {
        for bytes in &payloads {
            let p = &p;
            s.spawn(move || write_atomic(p, bytes).unwrap());
        }
    });
    let got = std::fs::read(&p).unwrap();
    assert!(payloads.contains(&got), "file is a mix of writers");
    assert_eq!(entries(&d), vec!["out.xml"]);
}

#[test]
fn a_path_without_file_name_is_an_error() {
    assert!(matches!(write_atomic(std::path::Path::new("/"), b"x"), Err(Error::WriteFile { .. })));
}

/// A pipe (like a device such as `/dev/null`) is written in place: a rename over it would leave
/// a regular file where the pipe was (as root, over `/dev/null`, a broken machine).
#[test]
fn a_fifo_target_is_written_in_place_and_stays_a_fifo() {
    let d = fresh_dir("fifo");
    let p = d.join("pipe");
    let Some(fifo) = testkit::Fifo::new(&p) else { return };
    assert!(commonroad::xml::is_special_file(&p));
    write_atomic(&p, b"through the pipe").unwrap();
    assert_eq!(fifo.received(), b"through the pipe");
    assert_eq!(entries(&d), vec!["pipe"]);
    assert!(!commonroad::xml::is_special_file(&d.join("absent")));
}
