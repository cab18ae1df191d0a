//! What a `storyboardElementRef` names. esmini (ScenarioReader.cpp, Storyboard.cpp
//! `FindChildByTypeAndName`) gives every element a full path, `Story::Act::ManeuverGroup::
//! Maneuver::Event::Action` down to it, and takes a reference to mean each element of the type
//! whose full path ends with the reference and whose own name is not longer than it — so `E`,
//! `M::E` and `S::A::G::M::E` all name event `E` of maneuver `M`. The standard asks for a
//! reference that resolves to exactly one element; esmini takes the first of several.

use crate::model::*;

/// Every named storyboard element with its type and full path, in file order.
pub(super) struct Elements {
    all: Vec<(StoryboardElementType, String, usize)>,
}

impl Elements {
    pub(super) fn of(s: &Scenario) -> Elements {
        use StoryboardElementType as T;
        let mut all = Vec::new();
        let mut add = |t: T, path: &str, own: &str| {
            all.push((t, path.to_string(), own.chars().count()));
        };
        for story in &s.storyboard.stories {
            let p_story = story.name.clone();
            add(T::Story, &p_story, &story.name);
            for act in &story.acts {
                let p_act = format!("{p_story}::{}", act.name);
                add(T::Act, &p_act, &act.name);
                for mg in &act.maneuver_groups {
                    let p_mg = format!("{p_act}::{}", mg.name);
                    add(T::ManeuverGroup, &p_mg, &mg.name);
                    for m in &mg.maneuvers {
                        let p_m = format!("{p_mg}::{}", m.name);
                        add(T::Maneuver, &p_m, &m.name);
                        for e in &m.events {
                            let p_e = format!("{p_m}::{}", e.name);
                            add(T::Event, &p_e, &e.name);
                            for a in &e.actions {
                                add(T::Action, &format!("{p_e}::{}", a.name), &a.name);
                            }
                        }
                    }
                }
            }
        }
        Elements { all }
    }

    /// What `reference` names of type `t`: one element (`Ok`), or none or several (`Err`).
    pub(super) fn resolve(&self, t: StoryboardElementType, reference: &str) -> Result<(), Unresolved> {
        let len = reference.chars().count();
        let matching: Vec<&str> =
            self.all.iter().filter(|(ty, path, own)| *ty == t && len >= *own && path.ends_with(reference)).map(|(_, path, _)| path.as_str()).collect();
        match matching.len() {
            0 => Err(Unresolved::None(format!("there is no {t} named `{reference}` in the storyboard"))),
            1 => Ok(()),
            n => Err(Unresolved::Several(format!(
                "`{reference}` names {n} {t}s ({}); esmini and osc2cr take the first, `{}` (the standard asks for a reference that \
                 resolves to one element: qualify it with its parents' names)",
                matching.join(", "),
                matching[0]
            ))),
        }
    }
}

/// Why a `storyboardElementRef` does not name one element.
pub(super) enum Unresolved {
    /// It names nothing: a problem.
    None(String),
    /// It names several, of which esmini takes the first: a warning (a catalog maneuver used
    /// twice holds such references by construction).
    Several(String),
}
