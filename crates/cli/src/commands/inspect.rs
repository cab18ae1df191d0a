//! `osc2cr inspect`: show what an OpenSCENARIO file resolves to — entities with their resolved
//! properties, the storyboard outline, parameters with their final values, warnings — as text
//! or JSON. Distribution files show their run count and first runs; catalogs their entries.

use crate::failure::Failure;
use crate::shared_options::ParamArgs;
use openscenario::{
    Action, CatalogEntry, CatalogFile, Condition, ConditionKind, Content, Diagnostic, Distribution, Entity, EntityObject, LoadOptions, Scenario, Trigger,
};
use std::fmt::Write as _;
use std::path::PathBuf;

/// Runs shown for a distribution in text output.
const SHOWN_RUNS: u64 = 10;

#[derive(clap::Args)]
pub(crate) struct InspectArgs {
    /// The OpenSCENARIO file (.xosc).
    pub file: PathBuf,
    /// Print JSON instead of text.
    #[arg(long)]
    pub json: bool,
    #[command(flatten)]
    pub params: ParamArgs,
    /// Seed for stochastic parameter distributions (default: the file's randomSeed).
    #[arg(long, allow_negative_numbers = true, value_parser = crate::shared_options::whole::<u64>)]
    pub seed: Option<u64>,
}

pub(crate) fn run(args: &InspectArgs) -> Result<(), Failure> {
    let options = LoadOptions { parameters: args.params.values.clone(), seed: args.seed, ..Default::default() };
    let loaded = crate::scenario_input::load(&args.file, &options)?;
    let out = if args.json { json(args, &loaded.content, &loaded.warnings)? } else { text(args, &loaded.content, &loaded.warnings) };
    print!("{out}");
    Ok(())
}

fn json(args: &InspectArgs, content: &Content, warnings: &[Diagnostic]) -> Result<String, Failure> {
    let file = args.file.display().to_string();
    let value = match content {
        Content::Scenario(s) => serde_json::json!({ "file": file, "kind": "scenario", "scenario": s, "warnings": warnings }),
        Content::Distribution(d) => {
            let runs: Vec<_> = d.iter().take(usize::try_from(SHOWN_RUNS).unwrap_or(10)).collect();
            serde_json::json!({
                "file": file, "kind": "distribution", "distribution": d, "runs": d.len(),
                "first_runs": runs, "warnings": warnings,
            })
        }
        Content::Catalog(c) => serde_json::json!({ "file": file, "kind": "catalog", "catalog": c, "warnings": warnings }),
    };
    let mut s = serde_json::to_string_pretty(&value).map_err(|e| Failure::input(format!("cannot write JSON: {e}")))?;
    s.push('\n');
    Ok(s)
}

fn text(args: &InspectArgs, content: &Content, warnings: &[Diagnostic]) -> String {
    let mut o = String::new();
    let _ = writeln!(o, "file: {}", args.file.display());
    match content {
        Content::Scenario(s) => scenario_text(&mut o, s),
        Content::Distribution(d) => distribution_text(&mut o, d),
        Content::Catalog(c) => catalog_text(&mut o, c),
    }
    let _ = writeln!(o, "warnings: {}", warnings.len());
    for w in warnings {
        let _ = writeln!(o, "  {w}");
    }
    o
}

/// Compact JSON of a model value, for one-line details.
fn compact<T: serde::Serialize>(v: &T) -> String {
    serde_json::to_string(v).unwrap_or_default()
}

fn scenario_text(o: &mut String, s: &Scenario) {
    let h = &s.header;
    let _ = writeln!(o, "OpenSCENARIO {}.{}: {} ({})", h.rev_major, h.rev_minor, h.description, h.author);
    match &s.road_network.logic_file {
        Some(p) => {
            let _ = writeln!(o, "road network: {}", p.display());
        }
        None => {
            let _ = writeln!(o, "road network: none");
        }
    }
    let _ = writeln!(o, "parameters: {}", s.parameters.len());
    for p in &s.parameters {
        let _ = writeln!(o, "  {} ({}) = {}", p.name, p.parameter_type, p.value);
    }
    if !s.variables.is_empty() {
        let _ = writeln!(o, "variables: {}", s.variables.len());
        for p in &s.variables {
            let _ = writeln!(o, "  {} ({}) = {}", p.name, p.parameter_type, p.value);
        }
    }
    let _ = writeln!(o, "entities: {}", s.entities.len());
    for e in &s.entities {
        entity_text(o, e);
    }
    let sb = &s.storyboard;
    let _ = writeln!(o, "storyboard:");
    let _ = writeln!(o, "  init:");
    for a in &sb.init.global {
        action_text(o, "    ", a);
    }
    for p in &sb.init.private {
        let _ = writeln!(o, "    {}:", p.entity);
        for a in &p.actions {
            action_text(o, "      ", a);
        }
    }
    for story in &sb.stories {
        let _ = writeln!(o, "  story '{}'", story.name);
        for act in &story.acts {
            let _ = writeln!(o, "    act '{}'", act.name);
            trigger_text(o, "      ", "start", act.start_trigger.as_ref());
            trigger_text(o, "      ", "stop", act.stop_trigger.as_ref());
            for g in &act.maneuver_groups {
                let _ = writeln!(
                    o,
                    "      maneuver group '{}' (max {}) actors [{}]{}",
                    g.name,
                    g.maximum_execution_count,
                    g.actors.join(", "),
                    if g.select_triggering_entities { " + triggering entities" } else { "" }
                );
                for m in &g.maneuvers {
                    let _ = writeln!(o, "        maneuver '{}'", m.name);
                    for ev in &m.events {
                        let _ = writeln!(o, "          event '{}' ({}, max {})", ev.name, ev.priority, ev.maximum_execution_count);
                        trigger_text(o, "            ", "start", ev.start_trigger.as_ref());
                        for a in &ev.actions {
                            action_text(o, "            ", a);
                        }
                    }
                }
            }
        }
    }
    trigger_text(o, "  ", "stop", sb.stop_trigger.as_ref());
}

