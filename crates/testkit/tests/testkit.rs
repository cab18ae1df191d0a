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

#[test]
fn esmini_is_found_and_run_headless_at_a_fixed_step() {
    let Some(bin) = testkit::esmini(false) else { return };
    assert!(bin.ends_with("tools/esmini/bin/esmini-3.6.0"), "{}", bin.display());
    let command = testkit::esmini_command(&bin, 0.05, std::path::Path::new("a.xosc"));
    let args: Vec<String> = command.get_args().map(|a| a.to_string_lossy().into_owned()).collect();
    assert_eq!(args, ["--headless", "--fixed_timestep", "0.05", "--osc", "a.xosc"]);
}

#[test]
fn a_stochastic_set_names_its_scenario_parameter_and_distribution() {
    let text = testkit::stochastic_set("s.xosc", "Speed", "<UniformDistribution/>");
    assert!(text.contains(r#"<ScenarioFile filepath="s.xosc"/>"#), "{text}");
    assert!(text.contains(r#"parameterName="Speed">"#) && text.contains("\n<UniformDistribution/>\n"), "{text}");
}
