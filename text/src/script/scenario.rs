//! The words of a refused scenario line, `scenario` script line or scenario name
//! (docs/scenarios.md).

use crate::Lang;
use ladder_engine::scenario::{NAME_MAX, NameError};
use ladder_engine::sim::{ScenarioReason, ScriptError};

/// What `r` says, in English and in Chinese.
pub(super) fn words(r: &ScenarioReason) -> (String, String) {
    use ScenarioReason as R;
    match r {
        R::NotScenarioLine { verb } => (
            format!(
                "`{verb}` cannot be part of a scenario: its lines are `set`, `force`, `panel` and `device NAME fault …`"
            ),
            format!(
                "`{verb}` 不能用在场景中：场景的行只能是 `set`、`force`、`panel` 和 `device NAME fault …`"
            ),
        ),
        R::FaultsOnly => (
            "a scenario injects device faults only (`device NAME fault …`); its release clears them".into(),
            "场景中的设备行只能注入故障（`device NAME fault …`）；解除场景时故障随之清除".into(),
        ),
        R::NoPanelItem { label } => (
            format!(
                "the operator panel has no item `{label}`: write its label as the panel shows it, in quotes if it has spaces"
            ),
            format!("操作面板上没有 `{label}` 项：请按面板上的标签书写，含空格时加引号"),
        ),
        R::KeyState { label, value } => (
            format!("`{label}` is a key or switch: its state is 0 or 1, not `{value}`"),
            format!("`{label}` 是按键或开关：状态只能是 0 或 1，不是 `{value}`"),
        ),
        R::NoKnobPosition {
            label,
            value,
            positions,
        } => (
            format!(
                "knob `{label}` has no position `{value}` (positions: {})",
                positions.join(", ")
            ),
            format!(
                "波段开关 `{label}` 没有 `{value}` 挡（挡位：{}）",
                positions.join("、")
            ),
        ),
        R::Lamp { label } => (
            format!("`{label}` is a lamp: the program lights it, a scenario cannot set it"),
            format!("`{label}` 是指示灯：由程序点亮，场景不能设置它"),
        ),
        R::NoProject => (
            "scenarios are kept in a project: run the script against a .ldp".into(),
            "场景保存在工程中：请对 .ldp 工程运行脚本".into(),
        ),
        R::NoScenario { name, names } if names.is_empty() => (
            format!("no scenario `{name}`: the project has none"),
            format!("没有场景 `{name}`：工程中没有场景"),
        ),
        R::NoScenario { name, names } => (
            format!("no scenario `{name}`: the project has {}", names.join(", ")),
            format!("没有场景 `{name}`：工程中有 {}", names.join("、")),
        ),
        R::Broken { scenario, error } => (
            broken_scenario(scenario, error, Lang::En),
            broken_scenario(scenario, error, Lang::Zh),
        ),
    }
}

/// The line of the scenario `name` that does not apply, and why, in `lang`: the `scenario`
/// script line, the check of the saved scenarios (W019) and the editor's Apply say it alike.
pub fn broken_scenario(name: &str, e: &ScriptError, lang: Lang) -> String {
    let reason = super::script_error(e, lang);
    match lang {
        Lang::En => format!("scenario `{name}`, line {}: {reason}", e.line),
        Lang::Zh => format!("场景 `{name}` 第 {} 行：{reason}", e.line),
    }
}

/// Why a scenario's name cannot be used, in `lang`.
pub fn name_error(e: &NameError, lang: Lang) -> String {
    let (en, zh) = match e {
        NameError::Empty => ("a scenario needs a name".into(), "场景需要一个名称".into()),
        NameError::Malformed { name } => (
            format!(
                "scenario name `{name}`: use at most {NAME_MAX} letters, digits, `_` or `-` (a script line names it)"
            ),
            format!(
                "场景名称 `{name}`：最多 {NAME_MAX} 个字母、数字、`_` 或 `-`（脚本行会用到它）"
            ),
        ),
        NameError::Taken { name } => (
            format!("scenario name `{name}` is already used; give each scenario its own"),
            format!("场景名称 `{name}` 已被使用；请为每个场景取不同的名称"),
        ),
    };
    match lang {
        Lang::En => en,
        Lang::Zh => zh,
    }
}
