//! The editing rules the editor applies through its one door, written as small grid drawings:
//! regions deleted, copied and pasted, the gestures planned as edits, and why an operand is
//! refused where it stands.
//!
//! A row is cells separated by spaces: `X1.0` a normally-open contact, `/X1.0` a
//! normally-closed one, `-` a wire, `.` empty, `(Y1.0)` a coil. A line `| 1 3` puts vertical
//! links below the previous row at junctions 1 and 3.

use ladder_engine::compiler::Code;
use ladder_engine::compiler::{OperandRefusal, operand_error};
use ladder_engine::model::region::{Clip, Region};
use ladder_engine::model::{Cell, CellRef, Edit, EditError, Ladder, Network, Operand, Row};
use ladder_engine::{Op, Profile, ProfileId};

const WIDTH: usize = 4;

fn cell(text: &str) -> Cell {
    let op = |s: &str| Operand::parse(s).unwrap();
    match text {
        "." => Cell::Empty,
        "-" => Cell::Wire,
        t if t.starts_with('(') => Cell::Coil {
            negated: false,
            operand: op(&t[1..t.len() - 1]),
        },
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

fn network(ladder: &Ladder, drawing: &[&str]) -> Network {
    let mut n = ladder.new_network();
    n.rows.clear();
    for line in drawing {
        if let Some(links) = line.strip_prefix('|') {
            let last = n.rows.last_mut().expect("a row before its links");
            for j in links.split_whitespace() {
                last.links[j.parse::<usize>().unwrap()] = true;
            }
        } else {
            let cells: Vec<Cell> = line.split_whitespace().map(cell).collect();
            assert_eq!(cells.len(), WIDTH + 1, "{line}");
            n.rows.push(Row {
                cells,
                links: vec![false; WIDTH + 1],
            });
        }
    }
    n
}

/// A ladder whose level 2 holds the drawn networks.
fn ladder(drawings: &[&[&str]]) -> Ladder {
    let mut l = Ladder::new(WIDTH);
    for d in drawings {
        let n = network(&l, d);
        l.blocks[1].networks.push(n);
    }
    l
}

/// An operand as the drawings write it: `X0001.0` is `X1.0`.
fn short(o: &Operand) -> String {
    let t = o.to_string();
    let letters: String = t.chars().take_while(|c| c.is_ascii_alphabetic()).collect();
    let rest = t[letters.len()..].trim_start_matches('0');
    let rest = if rest.is_empty() || rest.starts_with('.') {
        format!("0{rest}")
    } else {
        rest.to_string()
    };
    format!("{letters}{rest}")
}

/// The drawing of a network, back as text.
fn drawing(l: &Ladder, network: usize) -> Vec<String> {
    let text = |c: &Cell| match c {
        Cell::Empty => ".".to_string(),
        Cell::Wire => "-".to_string(),
        Cell::Contact { negated, operand } => {
            format!("{}{}", if *negated { "/" } else { "" }, short(operand))
        }
        Cell::Coil { operand, .. } => format!("({})", short(operand)),
        Cell::Box { op, .. } => format!("[{}]", op.name()),
    };
    let mut out = Vec::new();
    for r in &l.blocks[1].networks[network].rows {
        out.push(r.cells.iter().map(text).collect::<Vec<_>>().join(" "));
        let links: Vec<String> = (0..=WIDTH)
            .filter(|j| r.links[*j])
            .map(|j| j.to_string())
            .collect();
        if !links.is_empty() {
            out.push(format!("| {}", links.join(" ")));
        }
    }
    out
}

fn at(network: usize, row: usize, col: usize) -> CellRef {
    CellRef {
        block: 1,
        network,
        row,
        col,
    }
}

#[test]
fn deleting_cells_takes_their_left_links_and_one_undo_brings_them_back() {
    let mut l = ladder(&[&["X1.0 X1.1 - - (Y1.0)", "| 1", "X1.2 . . . ."]]);
    let before = l.clone();
    let region = Region::Cells {
        network: 0,
        rows: (0, 0),
        cols: (1, 1),
    };
    let inverse = l.apply(l.plan_delete_region(1, region)).unwrap();
    assert_eq!(drawing(&l, 0), ["X1.0 . - - (Y1.0)", "X1.2 . . . ."]);
    l.apply(inverse).unwrap();
    assert_eq!(l, before);
}

#[test]
fn deleting_the_last_row_clears_the_links_into_it_and_a_network_keeps_one_row() {
    let mut l = ladder(&[&["X1.0 - - - (Y1.0)", "| 1 2", "X1.1 . . . ."]]);
    let last = Region::Rows {
        network: 0,
        rows: (1, 1),
    };
    l.apply(l.plan_delete_region(1, last)).unwrap();
    assert_eq!(
        drawing(&l, 0),
        ["X1.0 - - - (Y1.0)"],
        "no link hangs in the air"
    );
    let all = Region::Rows {
        network: 0,
        rows: (0, 0),
    };
    l.apply(l.plan_delete_region(1, all)).unwrap();
    assert_eq!(drawing(&l, 0), [". . . . ."], "an empty row stays");
    // A block keeps one network too.
    let networks = Region::Networks { networks: (0, 0) };
    l.apply(l.plan_delete_region(1, networks)).unwrap();
    assert_eq!(l.blocks[1].networks.len(), 1);
}

#[test]
fn copied_cells_paste_over_the_cursor_rectangle_with_rows_added_below() {
    let mut l = ladder(&[&["X1.0 X1.1 . . (Y1.0)", "| 1", "X1.2 . . . ."]]);
    let region = Region::Cells {
        network: 0,
        rows: (0, 1),
        cols: (0, 1),
    };
    let clip = l.copy_region(1, region).expect("the region exists");
    assert!(matches!(&clip, Clip::Cells { cells, .. } if cells.len() == 2));
    let paste = l.plan_paste(at(0, 1, 2), clip).unwrap();
    l.apply(paste).unwrap();
    assert_eq!(
        drawing(&l, 0),
        [
            "X1.0 X1.1 . . (Y1.0)",
            "| 1",
            "X1.2 . X1.0 X1.1 .",
            "| 3",
            ". . X1.2 . ."
        ]
    );
}

#[test]
fn pasted_networks_are_new_networks_and_a_paste_outside_the_ladder_is_refused() {
    let mut l = ladder(&[&["X1.0 - - - (Y1.0)"]]);
    let clip = l
        .copy_region(1, Region::Networks { networks: (0, 0) })
        .unwrap();
    l.apply(l.plan_paste(at(0, 0, 0), clip.clone()).unwrap())
        .unwrap();
    let n = &l.blocks[1].networks;
    assert_eq!(n.len(), 2);
    assert_ne!(n[0].id, n[1].id, "a pasted network gets its own identity");
    assert_eq!(
        l.plan_paste(at(9, 0, 0), clip),
        Err(EditError::NoSuchPlace(
            ladder_engine::model::Missing::Network
        ))
    );
}

#[test]
fn a_coil_or_box_goes_to_the_output_column_joined_by_wire() {
    let mut l = ladder(&[&["X1.0 . . . ."]]);
    let coil = cell("(Y1.0)");
    let plan = l.plan_output(at(0, 0, 1), coil).unwrap();
    l.apply(plan).unwrap();
    assert_eq!(drawing(&l, 0), ["X1.0 - - - (Y1.0)"]);
    assert!(l.plan_output(at(0, 3, 0), cell("(Y1.1)")).is_err());
}

#[test]
fn f6_and_f5_and_the_pen_plan_their_links() {
    let mut l = ladder(&[&["X1.0 - - - (Y1.0)", ". . . . ."]]);
    let parallel = Ladder::plan_parallel_contact(at(0, 1, 0), cell("Y1.0")).unwrap();
    l.apply(parallel).unwrap();
    assert_eq!(drawing(&l, 0), ["X1.0 - - - (Y1.0)", "| 1", "Y1.0 . . . ."]);
    assert_eq!(
        Ladder::plan_parallel_contact(at(0, 0, 0), cell("Y1.0")),
        Err(EditError::NothingAbove)
    );
    // F5 on the last row adds the row the link leads to.
    let link = l.plan_toggle_link(at(0, 1, 2)).unwrap();
    l.apply(link).unwrap();
    assert_eq!(l.blocks[1].networks[0].rows.len(), 3);
    // The pen along a row draws wires over the empty cells only.
    let line = l.plan_line(at(0, 2, 0), at(0, 2, 3)).unwrap();
    l.apply(line).unwrap();
    assert_eq!(drawing(&l, 0)[4], "- - - - .");
}

#[test]
fn an_unchanged_edit_is_known_as_such() {
    let mut l = ladder(&[&["X1.0 - - - (Y1.0)"]]);
    let inverse = l
        .apply(Edit::SetCell {
            at: at(0, 0, 1),
            cell: Cell::Wire,
        })
        .unwrap();
    assert!(l.is_unchanged_by(&inverse), "a wire over a wire");
    let inverse = l
        .apply(Edit::SetCell {
            at: at(0, 0, 1),
            cell: Cell::Empty,
        })
        .unwrap();
    assert!(!l.is_unchanged_by(&inverse));
}

#[test]
fn an_operand_is_refused_with_its_reason_and_the_compiler_code() {
    let profile = Profile::get(ProfileId::Gsk988ta);
    let ops = |text: &str| -> Vec<Operand> {
        text.split_whitespace()
            .map(|w| Operand::parse(w).unwrap())
            .collect()
    };
    let refused = |op, text: &str, i| operand_error(op, &ops(text), i, profile).unwrap_err();
    let r = refused(Op::Tmrb, "Y0 DT4 R300.0", 0);
    assert!(matches!(r, OperandRefusal::Area { .. }), "{r:?}");
    assert_eq!(r.code(), Code::L022Area);
    let r = refused(Op::Tmrb, "T0 DT4 R300", 2);
    assert!(matches!(r, OperandRefusal::WantsBit(_)));
    assert_eq!(r.code(), Code::L021OperandKind);
    let r = refused(Op::Movn, "3 1 R10", 0);
    assert_eq!(r, OperandRefusal::Size(3));
    assert_eq!(r.code(), Code::L024ConstRange);
    let r = refused(Op::Set, "X0.0", 0);
    assert!(matches!(r, OperandRefusal::ReadOnly { .. }), "{r:?}");
    assert_eq!(r.code(), Code::L025ReadOnly);
    let r = refused(Op::Tmrb, "T9999 DT4 R300.0", 0);
    assert!(matches!(r, OperandRefusal::Range(_)));
    assert!(r.to_string().contains("out of range"), "{r}");
    assert!(operand_error(Op::Tmrb, &ops("T0 DT4 R300.0"), 0, profile).is_ok());
    assert_eq!(
        operand_error(Op::Tmrb, &ops("T0 DT4 R300.0"), 3, profile),
        Err(OperandRefusal::TooMany)
    );
}

#[test]
fn view_calls_finds_every_call_and_callu_of_a_subprogram() {
    let p = ladder_engine::il::import(
        "LEVEL1\nNETWORK\nLD X0000.0\nOUT R0000.0\nLEVEL2\nNETWORK\nLD X0001.0\nCALL P0007\nNETWORK\nCALLU P0007\nNETWORK\nLD X0001.2\nCALL P0008\nSUB P0007 \"LUBE\"\nNETWORK\nLD X0002.0\nOUT Y0002.0\nSUB P0008 \"OTHER\"\nNETWORK\nLD X0002.1\nOUT Y0002.1\nEND\n",
    )
    .project
    .unwrap();
    let calls = ladder_engine::xref::calls_of(&p, 7);
    let found: Vec<(usize, usize, Op)> = calls
        .iter()
        .map(|c| (c.at.block, c.at.network, c.op))
        .collect();
    assert_eq!(found, [(1, 0, Op::Call), (1, 1, Op::Callu)]);
    assert!(ladder_engine::xref::calls_of(&p, 9).is_empty());
}
