//! Failures → `osc2cr.ConversionError` (defined in Python, `osc2cr/_errors.py`, so that it
//! pickles across processes with its attributes): the message, and the file, line and column
//! when the message starts with a position (`path:line:col: …` or `path: …`, the form every
//! loader error takes).

use std::path::Path;

use convert::{Failure, Stage};
use pyo3::prelude::*;

use crate::options::pythonic;

/// Where a failure happened, as far as its message says.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct Position {
    pub file: String,
    pub line: Option<u32>,
    pub column: Option<u32>,
    /// The message without the position.
    pub detail: String,
}

/// Splits `path:line:col: detail` (the path may itself contain `:`); else `path: detail` when
/// the message starts with `fallback` (the file converted); else no file is known from the text
/// and `fallback` is the file. A strict reading's error lists its problems one a line under a
/// header: the first line that starts with a position gives it.
pub(crate) fn position(message: &str, fallback: &Path) -> Position {
    for line_text in message.lines() {
        if let Some(p) = line_position(line_text) {
            return p;
        }
    }
    let file = fallback.display().to_string();
    let detail = message.strip_prefix(file.as_str()).and_then(|r| r.strip_prefix(": ")).unwrap_or(message);
    Position { file, line: None, column: None, detail: detail.to_string() }
}

/// `path:line:col: detail` at the start of one line; the first `:<digits>:<digits>:` ends the path.
fn line_position(text: &str) -> Option<Position> {
    let mut i = 0;
    while let Some(off) = text[i..].find(':') {
        let start = i + off;
        if let Some((line, col, rest)) = numbers_after(&text[start + 1..]) {
            if start > 0 {
                return Some(Position { file: text[..start].to_string(), line: Some(line), column: Some(col), detail: rest.to_string() });
            }
        }
        i = start + 1;
        if i >= text.len() {
            break;
        }
    }
    None
}

/// `"12:5: rest"` → (12, 5, "rest").
fn numbers_after(s: &str) -> Option<(u32, u32, &str)> {
    let (line, rest) = s.split_once(':')?;
    let (col, rest) = rest.split_once(':')?;
    let line = digits(line)?;
    let col = digits(col)?;
    Some((line, col, rest.strip_prefix(' ').unwrap_or(rest)))
}

fn digits(s: &str) -> Option<u32> {
    if s.is_empty() || !s.bytes().all(|b| b.is_ascii_digit()) {
        return None;
    }
    s.parse().ok()
}

/// The Python exception for `failure` of converting `file` (variation `variation`, if any):
/// `ScenarioNotFoundError` (a `ConversionError` and a `FileNotFoundError`) when `file` is not
/// there, else `ConversionError`; the message names options as Python spells them
/// ([`pythonic`]).
pub(crate) fn conversion_error(py: Python<'_>, failure: &Failure, file: &Path, variation: Option<u64>) -> PyErr {
    let message = pythonic(&failure.message);
    let p = position(&message, file);
    let class_name = if failure.stage == Stage::Load && !file.exists() { "ScenarioNotFoundError" } else { "ConversionError" };
    let made = (|| -> PyResult<PyErr> {
        let class = py.import("osc2cr._errors")?.getattr(class_name)?;
        let value = class.call1((message.clone(), p.file, p.line, p.column, failure.stage.as_str(), variation))?;
        Ok(PyErr::from_value(value))
    })();
    made.unwrap_or_else(|e| e)
}

/// A reason given as text (e.g. "not a scenario"), for `file`.
pub(crate) fn message_error(py: Python<'_>, message: String, file: &Path) -> PyErr {
    conversion_error(py, &Failure { stage: Stage::Load, message }, file, None)
}

/// A conversion's warnings as (stage, message) pairs for Python, the messages [`pythonic`].
pub(crate) fn warnings_of(list: &[convert::StageWarning]) -> Vec<(&'static str, String)> {
    list.iter().map(|w| (w.stage.as_str(), pythonic(&w.message))).collect()
}
