//! Instruction lists run and round-trip as written (docs/files.md, "Imported instruction
//! lists"): import → export gives the same instruction sequence, and the list, the imported
//! project and the exported list run alike after every tick, at every level-2 division.
//!
//! The generator draws random rung trees (the constructs of `vm/differential_tests.rs`, on
//! both levels and in subprograms) and writes each one the ways other tools write it:
//! MPS/MRD/MPP at every branch point or only where needed, `LD x / ANB` for `AND x`,
//! `LD x / ORB` for `OR x`, an empty `MPS / MPP` before a block, outputs under their own MPS.
//!
//! A unit test of the engine because the generator builds the compiler's own rung trees
//! (`rung`), which are private to it; everything it checks goes through the public doors.

use crate::Op;
use crate::address::{Address, Area};
use crate::compiler::rung::{Expr, Item, Node, Output, and, or};
use crate::compiler::{CheckFinding, Finding, Origin, Sink, compile, compile_program};
use crate::generate::SplitMix64;
use crate::il;
use crate::model::{Cell, Operand, Project};
use crate::vm::Vm;
use crate::vm::cnc::NoCnc;

struct Gen {
    rng: SplitMix64,
    timers: u16,
    lines: Vec<String>,
}

fn contact_of(e: &Expr) -> (bool, &Operand) {
    match e {
        Expr::Contact {
            negated, operand, ..
        } => (*negated, operand),
        _ => unreachable!("only contacts are leaves"),
    }
}

impl Gen {
    fn bit(&mut self) -> Operand {
        let r = &mut self.rng;
        let (area, n) = match r.below(3) {
            0 => (Area::X, r.below(2) as u16),
            1 => (Area::Y, r.below(2) as u16),
            _ => (Area::R, r.below(4) as u16),
        };
        Operand::Addr(Address::bit(area, n, r.below(8) as u8))
    }
    fn out_bit(&mut self) -> Operand {
        let r = &mut self.rng;
        let (area, n) = if r.chance(50) {
            (Area::Y, r.below(2) as u16)
        } else {
            (Area::R, r.below(4) as u16)
        };
        Operand::Addr(Address::bit(area, n, r.below(8) as u8))
    }
    fn expr(&mut self, depth: u32) -> Expr {
        if depth == 0 || self.rng.chance(40) {
            return Expr::Contact {
                negated: self.rng.chance(30),
                operand: self.bit(),
                origin: Origin::None,
            };
        }
        let n = 2 + self.rng.below(2);
        let terms: Vec<Expr> = (0..n).map(|_| self.expr(depth - 1)).collect();
        if self.rng.chance(50) {
            terms.into_iter().reduce(and).unwrap()
        } else {
            terms.into_iter().reduce(or).unwrap()
        }
    }
    fn output(&mut self, subs: u16) -> Output {
        let (op, operands) = match self.rng.below(12) {
            0 => (Op::Set, vec![self.out_bit()]),
            1 => (Op::Rst, vec![self.out_bit()]),
            2 => (Op::Difu, vec![self.out_bit()]),
            3 => (Op::Difd, vec![self.out_bit()]),
            4 => (Op::Alt, vec![self.out_bit()]),
            5 | 6 if self.timers < 200 => {
                self.timers += 1;
                let pt = 8 * self.rng.below(6) as i64;
                (
                    Op::Tmrb,
                    vec![
                        Operand::Addr(Address::byte(Area::T, self.timers - 1)),
                        Operand::Int(pt),
                        self.out_bit(),
                    ],
                )
            }
            7 if subs > 0 => (
                Op::Call,
                vec![Operand::Addr(Address::byte(
                    Area::P,
                    1 + self.rng.below(u64::from(subs)) as u16,
                ))],
            ),
            8 => (Op::Outn, vec![self.out_bit()]),
            _ => (Op::Out, vec![self.out_bit()]),
        };
        Output {
            op,
            operands,
            origin: Origin::None,
        }
    }
    fn tree(&mut self, depth: u32, subs: u16) -> Node {
        let n = 1 + self.rng.below(3);
        let items = (0..n)
            .map(|_| {
                if depth > 0 && self.rng.chance(35) {
                    Item::Branch(self.expr(1), self.tree(depth - 1, subs))
                } else {
                    Item::Output(self.output(subs))
                }
            })
            .collect();
        Node { items }
    }

