//! LaneChangeAction: its transition, a step of it, a target lane the road does not have, a
//! change going on into a junction.

mod across_a_split;
mod at_a_dead_end;
mod at_standstill_keeps_road_end_stop;
mod end_with_dangling_link;
mod into_junction;
mod missing_lane;
mod segment_s;
mod standing_aligns;
mod step;
mod target_lane_drift;
mod too_fast_and_road_end;
mod transition;
