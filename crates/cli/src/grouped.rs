//! Findings as a person reads them: one line per kind of finding and file — the first position
//! and how many more there are — instead of the same message at 216 lines (`<lane><height> is
//! not modelled` in one map). `-vv` and the JSON outputs keep every position.

use std::collections::BTreeMap;

/// `items` in their order, each kind (equal `key`) once: its first item and how many more
/// there are.
pub(crate) fn by_kind<T, K: Ord>(items: &[T], key: impl Fn(&T) -> K) -> Vec<(&T, usize)> {
    let mut index: BTreeMap<K, usize> = BTreeMap::new();
    let mut out: Vec<(&T, usize)> = Vec::new();
    for item in items {
        match index.get(&key(item)) {
            Some(&i) => out[i].1 += 1,
            None => {
                index.insert(key(item), out.len());
                out.push((item, 0));
            }
        }
    }
    out
}

/// What a grouped line adds: nothing for a single finding.
pub(crate) fn more(n: usize) -> String {
    match n {
        0 => String::new(),
        n => format!(" (and {n} more like it in this file; -vv lists each)"),
    }
}

/// The kind of a finding: its message with the names it quotes in backticks and its numbers
/// left out, so that "road `196` signal `305`: dropped: pedestrian light" and the same for
/// signal `304` are one kind.
pub(crate) fn kind(message: &str) -> String {
    let mut out = String::with_capacity(message.len());
    let mut quoted = false;
    let mut in_number = false;
    for c in message.chars() {
        if c == '`' {
            if !quoted {
                out.push_str("`…`");
            }
            quoted = !quoted;
            continue;
        }
        if quoted {
            continue;
        }
        let numeric = c.is_ascii_digit() || (in_number && c == '.');
        if numeric {
            if !in_number {
                out.push('#');
            }
        } else {
            out.push(c);
        }
        in_number = numeric;
    }
    out
}

/// A message that starts with a position, `FILE:LINE:COL: rest`, split into the file and the
/// rest (the kind of the finding); a message without one is all rest.
pub(crate) fn split_position(message: &str) -> (&str, &str) {
    let mut from = 0;
    while let Some(i) = message[from..].find(": ").map(|i| i + from) {
        let head = &message[..i];
        let mut parts = head.rsplitn(3, ':');
        let (col, line, file) = (parts.next(), parts.next(), parts.next());
        let digits = |s: Option<&str>| s.is_some_and(|s| !s.is_empty() && s.bytes().all(|b| b.is_ascii_digit()));
        if digits(col) && digits(line) {
            return (file.unwrap_or(""), &message[i + 2..]);
        }
        from = i + 2;
    }
    ("", message)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn repeated_kinds_collapse_to_their_first() {
        let items = ["a:1", "b:2", "a:3", "a:4"];
        let grouped = by_kind(&items, |s| s.split(':').next().unwrap_or_default().to_string());
        assert_eq!(grouped, vec![(&"a:1", 2), (&"b:2", 0)]);
        assert_eq!(more(0), "");
        assert!(more(2).starts_with(" (and 2 more"));
    }

    #[test]
    fn names_and_numbers_do_not_make_a_kind() {
        assert_eq!(kind("road `196` signal `305`: dropped: pedestrian light"), kind("road `7` signal `3`: dropped: pedestrian light"));
        assert_eq!(kind("entity `A` jumps 1.88 m at 13.03 s"), "entity `…` jumps # m at # s");
        assert_ne!(kind("lane `1`: dropped"), kind("lane `1`: kept"));
    }

    #[test]
    fn a_position_is_split_off() {
        assert_eq!(split_position("/m/x.xodr:38:25: warning: <lane><height> is not modelled"), ("/m/x.xodr", "warning: <lane><height> is not modelled"));
        assert_eq!(split_position("c:/odd: name/x.xosc:3:4: msg: detail"), ("c:/odd: name/x.xosc", "msg: detail"));
        assert_eq!(split_position("no position: here"), ("", "no position: here"));
    }
}
