//! The editor's colours as named tokens. Every colour the editor paints is one of these, so
//! a change of scheme is made here once; `clippy.toml` refuses colour constructors elsewhere.
#![allow(clippy::disallowed_methods)] // The one place colours are made.

use egui::Color32;

/// Text of a refusal or an error (the output window, prompts, dialogs, tables).
pub const ERROR: Color32 = Color32::from_rgb(0xc0, 0x10, 0x10);
/// The ground of error text on a table row, so it reads on a selected (blue) row too.
pub const ERROR_GROUND: Color32 = Color32::from_rgb(0xff, 0xec, 0xec);
/// Text of an accepted value (a table's check mark).
pub const OK: Color32 = Color32::from_rgb(0x10, 0x80, 0x10);
/// An operand that can be used but will not compile yet (an undefined symbol).
pub const CAUTION: Color32 = Color32::from_rgb(0xb0, 0x60, 0x00);
/// Coverage: an element seen both ways (translucent over the ladder's paper).
pub const COVER_FULL: Color32 = Color32::from_rgba_unmultiplied_const(0x30, 0xb0, 0x50, 0x50);
/// Coverage: an element seen one way only.
pub const COVER_HALF: Color32 = Color32::from_rgba_unmultiplied_const(0xf0, 0xb0, 0x00, 0x70);
/// Coverage: an element never run.
pub const COVER_NEVER: Color32 = Color32::from_rgba_unmultiplied_const(0xe0, 0x30, 0x30, 0x60);
/// The background of the "forces active" badge: amber, as a warning lamp.
pub const AMBER: Color32 = Color32::from_rgb(0xff, 0xbf, 0x00);

/// The ladder's paper: black on white like a printed ladder, whatever the UI theme.
pub const PAPER: Color32 = Color32::WHITE;
/// Ink of elements, operands and box names.
pub const INK: Color32 = Color32::BLACK;
/// Wires and element outlines.
pub const WIRE: Color32 = Color32::from_gray(40);
/// The power rails.
pub const RAIL: Color32 = Color32::from_gray(30);
/// The line between networks.
pub const NETWORK_RULE: Color32 = Color32::from_gray(200);
/// A network's number and title.
pub const TITLE: Color32 = Color32::from_rgb(0, 100, 0);
/// A network's comment.
pub const COMMENT: Color32 = Color32::DARK_GREEN;
/// The cell cursor's frame.
pub const CURSOR: Color32 = Color32::from_rgb(0x20, 0x60, 0xff);
/// The fill of selected cells, rows and networks.
pub const SELECTED: Color32 = Color32::from_rgb(0xcc, 0xe0, 0xff);

/// Online: an energised wire, lead or rail.
pub const POWER: Color32 = Color32::from_rgb(0x00, 0xa0, 0x30);
/// Online: the inside of a closed contact or an energised coil.
pub const POWER_FILL: Color32 = Color32::from_rgb(0x40, 0xd0, 0x60);
/// Online: the inside of a function box whose ACT is on.
pub const POWER_BOX: Color32 = Color32::from_rgb(0xdc, 0xf5, 0xe0);
/// Online: a box operand's live value.
pub const LIVE_VALUE: Color32 = Color32::from_rgb(0x00, 0x50, 0xa0);
/// Online: the mark of a forced element.
pub const FORCED: Color32 = Color32::from_rgb(0xc0, 0x00, 0xc0);
/// Online: the frame "why?" draws round a deciding contact.
pub const WHY: Color32 = Color32::from_rgb(0xff, 0x8c, 0x00);
/// Online: the paper while the view shows a recorded past tick.
pub const PAPER_PAST: Color32 = Color32::from_rgb(0xf6, 0xf2, 0xe6);

/// Operand colours (manual §3.4.3.3): a symbol mapped to an address is blue.
pub const MAPPED: Color32 = Color32::from_rgb(0x1f, 0x4f, 0xd0);
/// An undefined symbol is red.
pub const UNDEFINED: Color32 = Color32::from_rgb(0xd0, 0x20, 0x20);
/// An operand of the wrong type for its place (a byte address on a contact, an area the
/// instruction does not take) is orange.
pub const WRONG_TYPE: Color32 = Color32::from_rgb(0xe0, 0x80, 0x00);

/// A lit lamp of the operator panel, and the fill of a key whose lamp is lit.
pub const PANEL_LIT: Color32 = Color32::from_rgb(0xff, 0xc0, 0x30);
/// An unlit lamp of the operator panel.
pub const PANEL_DARK: Color32 = Color32::from_gray(0x60);
/// The rim of a panel lamp, so an unlit lamp still shows on a dark theme.
pub const PANEL_RIM: Color32 = Color32::from_gray(0x20);
/// A CNC status lamp that is on (MF, SF, TF, FIN, DEN).
pub const CNC_LAMP_ON: Color32 = Color32::from_rgb(0x20, 0xc0, 0x40);
/// The background of the NC block being executed in the program listing.
pub const CNC_CURRENT_LINE: Color32 = Color32::from_rgb(0xff, 0xe8, 0x80);
/// The background of the NC block picked on the toolpath.
pub const CNC_PICKED_LINE: Color32 = Color32::from_rgb(0xfa, 0xd4, 0xe8);
/// Toolpath: rapids (dashed).
pub const TOOLPATH_RAPID: Color32 = Color32::from_rgb(0x90, 0x90, 0x90);
/// Toolpath: cutting feed.
pub const TOOLPATH_FEED: Color32 = Color32::from_rgb(0x20, 0x50, 0xc0);
/// Toolpath: threads.
pub const TOOLPATH_THREAD: Color32 = Color32::from_rgb(0x90, 0x30, 0xb0);
/// Toolpath: the path the tool has taken.
pub const TOOLPATH_EXECUTED: Color32 = Color32::from_rgb(0x10, 0xa0, 0x40);
/// Toolpath: the block executing.
pub const TOOLPATH_CURRENT: Color32 = Color32::from_rgb(0xff, 0x8c, 0x00);
/// Toolpath: the block a click picked.
pub const TOOLPATH_PICKED: Color32 = Color32::from_rgb(0xd0, 0x20, 0x80);
/// Toolpath: the tool's point.
pub const TOOLPATH_TOOL: Color32 = Color32::from_rgb(0xc0, 0x10, 0x10);
/// A bit's lane in the signal trace, where the bit is 1.
pub const TRACE_BIT: Color32 = Color32::from_rgb(0x10, 0xa0, 0x40);
/// A bit's lane in the signal trace, where the bit is 0.
pub const TRACE_BIT_LOW: Color32 = Color32::from_rgb(0x80, 0x80, 0x88);
/// The edges of a trace where a signal changes.
pub const TRACE_EDGE: Color32 = Color32::from_rgb(0x60, 0x90, 0x70);
/// A value's lane in the signal trace.
pub const TRACE_VALUE: Color32 = Color32::from_rgb(0x30, 0x70, 0xe0);
/// The cursor line of the signal trace.
pub const TRACE_CURSOR: Color32 = Color32::from_rgb(0xe0, 0x30, 0x30);

/// The grey ink of printed pages (comments, headers) in the print preview.
pub const PRINT_GREY: Color32 = Color32::from_gray(96);
/// Around the pages of the print preview.
pub const PRINT_DESK: Color32 = Color32::from_gray(150);
