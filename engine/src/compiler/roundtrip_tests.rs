//! Round trips on seeded random programs: ladder → IL → ladder → IL is a fixed point, and IL
//! written the way the compiler writes it comes back unchanged.
//!
//! A unit test of the engine rather than an integration test: it draws random rung trees
//! (`rung`) and lays them out as grids (`layout`), phases private to the compiler.

use crate::Op;
use crate::address::{Address, Area};
use crate::compiler::layout::{layout, width_needed};
use crate::compiler::rung::{Expr, Item, Node, Output, Rung, and, or};
use crate::compiler::{Origin, compile};
use crate::generate::SplitMix64;
use crate::il;
use crate::model::{Cell, DEFAULT_WIDTH, Ladder, Network, NetworkId, Operand, Project, Row};
use proptest::prelude::*;
use proptest::test_runner::{Config, RngAlgorithm, TestRng, TestRunner};

fn bit(area: Area, n: u16, b: u8) -> Operand {
    Operand::Addr(Address::bit(area, n, b))
}

fn contact() -> impl Strategy<Value = Expr> {
    (any::<bool>(), 0u16..4, 0u8..8).prop_map(|(negated, n, b)| Expr::Contact {
        negated,
        operand: bit(Area::X, n, b),
        origin: Origin::None,
    })
}

fn expr() -> impl Strategy<Value = Expr> {
    contact().prop_recursive(3, 12, 3, |inner| {
        prop_oneof![
            prop::collection::vec(inner.clone(), 2..4)
                .prop_map(|v| v.into_iter().reduce(and).unwrap()),
            prop::collection::vec(inner, 2..4).prop_map(|v| v.into_iter().reduce(or).unwrap()),
        ]
    })
}

fn output() -> impl Strategy<Value = Output> {
    (0u8..5, 0u16..16, 0u8..8).prop_map(|(kind, n, b)| {
        let (op, operands) = match kind {
            0 | 1 => (Op::Out, vec![bit(Area::Y, n, b)]),
            2 => (Op::Outn, vec![bit(Area::R, n, b)]),
            3 => (Op::Set, vec![bit(Area::R, 100 + n, b)]),
            _ => (
                Op::Movn,
                vec![
                    Operand::Int(1),
                    Operand::Int(i64::from(n)),
                    Operand::Addr(Address::byte(Area::D, n)),
                ],
            ),
        };
        Output {
            op,
            operands,
            origin: Origin::None,
        }
    })
}

fn node() -> impl Strategy<Value = Node> {
    let leaf = prop::collection::vec(output().prop_map(Item::Output), 1..3)
        .prop_map(|items| Node { items });
    leaf.prop_recursive(3, 16, 3, |inner| {
        prop::collection::vec(
            prop_oneof![
                output().prop_map(Item::Output),
                (expr(), inner).prop_map(|(e, n)| Item::Branch(e, n)),
            ],
            1..4,
        )
        .prop_map(|items| Node { items })
    })
}

fn rung() -> impl Strategy<Value = Rung> {
    prop_oneof![
        6 => (expr(), node()).prop_map(|(e, n)| Rung::Powered(e, n)),
        1 => Just(Rung::Standalone(Output {
            op: Op::Callu,
            operands: vec![Operand::Addr(Address::byte(Area::P, 1))],
            origin: Origin::None,
        })),
    ]
}

fn project_of(rows: Vec<Row>, width: usize) -> Project {
    let mut ladder = Ladder::new(width);
    let mut n = Network::new(NetworkId(1), width);
    n.rows = rows;
    ladder.blocks[1].networks.push(n);
    Project {
        ladder,
        ..Project::default()
    }
}

/// Ladder → IL → ladder → IL: the two lists are equal, and so are the two later ladders.
fn assert_fixed_point(project: &Project) -> Result<(), TestCaseError> {
    let first = compile(project);
    let structural: Vec<String> = first
        .diagnostics
        .iter()
        .filter(|d| d.code.as_str() < "L010")
        .map(|d| format!("{d:?}"))
        .collect();
    prop_assert!(structural.is_empty(), "{structural:?}");
    let il1 = il::print(&first.program);
    let imported = il::import(&il1);
    let Some(p2) = imported.project else {
        return Err(TestCaseError::fail(format!("the IL did not draw:\n{il1}")));
    };
    let il2 = il::print(&compile(&p2).program);
    prop_assert_eq!(&il1, &il2);
    let p3 = il::import(&il2).project.expect("drawn once, drawn again");
    prop_assert_eq!(&p3.ladder, &p2.ladder);
    Ok(())
}

#[test]
fn random_ladder_networks_are_a_fixed_point() {
    let config = Config {
        cases: 1200,
        failure_persistence: None,
        ..Config::default()
    };
    let rng = TestRng::from_seed(RngAlgorithm::ChaCha, &[42; 32]);
    let mut runner = TestRunner::new_with_rng(config, rng);
    runner
        .run(&prop::collection::vec(rung(), 1..4), |rungs| {
            let width = width_needed(&rungs).max(DEFAULT_WIDTH);
            let project = project_of(layout(&rungs, width), width);
            assert_fixed_point(&project)
        })
        .unwrap();
}

/// Hand-drawn style grids: random cells and links. Whatever compiles without a structural
/// error must round-trip; nothing may panic.
#[test]
fn random_drawn_grids_never_panic_and_round_trip_when_valid() {
    let mut rng = SplitMix64::new(7);
    let width = 4;
    let mut valid = 0;
    for _ in 0..5000 {
        let rows = 1 + rng.below(4) as usize;
        let mut grid = Vec::new();
        for _ in 0..rows {
            let mut row = Row::empty(width);
            for c in 0..width {
                row.cells[c] = match rng.below(10) {
                    0 => Cell::Empty,
                    1..=3 => Cell::Wire,
                    k => Cell::Contact {
                        negated: k == 9,
                        operand: bit(Area::X, 1, rng.below(8) as u8),
                    },
                };
            }
            row.cells[width] = match rng.below(20) {
                0 | 1 => Cell::Empty,
                2 => Cell::Box {
                    op: Op::Lbl,
                    operands: vec![Operand::Addr(Address::byte(Area::L, 1))],
                },
                _ => Cell::Coil {
                    negated: false,
                    operand: bit(Area::Y, 1, rng.below(8) as u8),
                },
            };
            for j in 1..=width {
                row.links[j] = rng.chance(20);
            }
            grid.push(row);
        }
        if let Some(last) = grid.last_mut() {
            last.links.iter_mut().for_each(|l| *l = false);
        }
        let project = project_of(grid, width);
        let c = compile(&project);
        if c.diagnostics.iter().all(|d| d.code.as_str() >= "L010") {
            valid += 1;
            // Once: a runner over `Just(())` would check the same grid 256 times.
            if let Err(e) = assert_fixed_point(&project) {
                panic!("{e}");
            }
        }
    }
    eprintln!("{valid} of 5000 random grids were valid");
    assert!(
        valid > 500,
        "only {valid} random grids were valid: the generator needs tuning"
    );
}
