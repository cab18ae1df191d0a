//! Lists every lanelet of a converted map with its origin (road id, section, lane, direction)
//! and links: a debugging aid. `cargo run -p osc2cr-map --example map_dump FILE.xodr`
fn main() {
    let Some(path) = std::env::args().nth(1) else {
        eprintln!("usage: map_dump FILE.xodr");
        std::process::exit(2);
    };
    let loaded = match opendrive::load(&path) {
        Ok(l) => l,
        Err(e) => {
            eprintln!("{e}");
            std::process::exit(2);
        }
    };
    let net = &loaded.network;
    let r = map::convert(net, &map::MapOptions::default());
    for (l, o) in r.network.lanelets.iter().zip(&r.origins) {
        let road = net.roads.get(o.lane.road).map_or("?", |r| r.id.as_str());
        let ids = |v: &[commonroad::LaneletId]| v.iter().map(|i| i.to_string()).collect::<Vec<_>>().join(",");
        println!(
            "{:>5} road {:>4} sec {} lane {:>3} {} pts {:>3} pred [{}] succ [{}] L {:?} R {:?}",
            l.id,
            road,
            o.lane.section,
            o.lane.lane,
            if o.along_s { "+s" } else { "-s" },
            l.bounds.len(),
            ids(&l.predecessors),
            ids(&l.successors),
            l.adjacent_left.map(|a| (a.lanelet.get(), a.driving_dir.as_str())),
            l.adjacent_right.map(|a| (a.lanelet.get(), a.driving_dir.as_str())),
        );
    }
    for i in &r.network.intersections {
        println!("intersection {}", i.id);
        for inc in &i.incomings {
            let ids = |v: &[commonroad::LaneletId]| v.iter().map(|i| i.to_string()).collect::<Vec<_>>().join(",");
            println!(
                "  incoming {} lanelets [{}] left [{}] straight [{}] right [{}] isLeftOf {:?}",
                inc.id,
                ids(&inc.incoming_lanelets),
                ids(&inc.successors_left),
                ids(&inc.successors_straight),
                ids(&inc.successors_right),
                inc.is_left_of.map(|x| x.get())
            );
        }
    }
    for w in &r.warnings {
        println!("{w}");
    }
}
