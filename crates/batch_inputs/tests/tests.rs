//! The tests of `batch_inputs`, one binary: what a folder yields (order, depth, sub-folders,
//! groups) and what a missing input says.

use std::path::{Path, PathBuf};

use batch_inputs::{files_of, label, MAX_DEPTH};

/// A fresh folder under the system's temporary folder, named for the test.
fn fresh(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("osc2cr-batch-inputs-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).expect("a temporary folder");
    d
}

fn touch(path: &Path) {
    std::fs::create_dir_all(path.parent().expect("a parent")).expect("folders");
    std::fs::write(path, "").expect("a file");
}

fn xml(p: &Path) -> bool {
    p.extension().is_some_and(|e| e == "xml")
}

#[test]
fn a_folder_gives_its_wanted_files_sorted_with_their_sub_folders_and_groups() {
    let d = fresh("sorted");
    for f in ["b.xml", "a.xml", "z/c.xml", "m/n/d.xml", "skip.txt"] {
        touch(&d.join(f));
    }
    let got = files_of(&d, &xml, "XML files").expect("the folder is read");
    let base = label(&d);
    let rows: Vec<(PathBuf, String, PathBuf)> = got.into_iter().map(|g| (g.path, g.folder, g.sub)).collect();
    assert_eq!(
        rows,
        [
            (d.join("a.xml"), base.clone(), PathBuf::new()),
            (d.join("b.xml"), base.clone(), PathBuf::new()),
            (d.join("m/n/d.xml"), format!("{base}/m/n"), PathBuf::from("m/n")),
            (d.join("z/c.xml"), format!("{base}/z"), PathBuf::from("z")),
        ]
    );
    let _ = std::fs::remove_dir_all(&d);
}

#[test]
fn a_file_is_taken_as_named_whatever_its_name_and_a_missing_one_is_an_error() {
    let d = fresh("file");
    let f = d.join("notes.txt");
    touch(&f);
    let got = files_of(&f, &xml, "XML files").expect("the file is given");
    assert_eq!(got.len(), 1);
    assert_eq!((got[0].path.as_path(), got[0].folder.as_str(), got[0].sub.as_path()), (f.as_path(), label(&d).as_str(), Path::new("")));
    let missing = d.join("gone.xml");
    assert_eq!(files_of(&missing, &xml, "XML files"), Err(format!("{}: no such file or directory", missing.display())));
    // a file named without a folder is in the group `.`, never an empty cell
    assert_eq!(label(Path::new("")), ".");
    assert_eq!(label(Path::new("..")), "..");
    let _ = std::fs::remove_dir_all(&d);
}

#[test]
fn folders_deeper_than_the_limit_are_not_searched() {
    let d = fresh("deep");
    let mut deep = d.clone();
    for k in 0..=MAX_DEPTH + 1 {
        deep = deep.join(format!("l{k}"));
    }
    touch(&deep.join("too_deep.xml"));
    touch(&d.join("top.xml"));
    let got = files_of(&d, &xml, "XML files").expect("the folder is read");
    assert_eq!(got.iter().map(|g| g.path.clone()).collect::<Vec<_>>(), [d.join("top.xml")]);
    let _ = std::fs::remove_dir_all(&d);
}
