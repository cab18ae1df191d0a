//! Whole-or-nothing file output: write a temporary file next to the target, then rename it
//! over the target (atomic on POSIX within one file system, which is why the temporary file
//! lives in the same directory). An error, or a crash of this process at any point, leaves
//! the old file or none, never a truncated one: the rename is the only step that makes the
//! new name visible, and it happens after the last byte was handed to the kernel.
//!
//! No fsync, on purpose. `fsync` only adds durability against a power loss or kernel crash
//! right after the rename (then some file systems could show an empty or partial file), and
//! it cost 8 ms per file at best and up to 0.75 s on a busy disk — most of a conversion's time.
//! Our outputs are derived data that a rerun regenerates; a caller that must survive power
//! loss can sync the file (and its directory) itself.
//!
//! A process killed between the two steps leaves its temporary file (`.<name>.<pid>.<n>.tmp`),
//! never a final name; [`remove_stale_temporaries`] clears those of processes that are gone.
//!
//! A target that is a device or a pipe (`--csv /dev/null`, a FIFO a reader waits on) is written
//! in place: a rename would replace it with a regular file — run as root, `/dev/null` itself
//! (which happened here once). See [`is_special_file`].

use std::fs::{self, File, OpenOptions};
use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};

use crate::Error;

/// Distinguishes temporary files of parallel writers within one process.
static COUNTER: AtomicU64 = AtomicU64::new(0);

/// Whether `path` exists and is neither a regular file nor a directory (following links): a
/// character or block device, a FIFO or a socket. Such a target is written in place, never
/// replaced by a rename.
pub fn is_special_file(path: &Path) -> bool {
    fs::metadata(path).is_ok_and(|m| !m.is_file() && !m.is_dir())
}

/// Writes `bytes` to `path` atomically (temp file in the same directory + rename); a device or
/// pipe is written in place ([`is_special_file`]).
pub fn write_atomic(path: &Path, bytes: &[u8]) -> Result<(), Error> {
    let io_err = |p: &Path| {
        let p = p.to_path_buf();
        move |source| Error::WriteFile { path: p, source: std::sync::Arc::new(source) }
    };
    if is_special_file(path) {
        return OpenOptions::new().write(true).open(path).and_then(|mut f| f.write_all(bytes)).map_err(io_err(path));
    }
    let file_name = path.file_name().ok_or_else(|| Error::WriteFile {
        path: path.to_path_buf(),
        source: std::sync::Arc::new(std::io::Error::new(std::io::ErrorKind::InvalidInput, "the path names no file")),
    })?;
    let dir = match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
        _ => PathBuf::from("."),
    };
    let n = COUNTER.fetch_add(1, Ordering::Relaxed);
    let mut tmp_name = std::ffi::OsString::from(".");
    tmp_name.push(file_name);
    tmp_name.push(format!(".{}.{n}.tmp", std::process::id()));
    let tmp = dir.join(tmp_name);

    let result = (|| {
        let mut f: File = OpenOptions::new().write(true).create_new(true).open(&tmp).map_err(io_err(&tmp))?;
        f.write_all(bytes).map_err(io_err(&tmp))?;
        // close before the rename (see the module doc for why there is no sync_all)
        drop(f);
        fs::rename(&tmp, path).map_err(io_err(path))
    })();
    if result.is_err() {
        // best effort: the temporary file must not linger; the original error is what matters
        let _ = fs::remove_file(&tmp);
    }
    result
}

/// The writer's process id if `name` is a temporary file name of [`write_atomic`]
/// (`.<name>.<pid>.<anything>.tmp`).
fn temporary_owner(name: &str) -> Option<u32> {
    let inner = name.strip_prefix('.')?.strip_suffix(".tmp")?;
    let mut parts = inner.rsplitn(3, '.');
    let _counter = parts.next()?;
    let pid = parts.next()?.parse::<u32>().ok()?;
    let target = parts.next()?;
    (!target.is_empty()).then_some(pid)
}

/// Whether process `pid` runs on this machine; `None` when that cannot be told (no `/proc`).
fn process_runs(pid: u32) -> Option<bool> {
    let proc_dir = Path::new("/proc");
    if !proc_dir.join("self").exists() {
        return None;
    }
    Some(proc_dir.join(pid.to_string()).exists())
}

/// Removes, below `dir` (recursively, not following links), the temporary files of
/// [`write_atomic`] whose writer process is no longer running — what a killed batch leaves. A
/// temporary file of a running process (another shard writing into the same folder) is left
/// alone, and so is every file when it cannot be told whether its writer runs (no `/proc`).
/// Returns the files removed.
pub fn remove_stale_temporaries(dir: &Path) -> Vec<PathBuf> {
    let mut removed = Vec::new();
    let mut stack = vec![(dir.to_path_buf(), 0usize)];
    while let Some((d, depth)) = stack.pop() {
        let Ok(entries) = fs::read_dir(&d) else { continue };
        for e in entries.flatten() {
            let Ok(kind) = e.file_type() else { continue };
            let path = e.path();
            if kind.is_dir() && depth < 64 {
                stack.push((path, depth + 1));
                continue;
            }
            let Some(pid) = e.file_name().to_str().and_then(temporary_owner) else { continue };
            if pid != std::process::id() && process_runs(pid) == Some(false) && fs::remove_file(&path).is_ok() {
                removed.push(path);
            }
        }
    }
    removed.sort();
    removed
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn temporary_names_are_recognised() {
        assert_eq!(temporary_owner(".cut_in.xml.4242.7.tmp"), Some(4242));
        assert_eq!(temporary_owner(".ZAM_0a-1.pb.17.stream.tmp"), Some(17));
        assert_eq!(temporary_owner("cut_in.xml"), None);
        assert_eq!(temporary_owner(".cut_in.xml.x.7.tmp"), None);
        assert_eq!(temporary_owner("..1.2.tmp"), None);
    }
}
