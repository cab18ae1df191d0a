//! OSI trace files as esmini writes them (`--osi_file`): each message preceded by its length as
//! a 4-byte little-endian unsigned integer, nothing else. The writer streams into a temporary
//! file beside the target and renames it when finished, so a trace file that exists is whole (a
//! device or pipe such as `/dev/null` is written in place: a rename would replace it);
//! `read` splits a file back into its messages (a cut-off last message is an error).

use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};

/// Largest message `read` accepts (a hostile length prefix must not make it allocate more).
pub const MAX_MESSAGE: usize = 1 << 30;

/// A trace file being written.
pub struct TraceWriter {
    /// `None` once finished.
    out: Option<BufWriter<File>>,
    temporary: PathBuf,
    path: PathBuf,
    /// The target is a device or pipe, written in place (`temporary` is the target itself).
    in_place: bool,
    messages: usize,
}

fn io_error(path: &Path, e: std::io::Error) -> String {
    format!("{}: {e}", path.display())
}

impl TraceWriter {
    /// Starts the trace file `path` (a temporary file until `finish`).
    pub fn create(path: &Path) -> Result<TraceWriter, String> {
        let dir = path.parent().filter(|d| !d.as_os_str().is_empty()).unwrap_or(Path::new("."));
        let name = path.file_name().ok_or_else(|| format!("{}: not a file name", path.display()))?;
        std::fs::create_dir_all(dir).map_err(|e| io_error(dir, e))?;
        let in_place = std::fs::metadata(path).is_ok_and(|m| !m.is_file() && !m.is_dir());
        let temporary = if in_place { path.to_path_buf() } else { dir.join(format!(".{}.{}.osi.tmp", name.to_string_lossy(), std::process::id())) };
        let file = File::create(&temporary).map_err(|e| io_error(&temporary, e))?;
        Ok(TraceWriter { out: Some(BufWriter::new(file)), temporary, path: path.to_path_buf(), in_place, messages: 0 })
    }

    /// Appends one encoded message.
    pub fn write(&mut self, message: &[u8]) -> Result<(), String> {
        let n = u32::try_from(message.len()).map_err(|_| format!("{}: a message of {} bytes is too long", self.path.display(), message.len()))?;
        let Some(out) = self.out.as_mut() else { return Err(format!("{}: already finished", self.path.display())) };
        out.write_all(&n.to_le_bytes()).and_then(|_| out.write_all(message)).map_err(|e| io_error(&self.temporary, e))?;
        self.messages += 1;
        Ok(())
    }

    /// Messages written so far.
    pub fn messages(&self) -> usize {
        self.messages
    }

    /// Puts the file in place.
    pub fn finish(mut self) -> Result<PathBuf, String> {
        let Some(out) = self.out.take() else { return Err(format!("{}: already finished", self.path.display())) };
        let file = out.into_inner().map_err(|e| io_error(&self.temporary, e.into_error()))?;
        if self.in_place {
            // a device or pipe: nothing to sync (fsync on /dev/null fails) or rename
            return Ok(self.path.clone());
        }
        file.sync_all().map_err(|e| io_error(&self.temporary, e))?;
        drop(file);
        std::fs::rename(&self.temporary, &self.path).map_err(|e| io_error(&self.path, e))?;
        Ok(self.path.clone())
    }
}

impl Drop for TraceWriter {
    fn drop(&mut self) {
        // not finished: no trace file (a device or pipe written in place is never removed)
        if self.out.is_some() && !self.in_place {
            let _ = std::fs::remove_file(&self.temporary);
        }
    }
}

/// Writes `messages` as the trace file `path`, whole or not at all.
pub fn write(path: &Path, messages: &[Vec<u8>]) -> Result<PathBuf, String> {
    let mut w = TraceWriter::create(path)?;
    for m in messages {
        w.write(m)?;
    }
    w.finish()
}

/// The messages of a trace file's bytes.
pub fn read(bytes: &[u8]) -> Result<Vec<&[u8]>, String> {
    let mut out = Vec::new();
    let mut rest = bytes;
    while !rest.is_empty() {
        let (len, body) = rest.split_first_chunk::<4>().ok_or_else(|| format!("message {}: a length prefix cut off", out.len()))?;
        let n = u32::from_le_bytes(*len) as usize;
        if n > MAX_MESSAGE || n > body.len() {
            return Err(format!("message {}: length {n}, but {} bytes are left", out.len(), body.len()));
        }
        let (m, r) = body.split_at(n);
        out.push(m);
        rest = r;
    }
    Ok(out)
}
