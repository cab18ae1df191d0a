//! Keyword options of the Python functions → `convert::ConvertOptions`. The names are the
//! CLI's long options with `_` for `-`; an option left out keeps the CLI's default. Unknown
//! names and wrong types are `TypeError`s, values no conversion could use `ValueError`s — the
//! same checks, with the same messages, as `osc2cr convert`. A message that names a CLI option
//! names its keyword instead (`pythonic`, for every error and warning Python sees).

use convert::{ConvertOptions, EgoChoice};
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyString};

/// Every option name the Python functions accept (documented in `osc2cr/__init__.py`).
pub(crate) const NAMES: &[&str] = &[
    "dt",
    "step",
    "max_time",
    "ego",
    "ego_pattern",
    "drop_ego",
    "params",
    "goal_length",
    "goal_width",
    "goal_time_window",
    "goal_speed_margin",
    "goal_velocity",
    "goal_orientation_margin",
    "country",
    "author",
    "affiliation",
    "source",
    "date",
    "seed",
    "max_variations",
    "map_tolerance",
    "engine_seed",
    "lenient",
    "format",
];

/// Options from keyword arguments; `None` values mean "the default", like an option not given.
/// Returns the options and `max_variations` (`None`: no cap — a Python caller streams them).
pub(crate) fn from_kwargs(kwargs: Option<&Bound<'_, PyDict>>) -> PyResult<(ConvertOptions, Option<u64>)> {
    let mut o = ConvertOptions::default();
    let mut max_variations = None;
    let mut ego_name: Option<String> = None;
    let mut ego_pattern: Option<String> = None;
    let mut goal_velocity = true;
    let Some(kwargs) = kwargs else {
        return Ok((o, None));
    };
    for (key, value) in kwargs.iter() {
        let key: String = key.extract()?;
        if value.is_none() {
            if !NAMES.contains(&key.as_str()) {
                return Err(unknown(&key));
            }
            continue;
        }
        let v = &value;
        match key.as_str() {
            "dt" => o.dt = float(&key, v)?,
            "step" => o.step = float(&key, v)?,
            "max_time" => o.max_time = float(&key, v)?,
            "ego" => ego_name = Some(string(&key, v)?),
            "ego_pattern" => ego_pattern = Some(string(&key, v)?),
            "drop_ego" => o.drop_ego = boolean(&key, v)?,
            "params" => o.parameters = params(v)?,
            "goal_length" => o.goal.length = float(&key, v)?,
            "goal_width" => o.goal.width = float(&key, v)?,
            "goal_time_window" => o.goal.time_window = unsigned(&key, v)?,
            "goal_speed_margin" => o.goal.speed_margin = Some(float(&key, v)?),
            "goal_velocity" => goal_velocity = boolean(&key, v)?,
            "goal_orientation_margin" => o.goal.orientation_margin = Some(float(&key, v)?),
            "country" => o.country = string(&key, v)?,
            "author" => o.author = Some(string(&key, v)?),
            "affiliation" => o.affiliation = string(&key, v)?,
            "source" => o.source = Some(string(&key, v)?),
            "date" => o.date = Some(date(v)?),
            "seed" => o.seed = Some(unsigned(&key, v)?),
            "max_variations" => max_variations = Some(unsigned(&key, v)?),
            "map_tolerance" => o.map_tolerance = Some(float(&key, v)?),
            "engine_seed" => {
                let n = unsigned(&key, v)?;
                o.engine_seed = u32::try_from(n).map_err(|_| PyValueError::new_err(format!("{key} must be below 2**32")))?;
            }
            "lenient" => o.lenient = boolean(&key, v)?,
            "format" => o.format = string(&key, v)?.parse().map_err(|e: String| PyValueError::new_err(format!("format: {e}")))?,
            _ => return Err(unknown(&key)),
        }
    }
    if !goal_velocity {
        o.goal.speed_margin = None;
    }
    o.ego = match (ego_name, ego_pattern) {
        (Some(name), _) => EgoChoice::Name(name),
        (None, Some(pattern)) => EgoChoice::Pattern(pattern),
        (None, None) => EgoChoice::default(),
    };
    if let Some(n) = max_variations {
        o.max_variations = n;
    }
    o.check().map_err(|m| PyValueError::new_err(pythonic(&m)))?;
    Ok((o, max_variations))
}

fn unknown(key: &str) -> PyErr {
    PyTypeError::new_err(format!("unexpected keyword argument {key:?}; the options are: {}", NAMES.join(", ")))
}

