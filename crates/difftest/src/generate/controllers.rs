//! esmini's driver models as ObjectControllers with their properties (ACC, ALKS, ALKS R157 in
//! every safety model, Looming, FollowGhost, FollowReference, FollowRoute, NaturalDriver,
//! OffroadFollower), and the controller actions: activating one (Init or story, longitudinal
//! and/or lateral), assigning one in the story.

use super::{Area, Gen};

/// The controller types the generator assigns.
pub(super) const TYPES: [&str; 10] = [
    "ACCController",
    "ALKSController",
    "ALKS_R157SM_Controller",
    "LoomingController",
    "FollowGhostController",
    "FollowReferenceController",
    "FollowRouteController",
    "NaturalDriver",
    "OffroadFollower",
    "ACCController",
];

impl Gen<'_> {
    fn property(name: &str, value: impl std::fmt::Display) -> String {
        format!(r#"<Property name="{name}" value="{value}"/>"#)
    }

    /// A `<Controller>` of `kind` for entity `owner` (its feature named), and whether the
    /// controller needs a route (FollowRoute).
    pub(crate) fn controller_xml(&mut self, kind: &str, owner: &str) -> String {
        let mut props = vec![Self::property("esminiController", kind)];
        let mut label = kind.to_string();
        match kind {
            "ACCController" | "ALKSController" | "LoomingController" => {
                props.push(Self::property("timeGap", self.num(0.5, 2.0)));
                props.push(Self::property("setSpeed", self.num(10.0, 30.0)));
                if kind != "LoomingController" {
                    let mode = self.pick(&["override", "additive"]);
                    props.push(Self::property("mode", mode));
                    label = format!("{kind}/{mode}");
                }
            }
            "ALKS_R157SM_Controller" => {
                let model = self.pick(&["Regulation", "ReferenceDriver", "RSS", "FSM"]);
                label = format!("{kind}/{model}");
                props.push(Self::property("model", model));
                if model == "ReferenceDriver" && self.chance(0.5) {
                    props.push(Self::property("cutInPerceptionDelayMode", self.pick(&["Dist", "Time"])));
                }
                if self.chance(0.3) {
                    props.push(Self::property("fullStop", self.pick(&["true", "false"])));
                }
                if self.chance(0.3) {
                    props.push(Self::property("cruise", self.pick(&["true", "false"])));
                }
                if self.chance(0.3) {
                    props.push(Self::property("lateralTrigDistance", self.num(0.2, 1.0)));
                }
            }
            "FollowGhostController" => {
                let mode = self.pick(&["time", "position"]);
                label = format!("{kind}/{mode}");
                props.push(Self::property("headstartTime", self.num(0.5, 3.0)));
                props.push(Self::property("followMode", mode));
                if self.chance(0.5) {
                    props.push(Self::property("lookaheadSteering", self.num(0.3, 2.0)));
                }
            }
            "FollowReferenceController" => {
                // it follows another entity (without one esmini wants a ghost and quits)
                if let Some(o) = self.followed(owner) {
                    props.push(Self::property("referenceEntity", o));
                }
                props.push(Self::property("speedControlStiffness", self.num(0.5, 3.0)));
            }
            "FollowRouteController" => {
                props.push(Self::property("minDistForCollision", self.num(5.0, 30.0)));
                props.push(Self::property("laneChangeTime", self.num(2.0, 6.0)));
                if self.chance(0.3) {
                    props.push(Self::property("testMode", "true"));
                }
            }
            "NaturalDriver" => {
                props.push(Self::property("desiredSpeed", self.num(10.0, 30.0)));
                props.push(Self::property("desiredDistance", self.num(10.0, 50.0)));
                props.push(Self::property("thw", self.num(0.8, 2.5)));
                props.push(Self::property("maxAcc", self.num(1.0, 4.0)));
                props.push(Self::property("maxDec", self.num(2.0, 8.0)));
                props.push(Self::property("laneChangeDuration", self.num(2.0, 5.0)));
                props.push(Self::property("politeness", self.num(0.0, 1.0)));
                props.push(Self::property("lookAheadDistance", self.num(20.0, 80.0)));
                let mode = self.pick(&["override", "additive"]);
                props.push(Self::property("mode", mode));
                label = format!("{kind}/{mode}");
            }
            _ => {
                // OffroadFollower follows another entity off road
                if let Some(o) = self.followed(owner) {
                    props.push(Self::property("followEntity", o));
                }
                props.push(Self::property("targetDistance", self.num(5.0, 30.0)));
                props.push(Self::property("speedFactor", self.num(0.8, 1.5)));
            }
        }
        self.feature(format!("controller:{label}"));
        format!(r#"<Controller name="{owner}Driver"><Properties>{}</Properties></Controller>"#, props.concat())
    }

    /// The entity a follower controller of `owner` follows: one declared before it (esmini looks
    /// it up when it reads the controller), moving by itself.
    pub(crate) fn followed(&self, owner: &str) -> Option<String> {
        let before = self.all_names.iter().take_while(|n| *n != owner);
        before.filter(|n| !n.starts_with("Obj") && !n.starts_with("Trailer")).last().cloned()
    }

    /// The opening `<ObjectController>` tag of `owner`'s controller: named `{owner}Ctrl` at
    /// times in a 1.3 file (esmini then renames the controller after it; the name attribute
    /// is new in 1.3).
    pub(crate) fn object_controller_open(&mut self, owner: &str) -> String {
        if self.rev_minor >= 3 && self.rich(Area::Controllers) && self.chance(0.4) {
            self.feature("controller:named-object-controller");
            self.named_wrappers.push(owner.to_string());
            return format!(r#"<ObjectController name="{owner}Ctrl">"#);
        }
        "<ObjectController>".into()
    }

    /// An ActivateControllerAction for `owner`'s controller of type `kind`, longitudinal
    /// and/or lateral (both mostly; always both for FollowReference, which esmini activates on
    /// both domains only), at times naming the controller: `objectControllerRef` in 1.3 (the
    /// wrapper's name, or now and then the Controller's own, which esmini no longer knows by
    /// it), `controllerRef` in 1.2 and, deprecated, in 1.3 (where esmini ignores it).
    pub(crate) fn activate_controller_action(&mut self, owner: &str, kind: &str) -> String {
        let (long, lat) = match self.pick_index(5) {
            0 if kind != "FollowReferenceController" => (true, false),
            1 if kind != "FollowReferenceController" => (false, true),
            _ => (true, true),
        };
        if !(long && lat) {
            self.feature(format!("controller:activate/longitudinal={long}/lateral={lat}"));
        }
        let mut reference = String::new();
        if self.rev_minor >= 2 && self.rich(Area::Controllers) && self.chance(0.35) {
            let wrapped = self.named_wrappers.iter().any(|n| n == owner);
            let own = format!("{owner}Driver");
            reference = match (self.rev_minor, wrapped) {
                (2, _) => {
                    self.feature("controller:activate-by-name/controllerRef");
                    format!(r#" controllerRef="{own}""#)
                }
                _ if self.chance(0.15) => {
                    self.feature("controller:activate-by-name/deprecated-controllerRef");
                    format!(r#" controllerRef="{own}""#)
                }
                (_, true) if self.chance(0.8) => {
                    self.feature("controller:activate-by-name/object-controller-name");
                    format!(r#" objectControllerRef="{owner}Ctrl""#)
                }
                (_, true) => {
                    self.feature("controller:activate-by-name/renamed-controller");
                    format!(r#" objectControllerRef="{own}""#)
                }
                (_, false) => {
                    self.feature("controller:activate-by-name/controller-name");
                    format!(r#" objectControllerRef="{own}""#)
                }
            };
        }
        let activate = format!(r#"<ActivateControllerAction{reference} longitudinal="{long}" lateral="{lat}"/>"#);
        if self.since(1) {
            format!("<PrivateAction><ControllerAction>{activate}</ControllerAction></PrivateAction>")
        } else {
            // 1.0 has it right under the PrivateAction (esmini reads both places)
            self.feature("controller:activate/1.0-place");
            format!("<PrivateAction>{activate}</PrivateAction>")
        }
    }

    /// An OverrideControllerValueAction: a throttle and/or a steering-wheel value, switched on
    /// or off (esmini records them and moves nothing headless; the action holds the domains).
    pub(crate) fn override_controller_value_action(&mut self) -> String {
        self.feature("action:OverrideControllerValueAction");
        let mut values = String::new();
        let which = self.pick_index(3);
        if which != 1 {
            let (active, value) = (self.chance(0.7), self.num(0.0, 1.0));
            values.push_str(&format!(r#"<Throttle active="{active}" value="{value}"/>"#));
        }
        if which != 0 {
            let (active, value) = (self.chance(0.7), self.num(-0.5, 0.5));
            values.push_str(&format!(r#"<SteeringWheel active="{active}" value="{value}"/>"#));
        }
        format!(
            r#"<PrivateAction><ControllerAction><OverrideControllerValueAction>{values}</OverrideControllerValueAction></ControllerAction></PrivateAction>"#
        )
    }

    /// An AssignControllerAction in the story, activating what it assigns: in 1.3 the
    /// Controller inside an ObjectController (named at times: esmini names the assigned
    /// controller after it), before 1.3 the Controller alone; 1.0 has no activate attributes
    /// (esmini reads them all the same).
    pub(crate) fn assign_controller_action(&mut self, actor: &str) -> String {
        // (a NaturalDriver assigned in the story makes esmini 3.6.0 crash)
        let kind = self.pick(&["ACCController", "ALKS_R157SM_Controller", "LoomingController"]);
        let controller = self.controller_xml(kind, actor);
        self.feature("action:AssignControllerAction");
        let body = if self.rev_minor >= 3 {
            if self.chance(0.4) {
                self.feature("controller:assigned-named-object-controller");
                format!(r#"<ObjectController name="{actor}Assigned">{controller}</ObjectController>"#)
            } else {
                format!("<ObjectController>{controller}</ObjectController>")
            }
        } else {
            self.feature("controller:assigned-without-object-controller");
            controller
        };
        format!(
            r#"<PrivateAction><ControllerAction><AssignControllerAction activateLongitudinal="true" activateLateral="true">{body}</AssignControllerAction></ControllerAction></PrivateAction>"#
        )
    }
}
