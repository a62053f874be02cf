//! The PLC's memory image: every area in one byte array, with the width rule of docs/plc.md.
//!
//! 1-byte areas (X Y F G R A K) hold one byte per address; an access of SIZE s at address n
//! covers n…n+s−1, little-endian. 4-byte areas (T C DT DC D) hold an i32 per address; an access
//! of SIZE 1 or 2 reads the low bits sign-extended and writes the value sign-extended. X and F
//! also have a copy that level 2 reads, latched at the start of each level-2 cycle.

use crate::address::{Address, Area};
use crate::profile::Profile;

/// A resolved data location: a byte offset into the image, and whether the area is 4-byte.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct Loc {
    /// Offset of the address's first byte.
    pub off: u32,
    /// One past the last byte of the area (bounds for run-time table accesses).
    pub end: u32,
    /// The area holds 4 bytes per address.
    pub wide: bool,
}

/// Where each area lives in the image.
#[derive(Clone, Debug)]
pub struct Layout {
    base: [u32; Area::COUNT],
    first: [u16; Area::COUNT],
    count: [u32; Area::COUNT],
    /// Base of level 2's latched copy of X.
    pub x_latch: u32,
    /// Base of level 2's latched copy of F.
    pub f_latch: u32,
    /// Total bytes.
    pub size: u32,
}

impl Layout {
    /// The layout for a profile's ranges.
    pub fn new(profile: &Profile) -> Layout {
        let mut base = [0u32; Area::COUNT];
        let mut first = [0u16; Area::COUNT];
        let mut count = [0u32; Area::COUNT];
        let mut at = 0u32;
        for area in Area::ALL {
            let (lo, hi) = profile.range(area);
            first[area.index()] = lo;
            let n = u32::from(hi) - u32::from(lo) + 1;
            count[area.index()] = n;
            base[area.index()] = at;
            at += n * u32::from(area.element_bytes());
        }
        let x_latch = at;
        at += count[Area::X.index()];
        let f_latch = at;
        at += count[Area::F.index()];
        Layout {
            base,
            first,
            count,
            x_latch,
            f_latch,
            size: at,
        }
    }

    /// Byte offset and bounds of an address (its bit is ignored). `latched` maps X and F to
    /// level 2's copy.
    pub fn loc(&self, a: Address, latched: bool) -> Loc {
        let i = a.area.index();
        let bytes = u32::from(a.area.element_bytes());
        let mut base = self.base[i];
        if latched {
            match a.area {
                Area::X => base = self.x_latch,
                Area::F => base = self.f_latch,
                _ => {}
            }
        }
        let rel = u32::from(a.number).saturating_sub(u32::from(self.first[i]));
        Loc {
            off: base + rel * bytes,
            end: base + self.count[i] * bytes,
            wide: bytes == 4,
        }
    }

    /// The address whose bytes include image offset `off` (live areas only, not level 2's
    /// latched copies), with `bit` when given and the area is 1-byte; for a 4-byte area,
    /// the address whose value holds the byte. The inverse of [`Layout::loc`], for naming
    /// forced bytes and recorded changes.
    pub fn address_at(&self, off: u32, bit: Option<u8>) -> Option<Address> {
        Area::ALL.into_iter().find_map(|area| {
            let i = area.index();
            let bytes = u32::from(area.element_bytes());
            let start = self.base[i];
            let end = start + self.count[i] * bytes;
            (start..end).contains(&off).then(|| Address {
                area,
                number: self.first[i] + ((off - start) / bytes) as u16,
                bit: if bytes == 1 { bit } else { None },
            })
        })
    }

    /// Byte range of a whole area in the live image.
    pub fn area_range(&self, area: Area) -> std::ops::Range<usize> {
        let i = area.index();
        let start = self.base[i] as usize;
        start..start + (self.count[i] * u32::from(area.element_bytes())) as usize
    }
}

/// Sign-extends the low `bytes` bytes of `v`.
#[inline]
pub fn sign_extend(v: u32, bytes: u32) -> i32 {
    match bytes {
        1 => v as u8 as i8 as i32,
        2 => v as u16 as i16 as i32,
        _ => v as i32,
    }
}

/// Reads a value of `bytes` (1, 2, 4) at `loc`, signed. Out-of-image reads give 0 (the
/// compiler refuses them for constant addresses; run-time tables are checked before).
#[inline]
pub fn read(mem: &[u8], loc: Loc, bytes: u32) -> i32 {
    let o = loc.off as usize;
    // A wide element is always 4 bytes, read whole, then taken at the width asked.
    let n = if loc.wide { 4 } else { bytes as usize };
    let Some(b) = mem.get(o..o + n) else {
        return 0;
    };
    // The widths instructions use, each as one load; any other as bytes in a row.
    let v = match *b {
        [b0] => u32::from(b0),
        [b0, b1] => u32::from(u16::from_le_bytes([b0, b1])),
        [b0, b1, b2, b3] => u32::from_le_bytes([b0, b1, b2, b3]),
        _ => b
            .iter()
            .enumerate()
            .fold(0, |v, (k, byte)| v | u32::from(*byte) << (8 * k)),
    };
    sign_extend(v, bytes)
}

/// Reads unsigned: the same bits as [`read`], zero-extended.
#[inline]
pub fn read_unsigned(mem: &[u8], loc: Loc, bytes: u32) -> u32 {
    let v = read(mem, loc, bytes) as u32;
    match bytes {
        1 => v & 0xFF,
        2 => v & 0xFFFF,
        _ => v,
    }
}

/// Writes the low `bytes` bytes of `v` at `loc` (sign-extended into a 4-byte area).
#[inline]
pub fn write(mem: &mut [u8], loc: Loc, bytes: u32, v: i32) {
    let o = loc.off as usize;
    if loc.wide {
        let stored = sign_extend(v as u32, bytes);
        if let Some(b) = mem.get_mut(o..o + 4) {
            b.copy_from_slice(&stored.to_le_bytes());
        }
    } else if let Some(b) = mem.get_mut(o..o + bytes as usize) {
        b.copy_from_slice(&v.to_le_bytes()[..bytes as usize]);
    }
}

/// Reads the binary32 real stored at a 4-byte location.
#[inline]
pub fn read_real(mem: &[u8], loc: Loc) -> f32 {
    f32::from_bits(read(mem, loc, 4) as u32)
}

/// Stores a binary32 real at a 4-byte location.
#[inline]
pub fn write_real(mem: &mut [u8], loc: Loc, v: f32) {
    write(mem, loc, 4, v.to_bits() as i32);
}

#[inline(always)]
pub(super) fn read_bit(mem: &[u8], arg: u32) -> u32 {
    u32::from(mem[(arg >> 3) as usize] >> (arg & 7)) & 1
}

#[inline(always)]
pub(super) fn write_bit(mem: &mut [u8], arg: u32, v: u32) {
    let byte = &mut mem[(arg >> 3) as usize];
    let sh = arg & 7;
    *byte = (*byte & !(1 << sh)) | ((v as u8) << sh);
}