    fn line(&mut self, op: Op, operands: &[Operand]) {
        self.lines.push(il::instr_text(op, operands));
    }

    /// `e` as a new block, starting with LD/LDI.
    fn load(&mut self, e: &Expr) {
        match e {
            Expr::Contact { .. } => {
                let (neg, o) = contact_of(e);
                self.line(if neg { Op::Ldi } else { Op::Ld }, std::slice::from_ref(o));
            }
            Expr::And(terms) => {
                self.load(&terms[0]);
                for t in terms.iter().skip(1) {
                    self.and_term(t, false);
                }
            }
            Expr::Or(terms) => {
                self.load(&terms[0]);
                for t in terms.iter().skip(1) {
                    self.or_term(t);
                }
            }
        }
    }

    /// `acc ∧ e`; with `no_load` the first instruction must not be an LD (it follows an
    /// output with no MPS open, where an LD would start a new rung).
    fn and_term(&mut self, e: &Expr, no_load: bool) {
        match e {
            Expr::Contact { .. } => {
                let (neg, o) = contact_of(e);
                if !no_load && self.rng.chance(30) {
                    self.line(if neg { Op::Ldi } else { Op::Ld }, std::slice::from_ref(o));
                    self.line(Op::Anb, &[]);
                } else {
                    self.line(if neg { Op::Ani } else { Op::And }, std::slice::from_ref(o));
                }
            }
            Expr::And(terms) => {
                self.and_term(&terms[0], no_load);
                for t in terms.iter().skip(1) {
                    self.and_term(t, false);
                }
            }
            Expr::Or(_) => {
                self.load(e);
                self.line(Op::Anb, &[]);
            }
        }
    }

    fn or_term(&mut self, e: &Expr) {
        match e {
            Expr::Contact { .. } => {
                let (neg, o) = contact_of(e);
                if self.rng.chance(30) {
                    self.line(if neg { Op::Ldi } else { Op::Ld }, std::slice::from_ref(o));
                    self.line(Op::Orb, &[]);
                } else {
                    self.line(if neg { Op::Ori } else { Op::Or }, std::slice::from_ref(o));
                }
            }
            Expr::Or(terms) => terms.iter().for_each(|t| self.or_term(t)),
            Expr::And(_) => {
                self.load(e);
                self.line(Op::Orb, &[]);
            }
        }
    }

    fn item(&mut self, item: &Item, no_load: bool) {
        match item {
            Item::Output(o) => self.line(o.op, &o.operands),
            Item::Branch(e, child) => {
                self.and_term(e, no_load);
                self.node(child);
            }
        }
    }

    /// What hangs off a point of known power, in one of the ways tools write it.
    fn node(&mut self, node: &Node) {
        let items = &node.items;
        let starts_with_block = |i: &Item| matches!(i, Item::Branch(e, _) if first_is_block(e));
        // Without MPS, outputs in a row and at most a last branch that begins with a contact.
        let plain_ok = items[..items.len() - 1]
            .iter()
            .all(|i| matches!(i, Item::Output(_)))
            && (items.len() == 1 || !starts_with_block(&items[items.len() - 1]));
        if items.len() == 1 || (plain_ok && self.rng.chance(50)) {
            if items.len() == 1 && self.rng.chance(20) {
                // A branch point opened and closed at once.
                self.line(Op::Mps, &[]);
                self.line(Op::Mpp, &[]);
            }
            for (k, item) in items.iter().enumerate() {
                self.item(item, k > 0);
            }
            return;
        }
        for (k, item) in items.iter().enumerate() {
            let op = if k == 0 {
                Op::Mps
            } else if k + 1 == items.len() {
                Op::Mpp
            } else {
                Op::Mrd
            };
            self.line(op, &[]);
            self.item(item, false);
        }
    }
}

