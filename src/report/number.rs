//! Numbers in the CSV reports, written as Rust's `Display` writes an `f64` (the shortest digits
//! that read back to the same value, never in exponent notation), by way of the `zmij` crate's
//! shortest digits (Schubfach, correctly rounded): the same text at a fraction of the cost,
//! which matters for the hundreds of thousands of values a sheet's histories write. Where two
//! shortest candidates are equally near the value the value is written as the standard library
//! writes it, whichever of the two the digits came as.

/// `x` as `format!("{x}")` writes it: `NaN`, `inf`, `-inf`, `-0`, `0.001`, `1000`, `1.5`.
pub fn display(x: f64) -> String {
    let mut out = Vec::with_capacity(24);
    write(x, &mut out);
    // Every byte written is ASCII.
    String::from_utf8(out).unwrap_or_default()
}

/// [`display`], appended to `out`.
pub fn write(x: f64, out: &mut Vec<u8>) {
    if !x.is_finite() {
        out.extend_from_slice(x.to_string().as_bytes());
        return;
    }
    let mut buffer = zmij::Buffer::new();
    let text = buffer.format_finite(x);
    if let Some(plain) = plain(text, x) {
        out.extend_from_slice(plain.as_bytes());
        return;
    }
    let (negative, text) = match text.strip_prefix('-') {
        Some(rest) => (true, rest),
        None => (false, text),
    };
    let (mantissa, exponent) = match text.split_once('e') {
        Some((m, e)) => (m, e.parse::<i32>().unwrap_or(0)),
        None => (text, 0),
    };
    let (whole, fraction) = mantissa.split_once('.').unwrap_or((mantissa, ""));
    // The value is 0.d₁d₂…dₙ × 10^point with d₁ ≠ 0 (no digits: zero).
    let mut all = [0u8; 40];
    let joined = &mut all[..whole.len() + fraction.len()];
    joined[..whole.len()].copy_from_slice(whole.as_bytes());
    joined[whole.len()..].copy_from_slice(fraction.as_bytes());
    let leading = joined.iter().take_while(|&&b| b == b'0').count();
    let trailing = joined[leading..].iter().rev().take_while(|&&b| b == b'0').count();
    let digits = std::str::from_utf8(&joined[leading..joined.len() - trailing]).unwrap_or("");
    let point = whole.len() as i32 - leading as i32 + exponent;
    if negative {
        out.push(b'-');
    }
    if digits.is_empty() {
        out.push(b'0');
        return;
    }
    let n = digits.len() as i32;
    // Two shortest candidates can lie equally near the value: the standard library takes the
    // one away from zero; digits that came as the even one of the two are moved to it.
    let rounded_up;
    // A tie needs a last place finer than the value's ulp: fifteen digits or more.
    let digits =
        if digits.len() >= 15 && digits.ends_with(['0', '2', '4', '6', '8']) && midpoint_above(x, digits, point - n) {
            rounded_up = (digits.parse::<u64>().unwrap_or(0) + 1).to_string();
            rounded_up.as_str()
        } else {
            digits
        };
    if point <= 0 {
        out.extend_from_slice(b"0.");
        out.resize(out.len() + (-point) as usize, b'0');
        out.extend_from_slice(digits.as_bytes());
    } else if point >= n {
        out.extend_from_slice(digits.as_bytes());
        out.resize(out.len() + (point - n) as usize, b'0');
    } else {
        let (a, b) = digits.split_at(point as usize);
        out.extend_from_slice(a.as_bytes());
        out.push(b'.');
        out.extend_from_slice(b.as_bytes());
    }
}

/// The shortest digits' text where it is already the standard library's: no exponent, its
/// `.0` dropped, and a value that cannot be a midpoint at all ([`may_tie`], checked first: most
/// values of the reports) or too few digits for a tie between two shortest candidates (below
/// fifteen, or an odd last digit); `None` sends the value through the general path.
fn plain(text: &str, x: f64) -> Option<&str> {
    let bytes = text.as_bytes();
    if bytes.contains(&b'e') {
        return None;
    }
    let text = text.strip_suffix(".0").unwrap_or(text);
    if !may_tie(x) {
        return Some(text);
    }
    let digits = text.bytes().filter(u8::is_ascii_digit);
    let leading = digits.clone().take_while(|&d| d == b'0').count();
    let significant = digits.count() - leading;
    let even_last = text.bytes().last().is_some_and(|d| matches!(d, b'0' | b'2' | b'4' | b'6' | b'8'));
    (significant < 15 || !even_last).then_some(text)
}

