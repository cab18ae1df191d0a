//! Storyboard: Init, stories, acts, maneuver groups, maneuvers, events.

use super::action::{read_action, read_action_kind, read_private_action};
use super::condition::read_trigger;
use super::Reader;
use crate::attr::Cx;
use crate::catalog::CatalogKind;
use crate::error::Error;
use crate::model::*;
use crate::xml::Elem;

pub(crate) fn read_storyboard(r: &mut Reader, cx: &Cx, e: &Elem) -> Result<Storyboard, Error> {
    let mut init = Init::default();
    if let Some(actions) = e.child("Init").and_then(|i| i.child("Actions")) {
        for a in actions.children() {
            match a.name.as_str() {
                "GlobalAction" | "UserDefinedAction" => {
                    init.global.push(Action { name: String::new(), kind: read_action_kind(r, cx, a)?, origin: cx.loc(a.pos) })
                }
                "Private" => {
                    let entity = cx.reference(a, "entityRef")?;
                    let mut list = Vec::new();
                    for p in a.children() {
                        if p.name == "PrivateAction" {
                            list.push(Action { name: String::new(), kind: read_private_action(r, cx, p)?, origin: cx.loc(p.pos) });
                        } else {
                            r.unsupported(cx, p, "Private");
                        }
                    }
                    init.private.push(InitPrivate { entity, actions: list, origin: cx.loc(a.pos) });
                }
                _ => r.unsupported(cx, a, "Init/Actions"),
            }
        }
    }
    let mut stories = Vec::new();
    for s in e.children_named("Story") {
        stories.push(read_story(r, cx, s)?);
    }
    let stop_trigger = e.child("StopTrigger").map(|t| read_trigger(r, cx, t)).transpose()?;
    Ok(Storyboard { init, stories, stop_trigger })
}

fn read_story(r: &mut Reader, cx: &Cx, e: &Elem) -> Result<Story, Error> {
    let (parameters, scope) = r.declarations(cx, e, &[])?;
    let cx = cx.scoped(&scope);
    let mut acts = Vec::new();
    for a in e.children_named("Act") {
        let mut groups = Vec::new();
        for g in a.children_named("ManeuverGroup") {
            groups.push(read_group(r, &cx, g)?);
        }
        acts.push(Act {
            name: cx.opt_text(a, "name")?.unwrap_or_default(),
            maneuver_groups: groups,
            start_trigger: a.child("StartTrigger").map(|t| read_trigger(r, &cx, t)).transpose()?,
            stop_trigger: a.child("StopTrigger").map(|t| read_trigger(r, &cx, t)).transpose()?,
            origin: cx.loc(a.pos),
        });
    }
    Ok(Story { name: cx.opt_text(e, "name")?.unwrap_or_default(), parameters, acts, origin: cx.loc(e.pos) })
}

fn read_group(r: &mut Reader, cx: &Cx, e: &Elem) -> Result<ManeuverGroup, Error> {
    let (select, actors) = match e.child("Actors") {
        Some(a) => (
            cx.bool_or(a, "selectTriggeringEntities", false)?,
            a.children_named("EntityRef").map(|x| cx.reference(x, "entityRef")).collect::<Result<Vec<_>, _>>()?,
        ),
        None => (false, Vec::new()),
    };
    let mut maneuvers = Vec::new();
    for m in e.children() {
        match m.name.as_str() {
            "Maneuver" => maneuvers.push(read_maneuver(r, cx, m, &[])?),
            "CatalogReference" => {
                maneuvers.extend(r.catalog_entry_or(cx, m, &[CatalogKind::Maneuver], |r, cx, e, asg| read_maneuver(r, cx, e, asg).map(Some), |_| None)?)
            }
            "Actors" => {}
            _ => r.unsupported(cx, m, "ManeuverGroup"),
        }
    }
    Ok(ManeuverGroup {
        name: cx.opt_text(e, "name")?.unwrap_or_default(),
        maximum_execution_count: cx.u32_or(e, "maximumExecutionCount", 1)?,
        select_triggering_entities: select,
        actors,
        maneuvers,
        origin: cx.loc(e.pos),
    })
}

pub(crate) fn read_maneuver(r: &mut Reader, cx: &Cx, e: &Elem, asg: &[(String, String)]) -> Result<Maneuver, Error> {
    let (parameters, scope) = r.declarations(cx, e, asg)?;
    let cx = cx.scoped(&scope);
    let mut events = Vec::new();
    for ev in e.children_named("Event") {
        // An Action with no child is outside the schema, but esmini reads it as no action at all
        // (ScenarioReader::parseOSCManeuver adds nothing for it); so do we, and say so.
        let mut actions = Vec::new();
        for a in ev.children_named("Action") {
            if a.children().is_empty() {
                let name = cx.opt_text(a, "name")?.unwrap_or_default();
                r.warn(cx.loc(a.pos), format!("Action '{name}' has no PrivateAction, GlobalAction or UserDefinedAction: it does nothing (as in esmini)"));
                continue;
            }
            actions.push(read_action(r, &cx, a)?);
        }
        events.push(Event {
            name: cx.opt_text(ev, "name")?.unwrap_or_default(),
            priority: cx.opt_enum(ev, "priority")?.unwrap_or(Priority::Override),
            maximum_execution_count: cx.u32_or(ev, "maximumExecutionCount", 1)?,
            actions,
            start_trigger: ev.child("StartTrigger").map(|t| read_trigger(r, &cx, t)).transpose()?,
            origin: cx.loc(ev.pos),
        });
    }
    Ok(Maneuver { name: cx.opt_text(e, "name")?.unwrap_or_default(), parameters, events, origin: cx.loc(e.pos) })
}
