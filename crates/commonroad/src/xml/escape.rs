//! Escaping of text and attribute values. Characters XML 1.0 cannot carry at all (most C0
//! controls, U+FFFE, U+FFFF) are refused rather than silently dropped.

/// Escapes `s` for use as element text or a (double- or single-quoted) attribute value.
/// Tab, LF and CR are written as character references so attribute-value normalisation and
/// end-of-line handling of the parser give back exactly `s`.
/// Returns the first character that XML 1.0 cannot represent, if any.
pub fn escape(s: &str) -> Result<String, char> {
    let mut out = String::with_capacity(s.len());
    escape_into(&mut out, s)?;
    Ok(out)
}

/// [`escape`] appended to `out` (which may be left partly written on error).
pub(crate) fn escape_into(out: &mut String, s: &str) -> Result<(), char> {
    // Most values (ids, enum words) need no escaping: copy them in one go.
    if !s.chars().any(|c| matches!(c, '&' | '<' | '>' | '"' | '\'') || (c as u32) < 0x20 || c == '\u{FFFE}' || c == '\u{FFFF}') {
        out.push_str(s);
        return Ok(());
    }
    for ch in s.chars() {
        match ch {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&apos;"),
            '\t' => out.push_str("&#9;"),
            '\n' => out.push_str("&#10;"),
            '\r' => out.push_str("&#13;"),
            c if (c as u32) < 0x20 || c == '\u{FFFE}' || c == '\u{FFFF}' => return Err(c),
            c => out.push(c),
        }
    }
    Ok(())
}
