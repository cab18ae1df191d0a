//! Traffic-light cycles as `TrafficSignalController`s, one per CommonRoad light, each naming
//! its light by the CommonRoad id (the map writes every light as an OpenDRIVE signal with that
//! id). A phase per cycle element, `duration` steps × dt long, setting the light's state in the
//! lamp form red;yellow;green (`on;off;off` is red). A controller's first phase starts at time
//! 0 and the phases repeat, as a CommonRoad cycle does; a cycle's `timeOffset` is written by
//! rotating the phases so that the one in force at time 0 comes first (the first part of the
//! split phase at the end), which says the same without relying on `delay` without a
//! `reference` (the standard leaves that open). An inactive light is one dark phase.
//!
//! esmini 3.6.0 does not read traffic-signal controllers (nor does CARLA's scenario runner);
//! the controllers are for simulators and tools that do (osc2cr's engine, as esmini, does not
//! run them, but its conversion writes their phases back as the lights' cycles: `declared_cycles`).

use commonroad::{TrafficLight, TrafficLightColor};

use crate::xml::{time, El};

/// The lamp states of a colour, top to bottom: red;yellow;green.
pub(crate) fn lamps(c: TrafficLightColor) -> &'static str {
    match c {
        TrafficLightColor::Red => "on;off;off",
        TrafficLightColor::RedYellow => "on;on;off",
        TrafficLightColor::Green => "off;off;on",
        TrafficLightColor::Yellow => "off;on;off",
        TrafficLightColor::Inactive => "off;off;off",
    }
}

/// The phases of a cycle from time 0: (steps, colour), rotated by the offset.
pub(crate) fn phases_from_zero(light: &TrafficLight) -> Vec<(u64, TrafficLightColor)> {
    let cycle: Vec<(u64, TrafficLightColor)> = light.cycle.iter().map(|e| (e.duration.get(), e.color)).collect();
    let total: u64 = cycle.iter().map(|p| p.0).sum();
    if total == 0 {
        return cycle;
    }
    if light.active == Some(false) {
        return vec![(total, TrafficLightColor::Inactive)];
    }
    // commonroad-io: the state at step t is the cycle's at (t − offset) mod total
    let start = (total - light.time_offset % total) % total;
    if start == 0 {
        return cycle;
    }
    let mut head = Vec::new();
    let mut tail = Vec::new();
    let mut at = 0;
    for &(d, c) in &cycle {
        let (from, to) = (at, at + d);
        if to <= start {
            tail.push((d, c));
        } else if from >= start {
            head.push((d, c));
        } else {
            head.push((to - start, c));
            tail.push((start - from, c));
        }
        at = to;
    }
    head.extend(tail);
    head
}

/// The controller of `light`.
pub(crate) fn controller(light: &TrafficLight, dt: f64) -> El {
    let id = light.id.get();
    let phases = phases_from_zero(light).into_iter().enumerate().map(|(i, (steps, colour))| {
        El::new("Phase")
            .attr("name", format!("{}_{}", i + 1, colour.as_str()))
            .attr("duration", time(steps as f64 * dt))
            .child(El::new("TrafficSignalState").attr("trafficSignalId", id.to_string()).attr("state", lamps(colour)))
    });
    El::new("TrafficSignalController").attr("name", format!("light_{id}")).children(phases)
}

#[cfg(test)]
mod tests {
    use super::*;
    use commonroad::{CycleElement, TrafficLightId};
    use std::num::NonZeroU64;
    use TrafficLightColor::*;

    fn light(offset: u64) -> TrafficLight {
        let e = |d: u64, color| CycleElement { duration: NonZeroU64::new(d).unwrap_or(NonZeroU64::MIN), color };
        TrafficLight {
            id: TrafficLightId::new(7).unwrap_or_else(|| unreachable!()),
            cycle: vec![e(30, Red), e(5, RedYellow), e(40, Green), e(5, Yellow)],
            time_offset: offset,
            position: None,
            direction: None,
            active: None,
        }
    }

    /// The colour at step t of the rotated phases.
    fn colour_at(phases: &[(u64, TrafficLightColor)], t: u64) -> TrafficLightColor {
        let total: u64 = phases.iter().map(|p| p.0).sum();
        let mut at = t % total;
        for &(d, c) in phases {
            if at < d {
                return c;
            }
            at -= d;
        }
        unreachable!()
    }

    #[test]
    fn an_offset_rotates_the_phases_as_commonroad_io_reads_it() {
        for offset in [0, 1, 12, 30, 33, 79, 80, 95] {
            let l = light(offset);
            let phases = phases_from_zero(&l);
            assert_eq!(phases.iter().map(|p| p.0).sum::<u64>(), 80);
            for t in 0..200 {
                // commonroad-io: position (t - offset) mod 80 of the cycle
                let pos = (t + 80 * 10 - offset) % 80;
                let want = colour_at(&[(30, Red), (5, RedYellow), (40, Green), (5, Yellow)], pos);
                assert_eq!(colour_at(&phases, t), want, "offset {offset} step {t}");
            }
        }
    }
}
