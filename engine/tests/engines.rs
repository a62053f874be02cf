//! The native scan engine against the interpreter, tick by tick, on seeded random programs
//! that use every function instruction of the catalogue, under random inputs, with level 2
//! divided by 1, 2 and 4: after every tick the memory image, the steps and any halt must be
//! the same.
//!
//! Each function instruction gets random operands drawn from its catalogue entry (areas,
//! ranges, sizes, CODB's table); a candidate is kept only when a one-rung program with it
//! compiles without errors, so the programs are valid whatever the draw.

use ladder_engine::address::{Address, Area};
use ladder_engine::catalog::{CATALOG, InstrClass, InstrSpec, OperandKind, OperandSpec};
use ladder_engine::compiler::compile;
use ladder_engine::generate::SplitMix64;
use ladder_engine::il;
use ladder_engine::model::Project;
use ladder_engine::profile::Profile;
use ladder_engine::vm::cnc::{AxisStatus, FakeCnc};
use ladder_engine::vm::{Engine, Vm};
use std::collections::BTreeSet;

/// The areas' first addresses a draw uses: small, so instructions meet each other's data.
fn span(area: Area) -> u16 {
    match area {
        Area::X | Area::Y | Area::G | Area::A | Area::K => 8,
        Area::F => 16,
        Area::R => 24,
        Area::D => 48,
        _ => 8,
    }
}

fn address(rng: &mut SplitMix64, spec: &OperandSpec, profile: &Profile, bit: bool) -> String {
    let areas: Vec<Area> = spec
        .areas
        .iter()
        .filter(|a| !matches!(a, Area::L | Area::P))
        .collect();
    let area = areas[rng.below(areas.len() as u64) as usize];
    let (lo, hi) = profile.range(area);
    let top = hi
        .min(lo + span(area))
        .saturating_sub(if bit { 0 } else { 4 });
    let number = lo + rng.below(u64::from(top.saturating_sub(lo)) + 1) as u16;
    let bit = bit.then(|| rng.below(8) as u8);
    Address { area, number, bit }.to_string()
}

fn constant(rng: &mut SplitMix64, spec: &OperandSpec) -> i64 {
    let (min, max) = (spec.min, spec.max);
    let pick = match rng.below(4) {
        0 => min,
        1 => max,
        2 => 0,
        _ => min + rng.below((max - min).min(200) as u64 + 1) as i64,
    };
    pick.clamp(min, max)
}

fn operand(rng: &mut SplitMix64, spec: &OperandSpec, profile: &Profile, n: &mut u16) -> String {
    match spec.kind {
        OperandKind::Size => [1, 2, 4]
            .into_iter()
            .filter(|s| (spec.min..=spec.max).contains(s))
            .nth(rng.below(3) as usize)
            .unwrap_or(spec.min.max(1))
            .to_string(),
        OperandKind::Const => constant(rng, spec).to_string(),
        OperandKind::Digits { max_digit } => (0..4)
            .map(|_| char::from(b'0' + rng.below(u64::from(max_digit) + 1) as u8))
            .collect(),
        OperandKind::Bit | OperandKind::BitOrByte => address(rng, spec, profile, true),
        OperandKind::Byte => address(rng, spec, profile, false),
        OperandKind::ConstOrByte => {
            if rng.chance(50) {
                constant(rng, spec).to_string()
            } else {
                address(rng, spec, profile, false)
            }
        }
        OperandKind::RealOrD => {
            if rng.chance(50) {
                format!("{}.5", rng.below(100))
            } else {
                address(rng, spec, profile, false)
            }
        }
        OperandKind::Timer | OperandKind::Counter => {
            *n += 1;
            let letter = if spec.kind == OperandKind::Timer {
                'T'
            } else {
                'C'
            };
            format!("{letter}{:04}", *n)
        }
        OperandKind::Label | OperandKind::Subprogram => "0".into(),
    }
}

/// One instruction of `spec` with random operands, as IL.
fn instruction(rng: &mut SplitMix64, spec: &InstrSpec, profile: &Profile, n: &mut u16) -> String {
    let mut words = vec![spec.name.to_string()];
    let mut values = Vec::new();
    for o in spec.operands {
        let text = operand(rng, o, profile, n);
        values.push(text.parse::<i64>().ok());
        words.push(text);
    }
    if let Some(table) = spec.table {
        let count = values[table.count_from].unwrap_or(1).max(1);
        for _ in 0..count {
            words.push(constant(rng, table.entry).to_string());
        }
    }
    words.join(" ")
}

/// A rung: one or two contacts, then the instruction.
fn rung(rng: &mut SplitMix64, spec: &InstrSpec, text: &str) -> String {
    let mut out = String::from("NETWORK\n");
    if spec.needs_act() {
        out += &format!("LD X{:04}.{}\n", rng.below(8), rng.below(8));
        if rng.chance(50) {
            out += &format!("ANI R{:04}.{}\n", rng.below(24), rng.below(8));
        }
    }
    out + text + "\n"
}

