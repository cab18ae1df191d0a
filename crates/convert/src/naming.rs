//! Output names of a batch, decided on the whole batch in its order, without holding every
//! name: a scenario is `<stem>`, variation k of a distribution `<stem>_<k>`, and a name already
//! claimed by an earlier conversion gets `-2`, `-3`, … (the first free one). Names are stems
//! (the output folder joined with the input's relative stem, no extension); the format adds
//! `.xml`, or `.pb` and `-SC.pb`.
//!
//! A distribution's variations are remembered as one range (`<stem>_1` … `<stem>_<n>`), single
//! names and the rare displaced variation one by one, so a sweep of 100,000 variations costs a
//! few entries, and a name is looked up in O(log n). The result is exactly that of claiming
//! every name in turn from one set.
//!
//! In the 2024 format a stem `s` stands for two files, `s.pb` and `s-SC.pb`, so `s` is also
//! taken when `s-SC` is, when `s` ends in `-SC` and the rest is taken, or when `s.pb` at the top
//! of the output folder could be a map's file name (`CCC_<16 hex digits>-1.pb`).

use std::collections::{BTreeMap, BTreeSet};
use std::ffi::OsString;
use std::path::{Path, PathBuf};

/// The names claimed so far.
pub(crate) struct Namer {
    out_dir: PathBuf,
    protobuf: bool,
    /// Single names and displaced variations (stem bytes).
    single: BTreeSet<Vec<u8>>,
    /// Variation ranges of earlier distributions: prefix (stem bytes) → largest k.
    ranges: BTreeMap<Vec<u8>, u64>,
}

impl Namer {
    pub(crate) fn new(out_dir: &Path, protobuf: bool) -> Self {
        Namer { out_dir: out_dir.to_path_buf(), protobuf, single: BTreeSet::new(), ranges: BTreeMap::new() }
    }

    /// Whether the stem `s` was claimed by an earlier name (as a stem).
    fn claimed(&self, s: &[u8]) -> bool {
        if self.single.contains(s) {
            return true;
        }
        // `<prefix>_<k>` with k in an earlier range
        let Some(us) = s.iter().rposition(|&b| b == b'_') else { return false };
        let digits = &s[us + 1..];
        let canonical = !digits.is_empty() && digits.iter().all(u8::is_ascii_digit) && digits[0] != b'0';
        if !canonical {
            return false;
        }
        let k = std::str::from_utf8(digits).ok().and_then(|d| d.parse::<u64>().ok());
        matches!((k, self.ranges.get(&s[..us])), (Some(k), Some(&n)) if k <= n)
    }

    /// Whether the stem `s` is free for this format.
    fn free(&self, s: &[u8]) -> bool {
        if self.claimed(s) {
            return false;
        }
        if !self.protobuf {
            return true;
        }
        let with_sc = [s, b"-SC"].concat();
        if self.claimed(&with_sc) {
            return false;
        }
        if let Some(base) = s.strip_suffix(b"-SC") {
            if self.claimed(base) {
                return false;
            }
        }
        !self.could_be_a_map(s)
    }

    fn could_be_a_map(&self, s: &[u8]) -> bool {
        let dir = self.out_dir.as_os_str().as_encoded_bytes();
        let Some(rest) = s.strip_prefix(dir) else { return false };
        let sep = std::path::MAIN_SEPARATOR_STR.as_bytes();
        let name = if dir.ends_with(sep) {
            rest
        } else {
            match rest.strip_prefix(sep) {
                Some(name) => name,
                None => return false,
            }
        };
        // CCC_<16 lower-case hex digits>-1
        name.len() == 3 + 1 + 16 + 2
            && name[..3].iter().all(u8::is_ascii_uppercase)
            && name[3] == b'_'
            && name[4..20].iter().all(|b| b.is_ascii_digit() || (b'a'..=b'f').contains(b))
            && &name[20..] == b"-1"
    }

    /// `stem`, or the first of `stem-2`, `stem-3`, … that is free; claims it.
    fn claim_displaced(&mut self, stem: OsString) -> PathBuf {
        let mut n = 1u64;
        loop {
            let mut candidate = stem.clone();
            if n > 1 {
                candidate.push(format!("-{n}"));
            }
            let bytes = candidate.as_encoded_bytes().to_vec();
            if self.free(&bytes) {
                self.single.insert(bytes);
                return PathBuf::from(candidate);
            }
            n += 1;
        }
    }

