//! W009: a timer's or counter's preset read from a data table (TMRB's and TMRC's PT from DT,
//! CTRC's N from DC) whose entry holds a value outside the range the instruction takes for
//! that operand. The program would compile, and the controller would count the value as
//! the nearest end of the range (a negative preset as 0, docs/plc.md "Timer/counter").
//!
//! The instructions and ranges come from the catalogue: every operand with [`Role::Preset`]
//! and its `min…max`.

use super::Program;
use super::diag::Sink;
use super::finding::CheckFinding;
use crate::address::Area;
use crate::catalog::Role;
use crate::model::{DataRow, Operand, Project};

/// The data table that holds the first values of `area`, if there is one.
fn table(project: &Project, area: Area) -> Option<&[DataRow]> {
    match area {
        Area::Dt => Some(&project.data.dt),
        Area::Dc => Some(&project.data.dc),
        Area::D => Some(&project.data.d),
        _ => None,
    }
}

/// Reports W009 at every instruction whose preset names a data-table entry outside the
/// preset's range. Symbols must be resolved already.
pub fn check_presets(program: &Program, project: &Project, sink: &mut Sink) {
    for (b, block) in program.blocks.iter().enumerate() {
        let label = block.kind.label();
        for (n, net) in block.networks.iter().enumerate() {
            sink.at(b, &label, n);
            for instr in &net.instrs {
                let spec = instr.op.spec();
                let Some(i) = spec.operand_with(Role::Preset) else {
                    continue;
                };
                let Some(a) = instr.operands.get(i).and_then(Operand::address) else {
                    continue;
                };
                let Some(rows) = table(project, a.area) else {
                    continue;
                };
                let Some((r, row)) = rows.iter().enumerate().find(|(_, r)| r.address == a) else {
                    continue;
                };
                let ospec = &spec.operands[i];
                let (min, max) = (ospec.min, ospec.max);
                if (min..=max).contains(&row.value) {
                    continue;
                }
                sink.find(
                    instr.origin,
                    CheckFinding::PresetRange {
                        op: instr.op,
                        operand: ospec.name.to_string(),
                        address: a,
                        row: r + 1,
                        value: row.value,
                        min,
                        max,
                    },
                );
            }
        }
    }
}
