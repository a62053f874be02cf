//! P/S alarm numbers of program errors (docs/cnc.md, "Program errors"; the macro errors in
//! docs/gcode.md, "Macros"): one constant per alarm, each with its text in `alarm_text.rs`.

/// Too many digits.
pub const DIGITS: u16 = 3;
/// Unknown address, letter without number, malformed number, address twice, no such axis.
pub const ADDRESS: u16 = 9;
/// A G code that is not modelled, or two of one group.
pub const G_CODE: u16 = 10;
/// G01 while F = 0.
pub const NO_FEED: u16 = 11;
/// More than three M codes.
pub const M_COUNT: u16 = 14;
/// An arc whose start and end radii differ by more than #3410, or an R arc whose chord
/// is longer than 2R by more than #3410.
pub const ARC_RADIUS: u16 = 20;
/// G02/G03 with neither R nor I/K.
pub const NO_RADIUS: u16 = 22;
/// `,C` or `,R` whose next block is not a G01 move.
pub const CORNER_NEXT: u16 = 52;
/// `,C` or `,R` larger than the move before or after the corner.
pub const CORNER_SIZE: u16 = 55;
/// G10 with a P (or L) that names no offset or workpiece system.
pub const G10_P: u16 = 31;
/// G70–G73 without P or Q.
pub const CYCLE_PQ: u16 = 61;
/// A multiple repetitive cycle with an impossible value (depth 0, count 0, no height…).
pub const CYCLE_VALUE: u16 = 62;
/// No block with the sequence number P or Q of G70–G73, or Q before P.
pub const NO_SEQUENCE: u16 = 63;
/// The profile of G71–G73 does not change monotonically along Z.
pub const NOT_MONOTONIC_Z: u16 = 64;
/// The first block of a profile (P) holds neither G00 nor G01.
pub const CYCLE_FIRST_BLOCK: u16 = 65;
/// A profile block holds a command a cycle cannot follow (a one-shot G code, G32, a cycle).
pub const CYCLE_COMMAND: u16 = 66;
/// The profile of a type I G71/G72 does not change monotonically along X.
pub const NOT_MONOTONIC_X: u16 = 329;
/// M98: no such program.
pub const NO_PROGRAM: u16 = 76;
/// M98 nested too deep.
pub const NESTING: u16 = 77;
/// G28 (or AXCTL 08h–0Ah) before the reference point is established.
pub const NO_REFERENCE: u16 = 90;
/// A macro value too large (a result that is not a finite number).
pub const OVERFLOW: u16 = 111;
/// A macro division (`/`, `MOD`) by zero.
pub const DIVISION: u16 = 112;
/// A macro statement or expression that cannot be read.
pub const FORMAT: u16 = 114;
/// A variable number the CNC does not have.
pub const VARIABLE: u16 = 115;
/// A write to a variable that is read only (#0, #1000–#1032, #4001+, #5001+…).
pub const PROTECTED: u16 = 116;
/// Brackets nested deeper than five.
pub const BRACKETS: u16 = 118;
/// A function's argument out of its domain (SQRT of a negative, BIN of a non-BCD…), or
/// #3000 beyond 200.
pub const ARGUMENT: u16 = 119;
/// DO and END do not pair (an END without its DO, a DO without its END, crossing loops).
pub const LOOP_END: u16 = 124;
/// DO or END with a number other than 1–3.
pub const LOOP_NUMBER: u16 = 126;
/// NC words and a macro statement in one block.
pub const MIXED: u16 = 127;
/// GOTO to a sequence number outside 1–99999 or not in the program.
pub const SEQUENCE: u16 = 128;
/// G65/G66 with G, L, N, O or P as an argument, or without P.
pub const ARG_ADDRESS: u16 = 129;
/// PLC axis control refused (no axis in the group, or an unknown command).
pub const PLC_AXIS: u16 = 130;
/// An axis claimed by both the CNC and the PLC.
pub const AXIS_CLAIM: u16 = 139;
/// 100 000 blocks skipped or returned through (M99) without one executing: the program
/// loops without doing anything (the simulator's number, docs/gcode.md "Reader").
pub const NO_PROGRESS: u16 = 79;
