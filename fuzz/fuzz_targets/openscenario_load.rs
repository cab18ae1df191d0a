//! Any text read as an OpenSCENARIO file (scenario, distribution or catalog) ends in Ok or a
//! positioned Err — never a panic, a hang or an unbounded allocation.
#![no_main]
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let text = String::from_utf8_lossy(data);
    let _ = openscenario::load_str(std::path::Path::new("/fuzz/input.xosc"), &text, &Default::default());
});
