//! Global actions: setting and modifying parameters and variables (which conditions then
//! read), deleting an entity and adding it back, the environment, and the traffic signals of
//! maps that have them (a signal's state, a signal controller's phase).

use super::positions::Scope;
use super::{Declared, Gen};

/// The phases of the generator's signal controller: (name, duration s); each signal's state
/// in a phase is `MapSignal::phase_state`.
pub(super) const PHASES: [(&str, f64); 3] = [("stop", 4.0), ("ready", 2.0), ("go", 5.0)];

impl Gen<'_> {
    /// A parameter (double): mostly the first one declared, else a new one; its name.
    pub(crate) fn parameter(&mut self) -> String {
        let mut declared = std::mem::take(&mut self.parameters);
        let name = self.declare(&mut declared, "P");
        self.parameters = declared;
        name
    }

    /// A variable (double), as `parameter`.
    pub(crate) fn variable(&mut self) -> String {
        let mut declared = std::mem::take(&mut self.variables);
        let name = self.declare(&mut declared, "V");
        self.variables = declared;
        name
    }

    fn declare(&mut self, declared: &mut Vec<Declared>, prefix: &str) -> String {
        if !declared.is_empty() && self.chance(0.6) {
            return declared[0].name.clone();
        }
        let name = format!("{prefix}{}", declared.len());
        let value = format!("{}", self.pick_index(5));
        declared.push(Declared { name: name.clone(), kind: "double", value });
        name
    }

    fn modify_rule(&mut self) -> String {
        if self.chance(0.5) {
            format!(r#"<AddValue value="{}"/>"#, self.pick(&[1, 2, -1]))
        } else {
            format!(r#"<MultiplyByValue value="{}"/>"#, self.pick(&[2, 3]))
        }
    }

    /// One global action, its kind named as a feature.
    pub(crate) fn global_action(&mut self) -> String {
        let mut kinds = vec!["ParameterSetAction", "ParameterModifyAction", "VariableSetAction", "VariableModifyAction", "EnvironmentAction"];
        let deletable: Vec<String> = self.names().into_iter().skip(1).filter(|n| !self.deleted.iter().any(|(d, _)| d == n)).collect();
        if !deletable.is_empty() {
            kinds.extend(["DeleteEntityAction", "DeleteEntityAction"]);
        }
        if !self.deleted.is_empty() {
            kinds.extend(["AddEntityAction", "AddEntityAction", "AddEntityAction"]);
        }
        if !self.map.signals.is_empty() {
            kinds.extend(["TrafficSignalStateAction", "TrafficSignalControllerAction"]);
        }
        let k = self.pick(&kinds);
        self.feature(format!("action:{k}"));
        // esmini 3.6.0 reads these with a warning and keeps no action (parseOSCGlobalAction)
        if matches!(k, "ParameterModifyAction" | "TrafficSignalControllerAction") {
            self.dropped_actions.push(self.current_event);
        }
        let body = match k {
            "ParameterSetAction" => {
                let p = self.parameter();
                format!(r#"<ParameterAction parameterRef="{p}"><SetAction value="{}"/></ParameterAction>"#, self.pick_index(6))
            }
            "ParameterModifyAction" => {
                let p = self.parameter();
                let rule = self.modify_rule();
                format!(r#"<ParameterAction parameterRef="{p}"><ModifyAction><Rule>{rule}</Rule></ModifyAction></ParameterAction>"#)
            }
            "VariableSetAction" => {
                let v = self.variable();
                format!(r#"<VariableAction variableRef="{v}"><SetAction value="{}"/></VariableAction>"#, self.pick_index(6))
            }
            "VariableModifyAction" => {
                let v = self.variable();
                let rule = self.modify_rule();
                format!(r#"<VariableAction variableRef="{v}"><ModifyAction><Rule>{rule}</Rule></ModifyAction></VariableAction>"#)
            }
            "DeleteEntityAction" => {
                let e = deletable[self.pick_index(deletable.len())].clone();
                let event = format!("E{}", self.current_event);
                self.deleted.push((e.clone(), event));
                format!(r#"<EntityAction entityRef="{e}"><DeleteEntityAction/></EntityAction>"#)
            }
            "AddEntityAction" => {
                // an entity deleted by an earlier event comes back once that event is over
                let i = self.pick_index(self.deleted.len());
                let (e, event) = self.deleted.remove(i);
                self.forced_condition = Some(format!(
                    r#"<Condition name="added" delay="{}" conditionEdge="none"><ByValueCondition><StoryboardElementStateCondition storyboardElementType="event" storyboardElementRef="{event}" state="completeState"/></ByValueCondition></Condition>"#,
                    self.num(0.0, 3.0)
                ));
                let actor = self.names()[0].clone();
                let position = self.target_position(&actor, Scope::Plain);
                format!(r#"<EntityAction entityRef="{e}"><AddEntityAction><Position>{position}</Position></AddEntityAction></EntityAction>"#)
            }
            "TrafficSignalStateAction" => {
                self.uses_signals = true;
                let signal = self.map.signals[self.pick_index(self.map.signals.len())].clone();
                let states = signal.states();
                let state = states[self.pick_index(states.len())].clone();
                let signal = signal.id;
                format!(
                    r#"<InfrastructureAction><TrafficSignalAction><TrafficSignalStateAction name="{signal}" state="{state}"/></TrafficSignalAction></InfrastructureAction>"#
                )
            }
            "TrafficSignalControllerAction" => {
                self.uses_signals = true;
                let phase = self.pick(&PHASES).0;
                format!(
                    r#"<InfrastructureAction><TrafficSignalAction><TrafficSignalControllerAction trafficSignalControllerRef="Lights" phase="{phase}"/></TrafficSignalAction></InfrastructureAction>"#
                )
            }
            _ => {
                let friction = self.pick(&[1.0, 0.6, 0.3]);
                format!(
                    r#"<EnvironmentAction><Environment name="Env"><TimeOfDay animation="false" dateTime="2026-06-01T12:00:00"/>{weather}<RoadCondition frictionScaleFactor="{friction}"/></Environment></EnvironmentAction>"#,
                    weather = self.weather()
                )
            }
        };
        format!("<GlobalAction>{body}</GlobalAction>")
    }

    /// The RoadNetwork's signal controller over every signal of the map.
    pub(crate) fn signal_controllers(&self) -> String {
        let phases: String = PHASES
            .iter()
            .enumerate()
            .map(|(phase, (name, duration))| {
                let states: String =
                    self.map.signals.iter().map(|s| format!(r#"<TrafficSignalState trafficSignalId="{}" state="{}"/>"#, s.id, s.phase_state(phase))).collect();
                format!(r#"<Phase name="{name}" duration="{duration}">{states}</Phase>"#)
            })
            .collect();
        format!(r#"<TrafficSignals><TrafficSignalController name="Lights">{phases}</TrafficSignalController></TrafficSignals>"#)
    }
}
