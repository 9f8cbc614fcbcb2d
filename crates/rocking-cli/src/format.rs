//! Numbers for people (the files get every digit; see `output`).

/// `x` with `digits` significant digits, trailing zeros dropped, in plain
/// notation between 1e-4 and 1e6 and in scientific notation outside.
pub fn sig(x: f64, digits: usize) -> String {
    if !x.is_finite() {
        return x.to_string();
    }
    if x.classify() == std::num::FpCategory::Zero {
        return "0".into();
    }
    let digits = digits.max(1);
    let exponent = x.abs().log10().floor() as i32;
    if (-4..6).contains(&exponent) {
        let decimals = usize::try_from(digits as i32 - 1 - exponent).unwrap_or(0);
        trim(format!("{x:.decimals$}"))
    } else {
        let text = format!("{x:.prec$e}", prec = digits - 1);
        match text.split_once('e') {
            Some((mantissa, exp)) => format!("{}e{exp}", trim(mantissa.to_string())),
            None => text,
        }
    }
}

fn trim(s: String) -> String {
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    }
}

#[cfg(test)]
mod tests {
    use super::sig;

    #[test]
    fn significant_digits() {
        assert_eq!(sig(0.321_750_554, 5), "0.32175");
        assert_eq!(sig(18.434_948_8, 5), "18.435");
        assert_eq!(sig(1.5e5, 4), "150000");
        assert_eq!(sig(8.0e6, 4), "8e6");
        assert_eq!(sig(1.0e-8, 3), "1e-8");
        assert_eq!(sig(-0.000_123_456, 3), "-0.000123");
        assert_eq!(sig(0.0, 3), "0");
        assert_eq!(sig(2.0, 6), "2");
    }
}
