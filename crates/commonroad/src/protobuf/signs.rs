//! Traffic-sign elements: a 2020a sign id (national, e.g. `274`) becomes the `TrafficSignID`
//! member of the map's country (`MAX_SPEED`), which commonroad-io maps back through the same
//! country's table. The map's country must be one commonroad-io has a table for (it looks the
//! table up by the map's country and fails for others), so a map of another country is written
//! as `ZAM`, whose table the 2020a readers use for such countries too.

use super::messages::commonroad_common as pb;
use super::sign_names::SIGN_NAMES;
use crate::traffic::TrafficSignElement;
use crate::Error;

/// The country whose sign table a map of `country` uses: itself if commonroad-io has a table
/// for it, else `ZAM`.
pub(super) fn sign_country(country: &str) -> &'static str {
    SIGN_NAMES.iter().map(|(c, _)| *c).find(|c| *c == country).unwrap_or("ZAM")
}

/// The member name of sign `id` in the table of `country` (a [`sign_country`]); `None` when the
/// table has no such id. Like the 2020a readers, `274` is the country's maximum speed sign
/// whatever its national id.
fn member_name(country: &str, id: &str) -> Option<&'static str> {
    let table = SIGN_NAMES.iter().find(|(c, _)| *c == country)?.1;
    if id == "274" && table.iter().any(|(_, name)| *name == "MAX_SPEED") {
        return Some("MAX_SPEED");
    }
    table.binary_search_by(|(v, _)| (*v).cmp(id)).ok().map(|i| table[i].1)
}

/// The element as a 2024 message; a sign id the country's table lacks is written `UNKNOWN`
/// (what the 2020a readers make of it), with a warning.
pub(super) fn element(
    el: &TrafficSignElement,
    country: &str,
    context: &dyn Fn() -> String,
    warnings: &mut Vec<String>,
) -> Result<pb::TrafficSignElement, Error> {
    use pb::traffic_sign_id_enum::TrafficSignId;
    let id = match member_name(country, &el.sign_id) {
        Some(name) => match TrafficSignId::from_str_name(name) {
            Some(id) => id,
            None => {
                warnings.push(format!(
                    "{}: sign {} ({name}) of commonroad-io's {country} table is not in the 2024 TrafficSignID                      enumeration; written as UNKNOWN",
                    context(),
                    el.sign_id
                ));
                TrafficSignId::Unknown
            }
        },
        None => {
            warnings.push(format!(
                "{}: sign id {:?} is not in commonroad-io's {country} table; written as UNKNOWN (as the 2020a \
                 readers read it)",
                context(),
                el.sign_id
            ));
            TrafficSignId::Unknown
        }
    };
    Ok(pb::TrafficSignElement { element_id: id.into(), additional_values: el.additional_values.clone() })
}

#[cfg(test)]
mod tests {
    use super::*;
    use pb::traffic_sign_id_enum::TrafficSignId;

    #[test]
    fn tables_are_sorted_and_a_name_the_enumeration_lacks_is_written_unknown() {
        let mut missing = Vec::new();
        for (country, table) in SIGN_NAMES {
            assert!(table.windows(2).all(|w| w[0].0 < w[1].0), "{country}: sorted by id");
            for (id, name) in *table {
                if TrafficSignId::from_str_name(name).is_none() {
                    missing.push(format!("{country} {id} {name}"));
                }
            }
        }
        // the German (= ZAM) table is whole; commonroad-io 2026.1's enumeration lacks some US
        // and Spanish signs its tables name: those are written UNKNOWN, with a warning
        assert!(missing.iter().all(|m| !m.starts_with("DEU") && !m.starts_with("ZAM")), "{missing:?}");
        assert!(missing.contains(&"ESP r307 NO_STOPPING".to_string()), "{missing:?}");
        let mut w = Vec::new();
        let el = element(&TrafficSignElement::new("r307"), "ESP", &|| "trafficSign 4".into(), &mut w).unwrap();
        assert_eq!(el.element_id, i32::from(TrafficSignId::Unknown));
        assert!(w[0].contains("NO_STOPPING"), "{w:?}");
    }

    #[test]
    fn national_ids_map_to_members_by_country() {
        assert_eq!(member_name("DEU", "274"), Some("MAX_SPEED"));
        assert_eq!(member_name("ZAM", "206"), Some("STOP"));
        assert_eq!(member_name("USA", "R1-1"), Some("STOP"));
        // 274 is read as the country's speed limit, as the 2020a readers do
        assert_eq!(member_name("USA", "274"), Some("MAX_SPEED"));
        assert_eq!(member_name("USA", "206"), None);
        assert_eq!(sign_country("NLD"), "ZAM");
        assert_eq!(sign_country("DEU"), "DEU");
        let mut w = Vec::new();
        let el = element(&TrafficSignElement::new("206"), "USA", &|| "trafficSign 3".into(), &mut w).unwrap();
        assert_eq!(el.element_id, i32::from(TrafficSignId::Unknown));
        assert!(w[0].contains("trafficSign 3") && w[0].contains("206"), "{w:?}");
    }
}
