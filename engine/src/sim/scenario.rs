//! Scenario lines (docs/scenarios.md) and the `scenario` script line: a scenario's lines are
//! script lines (`set`, `force`, `device … fault`) plus `panel LABEL VALUE`, read by the
//! script's own parser so the two never disagree.

use super::{Msg, Options, ScriptCommand, ScriptError, lex, msg, parse_line};
use crate::machine::{DeviceAction, MachineCommand};
use crate::model::{PanelKind, Project};
use crate::profile::Profile;
use crate::scenario::{Applied, Scenario, ScenarioAction};

/// The usage of the script line.
const USAGE: &str = "scenario NAME [off]";

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
        let err = |m: Msg| ScriptError {
            line: i + 1,
            message: m.en,
            message_zh: m.zh,
        };
        let words = lex::words(raw).map_err(err)?;
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
) -> Result<ScenarioAction, Msg> {
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
        return Err(msg(
            format!(
                "`{verb}` cannot be part of a scenario: its lines are `set`, `force`, `panel` and `device NAME fault …`"
            ),
            format!(
                "`{verb}` 不能用在场景中：场景的行只能是 `set`、`force`、`panel` 和 `device NAME fault …`"
            ),
        ));
    }
    match parse_line(verb, args, profile, options)? {
        ScriptCommand::Do(MachineCommand::Write(t, v)) => Ok(ScenarioAction::Write(t, v)),
        ScriptCommand::Do(MachineCommand::Force(a, v)) => Ok(ScenarioAction::Force(a, v)),
        ScriptCommand::Do(MachineCommand::Device(i, DeviceAction::Fault(f))) => {
            Ok(ScenarioAction::Fault(i, f))
        }
        _ => Err(msg(
            "a scenario injects device faults only (`device NAME fault …`); its release clears them",
            "场景中的设备行只能注入故障（`device NAME fault …`）；解除场景时故障随之清除",
        )),
    }
}

/// `panel LABEL VALUE`: a key or switch of the project's operator panel held at 0 or 1, or a
/// knob turned to a position (its label or value).
fn panel(args: &[&str], project: &Project) -> Result<ScenarioAction, Msg> {
    let [label, value] = args else {
        return Err(msg("usage: panel LABEL VALUE", "用法：`panel LABEL VALUE`"));
    };
    let panel = project.operator_panel();
    let Some(item) = panel
        .items
        .iter()
        .find(|i| i.label_en.eq_ignore_ascii_case(label) || i.label_zh == *label)
    else {
        return Err(msg(
            format!(
                "the operator panel has no item `{label}`: write its label as the panel shows it, in quotes if it has spaces"
            ),
            format!("操作面板上没有 `{label}` 项：请按面板上的标签书写，含空格时加引号"),
        ));
    };
    match &item.kind {
        PanelKind::Key { input }
        | PanelKind::Switch { input }
        | PanelKind::LampKey { input, .. } => match *value {
            "0" | "1" => Ok(ScenarioAction::Write(
                crate::machine::Target::whole(*input),
                i64::from(*value == "1"),
            )),
            _ => Err(msg(
                format!("`{label}` is a key or switch: its state is 0 or 1, not `{value}`"),
                format!("`{label}` 是按键或开关：状态只能是 0 或 1，不是 `{value}`"),
            )),
        },
        PanelKind::Knob { input, positions } => {
            let pos = positions
                .iter()
                .find(|(text, v)| text.eq_ignore_ascii_case(value) || v.to_string() == *value);
            let Some((_, v)) = pos else {
                let names: Vec<&str> = positions.iter().map(|(t, _)| t.as_str()).collect();
                return Err(msg(
                    format!(
                        "knob `{label}` has no position `{value}` (positions: {})",
                        names.join(", ")
                    ),
                    format!(
                        "波段开关 `{label}` 没有 `{value}` 挡（挡位：{}）",
                        names.join("、")
                    ),
                ));
            };
            Ok(ScenarioAction::Knob {
                input: *input,
                mask: item.kind.knob_mask(),
                value: *v,
            })
        }
        PanelKind::Lamp { .. } => Err(msg(
            format!("`{label}` is a lamp: the program lights it, a scenario cannot set it"),
            format!("`{label}` 是指示灯：由程序点亮，场景不能设置它"),
        )),
    }
}

/// The `scenario NAME [off]` script line.
pub(super) fn line(args: &[&str], options: &Options<'_>) -> Result<ScriptCommand, Msg> {
    let usage = || msg(format!("usage: {USAGE}"), format!("用法：`{USAGE}`"));
    let (name, off) = match args {
        [name] => (*name, false),
        [name, off] if off.eq_ignore_ascii_case("off") => (*name, true),
        _ => return Err(usage()),
    };
    let Some(project) = options.project else {
        return Err(msg(
            "scenarios are kept in a project: run the script against a .ldp",
            "场景保存在工程中：请对 .ldp 工程运行脚本",
        ));
    };
    let Some(scenario) = project
        .scenarios
        .iter()
        .find(|s| s.name.eq_ignore_ascii_case(name))
    else {
        let names: Vec<&str> = project.scenarios.iter().map(|s| s.name.as_str()).collect();
        let (en, zh) = if names.is_empty() {
            (
                "the project has none".to_string(),
                "工程中没有场景".to_string(),
            )
        } else {
            (
                format!("the project has {}", names.join(", ")),
                format!("工程中有 {}", names.join("、")),
            )
        };
        return Err(msg(
            format!("no scenario `{name}`: {en}"),
            format!("没有场景 `{name}`：{zh}"),
        ));
    };
    if off {
        return Ok(ScriptCommand::Do(MachineCommand::Release(
            scenario.name.clone(),
        )));
    }
    let applied = resolve(scenario, project, options).map_err(|e| {
        msg(
            format!(
                "scenario `{}`, line {}: {}",
                scenario.name, e.line, e.message
            ),
            format!(
                "场景 `{}` 第 {} 行：{}",
                scenario.name, e.line, e.message_zh
            ),
        )
    })?;
    Ok(ScriptCommand::Do(MachineCommand::Scenario(Box::new(
        applied,
    ))))
}
