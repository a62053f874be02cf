//! Checks of the machine model (docs/machine.md, "Checks"), reported like the tables': the
//! "block" is `MACHINE`, the "network" the device's index. Errors (M001–M005) are the
//! model's own ([`crate::devices::check`]); the warnings need the program: a device that
//! reads an output nothing writes (W010) and an input the operator panel also drives (W011).

use super::Program;
use super::diag::{Code, Origin, Sink};
use super::writes::writes;
use crate::address::{Address, Area};
use crate::devices::{DeviceKind, ModelError, check};
use crate::model::{PanelKind, Project};
use std::collections::HashSet;

/// The "block" number of the machine model, before the tables.
pub const MACHINE: usize = usize::MAX - 7;

/// Checks a project's machine model against its compiled program (symbols resolved).
pub fn check_machine(project: &Project, program: &Program, sink: &mut Sink) {
    let model = &project.machine;
    if model.devices.is_empty() {
        return;
    }
    for (i, e) in check::errors(model, project.profile()) {
        sink.at(MACHINE, "MACHINE", i);
        let code = match e {
            ModelError::Name(_) | ModelError::NameTwice { .. } => Code::M001DeviceName,
            ModelError::Address { .. }
            | ModelError::NotInput { .. }
            | ModelError::NotBit { .. } => Code::M002DeviceAddress,
            ModelError::Parameter { .. } | ModelError::Start { .. } => Code::M003DeviceParameter,
            ModelError::Expression { .. } => Code::M004DeviceCondition,
            ModelError::TwoWriters { .. } => Code::M005InputTwice,
        };
        sink.report(Origin::None, code, e.to_string(), e.zh());
    }
    let written = written(project, program);
    for (i, d) in model.devices.iter().enumerate() {
        sink.at(MACHINE, "MACHINE", i);
        for (field, a) in reads(&d.kind) {
            if !written.contains(&a) && !written.contains(&a.byte_address()) {
                sink.report(
                    Origin::None,
                    Code::W010DeviceReadsNothing,
                    format!(
                        "device `{}`, {field}: nothing writes {a} (no coil, box or device): the device never sees it change; bind an output the program drives",
                        d.name
                    ),
                    format!(
                        "设备 `{}` 的 {field}：没有线圈、功能指令或设备写 {a}，设备看不到它变化；请绑定程序驱动的输出",
                        d.name
                    ),
                );
            }
        }
    }
    panel_overlap(project, sink);
}

/// The addresses a device reads that the program should write: its outputs and every address
/// of its conditions, but F (the CNC writes it) and K (the data tables set it).
fn reads(kind: &DeviceKind) -> Vec<(&'static str, Address)> {
    let mut v = kind.outputs();
    v.retain(|(_, a)| !matches!(a.area, Area::F | Area::K));
    for (field, text) in kind.expressions() {
        for word in text.split(|c: char| !(c.is_alphanumeric() || c == '.' || c == '_')) {
            if let Ok(a) = Address::parse(word)
                && a.bit.is_some()
                && !matches!(a.area, Area::F | Area::K)
            {
                v.push((field, a));
            }
        }
    }
    v
}

/// Every bit or byte something writes: the program (coils and box outputs), the devices,
/// the operator panel, the CNC (F) and the data tables (K, D, DT, DC are set there).
fn written(project: &Project, program: &Program) -> HashSet<Address> {
    let mut w = HashSet::new();
    for instr in program
        .blocks
        .iter()
        .flat_map(|b| &b.networks)
        .flat_map(|n| &n.instrs)
    {
        let spec = instr.op.spec();
        for (i, operand) in instr.operands.iter().enumerate() {
            if let (Some(o), Some(a)) = (spec.operand(i), operand.address())
                && writes(o, &instr.operands)
            {
                w.insert(a);
            }
        }
    }
    for d in &project.machine.devices {
        w.extend(d.kind.inputs().into_iter().map(|(_, a)| a));
    }
    for item in &project.operator_panel().items {
        if let Some(a) = item.kind.input() {
            w.insert(a);
        }
    }
    w
}

/// Panel items of the project's own panel that drive an input a device writes (W011): the
/// device overwrites it every tick.
fn panel_overlap(project: &Project, sink: &mut Sink) {
    for (i, d) in project.machine.devices.iter().enumerate() {
        sink.at(MACHINE, "MACHINE", i);
        for (_, a) in d.kind.inputs() {
            let item = project
                .panel
                .items
                .iter()
                .find(|p| !matches!(p.kind, PanelKind::Lamp { .. }) && p.kind.drives(a));
            if let Some(item) = item {
                sink.report(
                    Origin::None,
                    Code::W011PanelDrivesDeviceInput,
                    format!(
                        "device `{}` writes {a}, which the panel item in row {}, column {} ({}) also drives: the device wins at every tick; make the item a lamp or unbind the device",
                        d.name,
                        item.row + 1,
                        item.col + 1,
                        item.label_en
                    ),
                    format!(
                        "设备 `{}` 写 {a}，第 {} 行第 {} 列的面板项（{}）也驱动它：每个周期都以设备为准；请把该项改为指示灯或解除设备的绑定",
                        d.name,
                        item.row + 1,
                        item.col + 1,
                        item.label_zh
                    ),
                );
            }
        }
    }
}
