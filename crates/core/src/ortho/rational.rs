//! Exact rational numbers for coordinates: an `i128` numerator over a positive `i128`
//! denominator in lowest terms. Arithmetic is checked (`None` on overflow, never a wrong value)
//! and comparison is exact for every pair of values (products are formed in 256 bits).
//!
//! Written here rather than as `num_rational::Ratio<i128>`, for a measured reason: with
//! `Ratio` (whose comparison divides at each step of a continued-fraction descent, and whose
//! sums always form an lcm) `mowmill solve --algo corollary4` on a 2,642-corner
//! `gen ortho-holed --n 3000 --seed 1` polygon took 0.98 s against 0.32 s with this type, and
//! still 0.75 s with fast paths for equal denominators and `i128` cross-products.

use crate::wkt::lexer::{ExactValue, exact_value, gcd};
use serde::{Deserialize, Deserializer, Serialize, Serializer};
use std::cmp::Ordering;
use std::fmt;

/// The largest magnitude of an input coordinate: 2^31, as for integral WKT, so that every
/// integer pixel of a polygon has `i32` coordinates.
pub const MAX_MAGNITUDE: i128 = 1 << 31;

/// The largest denominator (in lowest terms) of an input coordinate: 10^12, so any decimal with
/// at most 12 digits after the point and any `p/q` with `q <= 10^12` is accepted. With
/// [`MAX_MAGNITUDE`] this keeps numerators below 2^72, and the products the checker forms
/// (cross-multiplied differences, sums of a few) far inside `i128`.
pub const MAX_DENOMINATOR: i128 = 1_000_000_000_000;

/// An exact rational number `num / den`, `den > 0`, `gcd(num, den) = 1`.
#[derive(Clone, Copy, PartialEq, Eq, Hash)]
pub struct Rational {
    num: i128,
    den: i128,
}

impl Rational {
    pub const ZERO: Rational = Rational { num: 0, den: 1 };
    pub const ONE: Rational = Rational { num: 1, den: 1 };
    pub const HALF: Rational = Rational { num: 1, den: 2 };

    /// `num / den` in lowest terms; `None` when `den` is 0 or a sign change overflows.
    pub fn new(num: i128, den: i128) -> Option<Rational> {
        if den == 0 || num == i128::MIN || den == i128::MIN {
            return None;
        }
        let g = gcd(num.unsigned_abs(), den.unsigned_abs()) as i128;
        let (num, den) = (num / g, den / g);
        Some(if den < 0 {
            Rational {
                num: -num,
                den: -den,
            }
        } else {
            Rational { num, den }
        })
    }

    pub const fn integer(value: i64) -> Rational {
        Rational {
            num: value as i128,
            den: 1,
        }
    }

    pub fn numer(self) -> i128 {
        self.num
    }

    pub fn denom(self) -> i128 {
        self.den
    }

    /// The nearest `f64` (or one ulp off): for drawing only, never for deciding anything.
    pub fn to_f64(self) -> f64 {
        self.num as f64 / self.den as f64
    }

    pub fn is_integer(self) -> bool {
        self.den == 1
    }

    /// The largest integer `<= self`.
    pub fn floor(self) -> i128 {
        self.num.div_euclid(self.den)
    }

    /// The smallest integer `>= self`.
    pub fn ceil(self) -> i128 {
        -(-self.num).div_euclid(self.den)
    }

    pub fn checked_add(self, other: Rational) -> Option<Rational> {
        if self.den == other.den {
            return Rational::new(self.num.checked_add(other.num)?, self.den);
        }
        // Over lcm(den, other.den), to keep the numbers small.
        let g = gcd(self.den.unsigned_abs(), other.den.unsigned_abs()) as i128;
        let (a, b) = (self.den / g, other.den / g);
        let num = self
            .num
            .checked_mul(b)?
            .checked_add(other.num.checked_mul(a)?)?;
        Rational::new(num, self.den.checked_mul(b)?)
    }

    pub fn checked_sub(self, other: Rational) -> Option<Rational> {
        self.checked_add(other.checked_neg()?)
    }

