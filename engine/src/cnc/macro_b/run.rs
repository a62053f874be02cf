//! Running macro statements (docs/gcode.md, "Macros", "How statements run"): between NC
//! blocks, ahead of the NC block that has just started, and G65/G66 calls.
//!
//! Statements take no time: a run of them ends at the next NC block, at
//! [`STATEMENTS_PER_EXCHANGE`], or when a loop comes back to where it came back to before
//! without any variable written since — nothing can change before the next exchange samples
//! the PLC again, so the loop waits there (a program waiting in WHILE for #1000 costs one
//! pass per exchange).

use super::expr::{Expr, Value, Vars, round_half};
use super::vars::{LOCALS, Locals};
use super::{Assign, MacroBlock, Then, WordValue};
use crate::cnc::SimCnc;
use crate::cnc::frame::{Cursor, Frame, MDI};
use crate::cnc::params::{P3401, P3411, P6000};
use crate::cnc::program::NcProgram;
use crate::cnc::ps;

/// Most macro statements run in one exchange.
pub const STATEMENTS_PER_EXCHANGE: u32 = 10_000;

/// Most macro call levels (G65, G66) nested.
pub const CALL_LEVELS: usize = 5;

/// A G66 modal call in effect: the program called after each move, how many times, and the
/// arguments.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MacroCall {
    /// Program index.
    pub prog: usize,
    /// L.
    pub times: u32,
    /// The locals the call starts with.
    pub args: Locals,
}

/// What running one statement leads to.
pub(in crate::cnc) enum Flow {
    /// Go on at the cursor.
    Next,
    /// Wait for the next exchange.
    Yield,
    /// Stop (single block with #6000 bit 5 SBM).
    Stop,
    /// An alarm.
    Alarm(u16),
}

/// Truth of a condition: not 0 and not vacant.
fn truth(v: Value) -> bool {
    v.is_some_and(|x| x != 0.0)
}

/// FANUC's argument specification I: A B C D E F H I J K M Q R S T U V W X Y Z; I, J and K
/// also count in sets of three (specification II: I1 J1 K1 … I10 J10 K10, #4–#33), a set
/// ending when a letter does not come after the one before in I, J, K order.
fn arg_slot(letter: u8, ijk: &mut (usize, u8)) -> Option<usize> {
    let fixed = match letter {
        b'A' => 1,
        b'B' => 2,
        b'C' => 3,
        b'D' => 7,
        b'E' => 8,
        b'F' => 9,
        b'H' => 11,
        b'M' => 13,
        b'Q' => 17,
        b'R' => 18,
        b'S' => 19,
        b'T' => 20,
        b'U' => 21,
        b'V' => 22,
        b'W' => 23,
        b'X' => 24,
        b'Y' => 25,
        b'Z' => 26,
        b'I' | b'J' | b'K' => {
            let (set, last) = ijk;
            if *last != 0 && letter <= *last {
                *set += 1;
            }
            *last = letter;
            let slot = 4 + 3 * *set + usize::from(letter - b'I');
            return (slot <= LOCALS).then_some(slot);
        }
        _ => return None,
    };
    Some(fixed)
}

impl SimCnc {
    fn program_of(&self, prog: usize) -> &NcProgram {
        if prog == MDI {
            &self.mdi
        } else {
            &self.programs[prog]
        }
    }

    /// Runs the macro block at the cursor (a statement or a call).
    pub(in crate::cnc) fn macro_step(&mut self) -> Flow {
        let c = self.auto.cursor;
        // The programs are shared while the block runs: statements change variables and the
        // cursor, never the program text.
        let programs = std::sync::Arc::clone(&self.programs);
        let mdi = std::sync::Arc::clone(&self.mdi);
        let prog = if c.prog == MDI {
            &*mdi
        } else {
            &programs[c.prog]
        };
        if let Some(n) = prog.blocks[c.block].n {
            self.auto.read_n = n;
        }
        let flow = match prog.blocks[c.block].mac.as_deref() {
            Some(m) => self.run_statement(m, prog, &programs, c),
            None => Flow::Next,
        };
        if matches!(flow, Flow::Next) && self.single_block() && self.params.bit(P6000, 0, 5) {
            return Flow::Stop;
        }
        flow
    }

    /// Single block is in effect: SBK and not suppressed by #3003 bit 0.
    pub(in crate::cnc) fn single_block(&self) -> bool {
        self.inp.sbk && self.auto.m3003 & 1 == 0
    }

    /// Runs `#i = e`; true when it was #3006, which stops the program after it.
    fn assign(&mut self, a: &Assign) -> Result<bool, u16> {
        let v = a.value.eval(self as &dyn Vars)?;
        let n = a.target.var_number(self as &dyn Vars)?;
        self.write_var(n, v, a.message.as_deref())?;
        Ok(n == 3006)
    }

