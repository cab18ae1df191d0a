//! TeleportAction rules found in esmini's source and by the differential tester.

mod domains_and_relative_road;
mod travel_and_missing_lane;
