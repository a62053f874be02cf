//! Structure checks of drawn networks, written as small grid drawings.
//!
//! A row is cells separated by spaces: `X1.0` a normally-open contact, `/X1.0` a normally-closed
//! one, `-` a wire, `.` empty, `(Y1.0)` a coil, `(/Y1.0)` OUTN, `[TMRB T0 100 R1.0]` a box
//! (operands joined with `_` inside the brackets: `[TMRB_T0_100_R1.0]`). A line `| 1 3` puts
//! vertical links below the previous row at junctions 1 and 3.

use ladder_engine::Op;
use ladder_engine::compiler::{Code, Origin, compile};
use ladder_engine::il;
use ladder_engine::model::{Cell, Ladder, Network, NetworkId, Operand, Project, Row};

const WIDTH: usize = 4;

fn cell(text: &str) -> Cell {
    let op = |s: &str| Operand::parse(s).unwrap();
    match text {
        "." => Cell::Empty,
        "-" => Cell::Wire,
        t if t.starts_with("(/") => Cell::Coil {
            negated: true,
            operand: op(&t[2..t.len() - 1]),
        },
        t if t.starts_with('(') => Cell::Coil {
            negated: false,
            operand: op(&t[1..t.len() - 1]),
        },
        t if t.starts_with('[') => {
            let parts: Vec<&str> = t[1..t.len() - 1].split('_').collect();
            Cell::Box {
                op: Op::from_name(parts[0]).unwrap(),
                operands: parts[1..].iter().map(|p| op(p)).collect(),
            }
        }
        t if t.starts_with('/') => Cell::Contact {
            negated: true,
            operand: op(&t[1..]),
        },
        t => Cell::Contact {
            negated: false,
            operand: op(t),
        },
    }
}

fn network(drawing: &[&str]) -> Network {
    let mut rows: Vec<Row> = Vec::new();
    for line in drawing {
        if let Some(links) = line.strip_prefix('|') {
            let last = rows.last_mut().expect("a row before its links");
            for j in links.split_whitespace() {
                last.links[j.parse::<usize>().unwrap()] = true;
            }
        } else {
            let cells: Vec<Cell> = line.split_whitespace().map(cell).collect();
            assert_eq!(cells.len(), WIDTH + 1, "{line}");
            rows.push(Row {
                cells,
                links: vec![false; WIDTH + 1],
            });
        }
    }
    let mut n = Network::new(NetworkId(1), WIDTH);
    n.rows = rows;
    n
}

fn project(drawing: &[&str]) -> Project {
    let mut ladder = Ladder::new(WIDTH);
    ladder.blocks[1].networks.push(network(drawing));
    Project {
        ladder,
        ..Project::default()
    }
}