fn entity_text(o: &mut String, e: &Entity) {
    let desc = match &e.object {
        EntityObject::Vehicle(v) => format!(
            "vehicle {} '{}', max speed {} m/s, max acc {} m/s², max dec {} m/s²",
            v.category, v.name, v.performance.max_speed, v.performance.max_acceleration, v.performance.max_deceleration
        ),
        EntityObject::Pedestrian(p) => format!("pedestrian {} '{}', mass {} kg", p.category, p.name, p.mass),
        EntityObject::MiscObject(m) => format!("misc object {} '{}', mass {} kg", m.category, m.name, m.mass),
        EntityObject::External { name } => format!("external object '{name}'"),
    };
    let _ = writeln!(o, "  {}: {desc}", e.name);
    if let Some(b) = e.object.bounding_box() {
        let _ =
            writeln!(o, "    bounding box: centre ({}, {}, {}), length {} width {} height {}", b.center.x, b.center.y, b.center.z, b.length, b.width, b.height);
    }
    let props = match &e.object {
        EntityObject::Vehicle(v) => Some(&v.properties),
        EntityObject::Pedestrian(p) => Some(&p.properties),
        EntityObject::MiscObject(m) => Some(&m.properties),
        EntityObject::External { .. } => None,
    };
    if let Some(p) = props.filter(|p| !p.properties.is_empty()) {
        let list: Vec<String> = p.properties.iter().map(|(n, v)| format!("{n}={v}")).collect();
        let _ = writeln!(o, "    properties: {}", list.join(", "));
    }
    for c in &e.controllers {
        let list: Vec<String> = c.properties.properties.iter().map(|(n, v)| format!("{n}={v}")).collect();
        let _ = writeln!(o, "    controller '{}' {}", c.name, list.join(", "));
    }
}

fn action_text(o: &mut String, indent: &str, a: &Action) {
    let name = if a.name.is_empty() { String::new() } else { format!("'{}' ", a.name) };
    let detail = match &a.kind {
        openscenario::ActionKind::Private(p) => compact(p),
        openscenario::ActionKind::Global(g) => compact(g),
        other => compact(other),
    };
    let _ = writeln!(o, "{indent}action {name}{}: {detail}", a.kind.element_name());
}

fn condition_text(c: &Condition) -> String {
    let detail = match &c.kind {
        ConditionKind::ByEntity { rule, entities, condition } => {
            format!("{} of [{}]: {}", rule, entities.join(", "), compact(condition))
        }
        ConditionKind::ByValue(v) => compact(v),
        ConditionKind::Unsupported { .. } => "(unsupported)".to_string(),
    };
    let delay = if c.delay != 0.0 { format!(", delay {} s", c.delay) } else { String::new() };
    format!("{} '{}' ({}{delay}) {detail}", c.kind.element_name(), c.name, c.edge)
}

fn trigger_text(o: &mut String, indent: &str, what: &str, t: Option<&Trigger>) {
    let Some(t) = t else { return };
    if t.groups.is_empty() {
        let _ = writeln!(o, "{indent}{what} trigger: (empty)");
        return;
    }
    let _ = writeln!(o, "{indent}{what} trigger:");
    for (i, g) in t.groups.iter().enumerate() {
        let _ = writeln!(o, "{indent}  {}group {}:", if i > 0 { "OR " } else { "" }, i + 1);
        for (j, c) in g.conditions.iter().enumerate() {
            let _ = writeln!(o, "{indent}    {}{}", if j > 0 { "AND " } else { "" }, condition_text(c));
        }
    }
}

fn distribution_text(o: &mut String, d: &Distribution) {
    let _ = writeln!(o, "parameter value distribution for {}", d.scenario_file.display());
    let _ = writeln!(o, "runs: {}", d.len());
    for (i, set) in d.iter().take(usize::try_from(SHOWN_RUNS).unwrap_or(10)).enumerate() {
        let list: Vec<String> = set.iter().map(|(n, v)| format!("{n}={v}")).collect();
        let _ = writeln!(o, "  run {}: {}", i, list.join(", "));
    }
    if d.len() > SHOWN_RUNS {
        let _ = writeln!(o, "  ... ({} more)", d.len() - SHOWN_RUNS);
    }
}

fn catalog_text(o: &mut String, c: &CatalogFile) {
    let _ = writeln!(o, "catalog '{}': {} entries", c.name, c.entries.len());
    for e in &c.entries {
        let (kind, name) = match e {
            CatalogEntry::Object(EntityObject::Vehicle(v)) => ("vehicle", v.name.as_str()),
            CatalogEntry::Object(EntityObject::Pedestrian(p)) => ("pedestrian", p.name.as_str()),
            CatalogEntry::Object(EntityObject::MiscObject(m)) => ("misc object", m.name.as_str()),
            CatalogEntry::Object(EntityObject::External { name }) => ("external object", name.as_str()),
            CatalogEntry::Controller(x) => ("controller", x.name.as_str()),
            CatalogEntry::Environment(x) => ("environment", x.name.as_str()),
            CatalogEntry::Maneuver(x) => ("maneuver", x.name.as_str()),
            CatalogEntry::Trajectory(x) => ("trajectory", x.name.as_str()),
            CatalogEntry::Route(x) => ("route", x.name.as_str()),
        };
        let _ = writeln!(o, "  {kind} '{name}'");
    }
}
