//! esmini 3.6.0 loads every export: a scenario with one car teleported onto the first lane
//! of the first road runs for 0.1 s, exits 0 and logs no error.

use crate::common::{esmini_loads, exports, out_dir};

#[test]
fn esmini_loads_every_export() {
    let Some(exports) = exports() else { return };
    let Some(esmini) = testkit::esmini(false) else { return };
    let dir = out_dir().join("esmini");
    std::fs::create_dir_all(&dir).expect("creates the folder");
    let mut failures = Vec::new();
    for e in exports {
        if let Err(why) = esmini_loads(&esmini, &e.file, &dir) {
            failures.push(format!("{}: {why}", e.name));
        }
    }
    eprintln!("esmini loads {} of {} exports", exports.len() - failures.len(), exports.len());
    assert!(failures.is_empty(), "esmini does not load:\n{}", failures.join("\n"));
}
