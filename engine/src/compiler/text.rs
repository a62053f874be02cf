//! One instruction as an IL line: the mnemonic padded to four columns, then its operands as
//! the list writes them. The compiler keeps imported lines in this form and the IL printer,
//! the cross-reference index and the coverage report write it.

use crate::catalog::{Op, OperandKind};
use crate::model::Operand;
use std::fmt::Write as _;

/// Formats an operand as IL writes it: canonical addresses, decimal integers, 4-digit groups.
pub fn operand_text(op: Op, index: usize, operand: &Operand) -> String {
    match (op.spec().operand(index).map(|s| s.kind), operand) {
        (Some(OperandKind::Digits { .. }), Operand::Int(v)) if (0..=9999).contains(v) => {
            format!("{v:04}")
        }
        _ => operand.to_string(),
    }
}

/// One instruction as an IL line (without newline).
pub fn instr_text(op: Op, operands: &[Operand]) -> String {
    let mut s = String::new();
    if operands.is_empty() {
        s.push_str(op.name());
    } else {
        let _ = write!(s, "{:<4}", op.name());
        for (i, o) in operands.iter().enumerate() {
            s.push(' ');
            s.push_str(&operand_text(op, i, o));
        }
    }
    s
}
