//! Shards: the K-th of N deterministic parts of a batch (`--shard K/N`), so that a scheduler
//! (a Slurm job array, Kubernetes indexed jobs, GNU parallel) splits a library with no
//! coordination. Every conversion of the whole batch — each scenario and each parameter
//! variation — has a position in the batch's deterministic order; shard K takes the positions
//! p with p mod N = K − 1. Output names are decided on the whole batch before the split, so the
//! N shards together write exactly the files of one unsharded run.

use std::fmt;
use std::str::FromStr;

/// Part `index` (1-based) of `count` parts.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Shard {
    index: u64,
    count: u64,
}

impl Shard {
    /// Shard `index` of `count` (1 ≤ index ≤ count).
    pub fn new(index: u64, count: u64) -> Result<Self, String> {
        if count == 0 || index == 0 || index > count {
            return Err(format!("a shard is K/N with 1 <= K <= N, got {index}/{count}"));
        }
        Ok(Shard { index, count })
    }

    /// K, 1-based.
    pub fn index(&self) -> u64 {
        self.index
    }

    /// N.
    pub fn count(&self) -> u64 {
        self.count
    }

    /// Whether the conversion at `position` (0-based, in batch order) belongs to this shard.
    pub fn contains(&self, position: usize) -> bool {
        position as u64 % self.count == self.index - 1
    }
}

impl FromStr for Shard {
    type Err = String;
    fn from_str(s: &str) -> Result<Self, String> {
        let bad = || format!("expected K/N (e.g. 2/8), got {s:?}");
        let (k, n) = s.split_once('/').ok_or_else(bad)?;
        let k = k.trim().parse::<u64>().map_err(|_| bad())?;
        let n = n.trim().parse::<u64>().map_err(|_| bad())?;
        Shard::new(k, n)
    }
}

impl fmt::Display for Shard {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}/{}", self.index, self.count)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parses_and_rejects() {
        let s: Shard = "2/3".parse().unwrap();
        assert_eq!((s.index(), s.count()), (2, 3));
        assert_eq!(s.to_string(), "2/3");
        for bad in ["0/3", "4/3", "1/0", "x/3", "3", "", "1/-2"] {
            assert!(bad.parse::<Shard>().is_err(), "{bad}");
        }
    }

    #[test]
    fn shards_partition_positions() {
        let n = 4;
        for p in 0..100usize {
            let owners = (1..=n).filter(|&k| Shard::new(k, n).unwrap().contains(p)).count();
            assert_eq!(owners, 1, "position {p}");
        }
    }
}
