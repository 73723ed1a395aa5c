//! Lexing WKT: tokens with their line and column, and exact values of numbers: integers for
//! the pixel reader ([`number_value`]), reduced fractions for exact polygons ([`exact_value`]).

use super::{MAX_COORD, MIN_COORD};
use num_integer::Integer;

/// A place in the input; line and column start at 1 and columns count characters.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub(super) struct Pos {
    pub(super) line: usize,
    pub(super) column: usize,
}

#[derive(Clone, Debug, PartialEq)]
pub(super) enum Token<'a> {
    Word(&'a str),
    Number(&'a str),
    Open,
    Close,
    Comma,
    End,
}

impl Token<'_> {
    /// The token as an error message names it.
    pub(super) fn describe(&self) -> String {
        match self {
            Token::Word(w) => format!("'{}'", shorten(w)),
            Token::Number(n) => format!("number {}", shorten(n)),
            Token::Open => "'('".to_string(),
            Token::Close => "')'".to_string(),
            Token::Comma => "','".to_string(),
            Token::End => "end of input".to_string(),
        }
    }
}

/// A token's text cut to a length fit for an error message.
pub(super) fn shorten(s: &str) -> String {
    let mut short: String = s.chars().take(24).collect();
    if short.len() < s.len() {
        short.push('…');
    }
    short
}

pub(super) struct Lexer<'a> {
    pub(super) text: &'a str,
    pub(super) offset: usize,
    pub(super) pos: Pos,
}

impl<'a> Lexer<'a> {
    pub(super) fn new(text: &'a str) -> Self {
        Lexer {
            text,
            offset: 0,
            pos: Pos { line: 1, column: 1 },
        }
    }

    pub(super) fn peek_char(&self) -> Option<char> {
        self.text[self.offset..].chars().next()
    }

    pub(super) fn bump(&mut self) {
        if let Some(c) = self.peek_char() {
            self.offset += c.len_utf8();
            if c == '\n' {
                self.pos = Pos {
                    line: self.pos.line + 1,
                    column: 1,
                };
            } else {
                self.pos.column += 1;
            }
        }
    }

    pub(super) fn bump_while(&mut self, keep: impl Fn(char) -> bool) -> &'a str {
        let start = self.offset;
        while self.peek_char().is_some_and(&keep) {
            self.bump();
        }
        &self.text[start..self.offset]
    }

    /// The next token and where it starts, or the position and text of a stray character.
    pub(super) fn next(&mut self) -> std::result::Result<(Token<'a>, Pos), (Pos, char)> {
        self.bump_while(|c| c.is_whitespace() || c == '\u{feff}');
        let pos = self.pos;
        let Some(c) = self.peek_char() else {
            return Ok((Token::End, pos));
        };
        let token = if c.is_ascii_alphabetic() {
            Token::Word(self.bump_while(|c| c.is_ascii_alphanumeric() || c == '_'))
        } else if c.is_ascii_digit() || matches!(c, '+' | '-' | '.') {
            let number = self.bump_while(|c| {
                c.is_ascii_digit() || matches!(c, '+' | '-' | '.' | 'e' | 'E' | '/')
            });
            Token::Number(number)
        } else {
            self.bump();
            match c {
                '(' => Token::Open,
                ')' => Token::Close,
                ',' => Token::Comma,
                _ => return Err((pos, c)),
            }
        };
        Ok((token, pos))
    }
}

/// The value of a number token, computed exactly so that `3.0000000000000000001` is refused.
#[derive(Debug, PartialEq)]
pub enum NumberValue {
    Integer(i64),
    Fraction,
    OutOfRange,
    Malformed,
}

pub fn number_value(text: &str) -> NumberValue {
    // Fast path for plain integers such as `-12`, the common case.
    if text.len() <= 11
        && let Ok(value) = text.parse::<i64>()
    {
        return if (MIN_COORD..=MAX_COORD).contains(&value) {
            NumberValue::Integer(value)
        } else {
            NumberValue::OutOfRange
        };
    }
    if text.contains('/') {
        return match exact_value(text) {
            ExactValue::Fraction { num, den: 1 } => match i64::try_from(num) {
                Ok(value) if (MIN_COORD..=MAX_COORD).contains(&value) => {
                    NumberValue::Integer(value)
                }
                _ => NumberValue::OutOfRange,
            },
            ExactValue::Fraction { .. } => NumberValue::Fraction,
            ExactValue::OutOfRange => NumberValue::OutOfRange,
            ExactValue::Malformed => NumberValue::Malformed,
        };
    }
    let Some(Decimal {
        negative,
        mut digits,
        shift,
    }) = decimal_parts(text)
    else {
        return NumberValue::Malformed;
    };
    if digits.is_empty() {
        return NumberValue::Integer(0);
    }
    if shift < 0 {
        let drop = shift.unsigned_abs();
        let zeros = (digits.len() - digits.trim_end_matches('0').len()) as u64;
        if zeros < drop {
            return NumberValue::Fraction;
        }
        digits.truncate(digits.len() - drop as usize);
    } else if (digits.len() as i64).saturating_add(shift) > 11 {
        return NumberValue::OutOfRange;
    } else {
        digits.extend(std::iter::repeat_n('0', shift as usize));
    }
    if digits.len() > 11 {
        return NumberValue::OutOfRange;
    }
    let Ok(magnitude) = digits.parse::<i64>() else {
        return NumberValue::Malformed;
    };
    let value = if negative { -magnitude } else { magnitude };
    if (MIN_COORD..=MAX_COORD).contains(&value) {
        NumberValue::Integer(value)
    } else {
        NumberValue::OutOfRange
    }
}

