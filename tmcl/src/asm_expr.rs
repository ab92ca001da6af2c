//! The assembler's operand and constant expressions: integers (decimal, $hex, 0x hex,
//! %binary), symbols and the operators + - * / % & | ^ ~ ( ).

use std::collections::HashMap;

use tmc429_model::text::shown;

/// A character a symbol may start with.
pub(crate) fn is_ident_start(c: char) -> bool {
    c.is_ascii_alphabetic() || c == '_'
}

/// A character a symbol may go on with.
pub(crate) fn is_ident(c: char) -> bool {
    c.is_ascii_alphanumeric() || c == '_'
}

/// Deepest nesting of parentheses and unary operators an expression may have: the evaluator
/// recurses once per level, and a limit keeps a hostile source from exhausting the stack.
pub const MAX_EXPR_DEPTH: usize = 64;

/// Expression evaluator: integers (decimal, $hex, 0x hex, %binary), symbols, + - * / % & | ^ ~ ( ).
pub(crate) struct Expr<'a> {
    s: &'a [u8],
    i: usize,
    syms: &'a HashMap<String, i64>,
    /// Parentheses and unary operators open around the current position.
    depth: usize,
}

impl<'a> Expr<'a> {
    fn ws(&mut self) {
        while self.i < self.s.len() && (self.s[self.i] as char).is_ascii_whitespace() {
            self.i += 1;
        }
    }
    pub(crate) fn parse(s: &str, syms: &HashMap<String, i64>) -> Result<i64, String> {
        let mut e = Expr { s: s.as_bytes(), i: 0, syms, depth: 0 };
        let v = e.or()?;
        e.ws();
        if e.i != e.s.len() {
            return Err(format!("unexpected '{}' in expression '{}'", shown(&s[e.i..]), shown(s.trim())));
        }
        Ok(v)
    }
    fn or(&mut self) -> Result<i64, String> {
        let mut v = self.and()?;
        loop {
            self.ws();
            match self.s.get(self.i) {
                Some(b'|') => {
                    self.i += 1;
                    v |= self.and()?
                }
                Some(b'^') => {
                    self.i += 1;
                    v ^= self.and()?
                }
                _ => return Ok(v),
            }
        }
    }
    fn and(&mut self) -> Result<i64, String> {
        let mut v = self.add()?;
        loop {
            self.ws();
            if self.s.get(self.i) == Some(&b'&') {
                self.i += 1;
                v &= self.add()?;
            } else {
                return Ok(v);
            }
        }
    }
    fn add(&mut self) -> Result<i64, String> {
        let mut v = self.mul()?;
        loop {
            self.ws();
            match self.s.get(self.i) {
                Some(b'+') => {
                    self.i += 1;
                    v = v.wrapping_add(self.mul()?)
                }
                Some(b'-') => {
                    self.i += 1;
                    v = v.wrapping_sub(self.mul()?)
                }
                _ => return Ok(v),
            }
        }
    }
    fn mul(&mut self) -> Result<i64, String> {
        let mut v = self.unary()?;
        loop {
            self.ws();
            match self.s.get(self.i) {
                Some(&c @ (b'*' | b'/' | b'%')) => {
                    self.i += 1;
                    let r = self.unary()?;
                    if c == b'*' {
                        v = v.wrapping_mul(r);
                    } else if r == 0 {
                        return Err("division by zero in expression".into());
                    } else if c == b'/' {
                        v = v.wrapping_div(r);
                    } else {
                        v = v.wrapping_rem(r);
                    }
                }
                _ => return Ok(v),
            }
        }
    }
    fn unary(&mut self) -> Result<i64, String> {
        self.ws();
        match self.s.get(self.i).copied() {
            Some(op @ (b'-' | b'+' | b'~' | b'(')) => {
                if self.depth == MAX_EXPR_DEPTH {
                    return Err(format!("expression nested deeper than {MAX_EXPR_DEPTH} levels of parentheses and unary operators"));
                }
                self.i += 1;
                self.depth += 1;
                let v = self.operand_of(op);
                self.depth -= 1;
                v
            }
            Some(_) => self.atom(),
            None => Err("missing value".into()),
        }
    }
    /// The operand of a unary operator, or the expression inside `(` up to its `)`: one level
    /// deeper.
    fn operand_of(&mut self, op: u8) -> Result<i64, String> {
        match op {
            b'-' => Ok(self.unary()?.wrapping_neg()),
            b'+' => self.unary(),
            b'~' => Ok(!self.unary()?),
            _ => {
                let v = self.or()?;
                self.ws();
                if self.s.get(self.i) != Some(&b')') {
                    return Err("missing ')' in expression".into());
                }
                self.i += 1;
                Ok(v)
            }
        }
    }
    fn atom(&mut self) -> Result<i64, String> {
        let start = self.i;
        let c = self.s[self.i] as char;
        let text = |a: usize, b: usize, s: &[u8]| String::from_utf8_lossy(&s[a..b]).into_owned();
        if c == '$' || c == '%' || c.is_ascii_digit() {
            let (radix, skip) = if c == '$' {
                (16, 1)
            } else if c == '%' {
                (2, 1)
            } else if c == '0' && matches!(self.s.get(self.i + 1), Some(b'x' | b'X')) {
                (16, 2)
            } else {
                (10, 0)
            };
            self.i += skip;
            let ds = self.i;
            while self.i < self.s.len() && (self.s[self.i] as char).is_ascii_alphanumeric() {
                self.i += 1;
            }
            let digits = text(ds, self.i, self.s);
            return i64::from_str_radix(&digits, radix).map_err(|_| format!("'{}' is not a number", shown(&text(start, self.i, self.s))));
        }
        if is_ident_start(c) {
            while self.i < self.s.len() && is_ident(self.s[self.i] as char) {
                self.i += 1;
            }
            let name = text(start, self.i, self.s);
            return self.syms.get(&name).copied().ok_or_else(|| format!("unknown symbol '{}'", shown(&name)));
        }
        let rest = String::from_utf8_lossy(&self.s[self.i..]);
        Err(format!("unexpected '{}' where a value was expected", shown(&rest.chars().take(1).collect::<String>())))
    }
}
