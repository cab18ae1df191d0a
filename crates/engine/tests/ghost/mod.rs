//! The ghost of FollowGhost/FollowReference controllers: its head start, trajectories, restarts.

mod absolute_trajectory;
mod acquire_position;
mod act_of_other_entity;
mod added_teleport_from_nowhere;
mod back_on_road;
mod banked;
mod end_of_road_head_start;
mod follow;
mod head_start_holds_others;
mod init_trajectory_position;
mod lateral_distance_waits_on_follower;
mod lateral_only;
mod relative_lane_reference;
mod restart;
mod restart_steps_injected_lane_change;
mod shares_trailer_hitch;
mod steps_while_away;
mod teleport_relative_to_entity;
mod trail_end_lookahead;
mod trajectory_relative_to_entity;
