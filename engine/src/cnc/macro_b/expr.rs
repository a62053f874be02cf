//! Custom Macro B expressions (docs/gcode.md, "Macros"): read once from a block's text into a
//! tree, evaluated each time the block runs. A value is `Option<f64>`: `None` is a vacant
//! variable, which arithmetic reads as 0 but a plain variable reference, `EQ`/`NE` and a word
//! value keep apart from 0.

use crate::cnc::ps as alarm;

/// Deepest nesting of brackets (function brackets included); one more is alarm 0118.
pub const BRACKETS_MAX: usize = 5;

/// A binary operator.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Op {
    /// `+`.
    Add,
    /// `-`.
    Sub,
    /// `OR`, bit by bit on integers.
    Or,
    /// `XOR`, bit by bit on integers.
    Xor,
    /// `*`.
    Mul,
    /// `/`.
    Div,
    /// `AND`, bit by bit on integers.
    And,
    /// `MOD`: the remainder of the integers, with the sign of the dividend.
    Mod,
    /// `EQ`.
    Eq,
    /// `NE`.
    Ne,
    /// `GT`.
    Gt,
    /// `GE`.
    Ge,
    /// `LT`.
    Lt,
    /// `LE`.
    Le,
}

/// A function of one argument.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Func {
    /// Sine of degrees.
    Sin,
    /// Cosine of degrees.
    Cos,
    /// Tangent of degrees.
    Tan,
    /// Arc sine, −90…90°.
    Asin,
    /// Arc cosine, 0…180°.
    Acos,
    /// Arc tangent of one value, −90…90°.
    Atan,
    /// Square root.
    Sqrt,
    /// Absolute value.
    Abs,
    /// Rounded half away from zero.
    Round,
    /// Fraction dropped (towards zero).
    Fix,
    /// Fraction raised (away from zero).
    Fup,
    /// Natural logarithm.
    Ln,
    /// e to the power.
    Exp,
    /// BCD to binary.
    Bin,
    /// Binary to BCD.
    Bcd,
}

/// A function of two arguments.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Func2 {
    /// `ATAN[y]/[x]` or `ATAN[y,x]`: 0…360°.
    Atan2,
    /// `POW[a,b]`: a to the power b.
    Pow,
}

/// An expression.
#[derive(Clone, Debug, PartialEq)]
pub enum Expr {
    /// A constant.
    Const(f64),
    /// `#n`.
    Var(i64),
    /// `#[e]`: the variable whose number is the rounded value of e.
    VarAt(Box<Expr>),
    /// `-e`: keeps a vacant value vacant.
    Neg(Box<Expr>),
    /// `a op b`.
    Bin(Op, Box<Expr>, Box<Expr>),
    /// `F[e]`.
    Call(Func, Box<Expr>),
    /// `F[a,b]`.
    Call2(Func2, Box<Expr>, Box<Expr>),
}

/// Where an expression reads its variables.
pub trait Vars {
    /// The value of variable `n`, `None` when vacant, or the alarm reading it gives.
    fn read(&self, n: i64) -> Result<Option<f64>, u16>;

    /// #6004 bit 0 NAT: 1 gives ASIN and ATAN −90…90° and −180…180°, 0 gives 270…90° and
    /// 0…360°.
    fn nat(&self) -> bool {
        false
    }
}

/// How an expression is evaluated.
struct Ctx<'a> {
    vars: &'a dyn Vars,
    /// In an NC address: ROUND rounds to this many decimals (the address's least increment).
    round: Option<i32>,
    nat: bool,
}

/// A value: `None` is vacant.
pub type Value = Option<f64>;

/// Rounded half away from zero to an integer (a variable number, a bit operand).
pub fn round_half(v: f64) -> f64 {
    v.round()
}

fn int(v: Value) -> Result<i64, u16> {
    let r = round_half(v.unwrap_or(0.0));
    // Whole numbers are exact in f64 up to 2^53: beyond, bits and remainders mean nothing.
    if r.abs() > 9_007_199_254_740_992.0 {
        return Err(alarm::OVERFLOW);
    }
    Ok(r as i64)
}

fn finite(v: f64) -> Result<Value, u16> {
    if v.is_finite() {
        Ok(Some(if v == 0.0 { 0.0 } else { v }))
    } else {
        Err(alarm::OVERFLOW)
    }
}

fn rad(deg: f64) -> f64 {
    deg.to_radians()
}

fn deg(r: f64) -> f64 {
    r.to_degrees()
}

/// Sine and cosine snap to exact values at multiples of 90° (sin 180° is 0, not 1.2e-16).
fn trig(f: fn(f64) -> f64, d: f64) -> f64 {
    let v = f(rad(d));
    let r = v.round();
    if (v - r).abs() < 1e-15 { r } else { v }
}

