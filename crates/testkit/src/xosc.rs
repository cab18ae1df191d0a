//! OpenSCENARIO texts the tests of several crates write alike.

/// A car for scenarios written in tests: 4.5 × 2 × 1.5 m, box centre 1.5 m ahead of the rear
/// axle, the front axle 3 m ahead of it.
pub const VEHICLE: &str = r#"<Vehicle name="car" vehicleCategory="car">
          <BoundingBox><Center x="1.5" y="0" z="0.9"/><Dimensions width="2" length="4.5" height="1.5"/></BoundingBox>
          <Performance maxSpeed="70" maxAcceleration="5" maxDeceleration="9"/>
          <Axles>
            <FrontAxle maxSteering="0.5" wheelDiameter="0.6" trackWidth="1.8" positionX="3" positionZ="0.3"/>
            <RearAxle maxSteering="0" wheelDiameter="0.6" trackWidth="1.8" positionX="0" positionZ="0.3"/>
          </Axles>
          <Properties/>
        </Vehicle>"#;

/// A parameter value distribution file: five runs (seed 1) of `scenario_file` with `parameter`
/// drawn from `distribution` (the content of its `StochasticDistribution`).
pub fn stochastic_set(scenario_file: &str, parameter: &str, distribution: &str) -> String {
    format!(
        r#"<?xml version="1.0"?>
<OpenSCENARIO>
<FileHeader revMajor="1" revMinor="2" date="2024-01-01T00:00:00" description="" author=""/>
<ParameterValueDistribution><ScenarioFile filepath="{scenario_file}"/>
<Stochastic numberOfTestRuns="5" randomSeed="1"><StochasticDistribution parameterName="{parameter}">
{distribution}
</StochasticDistribution></Stochastic>
</ParameterValueDistribution>
</OpenSCENARIO>"#
    )
}