    pub fn checked_mul(self, other: Rational) -> Option<Rational> {
        // Cancel across first so that the products stay small.
        let g1 = gcd(self.num.unsigned_abs(), other.den.unsigned_abs()) as i128;
        let g2 = gcd(other.num.unsigned_abs(), self.den.unsigned_abs()) as i128;
        let num = (self.num / g1).checked_mul(other.num / g2)?;
        let den = (self.den / g2).checked_mul(other.den / g1)?;
        Rational::new(num, den)
    }

    pub fn checked_neg(self) -> Option<Rational> {
        Some(Rational {
            num: self.num.checked_neg()?,
            den: self.den,
        })
    }

    pub fn abs(self) -> Rational {
        // num is never i128::MIN (see `new`), so this cannot overflow.
        Rational {
            num: self.num.abs(),
            den: self.den,
        }
    }

    /// `(self + other) / 2`.
    pub fn midpoint(self, other: Rational) -> Option<Rational> {
        self.checked_add(other)?.checked_mul(Rational::HALF)
    }

    /// Whether the value is an input coordinate: magnitude at most [`MAX_MAGNITUDE`] and
    /// denominator at most [`MAX_DENOMINATOR`].
    pub fn within_input_limits(self) -> bool {
        self.den <= MAX_DENOMINATOR
            && self
                .num
                .unsigned_abs()
                .checked_div(self.den as u128)
                .is_some_and(|q| {
                    q < MAX_MAGNITUDE as u128
                        || (q == MAX_MAGNITUDE as u128
                            && self.num.unsigned_abs().is_multiple_of(self.den as u128))
                })
    }

    /// Reads a coordinate as written in WKT or in a tour file: a decimal (`3`, `-0.35`, `1e-3`)
    /// or a fraction `p/q` (`7/3`), exactly, within the input limits. The error says what was
    /// wrong.
    pub fn parse_coordinate(text: &str) -> Result<Rational, String> {
        let short: String = text.chars().take(24).collect();
        match exact_value(text) {
            ExactValue::Fraction { num, den } => {
                let value = Rational::new(num, den)
                    .ok_or_else(|| format!("number {short} is out of range"))?;
                if value.within_input_limits() {
                    Ok(value)
                } else {
                    Err(format!(
                        "coordinate {short} is out of range; expected a magnitude at most 2^31 \
                         and a denominator (in lowest terms) at most 10^12"
                    ))
                }
            }
            ExactValue::OutOfRange => Err(format!(
                "coordinate {short} has too many digits; expected a magnitude at most 2^31 and \
                 a denominator (in lowest terms) at most 10^12"
            )),
            ExactValue::Malformed => Err(format!(
                "malformed number {short}; expected a decimal such as -0.35 or a fraction such \
                 as 7/3"
            )),
        }
    }
}

impl From<i64> for Rational {
    fn from(value: i64) -> Rational {
        Rational::integer(value)
    }
}

impl From<i32> for Rational {
    fn from(value: i32) -> Rational {
        Rational::integer(i64::from(value))
    }
}

/// `a × b` as a 256-bit number (high, low halves).
fn wide_mul(a: u128, b: u128) -> (u128, u128) {
    const LOW: u128 = u64::MAX as u128;
    let (a1, a0) = (a >> 64, a & LOW);
    let (b1, b0) = (b >> 64, b & LOW);
    let (p00, p01, p10, p11) = (a0 * b0, a0 * b1, a1 * b0, a1 * b1);
    let mid = (p00 >> 64) + (p01 & LOW) + (p10 & LOW);
    let low = (p00 & LOW) | (mid << 64);
    let high = p11 + (p01 >> 64) + (p10 >> 64) + (mid >> 64);
    (high, low)
}

impl Ord for Rational {
    fn cmp(&self, other: &Rational) -> Ordering {
        // Compare num₁·den₂ with num₂·den₁ (denominators are positive), in 256 bits.
        let sign = |n: i128| n.cmp(&0);
        match sign(self.num).cmp(&sign(other.num)) {
            Ordering::Equal => {}
            unequal => return unequal,
        }
        let left = wide_mul(self.num.unsigned_abs(), other.den as u128);
        let right = wide_mul(other.num.unsigned_abs(), self.den as u128);
        if self.num < 0 {
            right.cmp(&left)
        } else {
            left.cmp(&right)
        }
    }
}

