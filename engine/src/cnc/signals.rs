//! The CNC side of the F/G interface (docs/cnc.md, "Signals"): the G signals sampled once per
//! exchange into plain fields (active-low signals turned into "active" flags), and the F bits
//! the CNC owns, written every exchange and no others.

/// G signals as sampled at one exchange.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Inputs {
    /// FIN G4.3.
    pub fin: bool,
    /// MFIN2 G4.4, MFIN3 G4.5.
    pub mfin2: bool,
    /// MFIN3 G4.5.
    pub mfin3: bool,
    /// MFIN G5.0.
    pub mfin: bool,
    /// SFIN G5.2.
    pub sfin: bool,
    /// TFIN G5.3.
    pub tfin: bool,
    /// AFL G5.6.
    pub afl: bool,
    /// SRN G6.0.
    pub srn: bool,
    /// ABSM G6.2 (manual absolute off).
    pub absm: bool,
    /// OVC G6.4.
    pub ovc: bool,
    /// ST G7.2.
    pub st: bool,
    /// EXLM G7.6.
    pub exlm: bool,
    /// *IT G8.0 = 0.
    pub interlock: bool,
    /// *CSL G8.1 = 0.
    pub csl: bool,
    /// *BSL G8.3 = 0.
    pub bsl: bool,
    /// *ESP G8.4 = 0.
    pub estop: bool,
    /// *SP G8.5 = 0.
    pub feed_hold: bool,
    /// ERS G8.7.
    pub ers: bool,
    /// JV G10–G11.
    pub jv: u16,
    /// FV G12.
    pub fv: u8,
    /// ROV2 ROV1 (G14.1, G14.0) as 0–3.
    pub rov: u8,
    /// HS1D–HS1A (G18.3–0) as 0–15.
    pub hs: u8,
    /// MP2 MP1 (G19.5, G19.4) as 0–3.
    pub mp: u8,
    /// RT G19.7.
    pub rt: bool,
    /// GR2 GR1 (G28.2, G28.1) as 0–3.
    pub gear: u8,
    /// *SSTP G29.6 = 0.
    pub sstp: bool,
    /// SOV G30.
    pub sov: u8,
    /// R01I–R12I G32.0–G33.3.
    pub ri: u16,
    /// SIND G38.7.
    pub sind: bool,
    /// G43 & 0xA7 (ZRN DNCI MD4 MD2 MD1).
    pub mode_code: u8,
    /// BDT1 G44.0.
    pub bdt1: bool,
    /// MLK G44.1.
    pub mlk: bool,
    /// SBK G46.1.
    pub sbk: bool,
    /// DRN G46.7.
    pub drn: bool,
    /// +J1–8 G100.
    pub jog_plus: u8,
    /// −J1–8 G102.
    pub jog_minus: u8,
    /// *+L1–8 G114 = 0, per axis bit.
    pub limit_plus: u8,
    /// *−L1–8 G116 = 0.
    pub limit_minus: u8,
    /// *IT1–8 G130 = 0.
    pub axis_interlock: u8,
    /// EAX1–8 G136.
    pub eax: u8,
    /// *DEC1–8 G196 = 0 (on the dog).
    pub dec: u8,
    /// NOWT G201.
    pub nowt: u8,
    /// G214–G217 (#1000–#1031).
    pub macro_in: u32,
}

#[inline]
fn bit(g: &[u8], byte: usize, b: u32) -> bool {
    g.get(byte).is_some_and(|x| x >> b & 1 == 1)
}

#[inline]
fn byte(g: &[u8], byte: usize) -> u8 {
    g.get(byte).copied().unwrap_or(0)
}

