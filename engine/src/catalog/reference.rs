//! The instruction reference as Markdown, generated from the catalogue so the page cannot
//! drift from what the compiler checks: `docs/instructions.md` is this text, and
//! `engine/tests/docs.rs` fails when it is not.

use super::{
    Access, CATALOG, CONST_MAX, Category, InstrClass, InstrSpec, OperandKind, OperandSpec, Role,
    Width,
};
use crate::address::AreaSet;
use std::fmt::Write;

/// The hand-written head of the page.
const INTRO: &str = "\
# Instruction reference

Every instruction of the GSK PLC language as the engine knows it: its class, step cost and
operands in IL order, with what each operand accepts, the address areas it may name, the width
of its data access, whether it is read or written, the range of a constant, and the help text
the editor's function dialog shows (English, then Chinese). What the instructions do is in
[plc.md](plc.md) and, for WINDR, AXCTL, PSGNL and PSGN2, [cnc.md](cnc.md).

This page is generated from the instruction catalogue (`engine/src/catalog/`) by
`ladder_engine::catalog::reference_markdown()`; `cargo test -p ladder-engine --test engine docs::` fails
when it is out of date, and `UPDATE_DOCS=1 cargo test -p ladder-engine --test engine docs::` rewrites it.
";

/// Renders every instruction of [`CATALOG`] as Markdown, category by category in menu order:
/// the text of `docs/instructions.md`.
pub fn reference_markdown() -> String {
    let mut out = String::from(INTRO);
    // Writing to a String cannot fail, so the results of `write!` are dropped throughout.
    for category in Category::ALL {
        let _ = write!(
            out,
            "\n## {} · {}\n",
            category.name_en(),
            category.name_zh()
        );
        for spec in CATALOG.iter().filter(|s| s.category == category) {
            instruction(&mut out, spec);
        }
    }
    out
}

fn instruction(out: &mut String, spec: &InstrSpec) {
    let _ = write!(
        out,
        "\n### {}\n\n{}\n\n{}\n\n{} · {}\n",
        spec.name,
        cell(spec.help_en),
        cell(spec.help_zh),
        class(spec.class),
        steps(spec)
    );
    if spec.operands.is_empty() {
        out.push_str("\nNo operands.\n");
        return;
    }
    out.push_str(
        "\n| # | operand | kind | areas | width | access | constants | help | 说明 |\n\
         | --- | --- | --- | --- | --- | --- | --- | --- | --- |\n",
    );
    for (i, o) in spec.operands.iter().enumerate() {
        row(out, spec, &(i + 1).to_string(), o.name, o);
    }
    if let Some(t) = spec.table {
        let count = spec.operands[t.count_from].name;
        let number = format!("{}…", t.first + 1);
        row(
            out,
            spec,
            &number,
            &format!("{} × {count}", t.entry.name),
            t.entry,
        );
    }
}

fn row(out: &mut String, spec: &InstrSpec, number: &str, name: &str, o: &OperandSpec) {
    let areas = if o.areas == AreaSet::EMPTY {
        "—".to_string()
    } else {
        o.areas.describe()
    };
    let _ = writeln!(
        out,
        "| {number} | {name} | {} | {areas} | {} | {} | {} | {} | {} |",
        kind(o),
        width(spec, o.width),
        access(spec, o.access),
        constants(o),
        cell(o.help_en),
        cell(o.help_zh),
    );
}

/// Text fit for a table cell: a `|` would end the cell.
fn cell(text: &str) -> String {
    text.replace('|', "\\|")
}

fn class(class: InstrClass) -> &'static str {
    match class {
        InstrClass::Contact => "contact",
        InstrClass::Stack => "block or branch operation",
        InstrClass::Coil => "coil",
        InstrClass::Function => "function instruction",
    }
}

fn steps(spec: &InstrSpec) -> String {
    match (spec.class, spec.table) {
        (InstrClass::Function, Some(t)) => format!(
            "{} steps + 1 per {} entry ({})",
            spec.steps(t.first),
            t.entry.name,
            spec.operands[t.count_from].name
        ),
        _ => {
            let n = spec.steps(spec.operands.len());
            format!("{n} step{}", if n == 1 { "" } else { "s" })
        }
    }
}

fn kind(o: &OperandSpec) -> String {
    let kind = match o.kind {
        OperandKind::Size => "size constant",
        OperandKind::Const => "constant",
        OperandKind::Digits { max_digit: 1 } => "4 binary digits",
        OperandKind::Digits { .. } => "4 decimal digits",
        OperandKind::Bit => "bit address",
        OperandKind::Byte => "byte/word address",
        OperandKind::ConstOrByte => "constant or byte/word address",
        OperandKind::RealOrD => "real constant or D address",
        OperandKind::BitOrByte => "bit or byte/word address",
        OperandKind::Label => "label",
        OperandKind::Subprogram => "subprogram",
        OperandKind::Timer => "timer number",
        OperandKind::Counter => "counter number",
    };
    match o.role {
        Role::Plain => kind.to_string(),
        Role::TimerNumber => format!("{kind}: the timer it runs"),
        Role::CounterNumber => format!("{kind}: the counter it runs"),
        Role::Preset => format!("{kind}: the preset"),
        Role::Driven => format!("{kind}, written at every execution whatever ACT"),
    }
}

fn width(spec: &InstrSpec, width: Width) -> String {
    match width {
        Width::None => "—".to_string(),
        Width::Bytes(1) => "1 byte".to_string(),
        Width::Bytes(n) => format!("{n} bytes"),
        Width::SizeOf(i) => format!("{} bytes", operand_name(spec, i)),
        Width::Bits3 => "3 bits".to_string(),
        Width::Elements4(n) => format!("{n} × 4 bytes"),
        Width::Table => "table".to_string(),
    }
}

fn access(spec: &InstrSpec, access: Access) -> String {
    match access {
        Access::Read => "read".to_string(),
        Access::Write => "written".to_string(),
        Access::ReadWrite => "read and written".to_string(),
        Access::WriteWhen { operand, value } => format!(
            "written when {} = {value}, else read",
            operand_name(spec, operand)
        ),
    }
}

fn constants(o: &OperandSpec) -> String {
    if !o.accepts_const() {
        return "—".to_string();
    }
    match o.kind {
        OperandKind::Size => "1, 2, 4".to_string(),
        OperandKind::Digits { .. } => format!("{:04}–{:04}", o.min, max_digits(o)),
        _ if o.min == -CONST_MAX && o.max == CONST_MAX => format!("±{CONST_MAX}"),
        _ => format!("{}…{}", o.min, o.max),
    }
}

/// The largest digit group: each of the 4 digits at its largest.
fn max_digits(o: &OperandSpec) -> i64 {
    match o.kind {
        OperandKind::Digits { max_digit } => i64::from(max_digit) * 1111,
        _ => o.max,
    }
}

fn operand_name(spec: &InstrSpec, i: u8) -> String {
    spec.operands
        .get(usize::from(i))
        .map_or_else(|| format!("operand {}", i + 1), |o| o.name.to_string())
}
