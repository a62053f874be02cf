//! The machine model's bindings as the tick reads them: bits as byte offsets and masks,
//! conditions as postfix terms over them, and what the devices see of the CNC.

use crate::address::Address;
use crate::cnc::{AXES, SimCnc};
use crate::vm::memory::Layout;

/// A postfix term with its address resolved.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Resolved {
    /// A bit: byte offset and mask.
    Bit(u32, u8),
    /// A device state, by its index in the plant's state list.
    State(u32),
    /// 0 or 1.
    Const(bool),
    /// Negates the top.
    Not,
    /// Ands the top two.
    And,
    /// Ors the top two.
    Or,
}

/// A bit of memory: byte offset and mask.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Bit {
    /// Byte offset in the image.
    pub off: u32,
    /// The bit's mask.
    pub mask: u8,
}

impl Bit {
    /// The bit of an address in a layout.
    pub(super) fn of(layout: &Layout, a: Address) -> Bit {
        Bit {
            off: layout.loc(a, false).off,
            mask: 1 << a.bit.unwrap_or(0),
        }
    }

    /// Reads the bit.
    #[inline]
    pub fn get(self, mem: &[u8]) -> bool {
        mem[self.off as usize] & self.mask != 0
    }

    /// Writes the bit, without a branch (a device writes its inputs every tick).
    #[inline]
    pub fn set(self, mem: &mut [u8], v: bool) {
        let b = &mut mem[self.off as usize];
        *b = (*b & !self.mask) | (self.mask & 0u8.wrapping_sub(u8::from(v)));
    }
}

/// What the devices see of the CNC at a tick.
#[derive(Clone, Copy, Debug, Default)]
pub struct CncView {
    /// Machine position of each axis, increments (0.001 mm).
    pub m: [i64; AXES],
    /// Reference point established.
    pub zrf: [bool; AXES],
    /// The spindle speed output.
    pub s_out: u32,
}

impl CncView {
    /// What a CNC shows.
    pub fn of(cnc: &SimCnc) -> CncView {
        let mut v = CncView {
            s_out: cnc.spindle_output(),
            ..CncView::default()
        };
        for (k, a) in cnc.axes().iter().enumerate() {
            v.m[k] = a.m;
            v.zrf[k] = a.zrf;
        }
        v
    }
}
