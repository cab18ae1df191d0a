//! The `<header>` of an OpenDRIVE file.

/// `<header><offset>`: a shift and rotation of the whole data set.
///
/// The parser applies it to the plan view and the elevation, as esmini 3.6 does
/// (`OpenDrive::LoadOpenDriveFile`), so world coordinates returned by this crate are in the
/// offset frame; OpenSCENARIO world positions are mapped into it with [`HeaderOffset::apply`]
/// (esmini's `ScenarioReader::parseOSCPosition`).
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