    fn run_statement(
        &mut self,
        m: &MacroBlock,
        prog: &NcProgram,
        programs: &[NcProgram],
        c: Cursor,
    ) -> Flow {
        let r = (|| -> Result<Flow, u16> {
            let next = Cursor {
                block: c.block + 1,
                ..c
            };
            match m {
                MacroBlock::Assign(a) => {
                    if self.assign(a)? {
                        // #3006 = n (MESSAGE): stop after this statement, as M00 does.
                        self.auto.cursor = next;
                        return Ok(Flow::Stop);
                    }
                }
                MacroBlock::If { cond, then } => {
                    if truth(cond.eval(self as &dyn Vars)?) {
                        match then {
                            Then::Goto(e) => return self.goto(e, prog, c),
                            Then::Assign(a) => {
                                if self.assign(a)? {
                                    self.auto.cursor = next;
                                    return Ok(Flow::Stop);
                                }
                            }
                        }
                    }
                }
                MacroBlock::Goto(e) => return self.goto(e, prog, c),
                MacroBlock::Do { cond, end, .. } => {
                    let end = (*end)?;
                    let go = match cond {
                        Some(e) => truth(e.eval(self as &dyn Vars)?),
                        None => true,
                    };
                    if !go {
                        self.auto.cursor.block = end + 1;
                        return Ok(Flow::Next);
                    }
                }
                MacroBlock::End { start, .. } => return Ok(self.jump(c, (*start)?)),
                MacroBlock::Call {
                    modal,
                    program,
                    count,
                    args,
                } => {
                    let call = self.macro_call(program, count.as_ref(), args, programs)?;
                    if *modal {
                        self.auto.g66 = Some(call);
                    } else {
                        self.push_call(call, next, false)?;
                        return Ok(Flow::Next);
                    }
                }
                MacroBlock::Nc(_) | MacroBlock::Output => {}
            }
            self.auto.cursor = next;
            Ok(Flow::Next)
        })();
        r.unwrap_or_else(Flow::Alarm)
    }

    /// Jumps to block `to` of the running program; a jump back to where the last jump back
    /// went, with no variable written since, waits for the next exchange.
    fn jump(&mut self, c: Cursor, to: usize) -> Flow {
        self.auto.cursor = Cursor { block: to, ..c };
        if to > c.block {
            return Flow::Next;
        }
        let mark = (c.prog, to, self.auto.macro_writes);
        if self.auto.idle_mark == Some(mark) {
            return Flow::Yield;
        }
        self.auto.idle_mark = Some(mark);
        Flow::Next
    }

    fn goto(&mut self, e: &Expr, prog: &NcProgram, c: Cursor) -> Result<Flow, u16> {
        let n = e.eval(self as &dyn Vars)?.ok_or(ps::SEQUENCE)?;
        let n = round_half(n);
        if !(1.0..=99_999.0).contains(&n) {
            return Err(ps::SEQUENCE);
        }
        let to =
            crate::cnc::program::find_sequence(prog, n as u32, c.block + 1).ok_or(ps::SEQUENCE)?;
        Ok(self.jump(c, to))
    }

    /// The value of an argument word: a number as written follows #3401 DPI for length
    /// addresses like the word itself would.
    fn arg_value(&self, letter: u8, v: &WordValue) -> Result<Value, u16> {
        match v {
            WordValue::Expr(e) => e.eval(self as &dyn Vars),
            WordValue::Lit(t) => {
                let x: f64 = t.parse().map_err(|_| ps::ADDRESS)?;
                let length = matches!(
                    letter,
                    b'X' | b'Y' | b'Z' | b'U' | b'V' | b'W' | b'I' | b'J' | b'K' | b'R'
                );
                if length && !t.contains('.') && !self.params.bit(P3401, 0, 0) {
                    let least = if self.auto.modal.inch { 0.0001 } else { 0.001 };
                    Ok(Some(x * least))
                } else {
                    Ok(Some(x))
                }
            }
        }
    }

    /// A G65/G66 block's program, count and locals.
    fn macro_call(
        &self,
        program: &WordValue,
        count: Option<&WordValue>,
        args: &[(u8, WordValue)],
        programs: &[NcProgram],
    ) -> Result<MacroCall, u16> {
        let whole = |v: Value| -> Result<u32, u16> {
            let x = round_half(v.ok_or(ps::ADDRESS)?);
            if !(0.0..=99_999_999.0).contains(&x) {
                return Err(ps::ADDRESS);
            }
            Ok(x as u32)
        };
        let number = whole(self.arg_value(b'P', program)?)?;
        let prog = programs
            .iter()
            .position(|p| p.number == number)
            .ok_or(ps::NO_PROGRAM)?;
        let times = match count {
            Some(v) => whole(self.arg_value(b'L', v)?)?.max(1),
            None => 1,
        };
        let mut locals = [None; LOCALS];
        let mut ijk = (0, 0);
        for (letter, v) in args {
            let slot = arg_slot(*letter, &mut ijk).ok_or(ps::ARG_ADDRESS)?;
            locals[slot - 1] = self.arg_value(*letter, v)?;
        }
        Ok(MacroCall {
            prog,
            times,
            args: locals,
        })
    }

