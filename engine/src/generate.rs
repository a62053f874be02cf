//! Generated programs for benchmarks and stress tests: realistic rungs of a given size, the
//! same for the same seed.

use std::fmt::Write as _;

/// A small, fast, seeded random number generator (SplitMix64), so generated programs and
/// seeded tests are reproducible without a dependency.
#[derive(Clone, Debug)]
pub struct SplitMix64(u64);

impl SplitMix64 {
    /// A generator from a seed.
    pub fn new(seed: u64) -> SplitMix64 {
        SplitMix64(seed)
    }

    /// The next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// A number in `0..n` (n > 0).
    pub fn below(&mut self, n: u64) -> u64 {
        self.next_u64() % n.max(1)
    }

    /// True with probability `percent` %.
    pub fn chance(&mut self, percent: u64) -> bool {
        self.below(100) < percent
    }
}

/// What kind of program to generate.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mix {
    /// Only rungs of LD/AND/OR/ANI/ORI/OUT (the bit-logic benchmark).
    BitLogic,
    /// About 80 % bit logic, 20 % timers, counters, MOVN, ADDB, CMP, DECB and a few CALLs.
    Mixed,
}

struct Gen {
    rng: SplitMix64,
    next_coil: u32,
    next_box_byte: u32,
    next_timer: u32,
    next_counter: u32,
    steps: u32,
    out: String,
}

impl Gen {
    fn contact(&mut self) -> String {
        // Inputs from X, F and R so the logic reads live and internal signals alike.
        match self.rng.below(4) {
            0 => format!("X{:04}.{}", self.rng.below(128), self.rng.below(8)),
            1 => format!("F{:04}.{}", self.rng.below(512), self.rng.below(8)),
            _ => format!("R{:04}.{}", self.rng.below(1000), self.rng.below(8)),
        }
    }

    fn coil(&mut self) -> String {
        let n = self.next_coil;
        self.next_coil += 1;
        // R0500.0 onwards, wrapping inside R (a repeated coil only warns).
        let byte = 500 + (n / 8) % 500;
        format!("R{byte:04}.{}", n % 8)
    }

    /// A byte of its own for a CMP or DECB result, R0100–R0499 (wrapping), away from the
    /// coils: DECB writes its byte at every execution, so sharing one with a coil or another
    /// box would be a real double write (W008).
    fn box_byte(&mut self) -> u32 {
        // The draw that once chose the byte is still made, so the rest of a program (and the
        // benchmarks' figures) stays what it was for the same seed.
        let _ = self.rng.below(490);
        let n = self.next_box_byte;
        self.next_box_byte += 1;
        100 + n % 400
    }

    fn line(&mut self, text: &str, steps: u32) {
        self.out.push_str(text);
        self.out.push('\n');
        self.steps += steps;
    }

    fn bit_rung(&mut self) {
        let c = self.contact();
        let first = if self.rng.chance(20) { "LDI" } else { "LD" };
        self.line(&format!("{first:<4} {c}"), 1);
        let terms = 1 + self.rng.below(5);
        for _ in 0..terms {
            let c = self.contact();
            let op = ["AND", "ANI", "OR", "ORI", "AND"][self.rng.below(5) as usize];
            self.line(&format!("{op:<4} {c}"), 1);
        }
        if self.rng.chance(15) {
            let (a, b) = (self.contact(), self.contact());
            self.line(&format!("LD   {a}"), 1);
            self.line(&format!("OR   {b}"), 1);
            self.line("ANB", 1);
        }
        let c = self.coil();
        self.line(&format!("OUT  {c}"), 1);
    }

    fn function_rung(&mut self) {
        let c = self.contact();
        self.line(&format!("LD   {c}"), 1);
        let d = self.rng.below(900) + 50;
        match self.rng.below(6) {
            0 if self.next_timer < 200 => {
                let (t, o) = (self.next_timer, self.coil());
                self.next_timer += 1;
                let pt = 100 + self.rng.below(2000);
                self.line(&format!("TMRB T{t:04} {pt} {o}"), 4);
            }
            1 if self.next_counter < 200 => {
                let (n, r, o) = (self.next_counter, self.contact(), self.coil());
                self.next_counter += 1;
                self.line(&format!("CTRC 0000 {r} C{n:04} 10 {o}"), 6);
            }
            2 => self.line(&format!("MOVN 4 D{d:04} D{:04}", d + 1), 4),
            3 => {
                let (r, e) = (self.contact(), self.coil());
                self.line(&format!("ADDB 4 D{d:04} 1 {r} D{d:04} {e}"), 7);
            }
            4 => {
                let byte = self.box_byte();
                self.line(&format!("CMP  4 D{d:04} 100 R{byte:04}.0"), 5);
            }
            _ => {
                let byte = self.box_byte();
                let src = self.rng.below(500);
                self.line(&format!("DECB 1 R{src:04} 0 R{byte:04}"), 5);
            }
        }
    }
}

/// Instruction-list text of a program of a little under `steps` steps: a small level 1, the rest in
/// level 2, and (for [`Mix::Mixed`]) two subprograms called from level 2.
pub fn program_il(steps: u32, mix: Mix, seed: u64) -> String {
    let mut g = Gen {
        rng: SplitMix64::new(seed),
        next_coil: 0,
        next_box_byte: 0,
        next_timer: 0,
        next_counter: 0,
        steps: 0,
        out: String::new(),
    };
    let level1 = (steps / 20).min(500);
    g.line("LEVEL1", 0);
    while g.steps < level1 {
        g.bit_rung();
    }
    g.line("LEVEL2", 0);
    let subs = if mix == Mix::Mixed { 2 } else { 0 };
    let sub_steps = if subs > 0 { steps / 20 } else { 0 };
    while g.steps + sub_steps + 12 < steps {
        if mix == Mix::Mixed && g.rng.chance(20) {
            if g.rng.chance(5) {
                let c = g.contact();
                g.line(&format!("LD   {c}"), 1);
                let p = 1 + g.rng.below(subs);
                g.line(&format!("CALL P{p:04}"), 2);
            } else {
                g.function_rung();
            }
        } else {
            g.bit_rung();
        }
    }
    for p in 1..=subs {
        let _ = writeln!(g.out, "SUB  P{p:04} \"GENERATED{p}\"");
        let end = g.steps + sub_steps / subs as u32;
        while g.steps + 10 < end {
            g.bit_rung();
        }
    }
    g.out.push_str("END\n");
    g.out
}
