//! What a conversion gives Python, by format: the XML text (2020a) or the 2024 files as bytes;
//! the same for one file (`convert_file`) and for each variation of a sweep (`Variations`).

use convert::Output;
use pyo3::prelude::*;
use pyo3::types::PyBytes;

/// The files of a 2024 conversion: (map id, map, scenario file, dynamic file).
pub(crate) type Files2024<'py> = (String, Bound<'py, PyBytes>, Bound<'py, PyBytes>, Bound<'py, PyBytes>);

/// What a conversion made, by format: the XML text (2020a) or the 2024 files.
pub(crate) type Payload<'py> = (Option<String>, Option<Files2024<'py>>);

pub(crate) fn payload(py: Python<'_>, output: Output) -> Payload<'_> {
    match output {
        Output::Xml(bytes) => (Some(String::from_utf8_lossy(&bytes).into_owned()), None),
        Output::Protobuf(p) => {
            let files = (p.map.id.clone(), PyBytes::new(py, &p.map.bytes), PyBytes::new(py, &p.scenario), PyBytes::new(py, &p.dynamic));
            (None, Some(files))
        }
    }
}
