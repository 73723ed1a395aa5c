//! Lexing WKT: tokens with their line and column, and exact integer values of numbers.

use super::{MAX_COORD, MIN_COORD};

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
            let number =
                self.bump_while(|c| c.is_ascii_digit() || matches!(c, '+' | '-' | '.' | 'e' | 'E'));
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
pub(crate) enum NumberValue {
    Integer(i64),
    Fraction,
    OutOfRange,
    Malformed,
}

pub(crate) fn number_value(text: &str) -> NumberValue {
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
        return NumberValue::Malformed;
    }
    let mut exp: i64 = 0;
    if let Some(e) = exponent {
        let (sign, digits) = match e.as_bytes().first() {
            Some(b'-') => (-1, &e[1..]),
            Some(b'+') => (1, &e[1..]),
            _ => (1, e),
        };
        if digits.is_empty() || !all_digits(digits) {
            return NumberValue::Malformed;
        }
        for b in digits.bytes() {
            exp = exp.saturating_mul(10).saturating_add(i64::from(b - b'0'));
        }
        exp *= sign;
    }
    // value = digits × 10^shift, with the digits stripped of leading zeros.
    let joined = format!("{whole}{fraction}");
    let mut digits = joined.trim_start_matches('0').to_string();
    if digits.is_empty() {
        return NumberValue::Integer(0);
    }
    let shift = exp.saturating_sub(fraction.len() as i64);
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
