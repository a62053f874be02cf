//! Why the running machine refused a command, in words (`ladder_engine::refusal`): the
//! editor's output window and a script's `SCRIPT:LINE: cnc: MESSAGE` line show the same text.

use crate::Lang;
use ladder_engine::refusal::Refusal;
use ladder_engine::vm::SwapError;

/// A refusal in `lang`.
pub fn refusal(r: &Refusal, lang: Lang) -> String {
    match lang {
        Lang::En => en(r),
        Lang::Zh => zh(r),
    }
}

fn en(r: &Refusal) -> String {
    match r {
        Refusal::Cnc(e) => e.en(),
        Refusal::ProgramBusy(state) => format!(
            "the program cannot be replaced while automatic operation is {} (reset first)",
            state.name()
        ),
        Refusal::OffsetNumber { lo, hi, number } => {
            format!("tool offsets are {lo}–{hi}, not {number}")
        }
        Refusal::MacroValue(n) => format!("#{n} cannot take that value"),
        Refusal::AxisMoving(name) => {
            format!("axis {name} is moving; its position can be set only while it is still")
        }
        Refusal::NoCnc => "no CNC is attached (run with the simulated CNC)".into(),
        Refusal::NoMachineModel => {
            "no machine model is running (the project has no devices, or it runs with --no-machine)"
                .into()
        }
        Refusal::NoDevice(i) => format!("there is no device {}", i + 1),
        Refusal::Model(e) => e.to_string(),
        Refusal::Swap(SwapError::Profile { old, new }) => {
            format!(
                "the program is for the {new} but the running PLC is a {old}: stop and run again"
            )
        }
        Refusal::ScenarioApplied(name) => {
            format!("scenario `{name}` is already applied; release it first")
        }
        Refusal::ScenarioNeedsModel { name, device } => format!(
            "scenario `{name}` injects a device fault, but no machine model is running (or it has no device {}): run with the machine model",
            device + 1
        ),
        Refusal::ScenarioNotApplied(name) => format!("scenario `{name}` is not applied"),
        Refusal::ScenarioOrder { name, other } => format!(
            "scenario `{name}` changed what `{other}`, applied after it, changed too: release `{other}` first"
        ),
    }
}

fn zh(r: &Refusal) -> String {
    match r {
        Refusal::Cnc(e) => crate::errors::cnc_error(e, crate::Lang::Zh),
        Refusal::ProgramBusy(state) => {
            format!("自动运行状态为 {} 时不能替换程序（请先复位）", state.name())
        }
        Refusal::OffsetNumber { lo, hi, number } => {
            format!("刀具补偿号为 {lo}–{hi}，不是 {number}")
        }
        Refusal::MacroValue(n) => format!("#{n} 不能取此值"),
        Refusal::AxisMoving(name) => format!("{name} 轴正在移动；只有停止时才能设定其位置"),
        Refusal::NoCnc => "没有连接 CNC（请带仿真 CNC 运行）".into(),
        Refusal::NoMachineModel => {
            "没有运行机床模型（工程中没有设备，或以 --no-machine 运行）".into()
        }
        Refusal::NoDevice(i) => format!("没有第 {} 号设备", i + 1),
        Refusal::Model(e) => crate::errors::model_error(e, crate::Lang::Zh),
        Refusal::Swap(SwapError::Profile { old, new }) => {
            format!("程序是为 {new} 编写的，而运行中的 PLC 是 {old}：请停止后重新运行")
        }
        Refusal::ScenarioApplied(name) => format!("场景 `{name}` 已经应用；请先解除"),
        Refusal::ScenarioNeedsModel { name, device } => format!(
            "场景 `{name}` 要向设备注入故障，但没有运行机床模型（或没有第 {} 号设备）：请带机床模型运行",
            device + 1
        ),
        Refusal::ScenarioNotApplied(name) => format!("场景 `{name}` 没有应用"),
        Refusal::ScenarioOrder { name, other } => {
            format!("场景 `{name}` 与其后应用的 `{other}` 改动了相同的对象：请先解除 `{other}`")
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use ladder_engine::cnc::{CncError, RunState};
    use ladder_engine::devices::ModelError;

    /// One refusal of every kind, with a specific its words must carry; the `match` fails to
    /// compile when a kind is added without an example here.
    fn examples() -> Vec<(Refusal, &'static str)> {
        let all = vec![
            (Refusal::Cnc(CncError::NoSubcommand), "program"),
            (Refusal::ProgramBusy(RunState::Run), "RUN"),
            (
                Refusal::OffsetNumber {
                    lo: 1,
                    hi: 32,
                    number: 40,
                },
                "40",
            ),
            (Refusal::MacroValue(3000), "#3000"),
            (Refusal::AxisMoving("Z"), "Z"),
            (Refusal::NoCnc, "CNC"),
            (Refusal::NoMachineModel, "--no-machine"),
            (Refusal::NoDevice(6), "7"),
            (Refusal::Model(ModelError::Name("1door".into())), "1door"),
            (
                Refusal::Swap(SwapError::Profile {
                    old: "GSK988TA",
                    new: "GSK980",
                }),
                "GSK980",
            ),
            (Refusal::ScenarioApplied("jam".into()), "`jam`"),
            (
                Refusal::ScenarioNeedsModel {
                    name: "jam".into(),
                    device: 2,
                },
                "3",
            ),
            (Refusal::ScenarioNotApplied("jam".into()), "`jam`"),
            (
                Refusal::ScenarioOrder {
                    name: "a".into(),
                    other: "b".into(),
                },
                "`b`",
            ),
        ];
        for (r, _) in &all {
            match r {
                Refusal::Cnc(_)
                | Refusal::ProgramBusy(_)
                | Refusal::OffsetNumber { .. }
                | Refusal::MacroValue(_)
                | Refusal::AxisMoving(_)
                | Refusal::NoCnc
                | Refusal::NoMachineModel
                | Refusal::NoDevice(_)
                | Refusal::Model(_)
                | Refusal::Swap(_)
                | Refusal::ScenarioApplied(_)
                | Refusal::ScenarioNeedsModel { .. }
                | Refusal::ScenarioNotApplied(_)
                | Refusal::ScenarioOrder { .. } => {}
            }
        }
        all
    }

    #[test]
    fn every_refusal_reads_in_both_languages_with_its_specifics() {
        let cjk = |s: &str| s.chars().any(|c| ('\u{4e00}'..='\u{9fff}').contains(&c));
        for (r, specific) in examples() {
            let (en, zh) = (refusal(&r, Lang::En), refusal(&r, Lang::Zh));
            assert!(!cjk(&en) && cjk(&zh), "{r:?}: {en} / {zh}");
            assert!(en.contains(specific), "{en}");
            assert!(zh.contains(specific), "{zh}");
        }
        // Scripts read the English: it stays as it was worded.
        let order = Refusal::ScenarioOrder {
            name: "a".into(),
            other: "b".into(),
        };
        assert_eq!(
            refusal(&order, Lang::En),
            "scenario `a` changed what `b`, applied after it, changed too: release `b` first"
        );
    }
}
