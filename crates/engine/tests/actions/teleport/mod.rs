//! TeleportAction rules found in esmini's source and by the differential tester.

mod domains_and_relative_road;
mod fresh_position_into_junction;
mod stuck_at_road_end;
mod travel_and_missing_lane;
mod world_position_without_heading;