impl PartialOrd for Rational {
    fn partial_cmp(&self, other: &Rational) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

/// Integers as `3`, values with a finite decimal expansion as decimals (`0.35`, `-2.5`), all
/// others as fractions `p/q` (`7/3`): text that [`Rational::parse_coordinate`] reads back to the
/// same value.
impl fmt::Display for Rational {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.den == 1 {
            return write!(f, "{}", self.num);
        }
        // den = 2^a 5^b has a decimal expansion with max(a, b) digits.
        let (mut rest, mut twos, mut fives) = (self.den, 0u32, 0u32);
        while rest % 2 == 0 {
            rest /= 2;
            twos += 1;
        }
        while rest % 5 == 0 {
            rest /= 5;
            fives += 1;
        }
        let places = twos.max(fives);
        let scaled = (rest == 1)
            .then(|| 10i128.checked_pow(places))
            .flatten()
            .and_then(|p| self.num.checked_mul(p / self.den));
        match scaled {
            Some(scaled) => {
                let digits = scaled.unsigned_abs().to_string();
                let places = places as usize;
                let padded = format!("{digits:0>width$}", width = places + 1);
                let (whole, fraction) = padded.split_at(padded.len() - places);
                let sign = if scaled < 0 { "-" } else { "" };
                write!(f, "{sign}{whole}.{fraction}")
            }
            None => write!(f, "{}/{}", self.num, self.den),
        }
    }
}

impl fmt::Debug for Rational {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{self}")
    }
}

impl std::str::FromStr for Rational {
    type Err = String;

    /// As [`Rational::parse_coordinate`], limits included.
    fn from_str(s: &str) -> Result<Rational, String> {
        Rational::parse_coordinate(s)
    }
}

/// Written as a JSON string (`"7/3"`, `"0.35"`), so that no reader rounds it.
impl Serialize for Rational {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.collect_str(self)
    }
}

/// Read from a JSON string (`"7/3"`, `"0.35"`) or a JSON integer; a JSON number with a
/// fraction or an exponent is refused, because a JSON reader may already have rounded it.
impl<'de> Deserialize<'de> for Rational {
    fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Rational, D::Error> {
        deserializer.deserialize_any(RationalVisitor)
    }
}

struct RationalVisitor;