/// Compiles a drawing; returns its IL and its diagnostics as (code, row, col), 1-based.
fn check(drawing: &[&str]) -> (String, Vec<(&'static str, u32, u32)>) {
    let c = compile(&project(drawing));
    let diags = c
        .diagnostics
        .iter()
        .map(|d| match d.location.origin {
            Origin::Cell { row, col } => (d.code.as_str(), row + 1, col + 1),
            _ => (d.code.as_str(), 0, 0),
        })
        .collect();
    let text = il::print(&c.program);
    let body: String = text
        .lines()
        .filter(|l| !matches!(*l, "LEVEL1" | "LEVEL2" | "NETWORK" | "END"))
        .map(|l| format!("{}\n", l.split_whitespace().collect::<Vec<_>>().join(" ")))
        .collect();
    (body, diags)
}

#[test]
fn the_self_holding_circuit_compiles_to_the_manual_il() {
    let (il, diags) = check(&["X2.1 /X2.2 - - (Y3.7)", "| 1", "Y3.7 . . . ."]);
    assert!(diags.is_empty(), "{diags:?}");
    assert_eq!(il, "LD X0002.1\nOR Y0003.7\nANI X0002.2\nOUT Y0003.7\n");
}

#[test]
fn parallel_blocks_and_branch_points() {
    let (il, diags) = check(&[
        "X1.0 X1.1 X1.2 - (Y1.0)",
        "| 1 2",
        "X1.3 X1.4 /X1.5 - (Y1.1)",
        "| 2",
        ". . X1.6 - (Y1.2)",
    ]);
    assert!(diags.is_empty(), "{diags:?}");
    assert_eq!(
        il,
        "LD X0001.0\nOR X0001.3\nLD X0001.1\nOR X0001.4\nANB\nMPS\nAND X0001.2\nOUT Y0001.0\nMRD\nANI X0001.5\nOUT Y0001.1\nMPP\nAND X0001.6\nOUT Y0001.2\n"
    );
}

#[test]
fn an_element_off_the_rail_is_reported() {
    let (_, diags) = check(&[". X1.0 - - (Y1.0)"]);
    assert!(diags.contains(&("L001", 1, 2)), "{diags:?}");
}

#[test]
fn a_dangling_contact_is_an_open_branch() {
    let (_, diags) = check(&["X1.0 - - - (Y1.0)", "| 1", ". X1.1 . . ."]);
    assert_eq!(diags, vec![("L002", 2, 2)]);
}

#[test]
fn an_open_branch_of_several_contacts_is_one_diagnostic_at_its_first_cell() {
    // Row 2 runs three contacts and a wire into nothing; row 3 is a second, separate branch.
    let (_, diags) = check(&[
        "X1.0 - - - (Y1.0)",
        "| 1",
        ". X1.1 X1.2 X1.3 .",
        "| 1",
        ". X1.4 . . .",
    ]);
    assert_eq!(
        diags,
        vec![("L002", 2, 2), ("L002", 3, 2)],
        "one line per branch"
    );
}

#[test]
fn a_wire_around_a_contact_is_a_short_circuit() {
    let (_, diags) = check(&["X1.0 X1.1 - - (Y1.0)", "| 1 2", ". - . . ."]);
    assert_eq!(diags, vec![("L003", 1, 2)]);
}

#[test]
fn branches_that_merge_after_a_split_are_a_bridge() {
    // Y1.1 = (X1.0 ∧ X1.1) ∨ X1.2, but X1.0 also drives Y1.0 on its own: the X1.2 branch joins
    // a path after its branch point, which IL has no instruction for.
    let (_, diags) = check(&[
        "X1.0 - - - (Y1.0)",
        "| 1",
        ". X1.1 - - (Y1.1)",
        "| 2",
        "X1.2 - . . .",
    ]);
    assert_eq!(
        diags.iter().filter(|d| d.0 == "L004").count(),
        1,
        "{diags:?}"
    );
}

#[test]
fn coils_in_contact_columns_and_contacts_in_the_output_column() {
    let mut p = project(&["X1.0 - - - (Y1.0)"]);
    p.ladder.blocks[1].networks[0].rows[0].cells[1] = cell("(Y1.1)");
    p.ladder.blocks[1].networks[0].rows[0].cells[4] = cell("X1.1");
    let c = compile(&p);
    let codes: Vec<_> = c
        .diagnostics
        .iter()
        .map(|d| (d.code, d.location.origin))
        .collect();
    assert!(
        codes.contains(&(Code::L005WrongColumn, Origin::Cell { row: 0, col: 1 })),
        "{codes:?}"
    );
    assert!(
        codes.contains(&(Code::L005WrongColumn, Origin::Cell { row: 0, col: 4 })),
        "{codes:?}"
    );
}

#[test]
fn a_coil_on_the_rail_needs_a_contact() {
    let (_, diags) = check(&["- - - - (Y1.0)"]);
    assert_eq!(diags, vec![("L006", 1, 1)]);
}

#[test]
fn lbl_stands_alone() {
    let (il, diags) = check(&["- - - - [LBL_L1]"]);
    assert!(diags.is_empty(), "{diags:?}");
    assert_eq!(il, "LBL L0001\n");
    let (_, diags) = check(&[". . . . [LBL_L1]"]);
    assert!(
        diags.is_empty(),
        "an LBL with nothing before it is fine: {diags:?}"
    );
    let (_, diags) = check(&["X1.0 - - - [LBL_L1]"]);
    assert_eq!(diags, vec![("L007", 1, 5)]);
}

#[test]
fn operand_errors_point_at_the_cell() {
    let (_, diags) = check(&["X1.0 R1000.0 - - [TMRB_T0_D4_R1.0]"]);
    assert_eq!(diags, vec![("L023", 1, 2), ("L022", 1, 5)]);
}
