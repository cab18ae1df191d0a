//! The `<header>` of an OpenDRIVE file.

/// `<header><offset>`: a shift and rotation of the whole data set.
///
/// World coordinates returned by this crate do NOT include it: esmini (whose traces the
/// scenarios must land on) ignores the header offset, and so does every position we compute.
/// Callers that want inertial coordinates of the standard can apply
/// [`HeaderOffset::apply`] themselves.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct HeaderOffset {
    pub x: f64,
    pub y: f64,
    pub z: f64,
    pub hdg: f64,
}

impl HeaderOffset {
    /// Map a point of the file's frame into the offset frame as the standard describes it:
    /// first translate by (x, y, z), then rotate by `hdg` around the new origin.
    pub fn apply(&self, x: f64, y: f64, z: f64) -> (f64, f64, f64) {
        let (tx, ty) = (x + self.x, y + self.y);
        let (sin, cos) = self.hdg.sin_cos();
        (tx * cos - ty * sin, tx * sin + ty * cos, z + self.z)
    }
}

/// The header: revision, naming, bounds, geo reference and offset.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Header {
    pub rev_major: u32,
    pub rev_minor: u32,
    pub name: Option<String>,
    pub version: Option<String>,
    pub date: Option<String>,
    pub vendor: Option<String>,
    pub north: Option<f64>,
    pub south: Option<f64>,
    pub east: Option<f64>,
    pub west: Option<f64>,
    /// Text of `<geoReference>` (a PROJ string), trimmed.
    pub geo_reference: Option<String>,
    /// `<offset>`; see [`HeaderOffset`] for why positions do not include it.
    pub offset: Option<HeaderOffset>,
}