fn compiles(text: &str) -> Option<Project> {
    let project = il::import(text).project?;
    (compile(&project).errors() == 0).then_some(project)
}

/// Random valid rungs for each function instruction, and the mnemonics that got one.
fn function_rungs(
    rng: &mut SplitMix64,
    profile: &Profile,
) -> (Vec<String>, BTreeSet<&'static str>) {
    let mut rungs = Vec::new();
    let mut covered = BTreeSet::new();
    let mut numbers = 0u16;
    for spec in CATALOG.iter().filter(|s| s.class == InstrClass::Function) {
        if matches!(spec.name, "JMPB" | "LBL" | "CALL" | "CALLU") {
            continue;
        }
        for _ in 0..40 {
            let text = instruction(rng, spec, profile, &mut numbers);
            let r = rung(rng, spec, &text);
            if compiles(&format!("LEVEL1\nLEVEL2\n{r}END\n")).is_some() {
                rungs.push(r);
                covered.insert(spec.name);
                break;
            }
        }
    }
    (rungs, covered)
}

/// Bit-logic rungs of every basic form, blocks and branches included.
fn bit_rung(rng: &mut SplitMix64) -> String {
    let mut c = || format!("R{:04}.{}", rng.below(24), rng.below(8));
    let (a, b, d, e, f, o1, o2) = (c(), c(), c(), c(), c(), c(), c());
    [
        format!("NETWORK\nLD {a}\nAND {b}\nLDI {d}\nOR {e}\nANB\nORI {f}\nOUT {o1}\n"),
        format!("NETWORK\nLDI {a}\nMPS\nAND {b}\nOUT {o1}\nMPP\nANI {d}\nSET {o2}\n"),
        format!("NETWORK\nLD {a}\nLD {b}\nAND {d}\nORB\nRST {o1}\nOUTN {o2}\n"),
    ][rng.below(3) as usize]
        .clone()
}

/// A program: bit logic in level 1 with a conditional call; level 2 with the function rungs
/// in random order, a forward jump over some, a backward loop that runs once or twice, and
/// calls; three subprograms (one calls another, one is called from both levels) holding a
/// few of the function rungs.
fn program(rng: &mut SplitMix64, functions: &[String]) -> String {
    let mut order: Vec<usize> = (0..functions.len()).collect();
    for i in (1..order.len()).rev() {
        order.swap(i, rng.below(i as u64 + 1) as usize);
    }
    let mut rungs = order.into_iter().map(|i| functions[i].clone());
    let mut text = String::from("LEVEL1\n");
    for _ in 0..3 {
        text += &bit_rung(rng);
    }
    text += "NETWORK\nLD X0007.1\nCALL P0001\nLEVEL2\nNETWORK\nCALLU P0002\n";
    let level2: Vec<String> = rungs
        .by_ref()
        .take(functions.len().saturating_sub(6))
        .collect();
    let (jump, land) = (
        rng.below(level2.len() as u64 / 2 + 1) as usize,
        level2.len() / 2 + 1,
    );
    for (k, r) in level2.iter().enumerate() {
        if k == jump {
            text += "NETWORK\nLD X0006.3\nJMPB L0002\n";
        }
        if k == land {
            text += "NETWORK\nLBL L0002\n";
        }
        if rng.chance(30) {
            text += &bit_rung(rng);
        }
        text += r;
    }
    if land >= level2.len() {
        text += "NETWORK\nLBL L0002\n";
    }
    text += "NETWORK\nLBL L0001\nNETWORK\nLDI R0030.0\nOUT R0030.0\n";
    text += "NETWORK\nLD R0030.0\nAND X0001.0\nJMPB L0001\n";
    text += "NETWORK\nLD X0005.5\nCALL P0001\n";
    for (p, name) in [(1, "ONE"), (2, "TWO"), (3, "THREE")] {
        text += &format!("SUB P{p:04} \"{name}\"\n");
        text += &bit_rung(rng);
        for r in rungs.by_ref().take(2) {
            text += &r;
        }
        if p == 2 {
            text += "NETWORK\nLD X0004.4\nCALL P0003\n";
        }
    }
    text + "END\n"
}

fn cnc() -> FakeCnc {
    FakeCnc {
        positions: vec![1000, -2500, 42],
        axes: [AxisStatus {
            ended: true,
            error: false,
        }; 4],
        low_speed: vec![17],
        window_data: vec![7, 8, 9],
        ..FakeCnc::default()
    }
}