impl Inputs {
    /// Samples the G image.
    pub fn read(g: &[u8]) -> Inputs {
        Inputs {
            fin: bit(g, 4, 3),
            mfin2: bit(g, 4, 4),
            mfin3: bit(g, 4, 5),
            mfin: bit(g, 5, 0),
            sfin: bit(g, 5, 2),
            tfin: bit(g, 5, 3),
            afl: bit(g, 5, 6),
            srn: bit(g, 6, 0),
            absm: bit(g, 6, 2),
            ovc: bit(g, 6, 4),
            st: bit(g, 7, 2),
            exlm: bit(g, 7, 6),
            interlock: !bit(g, 8, 0),
            csl: !bit(g, 8, 1),
            bsl: !bit(g, 8, 3),
            estop: !bit(g, 8, 4),
            feed_hold: !bit(g, 8, 5),
            ers: bit(g, 8, 7),
            jv: u16::from_le_bytes([byte(g, 10), byte(g, 11)]),
            fv: byte(g, 12),
            rov: byte(g, 14) & 3,
            hs: byte(g, 18) & 0x0F,
            mp: byte(g, 19) >> 4 & 3,
            rt: bit(g, 19, 7),
            gear: byte(g, 28) >> 1 & 3,
            sstp: !bit(g, 29, 6),
            sov: byte(g, 30),
            ri: u16::from_le_bytes([byte(g, 32), byte(g, 33) & 0x0F]),
            sind: bit(g, 38, 7),
            mode_code: byte(g, 43) & 0xA7,
            bdt1: bit(g, 44, 0),
            mlk: bit(g, 44, 1),
            sbk: bit(g, 46, 1),
            drn: bit(g, 46, 7),
            jog_plus: byte(g, 100),
            jog_minus: byte(g, 102),
            limit_plus: !byte(g, 114),
            limit_minus: !byte(g, 116),
            axis_interlock: !byte(g, 130),
            eax: byte(g, 136),
            dec: !byte(g, 196),
            nowt: byte(g, 201),
            macro_in: u32::from_le_bytes([byte(g, 214), byte(g, 215), byte(g, 216), byte(g, 217)]),
        }
    }

    /// A machine with nothing holding the program back: no E-stop, feed hold, interlock or
    /// limit, overrides at 100 %, the spindle enabled (the dry run of the toolpath).
    pub fn healthy() -> Inputs {
        let mut g = [0u8; 218];
        g[8] = 0b0011_1011;
        g[12] = 10;
        g[10] = 10;
        g[30] = 10;
        g[29] = 1 << 6;
        g[114] = 0xFF;
        g[116] = 0xFF;
        g[130] = 0xFF;
        g[196] = 0xFF;
        Inputs::read(&g)
    }

    /// The state of every G before exchange 1 (all 0).
    pub fn zero() -> Inputs {
        Inputs::read(&[])
    }
}

/// The G bytes of PLC axis group `g` (0–3): control byte, EC byte, EIF, EID.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct GroupInputs {
    /// EFINg.
    pub efin: bool,
    /// EMBUFg.
    pub embuf: bool,
    /// ESBKg.
    pub esbk: bool,
    /// ESTPg.
    pub estp: bool,
    /// ECLRg.
    pub eclr: bool,
    /// EBUFg.
    pub ebuf: bool,
    /// EC0–EC6.
    pub ec: u8,
    /// EMSBKg.
    pub emsbk: bool,
    /// EIF0–15.
    pub eif: u16,
    /// EID0–31.
    pub eid: i32,
}

impl GroupInputs {
    /// Samples group `k` (0 = A at G140).
    pub fn read(g: &[u8], k: usize) -> GroupInputs {
        let b = 140 + 10 * k;
        let c = byte(g, b);
        let e = byte(g, b + 1);
        GroupInputs {
            efin: c & 1 != 0,
            embuf: c >> 2 & 1 != 0,
            esbk: c >> 3 & 1 != 0,
            estp: c >> 5 & 1 != 0,
            eclr: c >> 6 & 1 != 0,
            ebuf: c >> 7 & 1 != 0,
            ec: e & 0x7F,
            emsbk: e >> 7 != 0,
            eif: u16::from_le_bytes([byte(g, b + 2), byte(g, b + 3)]),
            eid: i32::from_le_bytes([
                byte(g, b + 4),
                byte(g, b + 5),
                byte(g, b + 6),
                byte(g, b + 7),
            ]),
        }
    }
}