/// An angle of −90…90° as NAT = 0 gives it: 270…90°.
fn positive(d: f64, nat: bool) -> f64 {
    if !nat && d < 0.0 { d + 360.0 } else { d }
}

impl Func {
    fn apply(self, v: f64, ctx: &Ctx) -> Result<Value, u16> {
        let bad = Err(alarm::ARGUMENT);
        let r = match self {
            Func::Sin => trig(f64::sin, v),
            Func::Cos => trig(f64::cos, v),
            Func::Tan => {
                if ((v - 90.0) / 180.0).fract() == 0.0 {
                    return bad;
                }
                trig(f64::tan, v)
            }
            Func::Asin if v.abs() > 1.0 => return bad,
            Func::Asin => positive(deg(v.asin()), ctx.nat),
            Func::Acos if v.abs() > 1.0 => return bad,
            Func::Acos => deg(v.acos()),
            Func::Atan => positive(deg(v.atan()), ctx.nat),
            Func::Sqrt if v < 0.0 => return bad,
            Func::Sqrt => v.sqrt(),
            Func::Abs => v.abs(),
            Func::Round => match ctx.round {
                Some(p) => {
                    let scale = 10f64.powi(p);
                    (v * scale).round() / scale
                }
                None => v.round(),
            },
            Func::Fix => v.trunc(),
            Func::Fup => {
                let t = v.trunc();
                if t == v { t } else { t + v.signum() }
            }
            Func::Ln if v <= 0.0 => return bad,
            Func::Ln => v.ln(),
            Func::Exp => v.exp(),
            Func::Bin => bin(v)?,
            Func::Bcd => bcd(v)?,
        };
        finite(r)
    }
}

/// BCD to binary: every nibble must be a decimal digit.
fn bin(v: f64) -> Result<f64, u16> {
    if v < 0.0 || v.fract() != 0.0 || v > 4_294_967_295.0 {
        return Err(alarm::ARGUMENT);
    }
    let mut x = v as u64;
    let (mut out, mut place) = (0u64, 1u64);
    while x > 0 {
        let d = x & 0xF;
        if d > 9 {
            return Err(alarm::ARGUMENT);
        }
        out += d * place;
        place *= 10;
        x >>= 4;
    }
    Ok(out as f64)
}

/// Binary to BCD, up to eight digits.
fn bcd(v: f64) -> Result<f64, u16> {
    if v < 0.0 || v.fract() != 0.0 || v > 99_999_999.0 {
        return Err(alarm::ARGUMENT);
    }
    let mut x = v as u64;
    let (mut out, mut shift) = (0u64, 0);
    while x > 0 {
        out |= (x % 10) << shift;
        shift += 4;
        x /= 10;
    }
    Ok(out as f64)
}

impl Func2 {
    fn apply(self, a: f64, b: f64, nat: bool) -> Result<Value, u16> {
        let r = match self {
            Func2::Atan2 => {
                if a == 0.0 && b == 0.0 {
                    return Err(alarm::ARGUMENT);
                }
                // NAT = 0: 0…360°; NAT = 1: −180…180°.
                positive(deg(a.atan2(b)), nat)
            }
            Func2::Pow => {
                if (a == 0.0 && b <= 0.0) || (a < 0.0 && b.fract() != 0.0) {
                    return Err(alarm::ARGUMENT);
                }
                a.powf(b)
            }
        };
        finite(r)
    }
}

impl Op {
    fn apply(self, a: Value, b: Value) -> Result<Value, u16> {
        // EQ and NE tell vacant from 0; every other operator reads vacant as 0.
        match self {
            Op::Eq => return Ok(Some(f64::from(u8::from(a == b)))),
            Op::Ne => return Ok(Some(f64::from(u8::from(a != b)))),
            _ => {}
        }
        let (x, y) = (a.unwrap_or(0.0), b.unwrap_or(0.0));
        let truth = |t: bool| Ok(Some(f64::from(u8::from(t))));
        match self {
            Op::Add => finite(x + y),
            Op::Sub => finite(x - y),
            Op::Mul => finite(x * y),
            Op::Div if y == 0.0 => Err(alarm::DIVISION),
            Op::Div => finite(x / y),
            Op::Or => Ok(Some((int(a)? | int(b)?) as f64)),
            Op::Xor => Ok(Some((int(a)? ^ int(b)?) as f64)),
            Op::And => Ok(Some((int(a)? & int(b)?) as f64)),
            Op::Mod => {
                let (i, k) = (int(a)?, int(b)?);
                if k == 0 {
                    return Err(alarm::DIVISION);
                }
                Ok(Some((i % k) as f64))
            }
            Op::Gt => truth(x > y),
            Op::Ge => truth(x >= y),
            Op::Lt => truth(x < y),
            Op::Le => truth(x <= y),
            Op::Eq | Op::Ne => unreachable!("handled above"),
        }
    }
}