/// A decimal number token taken apart: its value is ±`digits` × 10^`shift`.
struct Decimal {
    negative: bool,
    /// The significant digits, without leading zeros (empty for zero).
    digits: String,
    shift: i64,
}

/// Splits `[+-]digits[.digits][e[+-]digits]` into sign, digits and power of ten; `None` when
/// the token is not of that form.
fn decimal_parts(text: &str) -> Option<Decimal> {
    let (negative, unsigned) = match text.as_bytes().first() {
        Some(b'-') => (true, &text[1..]),
        Some(b'+') => (false, &text[1..]),
        _ => (false, text),
    };
    let (mantissa, exponent) = match unsigned.find(['e', 'E']) {
        Some(k) => (&unsigned[..k], Some(&unsigned[k + 1..])),
        None => (unsigned, None),
    };
    let (whole, fraction) = mantissa.split_once('.').unwrap_or((mantissa, ""));
    let all_digits = |s: &str| s.bytes().all(|b| b.is_ascii_digit());
    if whole.len() + fraction.len() == 0 || !all_digits(whole) || !all_digits(fraction) {
        return None;
    }
    let mut exp: i64 = 0;
    if let Some(e) = exponent {
        let (sign, digits) = match e.as_bytes().first() {
            Some(b'-') => (-1, &e[1..]),
            Some(b'+') => (1, &e[1..]),
            _ => (1, e),
        };
        if digits.is_empty() || !all_digits(digits) {
            return None;
        }
        for b in digits.bytes() {
            exp = exp.saturating_mul(10).saturating_add(i64::from(b - b'0'));
        }
        exp *= sign;
    }
    let joined = format!("{whole}{fraction}");
    Some(Decimal {
        negative,
        digits: joined.trim_start_matches('0').to_string(),
        shift: exp.saturating_sub(fraction.len() as i64),
    })
}

/// The exact value of a number token as a reduced fraction.
#[derive(Debug, PartialEq)]
pub enum ExactValue {
    /// `num / den` in lowest terms, `den > 0`.
    Fraction {
        num: i128,
        den: i128,
    },
    /// The numerator or the denominator needs more than 38 decimal digits.
    OutOfRange,
    Malformed,
}

/// Reads a number exactly: a decimal as [`number_value`] takes it (`0.35`, `-2`, `1e-3`) or a
/// fraction `p/q` of two integers without spaces (`7/3`, `-1/2`; the sign, if any, before
/// `p`, and `q > 0`). Nothing is rounded: a value whose numerator or denominator in lowest terms
/// would not fit 38 decimal digits is [`ExactValue::OutOfRange`].
pub fn exact_value(text: &str) -> ExactValue {
    const MAX_DIGITS: usize = 38; // 10^38 < 2^127
    let integer = |digits: &str| -> Option<i128> {
        let digits = digits.trim_start_matches('0');
        if digits.len() > MAX_DIGITS {
            return None;
        }
        Some(digits.parse::<i128>().unwrap_or(0))
    };
    let all_digits = |s: &str| !s.is_empty() && s.bytes().all(|b| b.is_ascii_digit());
    let (num, den) = if let Some((p, q)) = text.split_once('/') {
        let (negative, magnitude) = match p.as_bytes().first() {
            Some(b'-') => (true, &p[1..]),
            Some(b'+') => (false, &p[1..]),
            _ => (false, p),
        };
        if !all_digits(magnitude) || !all_digits(q) {
            return ExactValue::Malformed;
        }
        let (Some(p), Some(q)) = (integer(magnitude), integer(q)) else {
            return ExactValue::OutOfRange;
        };
        if q == 0 {
            return ExactValue::Malformed;
        }
        (if negative { -p } else { p }, q)
    } else {
        let Some(Decimal {
            negative,
            digits,
            shift,
        }) = decimal_parts(text)
        else {
            return ExactValue::Malformed;
        };
        // Trailing zeros of the digits only move the power of ten.
        let significant = digits.trim_end_matches('0');
        let shift = shift.saturating_add((digits.len() - significant.len()) as i64);
        if significant.is_empty() {
            return ExactValue::Fraction { num: 0, den: 1 };
        }
        let Some(mantissa) = integer(significant) else {
            return ExactValue::OutOfRange;
        };
        let Some(power) = u32::try_from(shift.unsigned_abs())
            .ok()
            .and_then(|k| 10i128.checked_pow(k))
        else {
            return ExactValue::OutOfRange;
        };
        let signed = if negative { -mantissa } else { mantissa };
        if shift >= 0 {
            match signed.checked_mul(power) {
                Some(num) => (num, 1),
                None => return ExactValue::OutOfRange,
            }
        } else {
            (signed, power)
        }
    };
    let g = gcd(num.unsigned_abs(), den.unsigned_abs());
    // g divides both, and den > 0, so the quotients fit and den stays positive.
    ExactValue::Fraction {
        num: num / g as i128,
        den: den / g as i128,
    }
}

/// The greatest common divisor (gcd(0, 0) = 1, so that dividing by it is always defined).
pub fn gcd(a: u128, b: u128) -> u128 {
    a.gcd(&b).max(1)
}