#[test]
fn the_native_engine_matches_the_interpreter_tick_by_tick_with_every_function_instruction() {
    if !ladder_engine::vm::native::AVAILABLE {
        return;
    }
    let profile = Project::default().profile();
    let mut all = BTreeSet::new();
    let programs = if std::env::var_os("LADDER_LONG").is_some() {
        40
    } else {
        8
    };
    for seed in 0..programs {
        let mut rng = SplitMix64::new(seed);
        let (functions, covered) = function_rungs(&mut rng, profile);
        all.extend(covered);
        // Every program jumps, loops and calls (see `program`).
        all.extend(["JMPB", "LBL", "CALL", "CALLU"]);
        let text = program(&mut rng, &functions);
        let project = compiles(&text).unwrap_or_else(|| panic!("seed {seed}: {text}"));
        for division in [1, 2, 4] {
            // The interpreter and native code, and both again with some networks watched
            // (the native engine then hands those to the interpreter, which records them).
            // On even seeds only networks of the levels themselves, which native code hands
            // over one by one; on odd seeds subprograms' too, which makes the level interpreted.
            let watched: Vec<usize> = {
                let vm = Vm::new(&project).expect("compiles");
                let networks = &vm.code().networks;
                (0..networks.len())
                    .filter(|&n| seed % 2 == 1 || networks[n].block < 2)
                    .filter(|_| rng.chance(25))
                    .collect()
            };
            let mut vms = [
                (Engine::Interpreter, false),
                (Engine::Native, false),
                (Engine::Interpreter, true),
                (Engine::Native, true),
            ]
            .map(|(engine, watching)| {
                let mut vm = Vm::new(&project).expect("compiles");
                assert_eq!(vm.set_engine(engine), engine);
                vm.set_division(division);
                if watching {
                    for &n in &watched {
                        vm.watch(n, true);
                    }
                }
                (vm, cnc())
            });
            for tick in 0..60 {
                let x = rng.next_u64().to_le_bytes();
                let r = rng.next_u64().to_le_bytes();
                for (vm, cnc) in &mut vms {
                    for (i, (xb, rb)) in x.iter().zip(&r).enumerate() {
                        let at = |area, n| Address {
                            area,
                            number: n,
                            bit: None,
                        };
                        vm.write(at(Area::X, i as u16), 1, i64::from(*xb));
                        if tick % 7 == 0 {
                            vm.write(at(Area::R, 16 + i as u16), 1, i64::from(*rb));
                        }
                    }
                    vm.tick(cnc);
                }
                let at = format!("seed {seed}, division {division}, tick {tick}");
                let a = &vms[0].0;
                for (b, _) in &vms[1..] {
                    if let Some(i) = (0..a.image().len()).find(|&i| a.image()[i] != b.image()[i]) {
                        panic!(
                            "{at}, {:?}: memory byte {i}: interpreter {}, other {}\n{text}",
                            b.engine(),
                            a.image()[i],
                            b.image()[i]
                        );
                    }
                    assert_eq!(a.executed_steps(), b.executed_steps(), "{at}");
                    assert_eq!(a.halt(), b.halt(), "{at}");
                }
                // What the monitor sees of the watched networks.
                assert_eq!(
                    vms[2].0.trace(),
                    vms[3].0.trace(),
                    "{at}: watched {watched:?}"
                );
            }
        }
    }
    let missing: Vec<&str> = CATALOG
        .iter()
        .filter(|s| s.class == InstrClass::Function && !all.contains(s.name))
        .map(|s| s.name)
        .collect();
    assert!(missing.is_empty(), "never drawn valid: {missing:?}");
}

#[test]
fn both_engines_stop_a_runaway_loop_at_the_same_word_with_the_same_steps() {
    if !ladder_engine::vm::native::AVAILABLE {
        return;
    }
    for level in ["LEVEL1", "LEVEL2"] {
        let body = "NETWORK\nLBL L0001\nNETWORK\nLD R0001.0\nOUTN R0001.0\nNETWORK\nLD X0001.0\nJMPB L0001\n";
        let text = if level == "LEVEL1" {
            format!("LEVEL1\n{body}LEVEL2\nEND\n")
        } else {
            format!("LEVEL1\nLEVEL2\n{body}END\n")
        };
        let project = compiles(&text).expect("compiles");
        for division in [1, 2, 4] {
            let vms = [Engine::Interpreter, Engine::Native].map(|engine| {
                let mut vm = Vm::new(&project).expect("compiles");
                vm.set_engine(engine);
                vm.set_division(division);
                vm.write(Address::parse("X1.0").unwrap(), 1, 1);
                for _ in 0..3 {
                    vm.tick(&mut FakeCnc::default());
                }
                vm
            });
            let [a, b] = &vms;
            // Divided, level 2 suspends at each network of the loop and the watchdog counts
            // its whole cycle, so three ticks do not reach it.
            assert_eq!(
                a.halt().is_some(),
                division == 1 || level == "LEVEL1",
                "{level}, division {division}"
            );
            assert_eq!(a.halt(), b.halt(), "{level}, division {division}");
            assert_eq!(a.image(), b.image(), "{level}, division {division}");
            assert_eq!(a.executed_steps(), b.executed_steps());
        }
    }
}
