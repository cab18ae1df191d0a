//! Which CommonRoad lanelet types and road users an OpenDRIVE lane becomes, from its lane type
//! and the road type in force. Lane types CommonRoad cannot express give `None`.

use commonroad::{LaneletType, RoadUser};
use opendrive::{LaneType, RoadKind};

/// What a kept lane turns into.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct LaneClass {
    pub types: Vec<LaneletType>,
    pub one_way: Vec<RoadUser>,
    pub bidirectional: Vec<RoadUser>,
    /// A lane motor vehicles drive on (signs and lights are attached to these first).
    pub vehicular: bool,
}

/// Lanelet types of the road class (motorway → highway + interstate, town → urban, ...).
pub fn road_types(kind: Option<RoadKind>) -> Vec<LaneletType> {
    use RoadKind::*;
    match kind {
        Some(Motorway) => vec![LaneletType::Interstate, LaneletType::Highway],
        Some(Town | TownExpressway | TownCollector | TownArterial | TownPrivate | TownLocal | TownPlayStreet | LowSpeed | Pedestrian | Bicycle) => {
            vec![LaneletType::Urban]
        }
        Some(Rural) => vec![LaneletType::Country],
        Some(Unknown | Other) | None => vec![LaneletType::Unknown],
    }
}

/// The class of a lane of type `lane` on a road of class `road`; `in_junction` adds
/// `intersection`. `None` for lane types without a CommonRoad counterpart.
pub fn classify(lane: LaneType, road: Option<RoadKind>, in_junction: bool) -> Option<LaneClass> {
    use LaneType as L;
    let motorway = road == Some(RoadKind::Motorway);
    let base = road_types(road);
    let vehicle = vec![RoadUser::Vehicle];
    let mut class = match lane {
        L::Driving => {
            let mut t = base;
            if motorway {
                t.push(LaneletType::MainCarriageWay);
            }
            LaneClass { types: t, one_way: vehicle, bidirectional: vec![], vehicular: true }
        }
        L::Entry | L::OnRamp | L::MwyEntry => {
            let mut t = base;
            t.push(LaneletType::AccessRamp);
            LaneClass { types: t, one_way: vehicle, bidirectional: vec![], vehicular: true }
        }
        L::Exit | L::OffRamp | L::MwyExit => {
            let mut t = base;
            t.push(LaneletType::ExitRamp);
            LaneClass { types: t, one_way: vehicle, bidirectional: vec![], vehicular: true }
        }
        L::Bidirectional => LaneClass { types: base, one_way: vec![], bidirectional: vehicle, vehicular: true },
        L::Bus => LaneClass { types: vec![LaneletType::BusLane], one_way: vec![RoadUser::Bus], bidirectional: vec![], vehicular: true },
        L::Restricted => LaneClass { types: vec![LaneletType::Restricted], one_way: vec![], bidirectional: vec![], vehicular: false },
        L::Parking => LaneClass { types: vec![LaneletType::Parking], one_way: vec![], bidirectional: vec![], vehicular: false },
        L::Biking => LaneClass { types: vec![LaneletType::BicycleLane], one_way: vec![RoadUser::Bicycle], bidirectional: vec![], vehicular: false },
        L::Sidewalk => LaneClass { types: vec![LaneletType::Sidewalk], one_way: vec![], bidirectional: vec![RoadUser::Pedestrian], vehicular: false },
        // `stop` is OpenDRIVE 1.4's hard shoulder.
        L::Shoulder | L::Stop => LaneClass { types: vec![LaneletType::Shoulder], one_way: vec![], bidirectional: vec![], vehicular: false },
        L::Border => LaneClass { types: vec![LaneletType::Border], one_way: vec![], bidirectional: vec![], vehicular: false },
        _ => return None,
    };
    if in_junction {
        class.types.push(LaneletType::Intersection);
    }
    Some(class)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn motorway_driving_lane_is_highway_main_carriageway() {
        let c = classify(LaneType::Driving, Some(RoadKind::Motorway), false).unwrap();
        assert!(c.types.contains(&LaneletType::Highway));
        assert!(c.types.contains(&LaneletType::Interstate));
        assert!(c.types.contains(&LaneletType::MainCarriageWay));
        assert!(!c.types.contains(&LaneletType::Urban));
    }

    #[test]
    fn ramps_and_junctions() {
        let c = classify(LaneType::MwyEntry, Some(RoadKind::Motorway), false).unwrap();
        assert!(c.types.contains(&LaneletType::AccessRamp));
        let c = classify(LaneType::OffRamp, Some(RoadKind::Motorway), false).unwrap();
        assert!(c.types.contains(&LaneletType::ExitRamp));
        let c = classify(LaneType::Driving, Some(RoadKind::Town), true).unwrap();
        assert_eq!(c.types, vec![LaneletType::Urban, LaneletType::Intersection]);
        let c = classify(LaneType::Driving, Some(RoadKind::Rural), false).unwrap();
        assert_eq!(c.types, vec![LaneletType::Country]);
    }

    #[test]
    fn inexpressible_lanes_are_skipped() {
        for t in [LaneType::None, LaneType::Median, LaneType::Curb, LaneType::Rail, LaneType::Tram, LaneType::Special1] {
            assert!(classify(t, None, false).is_none(), "{t:?}");
        }
        assert_eq!(classify(LaneType::Sidewalk, None, false).unwrap().types, vec![LaneletType::Sidewalk]);
        assert_eq!(classify(LaneType::Biking, None, false).unwrap().types, vec![LaneletType::BicycleLane]);
    }
}
