//! Any ParameterValueDistribution text loads to a distribution or an error, and its runs — the
//! first ones and the last — can be drawn without a panic.
#![no_main]
use libfuzzer_sys::fuzz_target;
use openscenario::Content;

fuzz_target!(|data: &[u8]| {
    let text = String::from_utf8_lossy(data);
    let Ok(loaded) = openscenario::load_str(std::path::Path::new("/fuzz/dist.xosc"), &text, &Default::default()) else { return };
    if let Content::Distribution(d) = loaded.content {
        let n = d.len();
        for i in 0..n.min(50) {
            let _ = d.get(i);
        }
        let _ = d.get(n.saturating_sub(1));
        let _ = d.get(n);
    }
});
