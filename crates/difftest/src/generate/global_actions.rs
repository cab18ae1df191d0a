//! Global actions: setting and modifying parameters and variables (which conditions then
//! read), deleting an entity and adding it back, the environment, and the traffic signals of
//! maps that have them (a signal's state, a signal controller's phase).

use super::positions::Scope;
use super::{Declared, Gen};

/// The phases of the generator's signal controller: (name, duration s); each signal's state
/// in a phase is `MapSignal::phase_state`.
pub(super) const PHASES: [(&str, f64); 3] = [("stop", 4.0), ("ready", 2.0), ("go", 5.0)];

impl Gen<'_> {
    /// A parameter: mostly the first one declared, else a new one of a type drawn (double,
    /// integer, string or boolean; `numeric`: integer or double); its name and type.
    pub(crate) fn parameter(&mut self, numeric: bool) -> (String, &'static str) {
        let mut declared = std::mem::take(&mut self.parameters);
        let d = self.declare(&mut declared, "P", numeric);
        self.parameters = declared;
        d
    }

    /// A variable, as `parameter`; `numeric`: an integer or a double (what a modify rule
    /// works on: esmini changes no string or boolean).
    pub(crate) fn variable(&mut self, numeric: bool) -> (String, &'static str) {
        let mut declared = std::mem::take(&mut self.variables);
        let d = self.declare(&mut declared, "V", numeric);
        self.variables = declared;
        d
    }

    fn declare(&mut self, declared: &mut Vec<Declared>, prefix: &str, numeric: bool) -> (String, &'static str) {
        let usable: Vec<usize> = (0..declared.len()).filter(|&i| !numeric || matches!(declared[i].kind, "double" | "integer")).collect();
        if let Some(&first) = usable.first() {
            if self.chance(0.6) {
                return (declared[first].name.clone(), declared[first].kind);
            }
        }
        let name = format!("{prefix}{}", declared.len());
        let kind = if numeric { self.pick(&["double", "double", "integer"]) } else { self.pick(&["double", "double", "integer", "string", "boolean"]) };
        self.feature(format!("value-type:{prefix}/{kind}"));
        let value = self.value_of(kind);
        declared.push(Declared { name: name.clone(), kind, value });
        (name, kind)
    }

    /// A value of a declared type, as a set action or a condition writes it: small whole
    /// numbers, some doubles with a fraction, strings that order differently as text than
    /// as numbers ("10" before "9").
    pub(crate) fn value_of(&mut self, kind: &str) -> String {
        match kind {
            "integer" => format!("{}", self.pick_index(6)),
            "string" => self.pick(&["0", "1", "5", "9", "10", "25"]).to_string(),
            "boolean" => self.pick(&["true", "false"]).to_string(),
            _ if self.chance(0.3) => format!("{}.5", self.pick_index(5)),
            _ => format!("{}", self.pick_index(6)),
        }
    }

    /// A modify rule; on an integer a fractional value (esmini cuts it, or the product, to an
    /// integer).
    fn modify_rule(&mut self, kind: &str) -> String {
        let fraction = self.chance(0.3);
        if fraction {
            self.feature(format!("modify-fraction:{kind}"));
        }
        if self.chance(0.5) {
            let v = if fraction { self.pick(&["1.5", "-0.5", "2.7"]) } else { self.pick(&["1", "2", "-1"]) };
            format!(r#"<AddValue value="{v}"/>"#)
        } else {
            let v = if fraction { self.pick(&["1.5", "0.5"]) } else { self.pick(&["2", "3"]) };
            format!(r#"<MultiplyByValue value="{v}"/>"#)
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
                let (p, kind) = self.parameter(false);
                let value = self.value_of(kind);
                format!(r#"<ParameterAction parameterRef="{p}"><SetAction value="{value}"/></ParameterAction>"#)
            }
            "ParameterModifyAction" => {
                let (p, kind) = self.parameter(true);
                let rule = self.modify_rule(kind);
                format!(r#"<ParameterAction parameterRef="{p}"><ModifyAction><Rule>{rule}</Rule></ModifyAction></ParameterAction>"#)
            }
            "VariableSetAction" => {
                let (v, kind) = self.variable(false);
                let value = self.value_of(kind);
                format!(r#"<VariableAction variableRef="{v}"><SetAction value="{value}"/></VariableAction>"#)
            }
            "VariableModifyAction" => {
                let (v, kind) = self.variable(true);
                let rule = self.modify_rule(kind);
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
