//! One GroundTruth message per frame, as esmini's `OSIReporter::UpdateOSIGroundTruth` composes
//! it in its default reporting mode: the first frame carries the static part — the interface
//! version (3.5.0, the OSI esmini 3.6.0 links), the host vehicle (esmini's first object), the
//! MiscObjects as stationary objects, the lanes and lane boundaries — followed by the dynamic
//! part; every later frame only the dynamic part: the timestamp (simulated time, whole seconds
//! and nanoseconds, truncated as esmini truncates them) and a moving object per vehicle and
//! pedestrian in the run, in esmini's object order. A MiscObject that appears later is reported
//! as a stationary object in the frame it appears in.

use engine::{Sample, Trace};
use opendrive::RoadNetwork;
use openscenario::{EntityObject, Scenario};
use prost::Message;

use crate::global_ids::{GlobalIds, UNDEFINED};
use crate::kinematics::{road_pitch, Tracker};
use crate::lanes::lanes_and_boundaries;
use crate::moving::{id, moving_object, stationary_object};
use crate::objects::esmini_objects;
use crate::osi3::{GroundTruth, InterfaceVersion, Timestamp};

/// One entity of the run as OSI sees it.
#[derive(Debug, Clone)]
struct Object {
    name: String,
    /// esmini's object index.
    index: usize,
    model: EntityObject,
    tracker: Tracker,
    /// A MiscObject already reported.
    reported: bool,
}

/// Composes the frames of one run.
#[derive(Debug, Clone)]
pub struct Reporter {
    ids: GlobalIds,
    /// By the run's entity index (`Trace::entities`); `None`: not an esmini object (a ghost).
    objects: Vec<Option<Object>>,
    /// The static part (the first frame's, without the dynamic part).
    static_part: GroundTruth,
    /// The first frame is still to come.
    first: bool,
    last_time: Option<f64>,
    warnings: Vec<String>,
}

impl Reporter {
    /// A reporter for a run of `scenario` on `roads` whose entities are named `names` (in
    /// `Trace::entities` order).
    pub fn new(scenario: &Scenario, roads: Option<&RoadNetwork>, names: &[String]) -> Reporter {
        let mut warnings = Vec::new();
        let ids = GlobalIds::new(roads);
        let order = esmini_objects(scenario);
        let objects: Vec<Option<Object>> = names
            .iter()
            .map(|n| {
                let (index, (name, model)) = order.iter().enumerate().find(|(_, (name, _))| name == n)?;
                Some(Object { name: name.clone(), index, model: model.object.clone(), tracker: Tracker::default(), reported: false })
            })
            .collect();
        for (n, o) in names.iter().zip(&objects) {
            if o.is_none() {
                warnings.push(format!("OSI: `{n}` is not an object of the scenario (a ghost): not reported"));
            }
        }
        if objects.iter().flatten().any(|o| matches!(o.model, EntityObject::External { .. })) {
            warnings.push("OSI: an ExternalObjectReference has no type or size: not reported".into());
        }
        let host = order.first().map(|_| id(ids.first_entity)).unwrap_or_default();
        let (lane, lane_boundary) = roads.map(|net| lanes_and_boundaries(net, &ids)).unwrap_or_default();
        let static_part = GroundTruth {
            version: Some(InterfaceVersion { version_major: Some(3), version_minor: Some(5), version_patch: Some(0) }),
            host_vehicle_id: host,
            lane,
            lane_boundary,
            ..Default::default()
        };
        Reporter { ids, objects, static_part, first: true, last_time: None, warnings }
    }

    /// A reporter for the run of `trace`.
    pub fn for_trace(scenario: &Scenario, roads: Option<&RoadNetwork>, trace: &Trace) -> Reporter {
        let names: Vec<String> = trace.entities.iter().map(|e| e.name.clone()).collect();
        Reporter::new(scenario, roads, &names)
    }

    /// What could not be reported as esmini reports it.
    pub fn warnings(&self) -> &[String] {
        &self.warnings
    }

    /// The OSI id of the run's entity `index` (`None`: not reported).
    pub fn object_id(&self, index: usize) -> Option<u64> {
        self.objects.get(index)?.as_ref().map(|o| self.ids.first_entity + o.index as u64)
    }

    /// The static part: version, host vehicle, lanes and lane boundaries (the first frame has
    /// them, with the MiscObjects).
    pub fn static_part(&self) -> &GroundTruth {
        &self.static_part
    }

    /// The message of the frame at simulated time `time` where the run's entities are at
    /// `states` (by entity index; `None`: not in the run now) on `roads` (the network the
    /// reporter was made for).
    pub fn frame(&mut self, roads: Option<&RoadNetwork>, time: f64, states: &[Option<Sample>]) -> GroundTruth {
        let dt = self.last_time.map_or(0.0, |t| time - t);
        self.last_time = Some(time);
        let mut gt = if std::mem::take(&mut self.first) { self.static_part.clone() } else { GroundTruth::default() };
        let seconds = time.floor();
        gt.timestamp = Some(Timestamp { seconds: Some(seconds as i64), nanos: Some(((time - seconds) * 1e9) as u32) });
        // esmini's object order
        let mut order: Vec<(usize, usize)> = self.objects.iter().enumerate().filter_map(|(i, o)| o.as_ref().map(|o| (o.index, i))).collect();
        order.sort_unstable();
        for (_, i) in order {
            let Some(Some(o)) = self.objects.get_mut(i) else { continue };
            let Some(sample) = states.get(i).copied().flatten() else {
                o.tracker.reset();
                continue;
            };
            let osi_id = self.ids.first_entity + o.index as u64;
            let pitch = road_pitch(roads, &sample);
            let motion = o.tracker.next(&sample, pitch, dt);
            if let EntityObject::MiscObject(_) = o.model {
                if !o.reported {
                    o.reported = true;
                    gt.stationary_object.extend(stationary_object(&o.name, osi_id, &o.model, &motion));
                }
                continue;
            }
            let lane = sample.road.and_then(|r| {
                let road = roads?.roads.get(r.road as usize)?;
                Some(self.ids.lane((r.road as usize, road.section_index_at(r.s), r.lane_id)))
            });
            gt.moving_object.extend(moving_object(&o.name, o.index, osi_id, &o.model, &motion, lane.unwrap_or(UNDEFINED)));
        }
        gt
    }

    /// The frame's message encoded (what `frame` gives, as bytes).
    pub fn encoded_frame(&mut self, roads: Option<&RoadNetwork>, time: f64, states: &[Option<Sample>]) -> Vec<u8> {
        self.frame(roads, time, states).encode_to_vec()
    }
}

/// Every frame of `trace` from time 0 on (a ghost's head start left out), encoded.
pub fn trace_frames(scenario: &Scenario, roads: Option<&RoadNetwork>, trace: &Trace) -> (Vec<Vec<u8>>, Vec<String>) {
    let mut r = Reporter::for_trace(scenario, roads, trace);
    let mut frames = Vec::new();
    let mut states = Vec::with_capacity(trace.entities.len());
    for k in trace.zero_index()..trace.len {
        states.clear();
        states.extend(trace.entities.iter().map(|e| e.samples.get(k).copied().flatten()));
        frames.push(r.encoded_frame(roads, trace.time(k), &states));
    }
    (frames, r.warnings)
}
