//! The F signals the CNC writes (docs/cnc.md, "F signals written"), each named once: the
//! exchange writes them through these names (`signals::FImage`), the bits the CNC
//! owns ([`OWNED_MASK`]) are derived from this table alone, and the compiler's CNC-aware
//! checks read the strobes and answers by the same names. A bit the CNC owns but does not
//! model (SRNMV, MINC, ECKZ) is listed too: it is written, always as 0.

/// The F area's size in bytes (F0000–F0217).
pub const F_BYTES: usize = 218;

/// One F bit.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct FBit {
    /// Its name in the manual.
    pub name: &'static str,
    /// Its byte.
    pub byte: u16,
    /// Its bit, 0–7.
    pub bit: u8,
}

/// A byte with one bit per axis: bit n−1 for axis n (ZP1–8, MV1–8, …).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct FAxes {
    /// Its name in the manual, without the axis number.
    pub name: &'static str,
    /// Its byte.
    pub byte: u16,
}

/// A number over whole bytes, little-endian (an M code, the S12 code, #1100–#1131).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct FValue {
    /// Its name in the manual.
    pub name: &'static str,
    /// Its first byte.
    pub byte: u16,
    /// How many bytes.
    pub bytes: u8,
    /// The bits of the last byte it holds (F37 holds only the S12 code's top four bits).
    pub last: u8,
}

/// A bit of a PLC axis group's bytes: `offset` bytes after the group's first (F140, F150,
/// F160, F170 for groups A–D).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct FGroupBit {
    /// Its name in the manual.
    pub name: &'static str,
    /// The byte after the group's first.
    pub offset: u16,
    /// Its bit.
    pub bit: u8,
}

const fn bit(name: &'static str, byte: u16, bit: u8) -> FBit {
    FBit { name, byte, bit }
}

const fn axes(name: &'static str, byte: u16) -> FAxes {
    FAxes { name, byte }
}

const fn value(name: &'static str, byte: u16, bytes: u8) -> FValue {
    FValue {
        name,
        byte,
        bytes,
        last: 0xFF,
    }
}

const fn group(name: &'static str, offset: u16, bit: u8) -> FGroupBit {
    FGroupBit { name, offset, bit }
}

/// Spindle stop lamp (feed hold lamp).
pub const SPL: FBit = bit("SPL", 0, 4);
/// Cycle start lamp.
pub const STL: FBit = bit("STL", 0, 5);
/// Servo ready.
pub const SA: FBit = bit("SA", 0, 6);
/// Automatic operation.
pub const OP: FBit = bit("OP", 0, 7);
/// Alarm.
pub const AL: FBit = bit("AL", 1, 0);
/// Resetting.
pub const RST: FBit = bit("RST", 1, 1);
/// Distribution end.
pub const DEN: FBit = bit("DEN", 1, 3);
/// Spindle enable.
pub const ENB: FBit = bit("ENB", 1, 4);
/// CNC ready.
pub const MA: FBit = bit("MA", 1, 7);
/// Inch input (G20).
pub const INCH: FBit = bit("INCH", 2, 0);
/// Rapid traverse.
pub const RPDO: FBit = bit("RPDO", 2, 1);
/// Constant surface speed (G96).
pub const CSS: FBit = bit("CSS", 2, 2);
/// Threading.
pub const THRD: FBit = bit("THRD", 2, 3);
/// Program restart under way: not modelled, always 0.
pub const SRNMV: FBit = bit("SRNMV", 2, 4);
/// Cutting feed.
pub const CUT: FBit = bit("CUT", 2, 6);
/// Dry run confirmed.
pub const MDRN: FBit = bit("MDRN", 2, 7);
/// Incremental feed mode: not modelled, always 0.
pub const MINC: FBit = bit("MINC", 3, 0);
/// Handwheel mode.
pub const MH: FBit = bit("MH", 3, 1);
/// JOG mode.
pub const MJ: FBit = bit("MJ", 3, 2);
/// MDI mode.
pub const MMDI: FBit = bit("MMDI", 3, 3);
/// DNC mode.
pub const MRMT: FBit = bit("MRMT", 3, 4);
/// Memory (automatic) mode.
pub const MMEM: FBit = bit("MMEM", 3, 5);
/// EDIT mode.
pub const MEDT: FBit = bit("MEDT", 3, 6);
/// Block skip confirmed.
pub const MBDT1: FBit = bit("MBDT1", 4, 0);
/// Machine lock confirmed.
pub const MMLK: FBit = bit("MMLK", 4, 1);
/// Manual absolute confirmed (the inverse of *ABSM).
pub const MABSM: FBit = bit("MABSM", 4, 2);
/// Single block confirmed.
pub const MSBK: FBit = bit("MSBK", 4, 3);
/// Auxiliary function lock confirmed.
pub const MAFL: FBit = bit("MAFL", 4, 4);
/// Reference return mode.
pub const MREF: FBit = bit("MREF", 4, 5);
/// Stroke limit alarm.
pub const OTA: FBit = bit("OTA", 6, 0);
/// The MDI panel's RESET key.
pub const MDIRST: FBit = bit("MDIRST", 6, 1);
/// M code strobe.
pub const MF: FBit = bit("MF", 7, 0);
/// S code strobe.
pub const SF: FBit = bit("SF", 7, 2);
/// T code strobe.
pub const TF: FBit = bit("TF", 7, 3);
/// 2nd M code strobe.
pub const MF2: FBit = bit("MF2", 8, 4);
/// 3rd M code strobe.
pub const MF3: FBit = bit("MF3", 8, 5);
/// M99 decoded.
pub const DM99: FBit = bit("DM99", 9, 3);
/// M30 decoded.
pub const DM30: FBit = bit("DM30", 9, 4);
/// M02 decoded.
pub const DM02: FBit = bit("DM02", 9, 5);
/// M01 decoded.
pub const DM01: FBit = bit("DM01", 9, 6);
/// M00 decoded.
pub const DM00: FBit = bit("DM00", 9, 7);
/// The parts count reached the required parts.
pub const PRTSF: FBit = bit("PRTSF", 62, 7);
/// A PLC axis override of 0.
pub const EOV0: FBit = bit("EOV0", 129, 5);
/// PLC axis selection state.
pub const EAXSL: FBit = bit("*EAXSL", 129, 7);

