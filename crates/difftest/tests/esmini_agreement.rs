//! A handful of generated scenarios against esmini 3.6.0, when its binary is in
//! `../shared/tools/esmini` (the long runs are `difftest measure`: README).

use difftest::compare::Verdict;

use crate::common::tmp;

#[test]
fn agrees_with_esmini_on_a_few() {
    let Some(shared) = testkit::shared_dir() else { return };
    let esmini = shared.join("tools/esmini/bin/esmini-3.6.0");
    if !esmini.is_file() {
        assert!(std::env::var_os("CI").is_none(), "CI has the esmini binary in ../shared");
        eprintln!("notice: no esmini binary; comparison skipped");
        return;
    }
    let plan = difftest::Plan { seed: 1, count: 12, out: tmp("esmini"), esmini: Some(esmini), maps: None, max_maps: 0, osc2cr: None };
    let outcomes = difftest::run(&plan, |_, _| {}).expect("runs");
    // esmini accepts every scenario: it runs them all, and logs no error
    let compared = outcomes.iter().filter(|o| o.verdict.is_some()).count();
    assert_eq!(compared, 12, "every scenario ran in esmini: {outcomes:#?}");
    let agree = outcomes.iter().filter(|o| matches!(o.verdict, Some(Verdict::Exact | Verdict::Close))).count();
    // measured AGREED of these 12 with the widened grammar (the first grammar: 11 of its 12)
    assert!(agree >= AGREED, "{agree} of 12 agree: {outcomes:#?}");
}

const AGREED: usize = 4;
