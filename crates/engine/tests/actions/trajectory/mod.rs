//! FollowTrajectoryAction, forwards and backwards.

mod clothoid_spline_chained_on_slope;
mod clothoid_start_time;
mod end_at_junction_entry;
mod end_before_tight_curve;
mod end_inside_junction;
mod end_tolerance;
mod follow;
mod held_at_unlinked_start;
mod nurbs_control_point_at_road_end;
mod nurbs_control_point_past_road_end;
mod nurbs_headings;
mod nurbs_reverse_first_heading;
mod nurbs_small_basis_values;
mod offset_start_time;
mod past_road_end;
mod reverse;
mod reverse_first_vertex_heading;
mod reverse_vertex_headings;
mod start_at_rest;
mod start_speed_counts_as_set;
mod time_out_of_range;
mod timed_speed_sign;
mod timing;
