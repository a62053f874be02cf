//! The VM against a plain reference evaluator, on seeded random programs: after every tick,
//! every output and relay must agree.
//!
//! The reference walks the rung trees the ladder reads as (`compiler::lower`) with a map of
//! bits: no lowering, no words, no stacks. It implements the bit logic, SET/RST, DIFU/DIFD,
//! ALT and TMRB from docs/plc.md directly.
//!
//! A unit test of the engine rather than an integration test: it builds and reads back rung
//! trees with the compiler's private phases (`rung`, `layout`, `lower`).

use crate::Op;
use crate::address::{Address, Area};
use crate::compiler::layout::{layout, width_needed};
use crate::compiler::lower::lower_network;
use crate::compiler::rung::{Expr, Item, Node, Output, Rung, and, or};
use crate::compiler::{Origin, Sink};
use crate::generate::SplitMix64;
use crate::model::{DEFAULT_WIDTH, Ladder, Network, NetworkId, Operand, Project};
use crate::vm::Vm;
use crate::vm::cnc::NoCnc;
use std::collections::HashMap;

/// Bits and 4-byte words of the reference machine.
#[derive(Default)]
struct Reference {
    bits: HashMap<Address, bool>,
    words: HashMap<Address, i64>,
    /// Per output instance (network, rung, path): previous ACT and last execution time.
    edges: HashMap<(usize, usize, usize), (bool, u64)>,
}

impl Reference {
    fn bit(&self, o: &Operand) -> bool {
        match o {
            Operand::Addr(a) => *self.bits.get(a).unwrap_or(&false),
            _ => false,
        }
    }
    fn set(&mut self, o: &Operand, v: bool) {
        if let Operand::Addr(a) = o {
            self.bits.insert(*a, v);
        }
    }

    fn eval(&self, e: &Expr) -> bool {
        match e {
            Expr::Contact {
                negated, operand, ..
            } => self.bit(operand) != *negated,
            Expr::And(v) => v.iter().all(|t| self.eval(t)),
            Expr::Or(v) => v.iter().any(|t| self.eval(t)),
        }
    }

    fn output(&mut self, o: &Output, act: bool, key: (usize, usize, usize), now: u64) {
        let (prev, last) = *self.edges.get(&key).unwrap_or(&(false, 0));
        match o.op {
            Op::Out => self.set(&o.operands[0], act),
            Op::Outn => self.set(&o.operands[0], !act),
            Op::Set if act => self.set(&o.operands[0], true),
            Op::Rst if act => self.set(&o.operands[0], false),
            Op::Difu => self.set(&o.operands[0], act && !prev),
            Op::Difd => self.set(&o.operands[0], !act && prev),
            Op::Alt if act && !prev => {
                let v = self.bit(&o.operands[0]);
                self.set(&o.operands[0], !v);
            }
            Op::Tmrb => {
                let Operand::Addr(t) = o.operands[0] else {
                    return;
                };
                let Operand::Int(pt) = o.operands[1] else {
                    return;
                };
                let mut value = *self.words.get(&t).unwrap_or(&0);
                if act {
                    if !prev {
                        value = 0;
                    } else if value < pt {
                        value = (value + (now - last) as i64).min(pt);
                    }
                    self.set(&o.operands[2], value >= pt);
                } else {
                    value = 0;
                    self.set(&o.operands[2], false);
                }
                self.words.insert(t, value);
            }
            _ => {}
        }
        self.edges.insert(key, (act, now));
    }

    fn node(&mut self, n: &Node, power: bool, net: usize, rung: usize, path: &mut usize, now: u64) {
        for item in &n.items {
            match item {
                Item::Output(o) => {
                    *path += 1;
                    self.output(o, power, (net, rung, *path), now);
                }
                Item::Branch(e, child) => {
                    let p = power && self.eval(e);
                    self.node(child, p, net, rung, path, now);
                }
            }
        }
    }

    fn scan(&mut self, rungs: &[Vec<Rung>], now: u64) {
        for (net, rs) in rungs.iter().enumerate() {
            for (k, r) in rs.iter().enumerate() {
                if let Rung::Powered(e, n) = r {
                    let p = self.eval(e);
                    let mut path = 0;
                    self.node(n, p, net, k, &mut path, now);
                }
            }
        }
    }
}

struct Gen(SplitMix64);