/// Whether `x` can be a midpoint `(D + ½)·10^q` at all (the necessary condition of
/// [`midpoint_above`] that needs no digits): with `|x| = m·2^e`, `m` odd, a midpoint needs
/// `q = e + 1` and `|q| ≤ 25`. Most values of the reports (seventeen digits, a last place near
/// 1e-11) have `e` near −36 and cannot be one.
fn may_tie(x: f64) -> bool {
    odd_binary(x).is_some_and(|(_, e)| (e + 1).unsigned_abs() <= 25)
}

/// `|x| = m·2^e` with `m` odd, for a finite nonzero `x` (`None` for zero).
fn odd_binary(x: f64) -> Option<(u64, i32)> {
    let bits = x.abs().to_bits();
    let (exp_bits, fraction) = ((bits >> 52) as i32, bits & ((1u64 << 52) - 1));
    let (m, e) = if exp_bits == 0 { (fraction, -1074) } else { (fraction | (1u64 << 52), exp_bits - 1075) };
    (m != 0).then(|| (m >> m.trailing_zeros(), e + m.trailing_zeros() as i32))
}

/// Whether `|x|` is exactly `(D + ½)·10^q`, `D` the integer of `digits`: the midpoint between
/// `D` and `D + 1` in the last place. With `|x| = m·2^e`, `m` odd, that is
/// `m·2^(e+1−q)·5^(−q) = 2D + 1`, an odd integer: `q = e + 1` and `m·5^(−q) = 2D + 1` (or
/// `m = (2D + 1)·5^q` for `q > 0`). `D < 10^17`, so powers of 5 beyond 5^25 cannot match.
fn midpoint_above(x: f64, digits: &str, q: i32) -> bool {
    let Ok(d) = digits.parse::<u64>() else { return false };
    let Some((m, e)) = odd_binary(x) else { return false };
    if q != e + 1 || q.unsigned_abs() > 25 {
        return false;
    }
    let odd = 2 * u128::from(d) + 1;
    let five = 5u128.pow(q.unsigned_abs());
    if q <= 0 { u128::from(m) * five == odd } else { u128::from(m) == odd * five }
}

#[cfg(test)]
mod tests {
    use super::display;

    /// The reference is the standard library's own `Display`.
    fn same(x: f64) {
        assert_eq!(display(x), format!("{x}"), "bits {:#018x}", x.to_bits());
    }

    #[test]
    fn special_values_and_edges_read_as_the_standard_library_writes_them() {
        for x in [
            0.0,
            -0.0,
            1.0,
            -1.0,
            0.1,
            0.3,
            1.5,
            100.0,
            1e-7,
            1.5e-7,
            1e15,
            1e16,
            1e17,
            1e21,
            1e22,
            123456789012345680.0,
            f64::MIN_POSITIVE,
            5e-324,
            f64::MAX,
            f64::MIN,
            f64::EPSILON,
            f64::NAN,
            f64::INFINITY,
            f64::NEG_INFINITY,
            207670.7538660006,
            0.0008771929824561405,
            // ties between two shortest candidates (the standard library rounds away from zero);
            // each sum is exact
            662_936_471_232_937.0 + 0.25,
            26_829_767_983_277.0 + 0.3125,
            -(1_658_206_780_088_562.0 + 0.25),
        ] {
            same(x);
        }
    }

    #[test]
    fn random_bit_patterns_read_as_the_standard_library_writes_them() {
        // A fixed xorshift sequence over the whole range of f64 bit patterns, then over values
        // of the sizes the reports hold (1e-6 … 1e7).
        let mut s: u64 = 0x9E37_79B9_7F4A_7C15;
        let mut next = || {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            s
        };
        for _ in 0..200_000 {
            same(f64::from_bits(next()));
        }
        for _ in 0..200_000 {
            let u = (next() >> 11) as f64 / (1u64 << 53) as f64;
            same(10f64.powf(-6.0 + 13.0 * u) * if next() & 1 == 0 { 1.0 } else { -1.0 });
        }
    }
}
