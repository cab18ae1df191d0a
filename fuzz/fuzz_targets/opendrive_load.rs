//! Any text read as an OpenDRIVE file, and the lanelet network made of what parses, ends in
//! Ok or a positioned Err — never a panic or a hang.
#![no_main]
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let text = String::from_utf8_lossy(data);
    if let Ok(loaded) = opendrive::network::parse_str(&text, std::path::Path::new("/fuzz/input.xodr")) {
        let _ = map::convert(&loaded.network, &map::MapOptions::default());
    }
});
