//! Parameter value distributions: sizes computed by hand, lazy access, seeded sampling.

use crate::common;

use openscenario::*;
use std::path::Path;

fn distribution(path: &Path, seed: Option<u64>) -> Distribution {
    match load(path, &LoadOptions { parameters: Vec::new(), seed, ..Default::default() }) {
        Ok(Loaded { content: Content::Distribution(d), .. }) => d,
        Ok(_) => panic!("{}: not a distribution", path.display()),
        Err(e) => panic!("{e}"),
    }
}

fn value<'a>(set: &'a [(String, String)], name: &str) -> Option<&'a str> {
    set.iter().find(|(n, _)| n == name).map(|(_, v)| v.as_str())
}

#[test]
fn corpus_distribution_sizes() {
    let Some(shared) = common::shared() else { return };
    let c = shared.join("corpus");
    // By hand from the files:
    // - value sets: 1, 2 and 2 ParameterValueSets;
    // - stochastic: numberOfTestRuns="100";
    // - cut-in: 2 value sets x 2 EgoSpeed values x TargetSpeedFactor 1.1..1.5 step 0.2 (3) = 12.
    let expected = [
        ("osc-examples-1.2/EndOfTrafficJamParameterSet.xosc", 2),
        ("osc-examples-1.2/SlowPrecedingVehicleDeterministicParameterSet.xosc", 1),
        ("osc-examples-1.2/SlowPrecedingVehicleStochasticParameterSet.xosc", 100),
        ("osc-examples-1.3/SlowPrecedingVehicleDeterministicParameterSet.xosc", 2),
        ("osc-examples-1.3/SlowPrecedingVehicleStochasticParameterSet.xosc", 100),
        ("esmini/xosc/cut-in_parameter_set.xosc", 12),
    ];
    for (file, n) in expected {
        let d = distribution(&c.join(file), None);
        assert_eq!(d.len(), n, "{file}");
        assert_eq!(d.iter().count() as u64, n, "{file}");
        assert!(d.scenario_file.is_file(), "{file}");
    }
}

#[test]
fn cut_in_runs_in_odometer_order_and_every_run_loads() {
    let Some(shared) = common::shared() else { return };
    let d = distribution(&shared.join("corpus/esmini/xosc/cut-in_parameter_set.xosc"), None);
    let runs: Vec<_> = d.iter().collect();
    // Last factor fastest: TargetSpeedFactor cycles 1.1, 1.3, 1.5 within EgoSpeed, within the value set.
    let factors: Vec<_> = runs.iter().map(|r| value(r, "TargetSpeedFactor").unwrap_or("")).collect();
    assert_eq!(&factors[..6], ["1.1", "1.3", "1.5", "1.1", "1.3", "1.5"]);
    assert_eq!(value(&runs[3], "EgoSpeed"), Some("110.0"));
    assert_eq!(value(&runs[0], "HostVehicle"), Some("car_blue"));
    assert_eq!(value(&runs[6], "HostVehicle"), None); // the second set leaves it at its default
    assert_eq!(value(&runs[6], "TargetVehicle"), Some("van_red"));
    for (i, run) in runs.iter().enumerate() {
        let options = LoadOptions { parameters: run.clone(), seed: None, ..Default::default() };
        let (s, w) = load_scenario(&d.scenario_file, &options).unwrap_or_else(|e| panic!("run {i}: {e}"));
        assert!(w.is_empty(), "run {i}: {w:?}");
        let factor: f64 = value(run, "TargetSpeedFactor").and_then(|v| v.parse().ok()).expect("factor");
        let p = s.parameters.iter().find(|p| p.name == "TargetSpeedFactor").expect("declared");
        assert_eq!(p.as_f64(), Some(factor));
        let target = if i < 6 { "car_yellow" } else { "van_red" };
        let EntityObject::Vehicle(v) = &s.entities[1].object else { panic!() };
        assert_eq!(v.name, target, "run {i}");
    }
}