impl Expr {
    /// The value, or the alarm evaluating it gives.
    pub fn eval(&self, vars: &dyn Vars) -> Result<Value, u16> {
        self.eval_in(vars, None)
    }

    /// The value in an NC address whose least increment has `round` decimals (ROUND rounds
    /// to it), or anywhere else with `None`.
    pub fn eval_in(&self, vars: &dyn Vars, round: Option<i32>) -> Result<Value, u16> {
        self.value(&Ctx {
            vars,
            round,
            nat: vars.nat(),
        })
    }

    fn value(&self, c: &Ctx) -> Result<Value, u16> {
        match self {
            Expr::Const(v) => Ok(Some(*v)),
            Expr::Var(n) => c.vars.read(*n),
            Expr::VarAt(e) => c.vars.read(int(e.value(c)?)?),
            Expr::Neg(e) => Ok(e.value(c)?.map(|v| if v == 0.0 { 0.0 } else { -v })),
            Expr::Bin(op, a, b) => op.apply(a.value(c)?, b.value(c)?),
            Expr::Call(f, e) => f.apply(e.value(c)?.unwrap_or(0.0), c),
            Expr::Call2(f, a, b) => f.apply(
                a.value(c)?.unwrap_or(0.0),
                b.value(c)?.unwrap_or(0.0),
                c.nat,
            ),
        }
    }

    /// The variable number of a `#` target when it is a constant.
    pub fn var_number(&self, vars: &dyn Vars) -> Result<i64, u16> {
        match self {
            Expr::Var(n) => Ok(*n),
            Expr::VarAt(e) => int(e.eval(vars)?),
            _ => Err(alarm::FORMAT),
        }
    }
}

/// A reader of expressions over a block's text (upper case, no spaces).
pub struct Parser<'a> {
    b: &'a [u8],
    /// The byte the reader is at.
    pub at: usize,
    depth: usize,
}

const FUNCS: [(&str, Func); 15] = [
    ("ASIN", Func::Asin),
    ("ACOS", Func::Acos),
    ("ATAN", Func::Atan),
    ("SIN", Func::Sin),
    ("COS", Func::Cos),
    ("TAN", Func::Tan),
    ("SQRT", Func::Sqrt),
    ("ABS", Func::Abs),
    ("ROUND", Func::Round),
    ("FIX", Func::Fix),
    ("FUP", Func::Fup),
    ("LN", Func::Ln),
    ("EXP", Func::Exp),
    ("BIN", Func::Bin),
    ("BCD", Func::Bcd),
];

/// The operators of the lowest level but comparisons: XOR before OR, which it ends with.
const SUMS: [(&str, Op); 4] = [
    ("+", Op::Add),
    ("-", Op::Sub),
    ("XOR", Op::Xor),
    ("OR", Op::Or),
];

/// The operators that bind tighter than the sums.
const PRODUCTS: [(&str, Op); 4] = [
    ("*", Op::Mul),
    ("/", Op::Div),
    ("AND", Op::And),
    ("MOD", Op::Mod),
];

const COMPARISONS: [(&str, Op); 6] = [
    ("EQ", Op::Eq),
    ("NE", Op::Ne),
    ("GT", Op::Gt),
    ("GE", Op::Ge),
    ("LT", Op::Lt),
    ("LE", Op::Le),
];

impl<'a> Parser<'a> {
    /// A reader at the start of `text`.
    pub fn new(text: &'a str) -> Parser<'a> {
        Parser {
            b: text.as_bytes(),
            at: 0,
            depth: 0,
        }
    }

    /// The text not read yet.
    pub fn rest(&self) -> &'a [u8] {
        &self.b[self.at..]
    }

    /// Reads `word` when the text goes on with it.
    pub fn eat(&mut self, word: &str) -> bool {
        if self.rest().starts_with(word.as_bytes()) {
            self.at += word.len();
            true
        } else {
            false
        }
    }

    fn peek(&self) -> Option<u8> {
        self.b.get(self.at).copied()
    }

    /// A whole expression: a comparison at most, of sums.
    pub fn expr(&mut self) -> Result<Expr, u16> {
        let a = self.sum()?;
        match self.operator(&COMPARISONS) {
            Some(op) => {
                let b = self.sum()?;
                Ok(Expr::Bin(op, Box::new(a), Box::new(b)))
            }
            None => Ok(a),
        }
    }

    /// The operator the text goes on with, of those in `table` (tried in order).
    fn operator(&mut self, table: &[(&str, Op)]) -> Option<Op> {
        table
            .iter()
            .find(|(name, _)| self.eat(name))
            .map(|(_, op)| *op)
    }