    /// Enters a macro call: a new level of locals; `modal` for a G66 call.
    pub(in crate::cnc) fn push_call(
        &mut self,
        call: MacroCall,
        ret: Cursor,
        modal: bool,
    ) -> Result<(), u16> {
        let a = &mut self.auto;
        if a.stack.iter().filter(|f| f.args.is_some()).count() >= CALL_LEVELS {
            return Err(ps::NESTING);
        }
        if a.locals.is_empty() {
            a.locals.push([None; LOCALS]);
        }
        a.locals.push(call.args);
        a.stack.push(Frame {
            ret,
            sub: call.prog,
            start: 0,
            repeats: call.times - 1,
            until: None,
            args: Some(call.args),
            modal,
        });
        a.cursor = Cursor {
            prog: call.prog,
            block: 0,
        };
        Ok(())
    }

    /// Whether macro statements may run ahead of the NC block just started: not in single
    /// block, not inside a G70 profile, not after a block that ends, stops, calls or returns,
    /// and not after an M code of #3411–#3420.
    fn may_look_ahead(&self) -> bool {
        let a = &self.auto;
        let Some(e) = a.exec else { return false };
        let flow = e.stop_after
            || e.end
            || e.call.is_some()
            || e.ret
            || e.g70.is_some()
            || e.resume.is_some()
            || e.modal_call;
        let profile = a.stack.last().is_some_and(|f| f.until.is_some());
        let ms = &e.mst.m[..3];
        let unbuffered = (0..10).any(|k| {
            let p = self.params.one(P3411 + k);
            p != 0 && ms.iter().any(|&m| i64::from(m) == p && m != 0)
        });
        !(flow || profile || unbuffered || self.single_block())
    }

    /// Runs the macro statements after the NC block that has just started, up to the next
    /// NC block; the program goes on there when the block ends.
    pub(in crate::cnc) fn look_ahead(&mut self) {
        if !self.may_look_ahead() {
            return;
        }
        let from = Cursor {
            block: self.auto.cursor.block + 1,
            ..self.auto.cursor
        };
        self.run_ahead(from);
    }

    /// While the block executes, statements that ran ahead and stopped in a loop (waiting for
    /// the PLC, or out of the exchange's share) go on, once an exchange, as the CNC keeps
    /// reading ahead during the move.
    pub(in crate::cnc) fn continue_ahead(&mut self) {
        if let Some(e) = self.auto.exec
            && e.ahead_waiting
            && let Some(from) = e.next
            && self.alarms.is_empty()
            && !self.single_block()
        {
            self.run_ahead(from);
        }
    }

    /// Runs statements from `from` with the executing block's cursor kept; records where
    /// they stopped and whether they stopped short of an NC block.
    fn run_ahead(&mut self, from: Cursor) {
        let here = self.auto.cursor;
        self.auto.cursor = from;
        let mut budget = STATEMENTS_PER_EXCHANGE;
        let mut waiting = false;
        let mut stop = false;
        loop {
            let c = self.auto.cursor;
            let statement = self
                .program_of(c.prog)
                .blocks
                .get(c.block)
                .is_some_and(|b| !b.slash && b.mac.as_ref().is_some_and(|m| m.is_statement()));
            if !statement {
                break;
            }
            if budget == 0 {
                waiting = true;
                break;
            }
            budget -= 1;
            match self.macro_step() {
                Flow::Next => {}
                Flow::Stop => {
                    // #3006 (or SBM) ahead: the moving block ends, then the program stops.
                    stop = true;
                    break;
                }
                Flow::Yield => {
                    waiting = true;
                    break;
                }
                Flow::Alarm(n) => {
                    // The alarm names the statement's block and line, not the moving block's.
                    let (seq, line) = self
                        .program_of(c.prog)
                        .blocks
                        .get(c.block)
                        .map_or((None, None), |b| (b.n, Some(b.line)));
                    if let Some(seq) = seq {
                        self.auto.last_n = seq;
                    }
                    if let (Some(line), Some(e)) = (line, self.auto.exec.as_mut()) {
                        e.line = line;
                    }
                    self.raise(n);
                    break;
                }
            }
        }
        let next = self.auto.cursor;
        self.auto.cursor = here;
        if let Some(e) = self.auto.exec.as_mut() {
            e.next = Some(next);
            e.ahead_waiting = waiting;
            e.stop_after |= stop;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn arguments_follow_fanucs_two_specifications() {
        let slots = |letters: &str| {
            let mut ijk = (0, 0);
            letters
                .bytes()
                .map(|l| arg_slot(l, &mut ijk))
                .collect::<Vec<_>>()
        };
        assert_eq!(
            slots("ABCXYZ"),
            [Some(1), Some(2), Some(3), Some(24), Some(25), Some(26)]
        );
        // I J K then I again: the second set starts at #7.
        assert_eq!(
            slots("IJKIJK"),
            [Some(4), Some(5), Some(6), Some(7), Some(8), Some(9)]
        );
        // K then J: J belongs to the next set.
        assert_eq!(slots("IKJ"), [Some(4), Some(6), Some(8)]);
        // The tenth set is #31–#33; an eleventh has no slot.
        let ten = "I".repeat(11);
        let s = slots(&ten);
        assert_eq!((s[9], s[10]), (Some(31), None));
        assert_eq!(slots("G"), [None]);
    }
}
