//! A test rig for the simulated CNC: G, A and F images handed to the CNC one exchange at a
//! time, with an optional one-line "ladder" (FIN := MF ∨ SF ∨ TF) evaluated before each
//! exchange from the F of the exchange before, as a PLC scan would.

#![allow(dead_code)]

use ladder_engine::ProfileId;
use ladder_engine::cnc::command::{CncCommand, CncKey, CncValue};
use ladder_engine::cnc::{Mode, SimCnc};
use ladder_engine::model::tables::MessageTable;
use ladder_engine::vm::cnc::Cnc;

/// The CNC and its images.
pub struct Rig {
    pub cnc: SimCnc,
    pub g: Vec<u8>,
    pub a: Vec<u8>,
    pub f: Vec<u8>,
    /// Exchanges run.
    pub n: u64,
    /// Answer every strobe with FIN at the next scan.
    pub auto_fin: bool,
}

impl Rig {
    /// A GSK988TA CNC with healthy signals: no E-stop, no feed hold, interlocks released,
    /// limit switches closed, spindle enabled, overrides at 100 %, off the dogs.
    pub fn new() -> Rig {
        Rig::with(ProfileId::Gsk988ta, &MessageTable::default())
    }

    /// A rig for a profile and message table.
    pub fn with(profile: ProfileId, messages: &MessageTable) -> Rig {
        let mut r = Rig {
            cnc: SimCnc::new(profile, messages),
            g: vec![0; 512],
            a: vec![0; 50],
            f: vec![0; 512],
            n: 0,
            auto_fin: false,
        };
        r.g[8] = 0b0011_1011; // *IT *CSL *BSL *ESP *SP
        r.g[114] = 0xFF;
        r.g[116] = 0xFF;
        r.g[130] = 0xFF;
        r.g[196] = 0xFF;
        r.set(29, 6, true); // *SSTP
        r.g[12] = 10; // FV 100 %
        r.g[10] = 10; // JV 100 %
        r.g[30] = 10; // SOV 100 %
        r
    }

    /// A rig in MEM mode with `text` loaded and every strobe answered with FIN at the next
    /// exchange.
    pub fn mem(text: &str) -> Rig {
        let mut r = Rig::new();
        r.mode(Mode::Mem);
        r.x();
        r.program(text);
        r.auto_fin = true;
        r
    }

    /// One exchange.
    pub fn x(&mut self) {
        if self.auto_fin {
            let strobe = self.fb(7, 0) || self.fb(7, 2) || self.fb(7, 3);
            self.set(4, 3, strobe);
        }
        self.n += 1;
        self.cnc.exchange(8 * self.n, &self.g, &self.a, &mut self.f);
    }

    /// `k` exchanges.
    pub fn xs(&mut self, k: u64) {
        for _ in 0..k {
            self.x();
        }
    }

    /// Sets a G bit.
    pub fn set(&mut self, byte: usize, bit: u32, v: bool) {
        self.g[byte] = (self.g[byte] & !(1 << bit)) | (u8::from(v) << bit);
    }

    /// An F bit.
    pub fn fb(&self, byte: usize, bit: u32) -> bool {
        self.f[byte] >> bit & 1 == 1
    }

    /// `bytes` of F as an unsigned little-endian value.
    pub fn fv(&self, byte: usize, bytes: usize) -> u32 {
        let mut b = [0u8; 4];
        b[..bytes].copy_from_slice(&self.f[byte..byte + bytes]);
        u32::from_le_bytes(b)
    }

    /// Selects a mode through G43.
    pub fn mode(&mut self, m: Mode) {
        self.g[43] = match m {
            Mode::Edit => 3,
            Mode::Mem => 1,
            Mode::Mdi => 0,
            Mode::Handle => 4,
            Mode::Jog => 5,
            Mode::Dnc => 33,
            Mode::Ref => 133,
        };
    }

    /// Applies a `cnc` command given as words.
    pub fn cmd(&mut self, words: &[&str]) {
        let c = CncCommand::parse(words, self.cnc.profile(), &|_| Err("no files".into()))
            .unwrap_or_else(|e| panic!("{words:?}: {e}"));
        self.cnc
            .apply(&c)
            .unwrap_or_else(|e| panic!("{words:?}: {e:?}"));
    }

    /// Loads memory programs.
    pub fn program(&mut self, text: &str) {
        self.cnc
            .apply(&CncCommand::Program(text.into()))
            .expect("IDLE");
    }

    /// Presses and releases cycle start: ST = 1 for one exchange, then 0. Returns the
    /// exchange of the falling edge (where the program starts).
    pub fn start(&mut self) -> u64 {
        self.set(7, 2, true);
        self.x();
        self.set(7, 2, false);
        self.x();
        self.n
    }

    /// Establishes the reference points of axis slots `axes` by dog returns in REF mode: +J
    /// pressed, onto the dog, off it; the keys are released and the mode stays REF.
    pub fn home(&mut self, axes: &[usize]) {
        self.mode(Mode::Ref);
        self.x();
        for &n in axes {
            self.set(100, n as u32, true);
        }
        self.x();
        for &n in axes {
            self.set(196, n as u32, false);
        }
        self.x();
        for &n in axes {
            self.set(196, n as u32, true);
        }
        self.x();
        for &n in axes {
            self.set(100, n as u32, false);
        }
    }

    /// A CNC value as text.
    pub fn v(&self, key: &str) -> String {
        let k = CncKey::parse(key, self.cnc.profile()).unwrap();
        self.cnc.value(&k).unwrap().to_string()
    }

    /// A CNC value.
    pub fn value(&self, key: &str) -> CncValue {
        let k = CncKey::parse(key, self.cnc.profile()).unwrap();
        self.cnc.value(&k).unwrap()
    }

    /// Machine position of axis slot `n`, increments.
    pub fn m(&self, n: usize) -> i64 {
        self.cnc.axes()[n].m
    }

    /// Runs until `cond` holds (at most `limit` exchanges); returns the exchange.
    pub fn until(&mut self, limit: u64, cond: impl Fn(&Rig) -> bool) -> u64 {
        for _ in 0..limit {
            self.x();
            if cond(self) {
                return self.n;
            }
        }
        panic!("not reached within {limit} exchanges");
    }

    /// Calls WINDR with a block (function, number, attribute, length, data) and returns it.
    pub fn windr(
        &mut self,
        function: i32,
        number: i32,
        attr: i32,
        len: i32,
        data: &[i32],
    ) -> Vec<i32> {
        let mut b = vec![0i32; 40];
        b[0] = function;
        b[2] = len;
        b[3] = number;
        b[4] = attr;
        b[6..6 + data.len()].copy_from_slice(data);
        self.cnc.window(&mut b);
        b
    }
}

/// A seeded xorshift64* generator: the same seed gives the same run.
pub struct Rng(pub u64);

impl Rng {
    pub fn next(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }
    pub fn below(&mut self, n: u64) -> u64 {
        self.next() % n
    }
    pub fn chance(&mut self, per_thousand: u64) -> bool {
        self.below(1000) < per_thousand
    }
    pub fn index(&mut self, n: usize) -> usize {
        self.below(n as u64) as usize
    }
    pub fn pick<'a>(&mut self, xs: &[&'a str]) -> &'a str {
        xs[self.below(xs.len() as u64) as usize]
    }
}
