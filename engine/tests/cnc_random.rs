//! Seeded random runs of the simulated CNC (docs/cnc.md, "Determinism"): random G signals,
//! random programs (valid and invalid), random commands and window calls for 100 000
//! exchanges per seed. Nothing may panic, no F bit outside the CNC's own may ever change,
//! and the same seed gives the same run.

use crate::common::{Rig, Rng};
use ladder_engine::ProfileId;
use ladder_engine::cnc::command::CncCommand;
use ladder_engine::cnc::fsignals::OWNED_MASK;
use ladder_engine::model::tables::MessageTable;
use ladder_engine::vm::cnc::Cnc;

/// G bytes a CNC reads, so random flips there matter.
const G_BYTES: [usize; 40] = [
    4, 5, 6, 7, 8, 10, 11, 12, 14, 18, 19, 28, 29, 30, 32, 33, 38, 43, 44, 46, 100, 102, 114, 116,
    130, 136, 140, 141, 142, 144, 150, 151, 160, 170, 196, 201, 214, 145, 152, 154,
];

fn program(rng: &mut Rng) -> String {
    let mut text = String::new();
    if rng.chance(700) {
        text.push_str("O0001;");
    }
    if rng.chance(400) {
        // A valid opening, so some programs reach their strobes before a random error.
        text.push_str("G50 S2000;M03 S500 T0101;");
    }
    for _ in 0..rng.below(12) + 1 {
        if rng.chance(100) {
            text.push('/');
        }
        if rng.chance(600) {
            text.push_str(&format!("N{} ", rng.below(120_000)));
        }
        for _ in 0..rng.below(5) {
            let letter = rng.pick(&[
                "G", "X", "Z", "Y", "U", "W", "V", "F", "S", "T", "M", "P", "Q", "#", "G", "M",
                "I", "K", "R", "D", "L",
            ]);
            let number = match letter {
                "G" if rng.chance(250) => rng
                    .pick(&[
                        "3", "10", "20", "21", "32", "50", "53", "70", "71", "72", "73", "74",
                        "75", "76", "80", "83", "84", "85", "87", "88", "89", "90", "92", "94",
                        "96", "40", "41", "42",
                    ])
                    .to_string(),
                "G" => rng
                    .pick(&[
                        "0", "1", "4", "28", "54", "55", "98", "99", "2", "13.1", "97", "7",
                    ])
                    .to_string(),
                "M" => rng
                    .pick(&["3", "5", "8", "0", "1", "30", "2", "98", "99", "123456789"])
                    .to_string(),
                "P" => rng
                    .pick(&[
                        "1", "2", "20001", "100", "9", "0", "10", "1.5", "10001", "010060",
                    ])
                    .to_string(),
                "L" => rng.pick(&["1", "2", "10", "11", "3"]).to_string(),
                _ => {
                    let v = rng.below(40_000) as f64 / 100.0 - 100.0;
                    if rng.chance(100) {
                        "..".to_string()
                    } else {
                        format!("{v}")
                    }
                }
            };
            text.push_str(letter);
            text.push_str(&number);
        }
        text.push(';');
    }
    if rng.chance(300) {
        text.push_str("O0002;G04 P50;M99;");
    }
    if rng.chance(500) {
        text.push_str(rng.pick(&["M30;", "M99;", "M02;"]));
    }
    text
}

fn command(rng: &mut Rng) -> Option<CncCommand> {
    let words: Vec<String> = match rng.below(9) {
        0 => vec!["reset".into()],
        1 => vec!["alarm".into(), rng.pick(&["3", "401", "123"]).into()],
        2 => vec![
            "handwheel".into(),
            format!("{}", rng.below(200) as i64 - 100),
        ],
        3 => vec![
            "param".into(),
            rng.pick(&["1420", "1423", "1320", "8010", "1240"]).into(),
            format!("{}", rng.below(5) + 1),
            format!("{}", rng.below(9000)),
        ],
        4 => vec![
            "param".into(),
            rng.pick(&["3003", "3401", "3402", "3410", "5130"]).into(),
            format!("{}", rng.below(128)),
        ],
        5 => vec![
            "offset".into(),
            format!("{}", rng.below(99) + 1),
            rng.pick(&["X", "Z", "WX", "TIP"]).into(),
            format!("{}", rng.below(9)),
        ],
        6 => vec![
            "position".into(),
            rng.pick(&["X", "Z", "Y"]).into(),
            format!("{}", rng.below(100)),
        ],
        7 => vec!["macro".into(), "1100".into(), format!("{}", rng.below(2))],
        _ => vec![
            "param".into(),
            "8130".into(),
            format!("{}", rng.below(4) + 2),
        ],
    };
    let refs: Vec<&str> = words.iter().map(String::as_str).collect();
    CncCommand::parse(&refs, ProfileId::Gsk988ta, &|_| Err(String::new())).ok()
}