    fn sum(&mut self) -> Result<Expr, u16> {
        let mut a = self.product()?;
        while let Some(op) = self.operator(&SUMS) {
            let b = self.product()?;
            a = Expr::Bin(op, Box::new(a), Box::new(b));
        }
        Ok(a)
    }

    fn product(&mut self) -> Result<Expr, u16> {
        let mut a = self.unary()?;
        while let Some(op) = self.operator(&PRODUCTS) {
            let b = self.unary()?;
            a = Expr::Bin(op, Box::new(a), Box::new(b));
        }
        Ok(a)
    }

    /// A signed primary: what a word's value may be (`-#1`, `[#2+1]`, `1.5`).
    pub fn unary(&mut self) -> Result<Expr, u16> {
        // A run of signs is read in a loop: only whether the minus signs are odd counts.
        let mut negative = false;
        loop {
            if self.eat("-") {
                negative = !negative;
            } else if !self.eat("+") {
                break;
            }
        }
        let e = self.primary()?;
        Ok(if negative { Expr::Neg(Box::new(e)) } else { e })
    }

    fn bracket(&mut self) -> Result<Expr, u16> {
        if !self.eat("[") {
            return Err(alarm::FORMAT);
        }
        self.depth += 1;
        if self.depth > BRACKETS_MAX {
            return Err(alarm::BRACKETS);
        }
        let e = self.expr()?;
        if !self.eat("]") {
            return Err(alarm::FORMAT);
        }
        self.depth -= 1;
        Ok(e)
    }

    fn primary(&mut self) -> Result<Expr, u16> {
        match self.peek() {
            Some(b'#') => {
                self.at += 1;
                if self.peek() == Some(b'[') {
                    return Ok(Expr::VarAt(Box::new(self.bracket()?)));
                }
                let start = self.at;
                while self.peek().is_some_and(|c| c.is_ascii_digit()) {
                    self.at += 1;
                }
                if start == self.at || self.peek() == Some(b'.') {
                    return Err(alarm::FORMAT);
                }
                let text =
                    std::str::from_utf8(&self.b[start..self.at]).map_err(|_| alarm::FORMAT)?;
                let n: i64 = text.parse().map_err(|_| alarm::VARIABLE)?;
                Ok(Expr::Var(n))
            }
            Some(b'[') => self.bracket(),
            Some(c) if c.is_ascii_digit() || c == b'.' => self.constant(),
            _ => self.function(),
        }
    }

    fn constant(&mut self) -> Result<Expr, u16> {
        let start = self.at;
        while self.peek().is_some_and(|c| c.is_ascii_digit() || c == b'.') {
            self.at += 1;
        }
        let text = std::str::from_utf8(&self.b[start..self.at]).map_err(|_| alarm::FORMAT)?;
        let v: f64 = text.parse().map_err(|_| alarm::FORMAT)?;
        Ok(Expr::Const(v))
    }

    fn function(&mut self) -> Result<Expr, u16> {
        if self.eat("POW") {
            let (a, b) = self.two()?;
            return Ok(Expr::Call2(Func2::Pow, Box::new(a), Box::new(b)));
        }
        if self.rest().starts_with(b"ATAN") {
            // ATAN[a]/[b] and ATAN[a,b] take two arguments; ATAN[a] one.
            let save = self.at;
            self.at += 4;
            if let Ok((a, b)) = self.two() {
                return Ok(Expr::Call2(Func2::Atan2, Box::new(a), Box::new(b)));
            }
            self.at = save + 4;
            let a = self.bracket()?;
            if self.rest().starts_with(b"/[") {
                self.at += 1;
                let b = self.bracket()?;
                return Ok(Expr::Call2(Func2::Atan2, Box::new(a), Box::new(b)));
            }
            return Ok(Expr::Call(Func::Atan, Box::new(a)));
        }
        for (name, f) in FUNCS {
            if self.rest().starts_with(name.as_bytes())
                && self.b.get(self.at + name.len()) == Some(&b'[')
            {
                self.at += name.len();
                return Ok(Expr::Call(f, Box::new(self.bracket()?)));
            }
        }
        Err(alarm::FORMAT)
    }

    /// `[a,b]`.
    fn two(&mut self) -> Result<(Expr, Expr), u16> {
        let depth = self.depth;
        let save = self.at;
        let r = (|| {
            if !self.eat("[") {
                return Err(alarm::FORMAT);
            }
            self.depth += 1;
            if self.depth > BRACKETS_MAX {
                return Err(alarm::BRACKETS);
            }
            let a = self.expr()?;
            if !self.eat(",") {
                return Err(alarm::FORMAT);
            }
            let b = self.expr()?;
            if !self.eat("]") {
                return Err(alarm::FORMAT);
            }
            Ok((a, b))
        })();
        self.depth = depth;
        if r.is_err() {
            self.at = save;
        }
        r
    }
}