#[test]
fn stochastic_runs_are_seeded_and_respect_the_distributions() {
    let Some(shared) = common::shared() else { return };
    let f = shared.join("corpus/osc-examples-1.3/SlowPrecedingVehicleStochasticParameterSet.xosc");
    let a: Vec<_> = distribution(&f, None).iter().collect();
    let b: Vec<_> = distribution(&f, None).iter().collect();
    assert_eq!(a, b, "same seed, same runs");
    let c: Vec<_> = distribution(&f, Some(7)).iter().collect();
    assert_ne!(a, c, "another seed, other runs");
    let allowed = ["10.0", "22.0", "25.0", "27.0", "28.0", "40.0", "60.0"];
    let mut count_60 = 0;
    for run in &a {
        let ego = value(run, "Ego_Speed").expect("Ego_Speed");
        assert!(allowed.contains(&ego), "{ego}");
        count_60 += usize::from(ego == "60.0");
        let a1: f64 = value(run, "A1_Speed").and_then(|v| v.parse().ok()).expect("A1_Speed");
        assert!((15.0..=30.0).contains(&a1), "truncated to its Range: {a1}");
    }
    // Weight 1 of 35: expected 100/35 ≈ 2.9 of 100 runs; far more would mean the weights are ignored.
    assert!(count_60 < 15, "{count_60}");
    let d = distribution(&f, None);
    assert_eq!(d.get(42), Some(a[42].clone()), "random access equals iteration");
    assert_eq!(d.get(100), None);
}

fn write(dir: &Path, name: &str, body: &str) -> std::path::PathBuf {
    let text = format!(
        r#"<?xml version="1.0"?>
<OpenSCENARIO>
  <FileHeader revMajor="1" revMinor="2" date="2020-01-01T00:00:00" description="d" author="d"/>
  <ParameterValueDistribution>
    <ScenarioFile filepath="s.xosc"/>
    {body}
  </ParameterValueDistribution>
</OpenSCENARIO>
"#
    );
    let p = dir.join(name);
    std::fs::write(&p, text).expect("write");
    p
}

#[test]
fn huge_cross_products_are_never_materialised() {
    let dir = common::temp_dir("huge");
    let range = |name: &str| {
        format!(
            r#"<DeterministicSingleParameterDistribution parameterName="{name}"><DistributionRange stepWidth="1"><Range lowerLimit="0" upperLimit="999"/></DistributionRange></DeterministicSingleParameterDistribution>"#
        )
    };
    let body = format!("<Deterministic>{}{}{}{}</Deterministic>", range("a"), range("b"), range("c"), range("d"));
    let d = distribution(&write(&dir, "huge.xosc", &body), None);
    assert_eq!(d.len(), 1_000_000_000_000);
    let last = d.get(d.len() - 1).expect("last");
    assert_eq!(last, vec![("a".into(), "999".into()), ("b".into(), "999".into()), ("c".into(), "999".into()), ("d".into(), "999".into())]);
    // Run 1,002,003 = digits (0, 1, 2, 3) in base 1000.
    let r = d.get(1_002_003).expect("run");
    let vals: Vec<&str> = r.iter().map(|(_, v)| v.as_str()).collect();
    assert_eq!(vals, ["0", "1", "2", "3"]);
    assert_eq!(d.iter().size_hint().0, 1_000_000_000_000usize);
}

#[test]
fn every_stochastic_kind_samples_inside_its_support() {
    let dir = common::temp_dir("stochastic");
    let body = r#"<Stochastic numberOfTestRuns="200" randomSeed="3">
      <StochasticDistribution parameterName="u"><UniformDistribution><Range lowerLimit="2" upperLimit="4"/></UniformDistribution></StochasticDistribution>
      <StochasticDistribution parameterName="p"><PoissonDistribution expectedValue="3"><Range lowerLimit="0" upperLimit="6"/></PoissonDistribution></StochasticDistribution>
      <StochasticDistribution parameterName="l"><LogNormalDistribution expectedValue="0" variance="0.25"/></StochasticDistribution>
      <StochasticDistribution parameterName="h"><Histogram><Bin weight="1"><Range lowerLimit="0" upperLimit="1"/></Bin><Bin weight="0"><Range lowerLimit="5" upperLimit="6"/></Bin></Histogram></StochasticDistribution>
      <StochasticDistribution parameterName="n"><NormalDistribution expectedValue="10" variance="4"/></StochasticDistribution>
    </Stochastic>"#;
    let d = distribution(&write(&dir, "st.xosc", body), None);
    assert_eq!(d.len(), 200);
    let mut sum_n = 0.0;
    for run in d.iter() {
        let get = |n: &str| -> f64 { value(&run, n).and_then(|v| v.parse().ok()).expect(n) };
        assert!((2.0..4.0).contains(&get("u")));
        let p = get("p");
        assert!(p.fract() == 0.0 && (0.0..=6.0).contains(&p), "{p}");
        assert!(get("l") > 0.0);
        assert!((0.0..1.0).contains(&get("h")), "weight-0 bin never chosen");
        sum_n += get("n");
    }
    // Mean of 200 draws of N(10, 2²): standard error 2/sqrt(200) ≈ 0.14.
    assert!((sum_n / 200.0 - 10.0).abs() < 0.6, "{}", sum_n / 200.0);
}
