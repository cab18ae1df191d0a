//! The file's identity: benchmark id `CCC_<name>-1_<k>_T-1` (name reduced to ASCII letters and
//! digits, `k` the parameter variation, 1 without), and the date — fixed by the user, else the
//! OpenSCENARIO FileHeader's date, else 1970-01-01. Never "today": the same input must give
//! the same bytes on any day.

use commonroad::{BenchmarkId, Date};

/// Name used when nothing of the scenario name survives the reduction to letters and digits.
const FALLBACK_NAME: &str = "Scenario";

/// `country_<alnum name>-1_<config>_T-1`. `config` 0 is written as 1.
pub fn benchmark_id(country: &str, name: &str, config: u64) -> Result<BenchmarkId, commonroad::Error> {
    let mut map_name: String = name.chars().filter(char::is_ascii_alphanumeric).collect();
    if map_name.is_empty() {
        map_name = FALLBACK_NAME.to_string();
    }
    BenchmarkId::parse(&format!("{country}_{map_name}-1_{}_T-1", config.max(1)))
}

/// The date at the start of an `xs:dateTime` / `xs:date` text (`2020-03-20T12:00:00`).
pub fn date_prefix(text: &str) -> Option<Date> {
    let t = text.trim();
    let b = t.as_bytes();
    let digits = |r: std::ops::Range<usize>| -> Option<u32> {
        let s = t.get(r)?;
        s.bytes().all(|c| c.is_ascii_digit()).then(|| s.parse().ok())?
    };
    if b.get(4) != Some(&b'-') || b.get(7) != Some(&b'-') {
        return None;
    }
    let (y, m, d) = (digits(0..4)?, digits(5..7)?, digits(8..10)?);
    if matches!(b.get(10), Some(c) if c.is_ascii_digit()) {
        return None;
    }
    Date::new(u16::try_from(y).ok()?, u8::try_from(m).ok()?, u8::try_from(d).ok()?).ok()
}

/// Parses `YYYY-MM-DD` (`--date`).
pub fn parse_date(text: &str) -> Result<Date, String> {
    let t = text.trim();
    if t.len() != 10 {
        return Err(format!("expected a date YYYY-MM-DD, got {text:?}"));
    }
    date_prefix(t).ok_or_else(|| format!("expected a valid date YYYY-MM-DD, got {text:?}"))
}

/// A country code a benchmark id may start with: `ZAM` or an ISO 3166 alpha-3 code in upper
/// case (commonroad-io refuses to read a file with any other).
pub fn check_country(code: &str) -> Result<(), String> {
    if crate::country::is_known_country(code) {
        Ok(())
    } else {
        Err(format!("country must be ZAM or an ISO 3166 alpha-3 code in upper case (e.g. DEU, USA, SWE), got {code:?}"))
    }
}

/// The fallback date when neither `--date` nor the FileHeader gives one.
pub fn fallback_date() -> Date {
    // 1970-01-01 exists; the constructor cannot fail for it
    Date::new(1970, 1, 1).unwrap_or_else(|_| unreachable!())
}
