//! The test kit against the real shared directory (skipped with a notice when it is absent).

#[test]
fn corpus_files_are_sorted_and_have_the_extension() {
    if testkit::shared_dir().is_none() {
        return;
    }
    let files = testkit::corpus_files("xodr");
    assert!(!files.is_empty());
    assert!(files.windows(2).all(|w| w[0] < w[1]));
    assert!(files.iter().all(|f| f.extension().unwrap().eq_ignore_ascii_case("xodr")));
    assert!(testkit::corpus_files("no-such-extension").is_empty());
}

#[test]
fn python_envs_exist() {
    if testkit::shared_dir().is_none() {
        return;
    }
    let envs = testkit::python_envs().unwrap();
    assert!(envs.cr.exists() && envs.crd.exists());
    // second call: cached, same answer
    assert_eq!(testkit::python_envs().unwrap(), envs);
}

#[test]
fn cr_check_reports_each_file_of_a_batch_in_order() {
    let Some(shared) = testkit::shared_dir() else {
        return;
    };
    let good = shared.join("tools/examples/minimal_2020a.xml");
    let dir = std::path::PathBuf::from(env!("CARGO_TARGET_TMPDIR"));
    let bad = dir.join("testkit-bad.xml");
    // a lanelet whose bounds differ in point count, and no planning problem
    let text = std::fs::read_to_string(&good).unwrap();
    let broken = text.replacen("<point><x>50.0</x><y>3.5</y></point>", "", 1);
    assert_ne!(broken, text);
    std::fs::write(&bad, broken).unwrap();
    let missing = dir.join("testkit-missing.xml");
    let r = testkit::cr_check(&[good.clone(), bad.clone(), missing.clone()], &[]);
    assert_eq!(r.len(), 3);
    assert_eq!(r[0].file, good);
    assert!(r[0].ok, "{}", r[0].summary());
    assert_eq!((r[0].n_errors(), r[0].n_warnings()), (0, 0));
    assert_eq!(r[1].file, bad);
    assert!(!r[1].ok);
    assert!(r[1].n_errors() >= 1, "{}", r[1].summary());
    assert!(!r[2].ok);
    assert_eq!(r[2].error_counts.get("file"), Some(&1));
}
