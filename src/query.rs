//! Query strings, one rule for every route and the CLI's camera: `&`- or `;`-separated
//! `key=value` pairs, values percent-decoded, and inputs quoted in errors cut to a readable size.

/// The `(key, value)` pairs of a query, in order; a pair without `=` has an empty value.
pub fn pairs(query: &str) -> impl Iterator<Item = (&str, &str)> {
    query.split(['&', ';']).filter(|p| !p.is_empty()).map(|p| p.split_once('=').unwrap_or((p, "")))
}

/// Decodes `%XX` escapes and `+` (as space) in a query value.
pub fn percent_decode(s: &str) -> String {
    let bytes = s.as_bytes();
    let mut out = Vec::with_capacity(bytes.len());
    let mut i = 0;
    while i < bytes.len() {
        match bytes[i] {
            b'%' if i + 2 < bytes.len() && bytes[i + 1..i + 3].iter().all(u8::is_ascii_hexdigit) => {
                let hex = std::str::from_utf8(&bytes[i + 1..i + 3]).expect("hex digits");
                out.push(u8::from_str_radix(hex, 16).expect("hex digits"));
                i += 3;
                continue;
            }
            b'+' => out.push(b' '),
            b => out.push(b),
        }
        i += 1;
    }
    String::from_utf8_lossy(&out).into_owned()
}

/// An input as error messages and logs show it: at most 200 characters, marked where cut.
pub fn cut(s: &str) -> String {
    cut_to(s, 200)
}

/// `s` cut to `chars` characters, with an ellipsis where something was cut.
pub fn cut_to(s: &str, chars: usize) -> String {
    match s.char_indices().nth(chars) {
        Some((at, _)) => format!("{}…", &s[..at]),
        None => s.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn decodes_escapes_and_cuts_long_inputs() {
        // Only two hex digits make an escape.
        assert_eq!(percent_decode("a%+5b%2C%zz%4"), "a% 5b,%zz%4");
        assert_eq!(pairs("a=1&&b;c=").collect::<Vec<_>>(), [("a", "1"), ("b", ""), ("c", "")]);
        assert_eq!(cut("short"), "short");
        assert_eq!(cut(&"é".repeat(300)).chars().count(), 201);
    }
}
