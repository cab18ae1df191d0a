//! The lamps of a traffic light: how many a signal of a given type has, as esmini 3.6.0 reads
//! them. esmini refuses a signal state (TrafficSignalStateAction, TrafficSignalCondition) whose
//! number of `;`-separated lamp modes differs from the light's lamp count, so whoever writes a
//! state needs the count.

use crate::model::signals::Signal;

/// Lamp counts by `type[.subtype]` (the German catalogue's 1000xxx lights), as esmini's
/// `traffic_light_type_map` lists them (RoadManager.hpp), every key spelled out.
const LAMPS: &[(&str, usize)] = &[
    ("1000001", 3),
    ("1000011.10", 3),
    ("1000011.20", 3),
    ("1000011.30", 3),
    ("1000011.40", 3),
    ("1000011.50", 3),
    ("1000002.30", 3),
    ("1000013.10", 3),
    ("1000002", 2),
    ("1000009.10", 2),
    ("1000009.20", 2),
    ("1000009.30", 2),
    ("1000010.10", 2),
    ("1000010.20", 2),
    ("1000007", 2),
    ("1000013", 2),
    ("1000002.10", 1),
    ("1000002.20", 1),
    ("1000014.10", 1),
    ("1000007.10", 1),
    ("1000015", 1),
    ("1000007.20", 1),
    ("1000013.20", 1),
    ("1000007.30", 1),
    ("1000013.30", 1),
    ("1000013.40", 1),
    ("1000013.50", 1),
    ("1000013.60", 1),
    ("1000013.70", 1),
    ("1000013.80", 1),
    ("1000013.90", 1),
    ("1000013.100", 1),
    ("1000020", 1),
    ("1000008", 1),
    ("1000012", 1),
    ("1000020.10", 1),
    ("1000008.10", 1),
    ("1000012.10", 1),
    ("1000020.20", 1),
    ("1000008.20", 1),
    ("1000012.20", 1),
    ("1000020.30", 1),
    ("1000008.30", 1),
    ("1000012.30", 1),
    ("1000020.40", 1),
    ("1000008.40", 1),
    ("1000012.40", 1),
    ("1000020.50", 1),
    ("1000008.50", 1),
    ("1000012.50", 1),
    ("1000020.60", 1),
    ("1000008.60", 1),
    ("1000012.60", 1),
    ("1000020.70", 1),
    ("1000008.70", 1),
    ("1000012.70", 1),
    ("1000020.80", 1),
    ("1000008.80", 1),
    ("1000012.80", 1),
    ("1000020.90", 1),
    ("1000008.90", 1),
    ("1000012.90", 1),
    ("1000020.100", 1),
    ("1000008.100", 1),
    ("1000012.100", 1),
    ("1000021", 1),
    ("1000022.10", 1),
    ("1000022.20", 1),
    ("1000023", 1),
];

/// The number of lamps esmini gives `signal`, or None when esmini does not read it as a
/// traffic light it knows. esmini makes a traffic light of a dynamic signal of country
/// `OpenDRIVE` whose `countryRevision` is absent (RoadManager's OpenDrive::LoadOpenDriveFile:
/// the revision defaults to 2013 and is read only when the attribute is empty, and a light
/// needs a revision before 2013), then looks its `type` (dots removed) `.subtype` (unless
/// empty, `none` or `-1`) `-value` (when given) up in its table (TrafficLight::SetTrafficLightInfo).
pub fn traffic_light_lamps(signal: &Signal) -> Option<usize> {
    let opendrive = signal.country.as_deref().is_some_and(|c| c.eq_ignore_ascii_case("opendrive"));
    if !signal.dynamic || !opendrive || signal.country_revision.is_some() || signal.value.is_some() {
        return None;
    }
    let mut key: String = signal.type_raw.chars().filter(|c| *c != '.').collect();
    if let Some(sub) = signal.subtype.as_deref().filter(|s| !s.is_empty() && *s != "none" && *s != "-1") {
        key.push('.');
        key.push_str(sub);
    }
    LAMPS.iter().find(|(k, _)| *k == key).map(|(_, n)| *n)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::signals::SignalOrientation;

    fn light(kind: &str, subtype: Option<&str>) -> Signal {
        Signal {
            id: "1".into(),
            name: None,
            s: 0.0,
            t: 0.0,
            z_offset: 0.0,
            h_offset: 0.0,
            pitch: 0.0,
            roll: 0.0,
            country: Some("OpenDRIVE".into()),
            country_revision: None,
            type_raw: kind.into(),
            subtype: subtype.map(Into::into),
            value: None,
            unit: None,
            text: None,
            dynamic: true,
            orientation: SignalOrientation::Both,
            height: None,
            width: None,
            validity: Vec::new(),
        }
    }

    #[test]
    fn lamp_counts_follow_type_and_subtype() {
        assert_eq!(traffic_light_lamps(&light("1000001", Some("-1"))), Some(3));
        assert_eq!(traffic_light_lamps(&light("1000002", Some("-1"))), Some(2));
        assert_eq!(traffic_light_lamps(&light("1000002", Some("10"))), Some(1));
        assert_eq!(traffic_light_lamps(&light("1000002", Some("30"))), Some(3));
        assert_eq!(traffic_light_lamps(&light("1.000.001", None)), Some(3));
        assert_eq!(traffic_light_lamps(&light("1000013", Some("none"))), Some(2));
        assert_eq!(traffic_light_lamps(&light("1000013", Some("50"))), Some(1));
        assert_eq!(traffic_light_lamps(&light("1000020", Some("100"))), Some(1));
        assert_eq!(traffic_light_lamps(&light("1000020", Some("110"))), None);
        assert_eq!(traffic_light_lamps(&light("206", None)), None);
        // esmini's keys are strings: a subtype spelled otherwise is not in its table
        assert_eq!(traffic_light_lamps(&light("1000020", Some("010"))), None);
    }

    #[test]
    fn only_dynamic_opendrive_lights_without_revision_or_value() {
        let mut s = light("1000001", None);
        s.country_revision = Some("2017".into());
        assert_eq!(traffic_light_lamps(&s), None);
        let mut s = light("1000001", None);
        s.country = Some("DE".into());
        assert_eq!(traffic_light_lamps(&s), None);
        let mut s = light("1000001", None);
        s.dynamic = false;
        assert_eq!(traffic_light_lamps(&s), None);
        let mut s = light("1000001", None);
        s.value = Some(1.0);
        assert_eq!(traffic_light_lamps(&s), None);
    }
}
