//! A UDPDriverController's properties, read as esmini's `ControllerUDPDriver` constructor reads
//! them: `port` (0 or absent: the base port plus the object id), `basePort`, `execMode`
//! (`asynchronous`, the default, or `synchronous`) and `inputMode` (`driverInput`, the default,
//! `vehicleStateXYZHPR` or `vehicleStateXYH`; checked, but as in esmini it decides nothing: each
//! message's header says its mode). A name given twice counts the first time (esmini's
//! `OSCProperties`); numbers are read the way C's `atoi` reads them. A value esmini refuses
//! (it stops) is an error here; a number `atoi` reads only in part is a note.
//!
//! The base port belongs to all UDP drivers of a run: esmini keeps it in one static variable
//! that each controller with a `basePort` property sets as the scenario is read (the entities'
//! controllers, then the Init's, then the stories'), so the last one read wins; without any it
//! is 49950. esmini's controller catalog passes its `BasePort` parameter (default 49950) as that
//! property, so every catalog controller sets it.

use openscenario::{ActionKind, Controller, PrivateAction, Scenario};
use serde::Serialize;

/// esmini's default base port (`DEFAULT_UDP_DRIVER_PORT`).
pub const DEFAULT_BASE_PORT: u16 = 49950;
/// The controller type served (a controller's `esminiController` property, else its name).
pub const UDP_DRIVER: &str = "UDPDriverController";

/// How a port's datagrams are read each step.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum ExecMode {
    /// Every datagram queued is read and the newest kept; nothing is waited for.
    Asynchronous,
    /// One datagram is read, waiting for it up to esmini's 500 ms.
    Synchronous,
}

impl ExecMode {
    pub fn name(self) -> &'static str {
        match self {
            ExecMode::Asynchronous => "asynchronous",
            ExecMode::Synchronous => "synchronous",
        }
    }
}

/// What one UDPDriverController's properties say.
#[derive(Debug, Clone, PartialEq)]
pub struct DriverProperties {
    /// The `port` property; 0 when absent or 0 (the base port plus the object id).
    pub port: u16,
    /// The `basePort` property, when given.
    pub base_port: Option<u16>,
    pub exec: ExecMode,
}

/// Whether `c` is a UDPDriverController (esmini's rule for a controller's type, as the engine
/// applies it).
pub fn is_udp_driver(c: &Controller) -> bool {
    c.properties.get("esminiController").unwrap_or(c.name.as_str()) == UDP_DRIVER
}

/// The first property named `name` (esmini's `GetValueStr`).
fn first<'a>(c: &'a Controller, name: &str) -> Option<&'a str> {
    c.properties.properties.iter().find(|(n, _)| n == name).map(|(_, v)| v.as_str())
}

/// C's `atoi`: leading blanks, a sign, the digits that follow; 0 when there are none. Also
/// whether the whole text was that number.
fn atoi(text: &str) -> (i64, bool) {
    let t = text.trim_start();
    let (negative, rest) = match t.as_bytes().first() {
        Some(b'-') => (true, &t[1..]),
        Some(b'+') => (false, &t[1..]),
        _ => (false, t),
    };
    let digits: String = rest.chars().take_while(|c| c.is_ascii_digit()).collect();
    // more than 18 digits cannot be a port anyway; keep the value out of range, not wrapped
    let magnitude = if digits.len() > 18 { i64::MAX / 2 } else { digits.parse::<i64>().unwrap_or(0) };
    let whole = !digits.is_empty() && digits.len() == rest.len();
    (if negative { -magnitude } else { magnitude }, whole)
}