/// The one-bit signals, in byte order.
pub const BITS: &[FBit] = &[
    SPL, STL, SA, OP, AL, RST, DEN, ENB, MA, INCH, RPDO, CSS, THRD, SRNMV, CUT, MDRN, MINC, MH, MJ,
    MMDI, MRMT, MMEM, MEDT, MBDT1, MMLK, MABSM, MSBK, MAFL, MREF, OTA, MDIRST, MF, SF, TF, MF2,
    MF3, DM99, DM30, DM02, DM01, DM00, PRTSF, EOV0, EAXSL,
];

/// Reference position reached.
pub const ZP: FAxes = axes("ZP", 94);
/// 2nd reference position reached.
pub const ZP2: FAxes = axes("ZP2", 96);
/// 3rd reference position reached.
pub const ZP3: FAxes = axes("ZP3", 98);
/// 4th reference position reached.
pub const ZP4: FAxes = axes("ZP4", 100);
/// Axis moving.
pub const MV: FAxes = axes("MV", 102);
/// Axis moving in the negative direction.
pub const MVD: FAxes = axes("MVD", 106);
/// PLC axis distribution end.
pub const EADEN: FAxes = axes("EADEN", 112);
/// Reference position established.
pub const ZRF: FAxes = axes("ZRF", 120);
/// Positive stroke limit reached.
pub const OTP: FAxes = axes("+OT", 124);
/// Negative stroke limit reached.
pub const OTN: FAxes = axes("-OT", 126);
/// PLC axis controlled.
pub const EACNT: FAxes = axes("EACNT", 182);

/// The bytes of one bit per axis.
pub const AXES: &[FAxes] = &[ZP, ZP2, ZP3, ZP4, MV, MVD, EADEN, ZRF, OTP, OTN, EACNT];

/// The M code.
pub const M_CODE: FValue = value("M code", 10, 4);
/// The 2nd M code.
pub const M_CODE2: FValue = value("2nd M code", 14, 2);
/// The 3rd M code.
pub const M_CODE3: FValue = value("3rd M code", 16, 2);
/// The S code.
pub const S_CODE: FValue = value("S code", 22, 4);
/// The T code.
pub const T_CODE: FValue = value("T code", 26, 4);
/// The S12 code: the spindle speed in 12 bits, F36 and F37.0–.3.
pub const S12: FValue = FValue {
    last: 0x0F,
    ..value("S12 code", 36, 2)
};
/// The actual spindle speed.
pub const AR: FValue = value("AR", 40, 2);
/// The macro outputs #1100–#1131.
pub const MACRO_OUT: FValue = value("#1100–#1131", 214, 4);

/// The numbers.
pub const VALUES: &[FValue] = &[M_CODE, M_CODE2, M_CODE3, S_CODE, T_CODE, S12, AR, MACRO_OUT];

/// The first byte of each PLC axis group's signals (groups A–D).
pub const GROUPS: [u16; 4] = [140, 150, 160, 170];
/// In position.
pub const EINP: FGroupBit = group("EINP", 0, 0);
/// Following zero check: not modelled, always 0.
pub const ECKZ: FGroupBit = group("ECKZ", 0, 1);
/// PLC axis alarm.
pub const EIAL: FGroupBit = group("EIAL", 0, 2);
/// Auxiliary function under way.
pub const EDEN: FGroupBit = group("EDEN", 0, 3);
/// Axis moving.
pub const EGEN: FGroupBit = group("EGEN", 0, 4);
/// Positive overtravel.
pub const EOTP: FGroupBit = group("EOTP", 0, 5);
/// Negative overtravel.
pub const EOTN: FGroupBit = group("EOTN", 0, 6);
/// Axis busy.
pub const EBSY: FGroupBit = group("EBSY", 0, 7);
/// Auxiliary function strobe.
pub const EMF: FGroupBit = group("EMF", 1, 0);
/// Buffer full.
pub const EABUF: FGroupBit = group("EABUF", 1, 1);
/// 2nd auxiliary function strobe.
pub const EMF2: FGroupBit = group("EMF2", 1, 2);
/// 3rd auxiliary function strobe.
pub const EMF3: FGroupBit = group("EMF3", 1, 3);
/// The group's bits.
pub const GROUP_BITS: &[FGroupBit] = &[
    EINP, ECKZ, EIAL, EDEN, EGEN, EOTP, EOTN, EBSY, EMF, EABUF, EMF2, EMF3,
];
/// The group's auxiliary function code, two bytes from the group's third.
pub const EM_CODE: FValue = value("EM code", 2, 2);

