//! The whole conversion of any scenario text on a small fixed road (written once beside the
//! input): load, map, run (at most 10 s simulated, 2 s of wall clock), build, serialise. It ends
//! in bytes or a failure naming its stage — never a panic or a hang.
#![no_main]
use libfuzzer_sys::fuzz_target;
use std::path::PathBuf;
use std::sync::OnceLock;

/// A 500 m straight road with two lanes each way, named `road.xodr` in the fuzz directory.
fn dir() -> &'static PathBuf {
    static DIR: OnceLock<PathBuf> = OnceLock::new();
    DIR.get_or_init(|| {
        let d = std::env::temp_dir().join(format!("osc2cr-fuzz-convert-{}", std::process::id()));
        let _ = std::fs::create_dir_all(&d);
        let road = r#"<?xml version="1.0"?>
<OpenDRIVE><header revMajor="1" revMinor="6"/>
<road id="1" length="500" junction="-1"><link/>
<planView><geometry s="0" x="0" y="0" hdg="0" length="500"><line/></geometry></planView>
<lanes><laneSection s="0">
<left><lane id="2" type="driving"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane><lane id="1" type="driving"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane></left>
<center><lane id="0" type="none"/></center>
<right><lane id="-1" type="driving"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane><lane id="-2" type="driving"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane></right>
</laneSection></lanes></road></OpenDRIVE>"#;
        let _ = std::fs::write(d.join("road.xodr"), road);
        d
    })
}

fuzz_target!(|data: &[u8]| {
    let text = String::from_utf8_lossy(data);
    let path = dir().join("input.xosc");
    if std::fs::write(&path, text.as_bytes()).is_err() {
        return;
    }
    let options =
        convert::ConvertOptions { max_time: 10.0, deadline: Some(std::time::Instant::now() + std::time::Duration::from_secs(2)), ..Default::default() };
    let request = convert::Request::named(&path, "fuzz");
    let _ = convert::convert(&request, &options);
    let options = convert::ConvertOptions { lenient: true, ..options };
    let _ = convert::convert(&request, &options);
    // the same in the 2024 format: the protobuf writer sees whatever the model can hold
    let options = convert::ConvertOptions { format: convert::OutputFormat::Protobuf2024, ..options };
    let _ = convert::convert(&request, &options);
});
