//! Root attributes (`benchmarkID`, `date`, author, …, `timeStepSize`) and `location`.

use std::fmt;

use crate::error::Error;

/// The attributes of `<commonRoad>` (besides the fixed `commonRoadVersion="2020a"`).
#[derive(Debug, Clone, PartialEq)]
pub struct Header {
    pub benchmark_id: BenchmarkId,
    /// Given by the caller (never "today"), so that the same input gives the same bytes.
    pub date: Date,
    pub author: String,
    pub affiliation: String,
    pub source: String,
    /// Seconds per time step (> 0).
    pub time_step_size: f64,
}

/// A benchmark id the CommonRoad readers parse:
/// `(C-)?CCC_MapName-MapId[_ConfigId[_X-PredId(-PredId)*]]` with `X` in `S T P I`.
///
/// Not checked: that `CCC` is an ISO 3166 alpha-3 code (or `ZAM`); the readers reject other
/// country codes, so use `ZAM` unless the country is known.
#[derive(Debug, Clone, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct BenchmarkId(String);

impl BenchmarkId {
    /// Checks the reader's pattern (full match).
    pub fn parse(id: &str) -> Result<Self, Error> {
        match check_benchmark_id(id) {
            Ok(()) => Ok(Self(id.to_string())),
            Err(why) => Err(Error::InvalidBenchmarkId { id: id.to_string(), why }),
        }
    }

    /// `CCC_<name reduced to ASCII letters and digits>-1_1_T-1`, the id of a converted scenario.
    pub fn for_converted(country: &str, name: &str) -> Result<Self, Error> {
        let map_name: String = name.chars().filter(char::is_ascii_alphanumeric).collect();
        Self::parse(&format!("{country}_{map_name}-1_1_T-1"))
    }

    pub fn as_str(&self) -> &str {
        &self.0
    }

    /// The id's parts, as the readers split it (the id was checked when it was made).
    pub fn parts(&self) -> BenchmarkIdParts<'_> {
        let (cooperative, s) = match self.0.strip_prefix("C-") {
            Some(rest) => (true, rest),
            None => (false, self.0.as_str()),
        };
        let country = &s[..3];
        let s = &s[4..];
        let name_len = s.bytes().take_while(u8::is_ascii_alphanumeric).count();
        let map_name = &s[..name_len];
        // after the map name: -MapId[_ConfigId[_X-PredId(-PredId)*]]
        let mut fields = s[name_len + 1..].split('_');
        let number = |t: Option<&str>| t.and_then(|t| t.parse::<u64>().ok());
        let map_id = number(fields.next()).unwrap_or(1);
        let configuration_id = number(fields.next());
        let prediction = fields.next().map(|p| {
            let mut parts = p.split('-');
            let behaviour = parts.next().and_then(|b| b.chars().next()).unwrap_or('T');
            (behaviour, parts.filter_map(|n| n.parse::<u64>().ok()).collect())
        });
        BenchmarkIdParts { cooperative, country, map_name, map_id, configuration_id, prediction }
    }
}

/// A benchmark id taken apart: `(C-)?CCC_MapName-MapId[_ConfigId[_X-PredId(-PredId)*]]`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct BenchmarkIdParts<'a> {
    /// The `C-` prefix of a cooperative scenario.
    pub cooperative: bool,
    pub country: &'a str,
    pub map_name: &'a str,
    pub map_id: u64,
    pub configuration_id: Option<u64>,
    /// The obstacle behaviour letter (`S`, `T`, `P`, `I`) and the prediction ids.
    pub prediction: Option<(char, Vec<u64>)>,
}