    /// The name of a scenario whose relative stem is `stem`.
    pub(crate) fn scenario(&mut self, stem: &Path) -> PathBuf {
        self.claim_displaced(self.out_dir.join(stem).into_os_string())
    }

    /// The name of variation `k` of a distribution whose relative stem is `stem`; variations of
    /// one distribution are claimed in order, and [`Namer::end_distribution`] follows the last.
    pub(crate) fn variation(&mut self, stem: &Path, k: u64) -> PathBuf {
        let mut name = self.out_dir.join(stem).into_os_string();
        name.push(format!("_{k}"));
        let bytes = name.as_encoded_bytes();
        // the distribution's own earlier variations are `<stem>_<j>`, j < k: never this name
        if self.free(bytes) {
            return PathBuf::from(name);
        }
        self.claim_displaced(name)
    }

    /// Remembers that the distribution of relative stem `stem` claimed `<stem>_1` … `<stem>_<n>`
    /// (those that were free; the others were claimed one by one).
    pub(crate) fn end_distribution(&mut self, stem: &Path, n: u64) {
        if n == 0 {
            return;
        }
        let prefix = self.out_dir.join(stem).into_os_string().as_encoded_bytes().to_vec();
        let e = self.ranges.entry(prefix).or_insert(0);
        *e = (*e).max(n);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The old rule: every name claimed in turn from one set of full names.
    fn reference(items: &[(&str, Option<u64>)], protobuf: bool) -> Vec<String> {
        let mut used: BTreeSet<String> = BTreeSet::new();
        let mut out = Vec::new();
        let taken = |used: &BTreeSet<String>, s: &str| {
            if !protobuf {
                return used.contains(s);
            }
            let files = |s: &str| [format!("{s}.pb"), format!("{s}-SC.pb")];
            let mine = files(s);
            used.iter().any(|u| files(u).iter().any(|f| mine.contains(f)))
        };
        for (stem, n) in items {
            let candidates: Vec<String> = match n {
                None => vec![format!("out/{stem}")],
                Some(n) => (1..=*n).map(|k| format!("out/{stem}_{k}")).collect(),
            };
            for c in candidates {
                let mut k = 1;
                loop {
                    let name = if k == 1 { c.clone() } else { format!("{c}-{k}") };
                    if !taken(&used, &name) {
                        used.insert(name.clone());
                        out.push(name);
                        break;
                    }
                    k += 1;
                }
            }
        }
        out
    }

    fn lazy(items: &[(&str, Option<u64>)], protobuf: bool) -> Vec<String> {
        let mut namer = Namer::new(Path::new("out"), protobuf);
        let mut out = Vec::new();
        for (stem, n) in items {
            match n {
                None => out.push(namer.scenario(Path::new(stem))),
                Some(n) => {
                    for k in 1..=*n {
                        out.push(namer.variation(Path::new(stem), k));
                    }
                    namer.end_distribution(Path::new(stem), *n);
                }
            }
        }
        out.into_iter().map(|p| p.to_string_lossy().into_owned()).collect()
    }

    #[test]
    fn lazy_names_are_the_names_of_one_set() {
        let batches: &[&[(&str, Option<u64>)]] = &[
            &[("a", None), ("a", Some(3)), ("a_1", None), ("a", None), ("a", Some(2))],
            &[("a_2", None), ("a", Some(3)), ("a_2", None), ("a_2-2", None)],
            &[("x", Some(12)), ("x_1", Some(2)), ("x_12", None), ("x_1_2", None), ("x_012", None)],
            &[("s", None), ("s-SC", None), ("s", Some(2)), ("s_1-SC", None), ("sub/s", None)],
        ];
        for items in batches {
            for protobuf in [false, true] {
                assert_eq!(lazy(items, protobuf), reference(items, protobuf), "{items:?} protobuf={protobuf}");
            }
        }
    }

    #[test]
    fn a_stem_that_could_be_a_map_is_displaced_in_2024_only() {
        let map_like = "ZAM_0123456789abcdef-1";
        assert_eq!(lazy(&[(map_like, None)], false), [format!("out/{map_like}")]);
        assert_eq!(lazy(&[(map_like, None)], true), [format!("out/{map_like}-2")]);
        // in a sub-folder it cannot meet a map
        assert_eq!(lazy(&[(&format!("sub/{map_like}"), None)], true), [format!("out/sub/{map_like}")]);
    }
}
