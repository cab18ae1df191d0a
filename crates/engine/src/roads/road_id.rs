//! The road a scenario's `roadId` names, found as esmini finds it. esmini gives every road a
//! numeric internal id when it loads the map (`OpenDrive::EstablishUniqueIds`): a road whose id
//! is all digits (at most ten) keeps its number, and any other road takes the next free number
//! in file order (an earlier road that had taken a number a later numeric id claims is moved on
//! to the next free one). A `roadId` in a scenario (`ResolveRoadIdFromStr` in ScenarioReader)
//! is first read as a number with `std::stod`, which reads the longest leading number and
//! ignores the rest, so `"2Kalle3"` is road 2 even when a road `2Kalle3` exists; an integral
//! number names the road with that internal id, anything else (no leading number, or a
//! fraction) is looked up as the id string itself.

use opendrive::RoadNetwork;

/// esmini's `ID_MAX`: the largest internal id (`ID_UNDEFINED` is one more).
const ID_MAX: u64 = 0xffff_fffe;

/// Index of the road `id` names, as esmini resolves it; `None` if it names no road.
pub(crate) fn resolve_road_id(net: &RoadNetwork, id: &str) -> Option<usize> {
    let Some(v) = leading_number(id) else { return net.road_index(id) };
    if v.is_nan() {
        // esmini keeps ID_UNDEFINED: no road.
        return None;
    }
    // esmini casts to its 32-bit id type and compares within 1e-6 (NEAR_NUMBERS); a negative
    // or too large number cannot be such an id, so the string is looked up.
    if !(0.0..=ID_MAX as f64).contains(&v) || (v - v.trunc()).abs() >= 1e-6 {
        return net.road_index(id);
    }
    let n = v.trunc() as u64;
    // Usual case: a road whose id is that number written plainly keeps it.
    if let Some(r) = net.road_index(&n.to_string()) {
        return Some(r);
    }
    internal_ids(net).iter().position(|&i| i == n)
}

/// esmini's internal id of every road, in the network's (file) order.
fn internal_ids(net: &RoadNetwork) -> Vec<u64> {
    let mut ids: Vec<u64> = Vec::with_capacity(net.roads.len());
    let mut next = 0u64;
    for road in &net.roads {
        let s = road.id.as_str();
        let numeric = !s.is_empty() && s.len() <= 10 && s.bytes().all(|b| b.is_ascii_digit());
        let value = if numeric { s.parse::<u64>().ok().filter(|&v| v <= ID_MAX) } else { None };
        let current = match value {
            Some(v) => {
                for earlier in ids.iter_mut().filter(|i| **i == v) {
                    *earlier = next;
                    next += 1;
                }
                next = next.max(v + 1);
                v
            }
            None => {
                next += 1;
                next - 1
            }
        };
        ids.push(current);
    }
    ids
}

/// The number `std::stod` reads at the start of `s` (after white space): decimal with an
/// optional sign, fraction and exponent, `inf`/`infinity`/`nan`, or a hexadecimal integer;
/// `None` where it reads none (and throws).
fn leading_number(s: &str) -> Option<f64> {
    let t = s.trim_start();
    let (sign, rest) = match t.as_bytes().first() {
        Some(b'-') => (-1.0, &t[1..]),
        Some(b'+') => (1.0, &t[1..]),
        _ => (1.0, t),
    };
    let lower = rest.get(..8).unwrap_or(rest).to_ascii_lowercase();
    if lower.starts_with("inf") {
        return Some(sign * f64::INFINITY);
    }
    if lower.starts_with("nan") {
        return Some(f64::NAN);
    }
    let b = rest.as_bytes();
    if lower.starts_with("0x") && b.get(2).is_some_and(u8::is_ascii_hexdigit) {
        let digits: String = rest[2..].chars().take_while(char::is_ascii_hexdigit).collect();
        return u64::from_str_radix(&digits, 16).ok().map(|v| sign * v as f64).or(Some(sign * f64::INFINITY));
    }
    let mut end = b.iter().take_while(|c| c.is_ascii_digit()).count();
    let mut digits = end;
    if b.get(end) == Some(&b'.') {
        let frac = b[end + 1..].iter().take_while(|c| c.is_ascii_digit()).count();
        end += 1 + frac;
        digits += frac;
    }
    if digits == 0 {
        return None;
    }
    if matches!(b.get(end), Some(b'e' | b'E')) {
        let mut k = end + 1;
        if matches!(b.get(k), Some(b'+' | b'-')) {
            k += 1;
        }
        let exp = b[k.min(b.len())..].iter().take_while(|c| c.is_ascii_digit()).count();
        if exp > 0 {
            end = k + exp;
        }
    }
    rest[..end].parse::<f64>().ok().map(|v| sign * v)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn stod_reads_the_leading_number_only() {
        assert_eq!(leading_number("2Kalle3"), Some(2.0));
        assert_eq!(leading_number(" 12.5e1x"), Some(125.0));
        assert_eq!(leading_number("-3"), Some(-3.0));
        assert_eq!(leading_number("4."), Some(4.0));
        assert_eq!(leading_number("1e"), Some(1.0));
        assert_eq!(leading_number("0x1A"), Some(26.0));
        assert_eq!(leading_number("Kalle"), None);
        assert_eq!(leading_number("."), None);
        assert_eq!(leading_number(""), None);
        assert!(leading_number("nan").is_some_and(f64::is_nan));
    }

    fn net(ids: &[&str]) -> RoadNetwork {
        let roads: String = ids
            .iter()
            .map(|id| {
                format!(
                    r#"<road id="{id}" length="10" junction="-1"><planView><geometry s="0" x="0" y="0" hdg="0" length="10"><line/></geometry></planView>
<lanes><laneSection s="0"><center><lane id="0" type="none"/></center><right><lane id="-1" type="driving"><width sOffset="0" a="3.5" b="0" c="0" d="0"/></lane></right></laneSection></lanes></road>"#
                )
            })
            .collect();
        let xodr = format!(r#"<OpenDRIVE><header revMajor="1" revMinor="6"/>{roads}</OpenDRIVE>"#);
        opendrive::parse_str(&xodr, std::path::Path::new("t.xodr")).map(|l| l.network).unwrap_or_else(|e| panic!("{e}"))
    }

    #[test]
    fn ids_resolve_as_esmini_numbers_them() {
        // Kalle takes 2 first, then road "2" claims it and Kalle moves on to 3; 2Kalle3 gets 4.
        let n = net(&["0", "1", "Kalle", "2", "2Kalle3"]);
        assert_eq!(internal_ids(&n), vec![0, 1, 3, 2, 4]);
        assert_eq!(resolve_road_id(&n, "2Kalle3"), Some(3));
        assert_eq!(resolve_road_id(&n, "Kalle"), Some(2));
        assert_eq!(resolve_road_id(&n, "3"), Some(2));
        assert_eq!(resolve_road_id(&n, "2.0"), Some(3));
        assert_eq!(resolve_road_id(&n, "4"), Some(4));
        assert_eq!(resolve_road_id(&n, "1.5"), None);
        assert_eq!(resolve_road_id(&n, "7"), None);
        assert_eq!(resolve_road_id(&n, "nan"), None);
    }
}
