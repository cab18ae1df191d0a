//! A ghost reads a trajectory's absolute time stamps its head start later (esmini's
//! `FollowTrajectoryAction::Move`, timeOffset = headstart for a ghost), so it is where its
//! entity is meant to be one head start on. Figures from esmini 3.6.0 on this scenario.

use crate::common::*;

/// Ego at s = 50 (10 m/s, FollowGhost with a 2 s head start); at 1 s (−1 s for the ghost) it
/// follows a polyline stamped 1 s at x = 60, 4 s at x = 90 (y −3), 7 s at x = 120.
fn scenario() -> String {
    let init = ghost_ego_init(&teleport("Target", 300.0, -1));
    let traj = r#"<PrivateAction><RoutingAction><FollowTrajectoryAction><TrajectoryRef><Trajectory name="T" closed="false"><Shape><Polyline><Vertex time="1"><Position><WorldPosition x="60" y="-1.75" h="0"/></Position></Vertex><Vertex time="4"><Position><WorldPosition x="90" y="-3"/></Position></Vertex><Vertex time="7"><Position><WorldPosition x="120" y="-3"/></Position></Vertex></Polyline></Shape></Trajectory></TrajectoryRef><TimeReference><Timing domainAbsoluteRelative="absolute" scale="1" offset="0"/></TimeReference><TrajectoryFollowingMode followingMode="position"/></FollowTrajectoryAction></RoutingAction></PrivateAction>"#;
    let stories = story("Ego", &event("Follow", "overwrite", traj, &trigger(&sim_time(1.0, "greaterThan", "none", 0.0))));
    let stop = stop_at(5.0);
    with_follow_ghost(&xosc(&init, &stories, &stop), 2.0)
}

#[test]
fn the_ghost_reads_absolute_time_stamps_a_head_start_later() {
    let run = run(&scenario());
    // esmini: the ghost at (60.2, −1.7583) at −0.98 s (the stamp of 1.02 s), (75, −2.375) at
    // 0.5 s, (100, −3) at 3 s; the Ego following at (80.0025, −2.5738) at 3 s.
    for (who, t, x, y) in
        [("Ego_ghost", -0.98, 60.2, -1.7583), ("Ego_ghost", 0.5, 75.0, -2.375), ("Ego_ghost", 3.0, 100.0, -3.0), ("Ego", 3.0, 80.0025, -2.5738)]
    {
        let s = at(&run, who, t);
        assert!(close(s.x, x, 1e-4) && close(s.y, y, 1e-4), "{who} at {t}: ({}, {})", s.x, s.y);
    }
}
