//! Arithmetic over a check's named inputs, written once and read two ways: as a spreadsheet
//! formula (over the inputs' cells, or over their symbols for reading) and as its value in
//! double precision, which the workbook stores as the formula's cached result. A reader that
//! does not recalculate then shows the same number a spreadsheet recomputes.

use std::ops::{Add, Div, Mul, Sub};

/// An expression over named inputs.
#[derive(Debug, Clone, PartialEq)]
pub enum Expr {
    /// The input of this name (a check's [`crate::check::Quantity::name`]).
    Input(&'static str),
    /// A constant.
    Num(f64),
    /// `left op right`.
    Bin(Op, Box<Expr>, Box<Expr>),
    /// A spreadsheet function of its arguments.
    Call(Func, Vec<Expr>),
}

/// The four operations.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Op {
    /// `+`
    Add,
    /// `-`
    Sub,
    /// `*`
    Mul,
    /// `/`
    Div,
}

/// The spreadsheet functions the workbook uses, each as Excel and LibreOffice define it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Func {
    /// `MAX(a, b, …)`
    Max,
    /// `MIN(a, b, …)`
    Min,
    /// `ABS(x)`
    Abs,
    /// `EXP(x)`
    Exp,
    /// `RADIANS(x)`: degrees to radians.
    Radians,
    /// `SIGN(x)`: −1, 0 or 1.
    Sign,
    /// `SQRT(x)`.
    Sqrt,
}

impl Op {
    fn symbol(self) -> char {
        match self {
            Op::Add => '+',
            Op::Sub => '-',
            Op::Mul => '*',
            Op::Div => '/',
        }
    }

    fn precedence(self) -> u8 {
        match self {
            Op::Add | Op::Sub => 1,
            Op::Mul | Op::Div => 2,
        }
    }

    fn apply(self, a: f64, b: f64) -> f64 {
        match self {
            Op::Add => a + b,
            Op::Sub => a - b,
            Op::Mul => a * b,
            Op::Div => a / b,
        }
    }
}

impl Func {
    fn name(self) -> &'static str {
        match self {
            Func::Max => "MAX",
            Func::Min => "MIN",
            Func::Abs => "ABS",
            Func::Exp => "EXP",
            Func::Radians => "RADIANS",
            Func::Sign => "SIGN",
            Func::Sqrt => "SQRT",
        }
    }

    fn apply(self, args: &[f64]) -> Option<f64> {
        let first = *args.first()?;
        Some(match self {
            Func::Max => args.iter().copied().fold(first, f64::max),
            Func::Min => args.iter().copied().fold(first, f64::min),
            Func::Abs => first.abs(),
            Func::Exp => first.exp(),
            Func::Radians => first.to_radians(),
            Func::Sign if first > 0.0 => 1.0,
            Func::Sign if first < 0.0 => -1.0,
            Func::Sign => 0.0,
            Func::Sqrt => first.sqrt(),
        })
    }
}

impl Expr {
    /// The expression's value with each input's value from `value`; `None` when an input is
    /// missing or the result is not finite.
    pub fn eval(&self, value: &dyn Fn(&str) -> Option<f64>) -> Option<f64> {
        let v = match self {
            Expr::Input(name) => value(name)?,
            Expr::Num(x) => *x,
            Expr::Bin(op, a, b) => op.apply(a.eval(value)?, b.eval(value)?),
            Expr::Call(f, args) => f.apply(&args.iter().map(|a| a.eval(value)).collect::<Option<Vec<_>>>()?)?,
        };
        v.is_finite().then_some(v)
    }

    /// The expression as spreadsheet text (without the leading `=`), each input written as
    /// `token(name)` (a cell reference, or the input's symbol); `None` when a token is missing.
    pub fn render(&self, token: &dyn Fn(&str) -> Option<String>) -> Option<String> {
        Some(match self {
            Expr::Input(name) => token(name)?,
            Expr::Num(x) => x.to_string(),
            Expr::Bin(op, a, b) => {
                let p = op.precedence();
                // The right operand keeps its brackets at equal precedence: a − (b − c) needs
                // them, and a + (b + c) keeps wrapcalc's order of the additions, so that the
                // spreadsheet rounds as wrapcalc does.
                let left = a.bracketed(a.precedence() < p, token)?;
                let right = b.bracketed(b.precedence() <= p, token)?;
                format!("{left}{}{right}", op.symbol())
            }
            Expr::Call(f, args) => {
                let args: Option<Vec<String>> = args.iter().map(|a| a.render(token)).collect();
                format!("{}({})", f.name(), args?.join(","))
            }
        })
    }