pub use super::fsignals::{F_BYTES, OWNED_MASK};
use super::fsignals::{FAxes, FBit, FGroupBit, FValue, GROUPS};

/// The F image being built at the end of an exchange.
pub struct FImage(pub [u8; F_BYTES]);

impl FImage {
    /// All 0.
    pub fn new() -> FImage {
        FImage([0; F_BYTES])
    }

    /// Sets signal `s` when `v`.
    #[inline]
    pub fn set(&mut self, s: FBit, v: bool) {
        self.0[usize::from(s.byte)] |= u8::from(v) << s.bit;
    }

    /// Sets axis `n`'s bit (from 0) of `s` when `v`.
    #[inline]
    pub fn axis(&mut self, s: FAxes, n: usize, v: bool) {
        self.0[usize::from(s.byte)] |= u8::from(v) << n;
    }

    /// Writes the bits of axes 1–8 of `s` at once.
    #[inline]
    pub fn axes(&mut self, s: FAxes, bits: u8) {
        self.0[usize::from(s.byte)] = bits;
    }

    /// Writes the number `s` (little-endian over its bytes).
    #[inline]
    pub fn put(&mut self, s: FValue, v: u32) {
        let (n, bytes) = (usize::from(s.byte), usize::from(s.bytes));
        self.0[n..n + bytes].copy_from_slice(&v.to_le_bytes()[..bytes]);
    }

    /// Sets signal `s` of PLC axis group `g` (0–3) when `v`.
    #[inline]
    pub fn group(&mut self, g: usize, s: FGroupBit, v: bool) {
        self.set(
            FBit {
                name: s.name,
                byte: GROUPS[g] + s.offset,
                bit: s.bit,
            },
            v,
        );
    }

    /// Writes the number `s` of PLC axis group `g`, its byte counted from the group's first.
    #[inline]
    pub fn group_put(&mut self, g: usize, s: FValue, v: u32) {
        self.put(
            FValue {
                byte: GROUPS[g] + s.byte,
                ..s
            },
            v,
        );
    }

    /// Merges the owned bits into the PLC's F area, leaving every other bit as it was.
    pub fn store(&self, f: &mut [u8]) {
        // Byte by byte over a mask of the whole area: one straight loop the compiler turns
        // into vector operations, where a walk over the signals costs ten times more.
        let n = f.len().min(F_BYTES);
        for ((x, &v), &m) in f[..n].iter_mut().zip(&self.0[..n]).zip(&OWNED_MASK[..n]) {
            *x = (*x & !m) | (v & m);
        }
    }
}

impl Default for FImage {
    fn default() -> Self {
        FImage::new()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn active_low_signals_read_as_active_at_zero() {
        let zero = Inputs::zero();
        assert!(zero.estop && zero.feed_hold && zero.interlock && zero.sstp);
        assert_eq!(zero.limit_plus, 0xFF);
        let mut g = [0u8; 256];
        g[8] = 0xFF;
        g[43] = 0xFF;
        let i = Inputs::read(&g);
        assert!(!i.estop && !i.feed_hold && i.ers);
        assert_eq!(i.mode_code, 0xA7);
    }

    #[test]
    fn only_owned_bits_are_stored() {
        let mut img = FImage::new();
        img.0.fill(0xFF);
        let mut f = [0u8; 256];
        img.store(&mut f);
        assert_eq!(f[0], 0xF0);
        assert_eq!(f[3] & 0x80, 0, "F3.7 MMTE is not the CNC's");
        assert_eq!(f[5], 0);
        assert_eq!(f[64], 0, "tool life is not modelled");
        assert_eq!(f[217], 0xFF);
    }
}
