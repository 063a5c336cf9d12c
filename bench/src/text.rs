//! Numbers as the tables print them.

/// `n` with a comma between groups of three digits (1,234,567).
#[allow(dead_code)] // (not every table prints counts)
pub fn thousands(n: usize) -> String {
    let digits = n.to_string();
    let mut out = String::new();
    for (i, ch) in digits.chars().enumerate() {
        if i > 0 && (digits.len() - i) % 3 == 0 {
            out.push(',');
        }
        out.push(ch);
    }
    out
}

/// A time in seconds as the tables print it: `12.3 s`, `1.23 s`, `123 ms`.
#[allow(dead_code)] // (not every table prints times)
pub fn seconds(s: f64) -> String {
    if s >= 10.0 {
        format!("{s:.1} s")
    } else if s >= 1.0 {
        format!("{s:.2} s")
    } else {
        format!("{:.0} ms", s * 1e3)
    }
}