/// Whether an AND term's emission starts with a block (an OR needs LD … ANB).
fn first_is_block(e: &Expr) -> bool {
    match e {
        Expr::Contact { .. } => false,
        Expr::Or(_) => true,
        Expr::And(terms) => first_is_block(&terms[0]),
    }
}

/// A random program of both levels and up to three subprograms, written in mixed styles.
fn random_list(rng: SplitMix64) -> (String, SplitMix64) {
    let mut g = Gen {
        rng,
        timers: 0,
        lines: Vec::new(),
    };
    let subs = g.rng.below(4) as u16;
    let mut text = String::new();
    for block in 0..2 + subs {
        text.push_str(&match block {
            0 => "LEVEL1\n".to_string(),
            1 => "LEVEL2\n".to_string(),
            s => format!("SUB P{:04}\n", s - 1),
        });
        // Subprograms call nothing, so no call can recurse.
        let callable = if block < 2 { subs } else { 0 };
        for _ in 0..1 + g.rng.below(4) {
            text.push_str("NETWORK\n");
            for _ in 0..1 + g.rng.below(2) {
                let e = g.expr(2);
                let node = g.tree(2, callable);
                g.load(&e);
                g.node(&node);
            }
            for l in g.lines.drain(..) {
                text.push_str(&l);
                text.push('\n');
            }
        }
    }
    text.push_str("END\n");
    (text, g.rng)
}

/// The instruction lines of a list, without directives and comments.
fn instructions(text: &str) -> Vec<String> {
    let mut sink = Sink::default();
    let program = il::parse(text, &mut sink);
    program
        .instrs()
        .map(|(_, _, i)| il::instr_text(i.op, &i.operands))
        .collect()
}

/// A PLC running the list as parsed and checked, with no drawing in between.
fn list_vm(text: &str) -> Vm {
    let mut sink = Sink::default();
    let program = il::parse(text, &mut sink);
    let compiled = compile_program(program, &Project::default(), sink);
    assert_eq!(compiled.errors(), 0, "{:?}\n{text}", compiled.diagnostics);
    Vm::from_program(&compiled.program, Project::default().profile()).unwrap()
}

#[test]
fn import_then_export_keeps_every_list_and_every_list_runs_alike() {
    let mut rng = SplitMix64::new(13);
    let mut kept = 0;
    for program in 0..200 {
        let (text, next) = random_list(rng);
        rng = next;
        let imported = il::import(&text);
        let project = imported
            .project
            .unwrap_or_else(|| panic!("program {program} is drawable:\n{text}"));
        let exported = il::print(&compile(&project).program);
        assert_eq!(
            instructions(&exported),
            instructions(&text),
            "program {program}:\n{text}"
        );
        kept += project
            .ladder
            .blocks
            .iter()
            .flat_map(|b| &b.networks)
            .filter(|n| !n.il.is_empty())
            .count();
        // The steps the project counts are the list's.
        assert_eq!(
            compile(&project).steps,
            imported.compiled.steps,
            "program {program}"
        );
        for division in [1, 2, 4] {
            let mut written = list_vm(&text);
            let mut again = list_vm(&exported);
            let mut drawn = Vm::new(&project).unwrap();
            for vm in [&mut written, &mut again, &mut drawn] {
                vm.set_division(division);
            }
            let mut inputs = rng.clone();
            for tick in 0..24 {
                for n in 0..2u16 {
                    let byte = inputs.below(256) as i64;
                    for vm in [&mut written, &mut again, &mut drawn] {
                        vm.write(Address::byte(Area::X, n), 1, byte);
                    }
                }
                for vm in [&mut written, &mut again, &mut drawn] {
                    vm.tick(&mut NoCnc);
                }
                assert!(
                    written.image() == again.image() && written.image() == drawn.image(),
                    "program {program}, division {division}, tick {tick}:\n{text}"
                );
            }
        }
    }
    // The generator does write lists the editor would write differently.
    assert!(kept > 100, "only {kept} networks kept their written form");
}

