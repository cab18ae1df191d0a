//! OpenDRIVE sign codes → CommonRoad `trafficSignID`s (the 2020a XSD enumeration, whose
//! numbers are the German StVO catalogue). German signs are taken as they are; Swedish
//! ones are translated where the meaning is the same; anything else is refused with a reason.

use commonroad::{is_xsd_traffic_sign_id, xml::format_decimal, TrafficSignElement};

/// What a signal is in CommonRoad terms.
#[derive(Debug, Clone, PartialEq)]
pub enum SignKind {
    Sign(TrafficSignElement),
    /// Why it cannot be expressed.
    Dropped(String),
}

/// Country family of a signal, from its `country` attribute (or the default).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Country {
    Germany,
    Sweden,
    Other,
}

fn country_of(raw: &str) -> Country {
    match raw.trim().to_ascii_uppercase().as_str() {
        // "OpenDRIVE" is the catalogue of the standard's annex, i.e. the German one
        "" | "DE" | "DEU" | "OPENDRIVE" => Country::Germany,
        "SE" | "SWE" => Country::Sweden,
        _ => Country::Other,
    }
}

/// Speed in m/s of `value` given in `unit` (km/h when absent, as sign faces show).
pub fn speed_mps(value: f64, unit: Option<&str>) -> Option<f64> {
    let factor = match unit.map(|u| u.trim().to_ascii_lowercase()) {
        None => 1.0 / 3.6,
        Some(u) if u.is_empty() || u == "km/h" || u == "kmh" => 1.0 / 3.6,
        Some(u) if u == "m/s" => 1.0,
        Some(u) if u == "mph" => 0.44704,
        Some(_) => return None,
    };
    let v = value * factor;
    (v.is_finite() && v > 0.0).then_some(v)
}

fn speed_sign(id: &str, kmh_or_unit: Option<(f64, Option<&str>)>) -> SignKind {
    match kmh_or_unit.and_then(|(v, u)| speed_mps(v, u)).and_then(format_decimal) {
        Some(v) => SignKind::Sign(TrafficSignElement { sign_id: id.to_string(), additional_values: vec![v] }),
        None => SignKind::Dropped(format!("speed sign {id} without a usable value")),
    }
}

fn subtype_of(raw: Option<&str>) -> Option<&str> {
    raw.map(str::trim).filter(|s| !s.is_empty() && *s != "-1" && !s.eq_ignore_ascii_case("none"))
}

/// Maps one signal. `country` is the signal's attribute or the default country.
pub fn map_sign(country: &str, kind: &str, subtype: Option<&str>, value: Option<f64>, unit: Option<&str>) -> SignKind {
    let kind = kind.trim();
    let sub = subtype_of(subtype);
    match country_of(country) {
        Country::Germany => {
            if matches!(kind, "274" | "274.1" | "275") {
                // speed limits: the value is in the file (its unit), km/h if unit-less
                return speed_sign(kind, value.map(|v| (v, unit)));
            }
            if matches!(kind, "274.2" | "278") {
                // end of a limit: the value is optional
                return match value.and_then(|v| speed_mps(v, unit)).and_then(format_decimal) {
                    Some(v) => SignKind::Sign(TrafficSignElement { sign_id: kind.to_string(), additional_values: vec![v] }),
                    None => SignKind::Sign(TrafficSignElement::new(kind)),
                };
            }
            if let Some(sub) = sub {
                let full = format!("{kind}-{sub}");
                if is_xsd_traffic_sign_id(&full) {
                    return SignKind::Sign(TrafficSignElement::new(full));
                }
            }
            if is_xsd_traffic_sign_id(kind) {
                return SignKind::Sign(TrafficSignElement::new(kind));
            }
            SignKind::Dropped(format!("German sign `{kind}`{} is not in CommonRoad's sign list", sub.map(|s| format!("-{s}")).unwrap_or_default()))
        }
        Country::Sweden => {
            let code = format!("{}{}", kind.to_ascii_uppercase(), sub.unwrap_or(""));
            match code.as_str() {
                // C31-n: maximum speed n×10 km/h
                "C31" => speed_sign("274", value.map(|v| (v * 10.0, Some("km/h")))),
                "C27" => SignKind::Sign(TrafficSignElement::new("276")), // no overtaking
                "C28" => SignKind::Sign(TrafficSignElement::new("280")), // end of no overtaking
                "B1" => SignKind::Sign(TrafficSignElement::new("205")),  // give way
                "B2" => SignKind::Sign(TrafficSignElement::new("206")),  // stop
                "A20" => SignKind::Sign(TrafficSignElement::new("123")), // road works
                _ => SignKind::Dropped(format!("Swedish sign `{code}` has no CommonRoad equivalent here")),
            }
        }
        Country::Other => SignKind::Dropped(format!("sign `{kind}` of country `{country}` has no CommonRoad equivalent")),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sign(k: SignKind) -> TrafficSignElement {
        match k {
            SignKind::Sign(s) => s,
            SignKind::Dropped(why) => panic!("dropped: {why}"),
        }
    }

    #[test]
    fn german_speed_limit_in_mps() {
        // 120 km/h = 33.3333 m/s
        let s = sign(map_sign("OpenDRIVE", "274", Some("62"), Some(120.0), Some("km/h")));
        assert_eq!(s.sign_id, "274");
        let v: f64 = s.additional_values[0].parse().unwrap();
        assert!((v - 120.0 / 3.6).abs() < 1e-3);
        // value already in m/s
        let s = sign(map_sign("OpenDRIVE", "274", Some("56"), Some(16.666666), Some("m/s")));
        let v: f64 = s.additional_values[0].parse().unwrap();
        assert!((v - 16.666666).abs() < 1e-3);
        // unit-less value on a German sign face is km/h
        let s = sign(map_sign("de", "274", Some(""), Some(50.0), None));
        let v: f64 = s.additional_values[0].parse().unwrap();
        assert!((v - 13.8889).abs() < 1e-3);
    }

    #[test]
    fn german_signs_as_they_are() {
        assert_eq!(sign(map_sign("OpenDRIVE", "205", Some("-1"), None, None)).sign_id, "205");
        assert_eq!(sign(map_sign("OpenDRIVE", "1000", Some("12"), None, None)).sign_id, "1000");
        assert_eq!(sign(map_sign("DE", "1002", Some("10"), None, None)).sign_id, "1002-10");
        assert!(matches!(map_sign("OpenDRIVE", "436", None, None, None), SignKind::Dropped(_)));
        assert!(matches!(map_sign("OpenDRIVE", "-1", None, None, None), SignKind::Dropped(_)));
    }

    #[test]
    fn swedish_and_other_countries() {
        let s = sign(map_sign("se", "c", Some("31"), Some(5.0), None));
        assert_eq!(s.sign_id, "274");
        let v: f64 = s.additional_values[0].parse().unwrap();
        assert!((v - 50.0 / 3.6).abs() < 1e-3);
        assert_eq!(sign(map_sign("se", "c", Some("27"), Some(1.0), None)).sign_id, "276");
        assert!(matches!(map_sign("cn", "shi", None, Some(50.0), None), SignKind::Dropped(_)));
    }
}
