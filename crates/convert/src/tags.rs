//! Scenario tags that can be stated honestly: `simulated` (the trajectories come from running
//! the storyboard), the map's own tags (`map::derived_tags`: road class, lane count,
//! intersection, oncoming traffic — passed in by the pipeline), and `speed_limit` when the
//! network carries a maximum-speed sign. Nothing is guessed about the traffic situation
//! (critical, cut-in, …).

use std::collections::BTreeSet;

use commonroad::{LaneletNetwork, Tag};

/// Sign ids that mean "maximum speed" in the XSD enumeration (DEU/ZAM `274`, USA `R2-1`).
const SPEED_LIMIT_SIGNS: [&str; 2] = ["274", "R2-1"];

/// The tags this crate adds to a converted scenario on `network` (`None`: no road network).
pub fn scenario_tags(network: Option<&LaneletNetwork>) -> BTreeSet<Tag> {
    let mut tags = BTreeSet::from([Tag::Simulated]);
    let speed_sign = network.is_some_and(|net| net.traffic_signs.iter().flat_map(|s| &s.elements).any(|e| SPEED_LIMIT_SIGNS.contains(&e.sign_id.as_str())));
    if speed_sign {
        tags.insert(Tag::SpeedLimit);
    }
    tags
}
