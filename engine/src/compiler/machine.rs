//! Checks of the machine model (docs/machine.md, "Checks"), reported like the tables': the
//! "block" is `MACHINE`, the "network" the device's index. Errors (M001–M005) are the
//! model's own ([`crate::devices::check`]); the warnings need the program: a device that
//! reads an output nothing writes (W010) and an input the operator panel also drives (W011).

use super::Program;
use super::diag::{Origin, Sink};
use super::finding::MachineFinding;
use super::writes::writes;
use crate::address::{Address, Area};
use crate::devices::{DeviceKind, check};
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
        sink.find(Origin::None, MachineFinding::Device(e));
    }
    let written = written(project, program);
    for (i, d) in model.devices.iter().enumerate() {
        sink.at(MACHINE, "MACHINE", i);
        for (field, a) in reads(&d.kind) {
            if !written.contains(&a) && !written.contains(&a.byte_address()) {
                sink.find(
                    Origin::None,
                    MachineFinding::ReadsNothing {
                        device: d.name.clone(),
                        field: field.to_string(),
                        address: a,
                    },
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
                sink.find(
                    Origin::None,
                    MachineFinding::PanelDrivesInput {
                        device: d.name.clone(),
                        address: a,
                        row: item.row,
                        col: item.col,
                        label_en: item.label_en.clone(),
                        label_zh: item.label_zh.clone(),
                    },
                );
            }
        }
    }
}