impl Gen {
    fn bit(&mut self) -> Operand {
        // Inputs X0–X1 and relays R0–R3 are read; R0–R3 and Y0–Y1 are written, so later rungs
        // read what earlier ones wrote.
        let r = &mut self.0;
        let (area, n) = match r.below(3) {
            0 => (Area::X, r.below(2) as u16),
            1 => (Area::Y, r.below(2) as u16),
            _ => (Area::R, r.below(4) as u16),
        };
        Operand::Addr(Address::bit(area, n, r.below(8) as u8))
    }
    fn out_bit(&mut self) -> Operand {
        let r = &mut self.0;
        let (area, n) = if r.chance(50) {
            (Area::Y, r.below(2) as u16)
        } else {
            (Area::R, r.below(4) as u16)
        };
        Operand::Addr(Address::bit(area, n, r.below(8) as u8))
    }
    fn expr(&mut self, depth: u32) -> Expr {
        if depth == 0 || self.0.chance(40) {
            return Expr::Contact {
                negated: self.0.chance(30),
                operand: self.bit(),
                origin: Origin::None,
            };
        }
        let n = 2 + self.0.below(2);
        let terms: Vec<Expr> = (0..n).map(|_| self.expr(depth - 1)).collect();
        if self.0.chance(50) {
            terms.into_iter().reduce(and).unwrap()
        } else {
            terms.into_iter().reduce(or).unwrap()
        }
    }
    fn output(&mut self, timers: &mut u16) -> Output {
        let kind = self.0.below(10);
        let (op, operands) = match kind {
            0 => (Op::Set, vec![self.out_bit()]),
            1 => (Op::Rst, vec![self.out_bit()]),
            2 => (Op::Difu, vec![self.out_bit()]),
            3 => (Op::Difd, vec![self.out_bit()]),
            4 => (Op::Alt, vec![self.out_bit()]),
            5 if *timers < 200 => {
                *timers += 1;
                let pt = 8 * self.0.below(6) as i64;
                (
                    Op::Tmrb,
                    vec![
                        Operand::Addr(Address::byte(Area::T, *timers - 1)),
                        Operand::Int(pt),
                        self.out_bit(),
                    ],
                )
            }
            6 => (Op::Outn, vec![self.out_bit()]),
            _ => (Op::Out, vec![self.out_bit()]),
        };
        Output {
            op,
            operands,
            origin: Origin::None,
        }
    }
    fn node(&mut self, depth: u32, timers: &mut u16) -> Node {
        let n = 1 + self.0.below(3);
        let items = (0..n)
            .map(|_| {
                if depth > 0 && self.0.chance(35) {
                    Item::Branch(self.expr(1), self.node(depth - 1, timers))
                } else {
                    Item::Output(self.output(timers))
                }
            })
            .collect();
        Node { items }
    }
}

#[test]
fn the_vm_agrees_with_the_reference_on_1000_random_programs() {
    let mut rng = Gen(SplitMix64::new(2024));
    let mut ticks_checked = 0;
    for program in 0..1000 {
        // A few networks in level 2 (level 1 empty: X then reads the same in both).
        let mut timers = 0u16;
        let networks: Vec<Vec<Rung>> = (0..1 + rng.0.below(4))
            .map(|_| {
                (0..1 + rng.0.below(2))
                    .map(|_| Rung::Powered(rng.expr(2), rng.node(2, &mut timers)))
                    .collect()
            })
            .collect();
        let width = networks
            .iter()
            .map(|r| width_needed(r))
            .max()
            .unwrap_or(1)
            .max(DEFAULT_WIDTH);
        let mut ladder = Ladder::new(width);
        for (i, rungs) in networks.iter().enumerate() {
            let mut n = Network::new(NetworkId(i as u64 + 1), width);
            n.rows = layout(rungs, width);
            ladder.blocks[1].networks.push(n);
        }
        let project = Project {
            ladder,
            ..Project::default()
        };
        // The reference reads the drawing back the way the compiler does.
        let mut sink = Sink::default();
        let read_back: Vec<Vec<Rung>> = project.ladder.blocks[1]
            .networks
            .iter()
            .map(|n| lower_network(n, width, &mut sink))
            .collect();
        assert!(
            sink.diagnostics.is_empty(),
            "program {program}: {:?}",
            sink.diagnostics
        );
        let mut vm = Vm::new(&project).unwrap_or_else(|e| panic!("program {program}: {e}"));
        let mut reference = Reference::default();
        for tick in 0..40u64 {
            // New inputs every tick.
            for n in 0..2u16 {
                let byte = rng.0.below(256) as i64;
                vm.write(Address::byte(Area::X, n), 1, byte);
                for b in 0..8 {
                    reference
                        .bits
                        .insert(Address::bit(Area::X, n, b), byte >> b & 1 == 1);
                }
            }
            vm.tick(&mut NoCnc);
            reference.scan(&read_back, tick * 8);
            for (area, count) in [(Area::Y, 2u16), (Area::R, 4)] {
                for n in 0..count {
                    for b in 0..8 {
                        let a = Address::bit(area, n, b);
                        let want = *reference.bits.get(&a).unwrap_or(&false);
                        assert_eq!(
                            vm.read_bit(a),
                            want,
                            "program {program}, tick {tick}, {a}\n{}",
                            crate::il::print(&crate::compiler::compile(&project).program)
                        );
                    }
                }
            }
            for t in 0..timers {
                let a = Address::byte(Area::T, t);
                assert_eq!(
                    vm.read(a, 4),
                    *reference.words.get(&a).unwrap_or(&0),
                    "program {program}, tick {tick}, {a}"
                );
            }
            ticks_checked += 1;
        }
    }
    assert_eq!(ticks_checked, 40_000);
}
