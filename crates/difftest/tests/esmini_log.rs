//! Reading esmini's CSV log: a log with a non-finite position is no reference (esmini's
//! arithmetic failed; the engine never writes such a pose), so the run is not compared.

use difftest::esmini::{non_finite, parse_csv};

const HEADER: &str = "Index [-], TimeStamp [s], #1 Entity_Name [-], #1 Entity_ID [-], #1 Current_Speed [m/s], #1 World_Position_X [m], #1 World_Position_Y [m], #1 World_Heading_Angle [rad], #2 Entity_Name [-], #2 Entity_ID [-], #2 Current_Speed [m/s], #2 World_Position_X [m], #2 World_Position_Y [m], #2 World_Heading_Angle [rad], ";

fn log(rows: &[&str]) -> String {
    std::iter::once(HEADER).chain(rows.iter().copied()).collect::<Vec<_>>().join("\n")
}

#[test]
fn a_finite_log_is_a_reference() {
    let text = log(&[
        "0, 0.000, Car0, 0, 10.0, 1.0, 2.0, 0.0, Car1, 1, 5.0, 3.0, 4.0, 0.0, ",
        "1, 0.010, Car0, 0, 10.0, 1.1, 2.0, 0.0, Car1, 1, 5.0, 3.05, 4.0, 0.0, ",
    ]);
    let traces = parse_csv(&text).expect("parses");
    assert_eq!(traces.len(), 2);
    assert_eq!(non_finite(&traces), None);
}

#[test]
fn a_nan_position_makes_the_log_no_reference() {
    // as esmini writes it on Linux: "nan" and "-nan"
    let text = log(&[
        "0, 0.000, Car0, 0, 10.0, 1.0, 2.0, 0.0, Car1, 1, 5.0, 3.0, 4.0, 0.0, ",
        "1, 0.010, Car0, 0, 10.0, 1.1, 2.0, 0.0, Car1, 1, 0.0, -nan, nan, 0.0, ",
    ]);
    let traces = parse_csv(&text).expect("parses");
    let why = non_finite(&traces).expect("a NaN position is found");
    assert!(why.contains("Car1") && why.contains("0.01"), "{why}");
}
