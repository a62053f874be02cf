//! Scenario lines (docs/scenarios.md) and the `scenario` script line: a scenario's lines are
//! script lines (`set`, `force`, `device … fault`) plus `panel LABEL VALUE`, read by the
//! script's own parser so the two never disagree.

use super::{Options, ScenarioReason, ScriptCommand, ScriptError, ScriptReason, lex, parse_line};
use crate::machine::{DeviceAction, MachineCommand};
use crate::model::{PanelKind, Project};
use crate::profile::Profile;
use crate::scenario::{Applied, Scenario, ScenarioAction};

/// The usage of the script line.
const USAGE: ScriptReason = ScriptReason::Usage {
    usage: "scenario NAME [off]",
};

/// Resolves a scenario's lines against the project they run on, or says which line is wrong
/// (its `line` counts the scenario's own lines from 1).
pub fn resolve(
    scenario: &Scenario,
    project: &Project,
    options: &Options<'_>,
) -> Result<Applied, ScriptError> {
    let profile = project.profile();
    let mut actions = Vec::new();
    for (i, raw) in scenario.lines.iter().enumerate() {
        let err = |reason: ScriptReason| ScriptError {
            line: i + 1,
            reason,
        };
        let words = lex::words(raw).map_err(|e| err(e.into()))?;
        let Some(&verb) = words.first() else {
            continue;
        };
        actions.push(action(verb, &words[1..], project, profile, options).map_err(err)?);
    }
    Ok(Applied {
        name: scenario.name.clone(),
        actions,
    })
}

fn action(
    verb: &str,
    args: &[&str],
    project: &Project,
    profile: &Profile,
    options: &Options<'_>,
) -> Result<ScenarioAction, ScriptReason> {
    let lower = verb.to_ascii_lowercase();
    if lower == "panel" {
        let a = panel(args, project)?;
        // A device writes its inputs every tick: a panel state there would not hold.
        let t = match &a {
            ScenarioAction::Write(t, _) => *t,
            ScenarioAction::Knob { input, .. } => crate::machine::Target::whole(*input),
            _ => return Ok(a),
        };
        super::device::not_driven(&t, "panel", options.machine)?;
        return Ok(a);
    }
    if !matches!(lower.as_str(), "set" | "force" | "device") {
        return Err(ScenarioReason::NotScenarioLine { verb: verb.into() }.into());
    }
    match parse_line(verb, args, profile, options)? {
        ScriptCommand::Do(MachineCommand::Write(t, v)) => Ok(ScenarioAction::Write(t, v)),
        ScriptCommand::Do(MachineCommand::Force(a, v)) => Ok(ScenarioAction::Force(a, v)),
        ScriptCommand::Do(MachineCommand::Device(i, DeviceAction::Fault(f))) => {
            Ok(ScenarioAction::Fault(i, f))
        }
        _ => Err(ScenarioReason::FaultsOnly.into()),
    }
}

/// `panel LABEL VALUE`: a key or switch of the project's operator panel held at 0 or 1, or a
/// knob turned to a position (its label or value).
fn panel(args: &[&str], project: &Project) -> Result<ScenarioAction, ScriptReason> {
    let [label, value] = args else {
        return Err(ScriptReason::Usage {
            usage: "panel LABEL VALUE",
        });
    };
    let panel = project.operator_panel();
    let Some(item) = panel
        .items
        .iter()
        .find(|i| i.label_en.eq_ignore_ascii_case(label) || i.label_zh == *label)
    else {
        return Err(ScenarioReason::NoPanelItem {
            label: (*label).into(),
        }
        .into());
    };
    match &item.kind {
        PanelKind::Key { input }
        | PanelKind::Switch { input }
        | PanelKind::LampKey { input, .. } => match *value {
            "0" | "1" => Ok(ScenarioAction::Write(
                crate::machine::Target::whole(*input),
                i64::from(*value == "1"),
            )),
            _ => Err(ScenarioReason::KeyState {
                label: (*label).into(),
                value: (*value).into(),
            }
            .into()),
        },
        PanelKind::Knob { input, positions } => {
            let pos = positions
                .iter()
                .find(|(text, v)| text.eq_ignore_ascii_case(value) || v.to_string() == *value);
            let Some((_, v)) = pos else {
                return Err(ScenarioReason::NoKnobPosition {
                    label: (*label).into(),
                    value: (*value).into(),
                    positions: positions.iter().map(|(t, _)| t.clone()).collect(),
                }
                .into());
            };
            Ok(ScenarioAction::Knob {
                input: *input,
                mask: item.kind.knob_mask(),
                value: *v,
            })
        }
        PanelKind::Lamp { .. } => Err(ScenarioReason::Lamp {
            label: (*label).into(),
        }
        .into()),
    }
}

/// The `scenario NAME [off]` script line.
pub(super) fn line(args: &[&str], options: &Options<'_>) -> Result<ScriptCommand, ScriptReason> {
    let (name, off) = match args {
        [name] => (*name, false),
        [name, off] if off.eq_ignore_ascii_case("off") => (*name, true),
        _ => return Err(USAGE),
    };
    let Some(project) = options.project else {
        return Err(ScenarioReason::NoProject.into());
    };
    let Some(scenario) = project
        .scenarios
        .iter()
        .find(|s| s.name.eq_ignore_ascii_case(name))
    else {
        return Err(ScenarioReason::NoScenario {
            name: name.into(),
            names: project.scenarios.iter().map(|s| s.name.clone()).collect(),
        }
        .into());
    };
    if off {
        return Ok(ScriptCommand::Do(MachineCommand::Release(
            scenario.name.clone(),
        )));
    }
    let applied = resolve(scenario, project, options).map_err(|e| ScenarioReason::Broken {
        scenario: scenario.name.clone(),
        error: Box::new(e),
    })?;
    Ok(ScriptCommand::Do(MachineCommand::Scenario(Box::new(
        applied,
    ))))
}