impl serde::de::Visitor<'_> for RationalVisitor {
    type Value = Rational;

    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("an exact coordinate: a string such as \"7/3\" or \"0.35\", or an integer")
    }

    fn visit_str<E: serde::de::Error>(self, v: &str) -> Result<Rational, E> {
        Rational::parse_coordinate(v).map_err(E::custom)
    }

    fn visit_i64<E: serde::de::Error>(self, v: i64) -> Result<Rational, E> {
        let value = Rational::integer(v);
        if value.within_input_limits() {
            Ok(value)
        } else {
            Err(E::custom(format!(
                "coordinate {v} is out of range; expected a magnitude at most 2^31"
            )))
        }
    }

    fn visit_u64<E: serde::de::Error>(self, v: u64) -> Result<Rational, E> {
        match i64::try_from(v) {
            Ok(v) => self.visit_i64(v),
            Err(_) => Err(E::custom(format!(
                "coordinate {v} is out of range; expected a magnitude at most 2^31"
            ))),
        }
    }

    fn visit_f64<E: serde::de::Error>(self, v: f64) -> Result<Rational, E> {
        Err(E::custom(format!(
            "coordinate {v} is a JSON floating-point number; write non-integral coordinates as \
             strings (\"0.35\", \"7/20\") so that they are read exactly"
        )))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(text: &str) -> Rational {
        Rational::parse_coordinate(text).unwrap()
    }

    #[test]
    fn reads_decimals_and_fractions_exactly() {
        assert_eq!(q("0.35"), Rational::new(7, 20).unwrap());
        assert_eq!(q("7/3"), Rational::new(7, 3).unwrap());
        assert_eq!(q("-14/6"), Rational::new(-7, 3).unwrap());
        assert_eq!(q("+2.50"), Rational::new(5, 2).unwrap());
        assert_eq!(q("1e-3"), Rational::new(1, 1000).unwrap());
        assert_eq!(q("12.5e1"), Rational::integer(125));
        assert_eq!(q("-0"), Rational::ZERO);
        assert_eq!(
            q("0.000000000001"),
            Rational::new(1, 1_000_000_000_000).unwrap()
        );
        assert_eq!(q("2147483648"), Rational::integer(1 << 31));
        assert_eq!(q("-2147483648"), Rational::integer(-(1 << 31)));
        // 0.1 + 0.2 = 0.3 exactly, unlike floating point.
        assert_eq!(q("0.1").checked_add(q("0.2")), Some(q("0.3")));
    }

    #[test]
    fn refuses_out_of_limits_and_malformed() {
        let refused = [
            ("0.0000000000001", "out of range"),
            ("1/3000000000000", "out of range"),
            ("2147483648.5", "out of range"),
            ("1e400", "too many digits"),
            ("1/0", "malformed"),
            ("1/-2", "malformed"),
            ("1.5/2", "malformed"),
            ("--1", "malformed"),
            ("1e", "malformed"),
        ];
        for (text, words) in refused {
            let e = Rational::parse_coordinate(text).unwrap_err();
            assert!(e.contains(words), "{text}: {e}");
        }
    }

    #[test]
    fn displays_what_it_reads() {
        for text in [
            "3",
            "-3",
            "0.35",
            "-0.05",
            "7/3",
            "-1/6",
            "2.5",
            "0.000000000001",
        ] {
            assert_eq!(q(text).to_string(), text);
            assert_eq!(q(&q(text).to_string()), q(text));
        }
        assert_eq!(Rational::new(1, 8).unwrap().to_string(), "0.125");
        assert_eq!(Rational::new(-3, 40).unwrap().to_string(), "-0.075");
    }

    #[test]
    fn comparison_is_exact_beyond_i128_products() {
        let big = i128::MAX / 3;
        let a = Rational::new(big, big - 1).unwrap();
        let b = Rational::new(big - 1, big - 2).unwrap();
        // big/(big-1) < (big-1)/(big-2): both just above 1, the second farther.
        assert!(a < b);
        assert!(a.checked_neg().unwrap() > b.checked_neg().unwrap());
        assert!(Rational::new(-1, big).unwrap() < Rational::ZERO);
        let mut v = vec![q("1/2"), q("-7/3"), q("0.35"), q("0"), q("1/3")];
        v.sort();
        assert_eq!(v, vec![q("-7/3"), q("0"), q("1/3"), q("0.35"), q("1/2")]);
    }

    #[test]
    fn arithmetic_is_checked() {
        assert_eq!(q("1/3").checked_add(q("1/6")), Some(q("1/2")));
        assert_eq!(q("1/3").checked_sub(q("1/2")), Some(q("-1/6")));
        assert_eq!(q("2/3").checked_mul(q("9/4")), Some(q("3/2")));
        assert_eq!(q("1").midpoint(q("2")), Some(q("3/2")));
        let huge = Rational::new(i128::MAX, 1).unwrap();
        assert_eq!(huge.checked_add(Rational::ONE), None);
        assert_eq!(huge.checked_mul(Rational::integer(2)), None);
        // Denominators whose lcm overflows.
        let p = Rational::new(1, (1 << 100) - 1).unwrap();
        let r = Rational::new(1, (1 << 100) + 1).unwrap();
        assert_eq!(p.checked_add(r), None);
        assert_eq!((q("-7/2").floor(), q("-7/2").ceil()), (-4, -3));
        assert_eq!((q("7/2").floor(), q("7/2").ceil()), (3, 4));
    }

    #[test]
    fn json_strings_and_integers_only() {
        let v: Vec<Rational> = serde_json::from_str(r#"["7/3", 2, "-0.5"]"#).unwrap();
        assert_eq!(v, vec![q("7/3"), q("2"), q("-1/2")]);
        assert_eq!(serde_json::to_string(&v).unwrap(), r#"["7/3","2","-0.5"]"#);
        let e = serde_json::from_str::<Vec<Rational>>("[0.35]").unwrap_err();
        assert!(
            e.to_string()
                .contains("write non-integral coordinates as strings"),
            "{e}"
        );
    }
}