    fn bracketed(&self, brackets: bool, token: &dyn Fn(&str) -> Option<String>) -> Option<String> {
        let text = self.render(token)?;
        Some(if brackets { format!("({text})") } else { text })
    }

    fn precedence(&self) -> u8 {
        match self {
            Expr::Bin(op, ..) => op.precedence(),
            _ => 3,
        }
    }
}

/// The input named `name`.
pub fn input(name: &'static str) -> Expr {
    Expr::Input(name)
}

/// A constant.
pub fn num(x: f64) -> Expr {
    Expr::Num(x)
}

/// `f(args)`.
pub fn call(f: Func, args: Vec<Expr>) -> Expr {
    Expr::Call(f, args)
}

/// `MAX(a, b)`.
pub fn max(a: Expr, b: Expr) -> Expr {
    call(Func::Max, vec![a, b])
}

/// `MIN(a, b)`.
pub fn min(a: Expr, b: Expr) -> Expr {
    call(Func::Min, vec![a, b])
}

macro_rules! binary {
    ($trait:ident, $method:ident, $op:expr) => {
        impl $trait for Expr {
            type Output = Expr;
            fn $method(self, rhs: Expr) -> Expr {
                Expr::Bin($op, Box::new(self), Box::new(rhs))
            }
        }
    };
}
binary!(Add, add, Op::Add);
binary!(Sub, sub, Op::Sub);
binary!(Mul, mul, Op::Mul);
binary!(Div, div, Op::Div);

#[cfg(test)]
mod tests {
    use super::*;

    fn names(n: &str) -> Option<String> {
        Some(n.to_string())
    }

    #[test]
    fn brackets_only_where_precedence_needs_them() {
        let (a, b, c) = (input("a"), input("b"), input("c"));
        assert_eq!((a.clone() - (b.clone() - c.clone())).render(&names).unwrap(), "a-(b-c)");
        assert_eq!((a.clone() - b.clone() - c.clone()).render(&names).unwrap(), "a-b-c");
        assert_eq!(((a.clone() + b.clone()) * c.clone()).render(&names).unwrap(), "(a+b)*c");
        assert_eq!((a.clone() / (b.clone() * c.clone())).render(&names).unwrap(), "a/(b*c)");
        assert_eq!((a.clone() + (b.clone() + c.clone())).render(&names).unwrap(), "a+(b+c)");
        assert_eq!((a * b + c).render(&names).unwrap(), "a*b+c");
    }

    #[test]
    fn evaluates_as_the_spreadsheet_functions() {
        // Hand values: a = 3, b = −2: a − (b − 1) = 6; MAX = 3, MIN = −2, SIGN(b) = −1,
        // EXP(RADIANS(180)·0) = 1, |b|/a = 2/3.
        let value = |n: &str| match n {
            "a" => Some(3.0),
            "b" => Some(-2.0),
            _ => None,
        };
        let (a, b) = (input("a"), input("b"));
        assert_eq!((a.clone() - (b.clone() - num(1.0))).eval(&value), Some(6.0));
        assert_eq!(max(a.clone(), b.clone()).eval(&value), Some(3.0));
        assert_eq!(min(a.clone(), b.clone()).eval(&value), Some(-2.0));
        assert_eq!(call(Func::Sign, vec![b.clone()]).eval(&value), Some(-1.0));
        assert_eq!(call(Func::Exp, vec![call(Func::Radians, vec![num(180.0)]) * num(0.0)]).eval(&value), Some(1.0));
        assert_eq!((call(Func::Abs, vec![b.clone()]) / a.clone()).eval(&value), Some(2.0 / 3.0));
        // A missing input or a division by zero has no value.
        assert_eq!(input("c").eval(&value), None);
        assert_eq!((a / (b.clone() - b)).eval(&value), None);
    }
}