/// Reads `c`'s properties; `Err` for a value esmini refuses, naming the controller and where it
/// is; notes for numbers read only in part.
pub fn read_properties(c: &Controller, notes: &mut Vec<String>) -> Result<DriverProperties, String> {
    let at = &c.origin;
    let mut port_property = |name: &str| -> Result<Option<u16>, String> {
        let Some(text) = first(c, name) else { return Ok(None) };
        let (value, whole) = atoi(text);
        if !(0..=65535).contains(&value) {
            return Err(format!("{at}: UDPDriverController `{}`: {name} {text:?} is outside 0..=65535", c.name));
        }
        if !whole {
            notes.push(format!("{at}: UDPDriverController `{}`: {name} {text:?} is read as {value}, as esmini reads it", c.name));
        }
        Ok(Some(value as u16))
    };
    let port = port_property("port")?.unwrap_or(0);
    let base_port = port_property("basePort")?;
    let exec = match first(c, "execMode") {
        None | Some("asynchronous") => ExecMode::Asynchronous,
        Some("synchronous") => ExecMode::Synchronous,
        Some(other) => return Err(format!("{at}: UDPDriverController `{}`: execMode {other:?} is neither \"asynchronous\" nor \"synchronous\"", c.name)),
    };
    match first(c, "inputMode") {
        None | Some("driverInput" | "vehicleStateXYZHPR" | "vehicleStateXYH") => {}
        Some(other) => {
            return Err(format!(
                "{at}: UDPDriverController `{}`: inputMode {other:?} is not one esmini accepts (driverInput, vehicleStateXYZHPR, vehicleStateXYH; each message's header says its mode anyway)",
                c.name
            ))
        }
    }
    Ok(DriverProperties { port, base_port, exec })
}

/// Every UDPDriverController of `scenario` in the order esmini reads them: the entities'
/// ObjectControllers, then those of the Init's AssignControllerActions, then the stories'.
pub fn udp_drivers(scenario: &Scenario) -> Vec<&Controller> {
    let mut found: Vec<&Controller> = scenario.entities.iter().flat_map(|e| &e.controllers).collect();
    fn assigned(a: &openscenario::Action) -> Option<&Controller> {
        match &a.kind {
            ActionKind::Private(PrivateAction::AssignController { controller: Some(c), .. }) => Some(c),
            _ => None,
        }
    }
    let sb = &scenario.storyboard;
    found.extend(sb.init.private.iter().flat_map(|p| &p.actions).filter_map(assigned));
    found.extend(sb.events().flat_map(|e| &e.actions).filter_map(assigned));
    found.retain(|c| is_udp_driver(c));
    found
}

/// The base port of the run: `--base-port` when given, else the `basePort` of the last
/// UDPDriverController esmini reads that has one, else 49950. Also checks every UDP driver's
/// properties (esmini reads them all, used or not).
pub fn base_port(scenario: &Scenario, chosen: Option<u16>, notes: &mut Vec<String>) -> Result<u16, String> {
    let mut base = DEFAULT_BASE_PORT;
    for c in udp_drivers(scenario) {
        if let Some(b) = read_properties(c, notes)?.base_port {
            base = b;
        }
    }
    Ok(chosen.unwrap_or(base))
}

/// The port of an entity with esmini object id `object_id`: its controller's `port` unless 0,
/// else `base` + `object_id` (`ControllerUDPDriver::Activate`).
pub fn port(properties: &DriverProperties, base: u16, object_id: u32) -> Result<u16, String> {
    if properties.port != 0 {
        return Ok(properties.port);
    }
    u16::try_from(u32::from(base) + object_id).map_err(|_| format!("base port {base} + object id {object_id} is above 65535"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_are_read_as_atoi_reads_them() {
        assert_eq!(atoi("49950"), (49950, true));
        assert_eq!(atoi("  +7"), (7, true));
        assert_eq!(atoi("-3"), (-3, true));
        assert_eq!(atoi("12ab"), (12, false));
        assert_eq!(atoi("49950.0"), (49950, false));
        assert_eq!(atoi("port"), (0, false));
        assert_eq!(atoi(""), (0, false));
        assert!(atoi("99999999999999999999999").0 > 65535);
    }

    #[test]
    fn the_default_port_is_base_plus_object_id() {
        let p = DriverProperties { port: 0, base_port: None, exec: ExecMode::Asynchronous };
        assert_eq!(port(&p, 49950, 3), Ok(49953));
        assert!(port(&p, 65535, 1).is_err());
        let p = DriverProperties { port: 5000, ..p };
        assert_eq!(port(&p, 49950, 3), Ok(5000));
    }
}