/// The list of the report: the MPS/MPP pair makes the first network 5 steps, so with division
/// 2 the first slice ends after it and R0000.3 is written in the second tick only.
const SLICED: &str = "LEVEL2
NETWORK
LD X0000.0
MPS
OUT R0000.0
MPP
OUT R0000.1
NETWORK
LD X0000.0
OUT R0000.2
NETWORK
LD X0000.0
OUT R0000.3
";

#[test]
fn an_imported_list_is_sliced_by_its_own_steps() {
    let project = il::import(SLICED).project.unwrap();
    let mut vm = Vm::new(&project).unwrap();
    vm.set_division(2);
    vm.write(Address::byte(Area::X, 0), 1, 1);
    vm.tick(&mut NoCnc);
    assert_eq!(vm.read(Address::byte(Area::R, 0), 1), 3);
    vm.tick(&mut NoCnc);
    assert_eq!(vm.read(Address::byte(Area::R, 0), 1), 15);
    assert_eq!(compile(&project).steps.level2, 9);
}

#[test]
fn an_edit_makes_the_drawing_the_truth_and_undoing_it_restores_the_list() {
    let project = il::import(SLICED).project.unwrap();
    let net = &project.ladder.blocks[1].networks[0];
    assert_eq!(
        net.il,
        ["LD   X0000.0", "MPS", "OUT  R0000.0", "MPP", "OUT  R0000.1"]
    );
    // The other networks are written as the editor writes them: nothing to keep.
    assert!(project.ladder.blocks[1].networks[1].il.is_empty());

    let mut edited = project.clone();
    let row = edited.ladder.blocks[1].networks[0]
        .rows
        .iter_mut()
        .find(|r| r.cells.iter().any(|c| matches!(c, Cell::Coil { .. })))
        .unwrap();
    let coil = row
        .cells
        .iter_mut()
        .find(|c| matches!(c, Cell::Coil { .. }))
        .unwrap();
    let Cell::Coil { operand, .. } = coil else {
        unreachable!()
    };
    *operand = Operand::parse("R0001.0").unwrap();
    let first = |p: &Project| {
        let c = compile(p);
        let net = &c.program.blocks[1].networks[0];
        net.instrs
            .iter()
            .map(|i| il::instr_text(i.op, &i.operands))
            .collect::<Vec<_>>()
    };
    assert_eq!(
        first(&edited),
        ["LD   X0000.0", "OUT  R0001.0", "OUT  R0000.1"]
    );
    assert_eq!(compile(&edited).steps.level2, 7);
    assert_eq!(
        first(&project),
        ["LD   X0000.0", "MPS", "OUT  R0000.0", "MPP", "OUT  R0000.1"]
    );
}

#[test]
fn diagnostics_of_a_kept_list_point_at_the_drawn_cells() {
    let project = il::import("LEVEL2\nNETWORK\nLD X0000.0\nMPS\nOUT R0000.0\nMPP\nOUT NOWHERE\n")
        .project
        .unwrap();
    let c = compile(&project);
    let d = c
        .diagnostics
        .iter()
        .find(|d| {
            matches!(&d.finding, Finding::Check(CheckFinding::UndefinedSymbol { name })
                if name == "NOWHERE")
        })
        .unwrap();
    assert!(
        matches!(d.location.origin, Origin::Cell { .. }),
        "{:?}",
        d.location
    );
}
