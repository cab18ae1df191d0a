//! The driver models (controllers), each against hand computations or esmini 3.6.0's runs.

mod acc;
mod alks;
mod alks_r157;
mod alks_r157_beside_acc;
mod alks_r157_end_of_road;
mod alks_r157_lead_on_next_road;
mod alks_r157_one_domain;
mod alks_r157_reference_driver;
mod alks_r157_reversing_set_speed;
mod alks_r157_route;
mod alks_r157_rss_fsm;
mod assign_never_ends;
mod controllers_off_speed_from_displacement;
mod follow_reference_ties;
mod follow_route;
mod holds_lateral;
mod looming;
mod natural_driver;
mod natural_driver_additive;
mod natural_driver_junction_draw;
mod natural_driver_lane_change_while_deleted;
mod natural_driver_lanes_beside;
mod natural_driver_leader_across_junction;
mod natural_driver_standing_start;
mod offroad_follower;
mod teleport_under_controllers;