impl fmt::Display for BenchmarkId {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

/// `[1-9][0-9]*` at the start of `s`: returns the rest.
fn strip_positive_int(s: &str) -> Option<&str> {
    let digits = s.bytes().take_while(u8::is_ascii_digit).count();
    if digits == 0 || s.starts_with('0') {
        return None;
    }
    Some(&s[digits..])
}

fn check_benchmark_id(id: &str) -> Result<(), &'static str> {
    let s = id.strip_prefix("C-").unwrap_or(id);
    let country = s.get(..3).ok_or("too short")?;
    if !country.bytes().all(|b| b.is_ascii_uppercase()) {
        return Err("country code must be three upper-case letters");
    }
    let s = s[3..].strip_prefix('_').ok_or("expected '_' after the country code")?;
    let name_len = s.bytes().take_while(u8::is_ascii_alphanumeric).count();
    if name_len == 0 {
        return Err("map name must be non-empty ASCII letters and digits");
    }
    let s = s[name_len..].strip_prefix('-').ok_or("expected '-' after the map name")?;
    let s = strip_positive_int(s).ok_or("map id must be a positive integer without leading zero")?;
    if s.is_empty() {
        return Ok(());
    }
    let s = s.strip_prefix('_').ok_or("expected '_' before the configuration id")?;
    let s = strip_positive_int(s).ok_or("configuration id must be a positive integer")?;
    if s.is_empty() {
        return Ok(());
    }
    let s = s.strip_prefix('_').ok_or("expected '_' before the prediction type")?;
    let mut s = match s.as_bytes().first() {
        Some(b'S' | b'T' | b'P' | b'I') => &s[1..],
        _ => return Err("prediction type must be one of S, T, P, I"),
    };
    if s.is_empty() {
        return Err("prediction type needs at least one -id");
    }
    while !s.is_empty() {
        s = s.strip_prefix('-').ok_or("expected '-' before a prediction id")?;
        s = strip_positive_int(s).ok_or("prediction id must be a positive integer")?;
    }
    Ok(())
}

/// A calendar date (`xs:date`, written `YYYY-MM-DD`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Date {
    year: u16,
    month: u8,
    day: u8,
}

impl Date {
    /// Fails for a day that does not exist (Gregorian calendar, years 1–9999).
    pub fn new(year: u16, month: u8, day: u8) -> Result<Self, Error> {
        let leap = (year.is_multiple_of(4) && !year.is_multiple_of(100)) || year.is_multiple_of(400);
        let days = match month {
            1 | 3 | 5 | 7 | 8 | 10 | 12 => 31,
            4 | 6 | 9 | 11 => 30,
            2 if leap => 29,
            2 => 28,
            _ => 0,
        };
        if year == 0 || year > 9999 || day == 0 || day > days {
            return Err(Error::InvalidDate { year, month, day });
        }
        Ok(Self { year, month, day })
    }
    pub fn year(&self) -> u16 {
        self.year
    }
    pub fn month(&self) -> u8 {
        self.month
    }
    pub fn day(&self) -> u8 {
        self.day
    }
}

impl fmt::Display for Date {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{:04}-{:02}-{:02}", self.year, self.month, self.day)
    }
}

/// `<location>`: where on Earth the scenario is (not to be confused with `diagnostic::Location`,
/// a place in a file). The default is what commonroad-io writes for "unknown": -999 / 999 / 999.
/// `<environment>` is deliberately absent: the XSD's enums do not match the readers' enums.
#[derive(Debug, Clone, PartialEq)]
pub struct GeoLocation {
    pub geo_name_id: i64,
    pub gps_latitude: f64,
    pub gps_longitude: f64,
    pub geo_transformation: Option<GeoTransformation>,
}

impl Default for GeoLocation {
    fn default() -> Self {
        Self { geo_name_id: -999, gps_latitude: 999.0, gps_longitude: 999.0, geo_transformation: None }
    }
}

/// `<geoTransformation>`: a PROJ string (e.g. OpenDRIVE's `geoReference`) and the planar
/// transformation applied on top of it.
#[derive(Debug, Clone, PartialEq)]
pub struct GeoTransformation {
    pub geo_reference: String,
    pub x_translation: f64,
    pub y_translation: f64,
    pub z_rotation: f64,
    /// > 0.
    pub scaling: f64,
}

impl GeoTransformation {
    /// Only a PROJ string; identity transformation.
    pub fn proj(geo_reference: impl Into<String>) -> Self {
        Self { geo_reference: geo_reference.into(), x_translation: 0.0, y_translation: 0.0, z_rotation: 0.0, scaling: 1.0 }
    }
}
