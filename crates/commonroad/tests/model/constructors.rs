//! The checked constructors refuse what the format cannot hold.

use commonroad::*;

fn p(x: f64, y: f64) -> Point {
    Point::new(x, y)
}

#[test]
fn lanelet_bounds_need_equal_counts() {
    let e = LaneletBounds::new(vec![p(0.0, 1.0), p(1.0, 1.0), p(2.0, 1.0)], vec![p(0.0, 0.0), p(2.0, 0.0)]);
    let r = e;
    assert!(matches!(r, Err(Error::BoundPointCountMismatch { left: 3, right: 2 })), "{r:?}");
}

#[test]
fn lanelet_bounds_need_two_points() {
    let r = LaneletBounds::new(vec![p(0.0, 1.0)], vec![p(0.0, 0.0)]);
    assert!(matches!(r, Err(Error::TooFewBoundPoints { got: 1 })), "{r:?}");
    let r = LaneletBounds::new(vec![], vec![]);
    assert!(matches!(r, Err(Error::TooFewBoundPoints { got: 0 })), "{r:?}");
}

#[test]
fn lanelet_bounds_need_finite_points() {
    let r = LaneletBounds::new(vec![p(0.0, 1.0), p(f64::NAN, 1.0)], vec![p(0.0, 0.0), p(1.0, 0.0)]);
    assert!(matches!(r, Err(Error::NonFinite { .. })), "{r:?}");
    let r = LaneletBounds::new(vec![p(0.0, 1.0), p(1.0, 1.0)], vec![p(0.0, 0.0), Point::with_z(1.0, 0.0, f64::INFINITY)]);
    assert!(matches!(r, Err(Error::NonFinite { .. })), "{r:?}");
}

#[test]
fn valid_bounds_keep_their_points() {
    let b = LaneletBounds::new(vec![p(0.0, 1.0), p(1.0, 1.0)], vec![p(0.0, 0.0), p(1.0, 0.0)]).unwrap();
    assert_eq!(b.len(), 2);
    assert_eq!(b.left()[1], p(1.0, 1.0));
    assert_eq!(b.right()[0], p(0.0, 0.0));
}

#[test]
fn shapes_need_positive_sizes_and_three_polygon_points() {
    assert!(matches!(Rectangle::new(0.0, 1.0), Err(Error::NotPositive { .. })));
    assert!(matches!(Rectangle::new(1.0, -1.0), Err(Error::NotPositive { .. })));
    assert!(matches!(Rectangle::new(f64::NAN, 1.0), Err(Error::NonFinite { .. })));
    assert!(matches!(Shape::circle(0.0), Err(Error::NotPositive { .. })));
    assert!(matches!(Shape::circle(f64::INFINITY), Err(Error::NonFinite { .. })));
    let r = Polygon::new(vec![p(0.0, 0.0), p(1.0, 0.0)]);
    assert!(matches!(r, Err(Error::TooFewPolygonPoints { got: 2 })), "{r:?}");
    assert!(Polygon::new(vec![p(0.0, 0.0), p(1.0, 0.0), p(0.0, f64::NAN)]).is_err());
    assert_eq!(Shape::rectangle(4.5, 1.8).unwrap(), Shape::Rectangle(Rectangle::new(4.5, 1.8).unwrap()));
}

#[test]
fn intervals_are_ordered_and_finite() {
    let r = Interval::new(2.0, 1.0);
    assert!(matches!(r, Err(Error::ReversedInterval { start, end }) if start == 2.0 && end == 1.0), "{r:?}");
    assert!(Interval::new(f64::NAN, 1.0).is_err());
    assert!(Interval::new(1.0, 1.0).is_ok());
    let r = TimeInterval::new(0, 0);
    assert!(matches!(r, Err(Error::BadTimeInterval { start: 0, end: 0 })), "{r:?}");
    let r = TimeInterval::new(5, 4);
    assert!(matches!(r, Err(Error::BadTimeInterval { start: 5, end: 4 })), "{r:?}");
    let t = TimeInterval::new(0, 1).unwrap();
    assert_eq!((t.start(), t.end()), (0, 1));
}

#[test]
fn dates_must_exist() {
    assert_eq!(Date::new(2024, 2, 29).unwrap().to_string(), "2024-02-29");
    assert_eq!(Date::new(2000, 2, 29).unwrap().to_string(), "2000-02-29");
    assert!(Date::new(2023, 2, 29).is_err());
    assert!(Date::new(1900, 2, 29).is_err());
    assert!(Date::new(2026, 4, 31).is_err());
    assert!(Date::new(2026, 13, 1).is_err());
    assert!(Date::new(2026, 0, 1).is_err());
    assert!(Date::new(0, 1, 1).is_err());
    assert_eq!(Date::new(7, 1, 2).unwrap().to_string(), "0007-01-02");
}

#[test]
fn benchmark_ids_follow_the_readers_pattern() {
    for ok in ["DEU_Ffb-1_2_T-1", "ZAM_Test-1", "C-USA_Lanker-2_1_T-1", "ZAM_a1-10_3", "DEU_X-1_1_S-1-2-3", "ESP_M-1_1_I-7"] {
        assert!(BenchmarkId::parse(ok).is_ok(), "{ok}");
    }
    for bad in [
        "",
        "ZAM",
        "zam_Test-1",
        "ZAM_Test",
        "ZAM_Te_st-1",
        "ZAM_Te-st-1",
        "ZAM_Test-0",
        "ZAM_Test-01",
        "ZAM_Test-1_",
        "ZAM_Test-1_1_T",
        "ZAM_Test-1_1_X-1",
        "ZAM_Test-1_1_T-0",
        "ZAM_Test-1_1_T-1-",
        "ZAM_Tëst-1",
        "ÄÖÜ_Test-1",
        "DEUX_Test-1",
    ] {
        assert!(BenchmarkId::parse(bad).is_err(), "{bad:?} accepted");
    }
}

#[test]
fn converted_benchmark_id_reduces_the_name_to_letters_and_digits() {
    let id = BenchmarkId::for_converted("ZAM", "my-scenario_01.v2 (ß)").unwrap();
    assert_eq!(id.as_str(), "ZAM_myscenario01v2-1_1_T-1");
    assert!(BenchmarkId::for_converted("ZAM", "__--").is_err());
    assert!(BenchmarkId::for_converted("de", "x").is_err());
}

#[test]
fn ids_are_positive() {
    assert_eq!(LaneletId::new(0), None);
    assert_eq!(LaneletId::new(7).map(LaneletId::get), Some(7));
}

#[test]
fn allocator_never_repeats_across_kinds() {
    let mut a = IdAllocator::new();
    let ids = [
        a.lanelet().get(),
        a.traffic_sign().get(),
        a.traffic_light().get(),
        a.intersection().get(),
        a.incoming().get(),
        a.obstacle().get(),
        a.planning_problem().get(),
    ];
    assert_eq!(ids, [1, 2, 3, 4, 5, 6, 7]);
    assert_eq!(IdAllocator::starting_at(0).peek(), 1);
    assert_eq!(IdAllocator::starting_at(50).lanelet().get(), 50);
}