/// Runs one seed; returns a digest of every F image.
fn run(seed: u64, profile: ProfileId, exchanges: u64) -> u64 {
    let mut rng = Rng(seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1);
    let mut r = Rig::with(profile, &MessageTable::default());
    // Garbage in every F bit the CNC does not own: it must never change.
    for b in r.f.iter_mut() {
        *b = rng.next() as u8;
    }
    let mut mask = [0u8; 512];
    mask[..OWNED_MASK.len()].copy_from_slice(&OWNED_MASK);
    let foreign: Vec<u8> = r.f.iter().zip(&mask).map(|(f, m)| f & !m).collect();
    let mut digest = 0u64;
    let (mut ran, mut moved, mut strobed) = (0u32, 0u32, 0u32);
    for k in 0..exchanges {
        // Mostly a healthy machine, with random flips.
        for _ in 0..u64::from(rng.chance(300)) + u64::from(rng.chance(100)) {
            let byte = G_BYTES[rng.below(G_BYTES.len() as u64) as usize];
            r.g[byte] ^= 1 << rng.below(8);
        }
        if rng.chance(20) {
            r.g[8] |= 0b0011_1011;
            r.g[114] = 0xFF;
            r.g[116] = 0xFF;
            r.g[43] = [1, 0, 5, 4, 133, 1, 0][rng.below(7) as usize];
            r.g[12] = 10;
            r.a.fill(0);
            let _ = r.cnc.apply(&CncCommand::Reset);
        }
        if rng.chance(30) {
            r.g[7] ^= 0b100; // ST
        }
        if rng.chance(5) {
            r.a[rng.below(50) as usize] ^= 1 << rng.below(8);
        }
        if rng.chance(10) {
            let text = program(&mut rng);
            let c = if rng.chance(500) {
                CncCommand::Program(text)
            } else {
                CncCommand::Mdi(text)
            };
            let _ = r.cnc.apply(&c);
        }
        if rng.chance(10)
            && let Some(c) = command(&mut rng)
        {
            let _ = r.cnc.apply(&c);
        }
        if rng.chance(20) {
            let f = [
                0, 5, 13, 14, 15, 16, 17, 18, 21, 22, 23, 24, 25, 26, 27, 28, 32, 74, 75, 76, 81,
                151,
            ][rng.below(22) as usize];
            let mut block = vec![0i32; 6 + rng.below(8) as usize];
            for v in block.iter_mut() {
                *v = (rng.next() % 4000) as i32 - 2000;
            }
            block[0] = f;
            block[2] = rng.below(4) as i32;
            block[4] = rng.below(7) as i32 - 1;
            r.cnc.window(&mut block);
        }
        if rng.chance(1) {
            r.cnc.power_cycle();
        }
        r.set(4, 3, rng.chance(300)); // FIN now and then
        for g in 1..=4 {
            let _ = r.cnc.axis_status(g, rng.chance(500));
        }
        let _ = r.cnc.machine_position(rng.below(7) as u32);
        r.x();
        for (n, (&f, &m)) in r.f.iter().zip(&mask).enumerate() {
            assert_eq!(
                f & !m,
                foreign[n],
                "seed {seed}, exchange {k}: F{n} bits outside the CNC's were written"
            );
        }
        ran += u32::from(r.fb(0, 5));
        moved += u32::from(r.f[102] != 0);
        strobed += u32::from(r.fb(7, 0) || r.fb(7, 2) || r.fb(7, 3));
        digest = digest.rotate_left(5)
            ^ r.f
                .iter()
                .fold(0u64, |h, b| h.wrapping_mul(31) ^ u64::from(*b));
    }
    if exchanges >= 100_000 {
        // The run exercised the machine, not just an idle CNC.
        assert!(
            ran > 100 && moved > 100 && strobed > 0,
            "seed {seed}: {ran} {moved} {strobed}"
        );
    }
    digest
}

