//! Where operands may point: the area sets of the manual's operand lists (chapter 1 of the
//! manual, as docs/plc.md summarises it).

use crate::address::{Area, AreaSet};

/// Bit addresses a contact may read.
pub const BITS_READ: AreaSet = AreaSet::of(&[
    Area::X,
    Area::Y,
    Area::F,
    Area::G,
    Area::R,
    Area::A,
    Area::K,
]);
/// Bit addresses a coil may write.
pub const BITS_WRITE: AreaSet = AreaSet::of(&[Area::Y, Area::G, Area::R, Area::A, Area::K]);
/// Every data area a byte or word operand may read.
pub const BYTES_READ: AreaSet = AreaSet::MEMORY;
/// Every data area a byte or word operand may write.
pub const BYTES_WRITE: AreaSet = AreaSet::of(&[
    Area::Y,
    Area::G,
    Area::R,
    Area::A,
    Area::K,
    Area::T,
    Area::C,
    Area::Dt,
    Area::Dc,
    Area::D,
]);
/// The relay areas a byte result may go to (DECB OUT, MOVE OUT, CMP OUT).
pub(super) const RELAYS_WRITE: AreaSet = BITS_WRITE;
/// CMPR's OUT (§1.4.4: R Y K).
pub(super) const CMPR_OUT: AreaSet = AreaSet::of(&[Area::R, Area::Y, Area::K]);
/// CODB's OUT (§1.4.11: R Y G K A D DT DC).
pub(super) const CODB_OUT: AreaSet = AreaSet::of(&[
    Area::R,
    Area::Y,
    Area::G,
    Area::K,
    Area::A,
    Area::D,
    Area::Dt,
    Area::Dc,
]);
pub(super) const D_ONLY: AreaSet = AreaSet::of(&[Area::D]);
/// Relay and data areas without timers, counters and presets (CODB IN, PARI IN, MOVE IN).
pub(super) const RELAYS_AND_D: AreaSet = AreaSet::of(&[
    Area::X,
    Area::Y,
    Area::F,
    Area::G,
    Area::R,
    Area::A,
    Area::K,
    Area::D,
]);
/// MOVE OUT (§1.4.25: R A K Y G D).
pub(super) const MOVE_OUT: AreaSet =
    AreaSet::of(&[Area::Y, Area::G, Area::R, Area::A, Area::K, Area::D]);
/// ROTB IN_W/IN_D, DSCHB IN1/INL/DS (§1.4.16, §1.4.39: no T or C).
pub(super) const NO_TC_READ: AreaSet = AreaSet::of(&[
    Area::X,
    Area::Y,
    Area::F,
    Area::G,
    Area::R,
    Area::A,
    Area::K,
    Area::D,
    Area::Dc,
    Area::Dt,
]);
/// ROTB OUTE, DSCHB DI (§1.4.16, §1.4.39: no T or C).
pub(super) const NO_TC_WRITE: AreaSet = AreaSet::of(&[
    Area::Y,
    Area::G,
    Area::R,
    Area::A,
    Area::K,
    Area::D,
    Area::Dc,
    Area::Dt,
]);
/// ZCP inputs (§1.4.42: no DC or DT).
pub(super) const NO_PRESETS_READ: AreaSet = AreaSet::of(&[
    Area::X,
    Area::Y,
    Area::F,
    Area::G,
    Area::R,
    Area::A,
    Area::K,
    Area::D,
    Area::C,
    Area::T,
]);
/// RST of the real-number instructions (§1.4.19, §1.4.33, §1.4.43–46: X Y R K).
pub(super) const REAL_RST: AreaSet = AreaSet::of(&[Area::X, Area::Y, Area::R, Area::K]);
/// ERR of the real-number instructions (Y R K).
pub(super) const REAL_ERR: AreaSet = AreaSet::of(&[Area::Y, Area::R, Area::K]);
pub(super) const DT_ONLY: AreaSet = AreaSet::of(&[Area::Dt]);
pub(super) const DC_ONLY: AreaSet = AreaSet::of(&[Area::Dc]);
pub(super) const T_ONLY: AreaSet = AreaSet::of(&[Area::T]);
pub(super) const C_ONLY: AreaSet = AreaSet::of(&[Area::C]);
pub(super) const L_ONLY: AreaSet = AreaSet::of(&[Area::L]);
pub(super) const P_ONLY: AreaSet = AreaSet::of(&[Area::P]);
