//! Any text read as an OpenSCENARIO file (scenario, distribution or catalog) ends in Ok or a
//! positioned Err — never a panic, a hang or an unbounded allocation; the schema pass of
//! `osc2cr check` likewise ends in a list of findings.
#![no_main]
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let text = String::from_utf8_lossy(data);
    let path = std::path::Path::new("/fuzz/input.xosc");
    let _ = openscenario::validate::validate_str(path, &text, &[]);
    let _ = openscenario::load_str(path, &text, &Default::default());
});