fn float(key: &str, v: &Bound<'_, PyAny>) -> PyResult<f64> {
    if v.is_instance_of::<PyBool>() {
        return Err(PyTypeError::new_err(format!("{key} must be a number, got a bool")));
    }
    v.extract::<f64>().map_err(|_| PyTypeError::new_err(format!("{key} must be a number")))
}

fn unsigned(key: &str, v: &Bound<'_, PyAny>) -> PyResult<u64> {
    if v.is_instance_of::<PyBool>() {
        return Err(PyTypeError::new_err(format!("{key} must be an int, got a bool")));
    }
    v.extract::<u64>().map_err(|_| PyValueError::new_err(format!("{key} must be a non-negative int")))
}

fn boolean(key: &str, v: &Bound<'_, PyAny>) -> PyResult<bool> {
    if !v.is_instance_of::<PyBool>() {
        return Err(PyTypeError::new_err(format!("{key} must be True or False")));
    }
    v.extract::<bool>()
}

fn string(key: &str, v: &Bound<'_, PyAny>) -> PyResult<String> {
    if !v.is_instance_of::<PyString>() {
        return Err(PyTypeError::new_err(format!("{key} must be a str")));
    }
    v.extract::<String>()
}

/// A `datetime.date` or a `YYYY-MM-DD` string.
fn date(v: &Bound<'_, PyAny>) -> PyResult<commonroad::Date> {
    let text: String = if v.is_instance_of::<PyString>() {
        v.extract()?
    } else if v.hasattr("isoformat")? {
        let iso: String = v.call_method0("isoformat")?.extract()?;
        iso.chars().take(10).collect()
    } else {
        return Err(PyTypeError::new_err("date must be a datetime.date or a 'YYYY-MM-DD' str"));
    };
    convert::parse_date(&text).map_err(PyValueError::new_err)
}

/// `{name: value}` with str, int, float or bool values (bools as OpenSCENARIO's `true`/`false`),
/// in the dict's order.
fn params(v: &Bound<'_, PyAny>) -> PyResult<Vec<(String, String)>> {
    let dict = v.cast::<PyDict>().map_err(|_| PyTypeError::new_err("params must be a dict {name: value}"))?;
    let mut out = Vec::with_capacity(dict.len());
    for (name, value) in dict.iter() {
        let name: String = name.extract().map_err(|_| PyTypeError::new_err("params names must be str"))?;
        if name.trim().is_empty() {
            return Err(PyValueError::new_err("params names must not be empty"));
        }
        let text = if value.is_instance_of::<PyBool>() {
            if value.extract::<bool>()? { "true" } else { "false" }.to_string()
        } else if value.is_instance_of::<PyString>() {
            value.extract::<String>()?
        } else if value.extract::<i64>().is_ok() || value.extract::<f64>().is_ok() {
            value.str()?.extract::<String>()?
        } else {
            return Err(PyTypeError::new_err(format!("params[{name:?}] must be a str, int, float or bool")));
        };
        out.push((name.trim().to_string(), text));
    }
    Ok(out)
}

/// `message` with the command line's option names (`--lenient`, `--param`, `--max-variations`,
/// …), which the library's messages use, as the Python keyword arguments that set the same
/// thing (`lenient=True`, `params`, `max_variations`, …). Names Python has no keyword for are
/// left as they are.
pub(crate) fn pythonic(message: &str) -> String {
    let mut out = String::with_capacity(message.len());
    let mut rest = message;
    while let Some(at) = rest.find("--") {
        let (before, from) = rest.split_at(at);
        out.push_str(before);
        let after = &from[2..];
        let len = after.find(|c: char| !(c.is_ascii_lowercase() || c.is_ascii_digit() || c == '-')).unwrap_or(after.len());
        let name = &after[..len];
        let word_start = !before.ends_with(|c: char| c.is_alphanumeric() || c == '-' || c == '_') && name.starts_with(|c: char| c.is_ascii_lowercase());
        let keyword = match name {
            "lenient" => Some("lenient=True".to_string()),
            "param" => Some("params".to_string()),
            "no-goal-velocity" => Some("goal_velocity=False".to_string()),
            _ => Some(name.replace('-', "_")).filter(|k| NAMES.contains(&k.as_str())),
        };
        match keyword.filter(|_| word_start) {
            Some(k) => {
                out.push_str(&k);
                rest = &after[len..];
            }
            None => {
                out.push_str("--");
                rest = after;
            }
        }
    }
    out.push_str(rest);
    out
}
