//! Seeded fuzz loops over the parsers: no input may panic them.

use ladder_engine::address::{Address, Area};
use ladder_engine::compiler::compile;
use ladder_engine::generate::SplitMix64;
use ladder_engine::sim::Script;
use ladder_engine::vm::Vm;
use ladder_engine::vm::cnc::NoCnc;
use ladder_engine::{Profile, ProfileId, il};

const ALPHABET: &[char] = &[
    'X', 'Y', 'F', 'G', 'R', 'A', 'K', 'T', 'C', 'D', 'L', 'P', 'x', 'd', 't', 'c', '0', '1', '2',
    '7', '8', '9', '.', ' ', '-', '+', '_', '中', '\t', 'é',
];

#[test]
fn the_address_parser_survives_100_000_random_inputs() {
    let mut rng = SplitMix64::new(1);
    let profile = Profile::get(ProfileId::Gsk988ta);
    let mut ok = 0;
    for _ in 0..100_000 {
        let len = rng.below(12) as usize;
        let s: String = (0..len)
            .map(|_| ALPHABET[rng.below(ALPHABET.len() as u64) as usize])
            .collect();
        if let Ok(a) = Address::parse(&s) {
            ok += 1;
            // Whatever parses has a canonical text that parses to the same address.
            assert_eq!(Address::parse(&a.to_string()), Ok(a), "{s:?}");
            let _ = a.check_span(profile, 1 + rng.below(8) as u32);
        }
    }
    assert!(
        ok > 1000,
        "the generator should hit valid addresses too ({ok})"
    );
}

fn corpus_lines() -> Vec<String> {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/../tests/il/valid");
    let mut lines = Vec::new();
    let mut paths: Vec<_> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .collect();
    paths.sort();
    for p in paths {
        lines.extend(
            std::fs::read_to_string(p)
                .unwrap()
                .lines()
                .map(String::from),
        );
    }
    lines
}

fn mutate(line: &str, rng: &mut SplitMix64) -> String {
    let mut chars: Vec<char> = line.chars().collect();
    match rng.below(6) {
        0 if !chars.is_empty() => {
            let i = rng.below(chars.len() as u64) as usize;
            chars.remove(i);
        }
        1 => {
            let i = rng.below(chars.len() as u64 + 1) as usize;
            chars.insert(i, ALPHABET[rng.below(ALPHABET.len() as u64) as usize]);
        }
        2 if !chars.is_empty() => {
            let i = rng.below(chars.len() as u64) as usize;
            chars[i] = ['"', ';', '9', ' ', 'Z', '\\'][rng.below(6) as usize];
        }
        _ => {}
    }
    chars.into_iter().collect()
}

#[test]
fn the_il_parser_survives_100_000_mutated_programs() {
    let lines = corpus_lines();
    let mut rng = SplitMix64::new(2);
    let mut drawn = 0;
    for _ in 0..100_000 {
        let n = 1 + rng.below(10) as usize;
        let start = rng.below(lines.len() as u64) as usize;
        let mut text = String::new();
        for k in 0..n {
            let line = if rng.chance(30) {
                &lines[rng.below(lines.len() as u64) as usize]
            } else {
                &lines[(start + k) % lines.len()]
            };
            let line = if rng.chance(40) {
                mutate(line, &mut rng)
            } else {
                line.clone()
            };
            text.push_str(&line);
            text.push('\n');
        }
        let imported = il::import(&text);
        if let Some(p) = imported.project {
            drawn += 1;
            let c = compile(&p);
            let _ = il::print(&c.program);
            // Whatever compiles also runs: random operands through every instruction.
            if c.errors() == 0 {
                let mut vm = Vm::new(&p).expect("an error-free program runs");
                for k in 0..3 {
                    vm.write(Address::byte(Area::X, k), 1, rng.below(256) as i64);
                    vm.write(Address::byte(Area::R, k), 1, rng.below(256) as i64);
                    vm.tick(&mut NoCnc);
                }
            }
        }
    }
    assert!(drawn > 5_000, "many snippets should still draw ({drawn})");
}

#[test]
fn the_script_parser_survives_100_000_mutated_scripts() {
    let base = [
        "set X0002.1 1",
        "set R0010:2 -300",
        "setf D0004 1.5",
        "force Y0.1 1",
        "unforce Y0.1",
        "scan",
        "scan 14",
        "run 250ms",
        "run 2s",
        "expect T0000 96",
        "expect R0020:4 -1",
        "expectf D0004 1.5 0.01",
        "print R0010:2",
        "watch Y0003.7",
        "division 2",
        "power-cycle",
        "# comment",
        "; comment",
        "",
    ];
    let profile = Profile::get(ProfileId::Gsk988ta);
    let mut rng = SplitMix64::new(3);
    let mut ok = 0;
    for _ in 0..100_000 {
        let n = 1 + rng.below(6) as usize;
        let mut text = String::new();
        for _ in 0..n {
            let line = base[rng.below(base.len() as u64) as usize];
            let line = if rng.chance(50) {
                mutate(line, &mut rng)
            } else {
                line.to_string()
            };
            text.push_str(&line);
            text.push('\n');
        }
        if Script::parse(&text, profile).is_ok() {
            ok += 1;
        }
    }
    assert!(ok > 10_000, "many scripts should still parse ({ok})");
}