#[test]
fn random_runs_never_panic_or_write_foreign_f_bits() {
    for seed in 1..=3 {
        run(seed, ProfileId::Gsk988ta, 100_000);
    }
    run(4, ProfileId::Gsk980, 100_000);
}

#[test]
fn the_same_seed_gives_the_same_run() {
    assert_eq!(
        run(7, ProfileId::Gsk988ta, 5000),
        run(7, ProfileId::Gsk988ta, 5000)
    );
}

#[test]
fn random_cnc_scripts_are_refused_with_a_line_or_run_without_panic() {
    use ladder_engine::machine::Machine;
    use ladder_engine::profile::Profile;
    use ladder_engine::sim::{self, Options, Script};
    let base = [
        "cnc program \"O0001;N10 M03 S800;N20 G01 W-1 F600;N30 M30\"",
        "cnc mdi \"G04 P100;M05\"",
        "cnc param 1420 2 3000",
        "cnc offset 1 X 1.5",
        "cnc workpiece G54 Z -2",
        "cnc macro 100 1.25",
        "cnc position Z 3",
        "cnc alarm 3",
        "cnc reset",
        "cnc handwheel 10",
        "cnc clock 2026-05-01T12:00:00",
        "set X0000 1",
        "set X0001 7",
        "set X0001.0 0",
        "scan 20",
        "run 100ms",
        "expect cnc.run RUN",
        "expect cnc.pos.Z -1",
        "print cnc.block",
        "watch cnc.spindle",
        "expect cnc.macro.100 vacant",
        "power-cycle",
    ];
    let p = ladder_engine::il::import(
        "LEVEL2\nNETWORK\nLD F0007.0\nOR F0007.2\nOUT G0004.3\nNETWORK\nLDI R0999.7\nMOVN 1 X0000 G0043\nMOVN 1 255 G0114\nMOVN 1 255 G0116\nOUT G0008.0\nOUT G0008.1\nOUT G0008.3\nNETWORK\nLD X0001.0\nOUT G0007.2\nLD X0001.1\nOUT G0008.4\nLD X0001.2\nOUT G0008.5\n",
    )
    .project
    .expect("draws");
    let profile = Profile::get(ProfileId::Gsk988ta);
    let mut rng = Rng(99);
    let (mut ok, mut refused) = (0, 0);
    for _ in 0..3000 {
        let mut text = String::new();
        for _ in 0..1 + rng.below(8) {
            let mut line = rng.pick(&base).to_string();
            if rng.chance(300) {
                // Mutate: drop, double or replace a character.
                let mut chars: Vec<char> = line.chars().collect();
                let at = rng.below(chars.len() as u64) as usize;
                match rng.below(3) {
                    0 => {
                        chars.remove(at);
                    }
                    1 => chars.insert(at, chars[at]),
                    _ => chars[at] = ['"', ' ', '9', '.', 'x', ';', '#'][rng.below(7) as usize],
                }
                line = chars.into_iter().collect();
            }
            text.push_str(&line);
            text.push('\n');
        }
        let options = Options {
            cnc: true,
            read_file: &|_| Err("no files".into()),
            machine: None,
            project: None,
        };
        match Script::parse_with(&text, profile, &options) {
            Ok(script) => {
                ok += 1;
                let mut m = Machine::new(&p, true).unwrap();
                let _ = sim::run(&mut m, &script, "fuzz", true);
            }
            Err(e) => {
                refused += 1;
                assert!(e.line >= 1);
                let message = ladder_text::script::script_error(&e, ladder_text::Lang::En);
                assert!(!message.is_empty());
            }
        }
    }
    assert!(ok > 500 && refused > 100, "{ok} ran, {refused} refused");
}
