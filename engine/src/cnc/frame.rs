//! Where automatic operation is in its programs: a block position and the callers of
//! subprograms and macros (docs/cnc.md, "Automatic operation"; docs/gcode.md, "Macros").

use super::AXES;
use super::macro_b::Locals;

/// Program index of the MDI buffer in a [`Cursor`].
pub(super) const MDI: usize = usize::MAX;

/// A block position: program index (or [`MDI`]) and block index.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(super) struct Cursor {
    pub(super) prog: usize,
    pub(super) block: usize,
}

/// A caller of a subprogram.
#[derive(Clone, Copy, Debug)]
pub(super) struct Frame {
    pub(super) ret: Cursor,
    pub(super) sub: usize,
    /// The block the call starts at (0; an M97's sequence number's block).
    pub(super) start: usize,
    pub(super) repeats: u32,
    /// A G70 profile: the index of its last block (Q), after which the G70 block is
    /// returned to, and the cycle's start point.
    pub(super) until: Option<(usize, [i64; AXES])>,
    /// A macro call (G65, G66): the locals each repetition starts with.
    pub(super) args: Option<Locals>,
    /// A G66 modal call: moves inside it call nothing.
    pub(super) modal: bool,
}
