//! Strict reading accepts what esmini accepts: no corpus file (scenario or distribution, and
//! every run of a distribution) has a problem a strict reading would stop it for.

use crate::common;

use openscenario::{load, Content, LoadOptions};

#[test]
fn corpus_has_no_unresolved_reference() {
    let Some(shared) = common::shared() else { return };
    let corpus = shared.join("corpus");
    let mut found = Vec::new();
    let mut checked = 0;
    for f in common::xosc_files(&corpus) {
        let Ok(loaded) = load(&f, &LoadOptions::default()) else { continue };
        checked += 1;
        found.extend(loaded.problems.iter().map(ToString::to_string));
        if let Content::Distribution(d) = &loaded.content {
            // the first run of each distribution: its parameters must be declared by the scenario
            if let (Some(options), true) = (d.run_options(0, &LoadOptions::default()), d.scenario_file.is_file()) {
                if let Ok(run) = load(&d.scenario_file, &options) {
                    found.extend(run.problems.iter().map(ToString::to_string));
                }
            }
        }
    }
    assert!(checked >= 140, "only {checked} corpus files loaded");
    assert!(found.is_empty(), "{} problems in the corpus:\n{}", found.len(), found.join("\n"));
}
