//! openscenario
