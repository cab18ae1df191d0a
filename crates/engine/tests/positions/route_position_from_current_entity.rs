//! A RoutePosition FromCurrentEntity, which esmini 3.6 does not implement ("FromCurrentEntity
//! is not implemented"): its TeleportAction copies an unset position, the world origin with
//! heading 0 on no road; a RelativeRoadPosition from that entity is unset too. Without a road
//! the default controller's move fails at the road's end, and from the next step
//! ScenarioEngine::step stops the entity, a later SpeedAction included.
//!
//! Fixture `route_position_from_current_entity.xosc` on straight.xodr; the numbers are esmini
//! 3.6.0's run of it; where esmini runs here the whole run is compared.

use crate::common::oracle::{assert_matches_esmini, run_fixture_scenario};
use crate::common::*;

#[test]
fn an_entity_placed_from_current_entity_stays_stopped_at_the_origin() {
    let run = run_fixture_scenario("route_position_from_current_entity.xosc", 20.0);
    for name in ["FromCurrent", "Relative"] {
        let first = at(&run, name, 0.0);
        assert!(close(first.x, 0.0, 1e-12) && close(first.y, 0.0, 1e-12) && first.speed > 0.0, "{name} at 0 s: {first:?}");
        for t in [0.01, 2.5, 5.0] {
            let s = at(&run, name, t);
            assert!(close(s.x, 0.0, 1e-12) && close(s.y, 0.0, 1e-12) && close(s.speed, 0.0, 1e-12), "{name} at {t} s: {s:?}");
        }
    }
    assert!(close(at(&run, "Placed", 2.5).x, 75.0, 1e-9));
    assert_matches_esmini("route_position_from_current_entity.xosc", &run, 1e-3);
}
