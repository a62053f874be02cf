//! Custom Macro B (docs/gcode.md, "Macros"): variables, expressions, IF/GOTO, WHILE/DO/END,
//! G65/G66 calls and the macro side of the PLC interface (#1000–#1032 from G214–G217,
//! #1100–#1133 to F214–F217).
//!
//! A block is read once, when its program is loaded, into a [`MacroBlock`] when it holds a
//! statement or an expression (`parse`); `run` executes statements between NC blocks and
//! ahead of the executing one, `vars` reads and writes every variable, and `render` turns an
//! NC block's expressions into the words the G-code reader already knows.

pub(crate) mod expr;
pub(crate) mod parse;
mod render;
pub(super) mod run;
mod vars;

use expr::Expr;

pub use run::MacroCall;
pub use vars::{LOCALS, Locals, MacroTable, exists};

/// First number of the alarms #3000 raises: #3000 = n gives alarm 3000 + n.
pub const ALARM_BASE: u16 = 3000;

/// Largest n of `#3000 = n`.
pub const ALARM_MAX: u16 = 200;

/// A word's value as written: a number or an expression.
#[derive(Clone, Debug, PartialEq)]
pub enum WordValue {
    /// A number as written (sign, digits, point).
    Lit(String),
    /// An expression, evaluated when the block executes.
    Expr(Expr),
}

/// One word of an NC block that holds expressions. `,C` and `,R` are the letters `c` and
/// `r`.
#[derive(Clone, Debug, PartialEq)]
pub struct Word {
    /// The address letter.
    pub letter: u8,
    /// Its value.
    pub value: WordValue,
}

/// `#i = e`.
#[derive(Clone, Debug, PartialEq)]
pub struct Assign {
    /// The variable written: `Expr::Var` or `Expr::VarAt`.
    pub target: Expr,
    /// The value written.
    pub value: Expr,
    /// The block's comment: the message of `#3000 = n (MESSAGE)`.
    pub message: Option<String>,
}

/// What `IF [cond]` does when the condition holds.
#[derive(Clone, Debug, PartialEq)]
pub enum Then {
    /// `GOTO n`.
    Goto(Expr),
    /// `THEN #i = e`.
    Assign(Assign),
}

/// A block that is a macro statement, an NC block with expressions, or a macro call.
#[derive(Clone, Debug, PartialEq)]
pub enum MacroBlock {
    /// `#i = e`.
    Assign(Assign),
    /// `IF [cond] GOTO n` or `IF [cond] THEN #i = e`.
    If {
        /// The condition: true when not 0 and not vacant.
        cond: Expr,
        /// What it does.
        then: Then,
    },
    /// `GOTO n`.
    Goto(Expr),
    /// `WHILE [cond] DO m`, or `DO m` alone (an endless loop).
    Do {
        /// The condition, `None` for `DO m` alone.
        cond: Option<Expr>,
        /// m as written.
        id: u8,
        /// The block index of its END, or the alarm a missing pair gives.
        end: Result<usize, u16>,
    },
    /// `END m`.
    End {
        /// m as written.
        id: u8,
        /// The block index of its DO, or the alarm.
        start: Result<usize, u16>,
    },
    /// An NC block with at least one expression word.
    Nc(Vec<Word>),
    /// POPEN, PCLOS, DPRNT[…] or BPRNT[…]: external output, which has no device here and
    /// does nothing.
    Output,
    /// `G65 P L args` or `G66 P L args`.
    Call {
        /// G66: a modal call after each move.
        modal: bool,
        /// P: the program number.
        program: WordValue,
        /// L: how many times.
        count: Option<WordValue>,
        /// The arguments in the order written.
        args: Vec<(u8, WordValue)>,
    },
}

impl MacroBlock {
    /// Whether the block is a macro statement: runs ahead of the NC block before it and does
    /// not stop single block (an NC block with expressions and a call are not).
    pub fn is_statement(&self) -> bool {
        !matches!(self, MacroBlock::Nc(_) | MacroBlock::Call { .. })
    }
}