/// Every F bit the CNC owns as one mask byte per F byte: the bits of this table and no
/// other. The exchange writes exactly these; every other F bit keeps what the user set.
pub const OWNED_MASK: [u8; F_BYTES] = {
    let mut mask = [0u8; F_BYTES];
    let mut i = 0;
    while i < BITS.len() {
        mask[BITS[i].byte as usize] |= 1 << BITS[i].bit;
        i += 1;
    }
    let mut i = 0;
    while i < AXES.len() {
        mask[AXES[i].byte as usize] = 0xFF;
        i += 1;
    }
    let mut i = 0;
    while i < VALUES.len() {
        let v = VALUES[i];
        let mut k = 0;
        while k < v.bytes as usize {
            let last = k + 1 == v.bytes as usize;
            mask[v.byte as usize + k] |= if last { v.last } else { 0xFF };
            k += 1;
        }
        i += 1;
    }
    let mut g = 0;
    while g < GROUPS.len() {
        let mut i = 0;
        while i < GROUP_BITS.len() {
            let b = GROUP_BITS[i];
            mask[(GROUPS[g] + b.offset) as usize] |= 1 << b.bit;
            i += 1;
        }
        let base = (GROUPS[g] + EM_CODE.byte) as usize;
        mask[base] = 0xFF;
        mask[base + 1] = 0xFF;
        g += 1;
    }
    mask
};

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_table_owns_exactly_the_bits_docs_cnc_lists() {
        // docs/cnc.md, "F signals written", byte by byte.
        let listed: &[(usize, u8)] = &[
            (0, 0xF0),
            (1, 0x9B),
            (2, 0xDF),
            (3, 0x7F),
            (4, 0x3F),
            (6, 0x03),
            (7, 0x0D),
            (8, 0x30),
            (9, 0xF8),
            (10, 0xFF),
            (11, 0xFF),
            (12, 0xFF),
            (13, 0xFF),
            (14, 0xFF),
            (15, 0xFF),
            (16, 0xFF),
            (17, 0xFF),
            (22, 0xFF),
            (23, 0xFF),
            (24, 0xFF),
            (25, 0xFF),
            (26, 0xFF),
            (27, 0xFF),
            (28, 0xFF),
            (29, 0xFF),
            (36, 0xFF),
            (37, 0x0F),
            (40, 0xFF),
            (41, 0xFF),
            (62, 0x80),
            (94, 0xFF),
            (96, 0xFF),
            (98, 0xFF),
            (100, 0xFF),
            (102, 0xFF),
            (106, 0xFF),
            (112, 0xFF),
            (120, 0xFF),
            (124, 0xFF),
            (126, 0xFF),
            (129, 0xA0),
            (140, 0xFF),
            (141, 0x0F),
            (142, 0xFF),
            (143, 0xFF),
            (150, 0xFF),
            (151, 0x0F),
            (152, 0xFF),
            (153, 0xFF),
            (160, 0xFF),
            (161, 0x0F),
            (162, 0xFF),
            (163, 0xFF),
            (170, 0xFF),
            (171, 0x0F),
            (172, 0xFF),
            (173, 0xFF),
            (182, 0xFF),
            (214, 0xFF),
            (215, 0xFF),
            (216, 0xFF),
            (217, 0xFF),
        ];
        let mut expected = [0u8; F_BYTES];
        for &(n, m) in listed {
            expected[n] = m;
        }
        for n in 0..F_BYTES {
            assert_eq!(OWNED_MASK[n], expected[n], "F{n}: {:08b}", OWNED_MASK[n]);
        }
    }

    #[test]
    fn no_two_signals_share_a_bit() {
        let mut seen = [0u8; F_BYTES];
        let mut claim = |byte: usize, mask: u8, name: &str| {
            assert_eq!(seen[byte] & mask, 0, "{name} overlaps F{byte}");
            seen[byte] |= mask;
        };
        for s in BITS {
            claim(usize::from(s.byte), 1 << s.bit, s.name);
        }
        for s in AXES {
            claim(usize::from(s.byte), 0xFF, s.name);
        }
        for s in VALUES {
            for k in 0..usize::from(s.bytes) {
                let last = k + 1 == usize::from(s.bytes);
                claim(
                    usize::from(s.byte) + k,
                    if last { s.last } else { 0xFF },
                    s.name,
                );
            }
        }
    }
}
