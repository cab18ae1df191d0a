//! A small element tree for the OpenSCENARIO document and its writer: attributes in the order
//! they were added, two-space indentation, escaped values, coordinates in their shortest
//! round-trip form (never an exponent, never `-0`: every coordinate written exactly), times as
//! CommonRoad writes decimals; the same scenario gives the same bytes.

/// An element: name, attributes in order, children in order.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct El {
    name: &'static str,
    attrs: Vec<(&'static str, String)>,
    children: Vec<El>,
}

impl El {
    pub(crate) fn new(name: &'static str) -> Self {
        Self { name, attrs: Vec::new(), children: Vec::new() }
    }

    /// Adds an attribute.
    pub(crate) fn attr(mut self, key: &'static str, value: impl Into<String>) -> Self {
        self.attrs.push((key, value.into()));
        self
    }

    /// Adds a numeric attribute.
    pub(crate) fn num(self, key: &'static str, value: f64) -> Self {
        self.attr(key, num(value))
    }

    /// Adds a child.
    pub(crate) fn child(mut self, c: El) -> Self {
        self.children.push(c);
        self
    }

    /// Adds a child when there is one.
    pub(crate) fn child_opt(mut self, c: Option<El>) -> Self {
        self.children.extend(c);
        self
    }

    /// Adds children.
    pub(crate) fn children(mut self, cs: impl IntoIterator<Item = El>) -> Self {
        self.children.extend(cs);
        self
    }

    /// Adds a child in place.
    pub(crate) fn push(&mut self, c: El) {
        self.children.push(c);
    }

    fn write(&self, out: &mut String, depth: usize) {
        for _ in 0..depth {
            out.push_str("  ");
        }
        out.push('<');
        out.push_str(self.name);
        for (k, v) in &self.attrs {
            out.push(' ');
            out.push_str(k);
            out.push_str("=\"");
            escape_into(out, v);
            out.push('"');
        }
        if self.children.is_empty() {
            out.push_str("/>\n");
            return;
        }
        out.push_str(">\n");
        for c in &self.children {
            c.write(out, depth + 1);
        }
        for _ in 0..depth {
            out.push_str("  ");
        }
        out.push_str("</");
        out.push_str(self.name);
        out.push_str(">\n");
    }
}

/// The document: the XML declaration and `root`.
pub(crate) fn document(root: &El) -> String {
    let mut out = String::from("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    root.write(&mut out, 0);
    out
}

/// Escapes an attribute value (`commonroad::xml::escape`: line breaks and tabs as character
/// references, so a reader's attribute-value normalisation keeps them). Characters XML 1.0
/// cannot hold at all become U+FFFD.
fn escape_into(out: &mut String, s: &str) {
    let holdable = |c: char| !(((c as u32) < 0x20 && !matches!(c, '\t' | '\n' | '\r')) || c == '\u{FFFE}' || c == '\u{FFFF}');
    let clean: String = s.chars().map(|c| if holdable(c) { c } else { '\u{FFFD}' }).collect();
    out.push_str(&commonroad::xml::escape(&clean).unwrap_or_default());
}

/// A number in its shortest round-trip form; `-0` is `0`. The caller has checked it is finite.
pub(crate) fn num(v: f64) -> String {
    if v == 0.0 {
        "0".to_string()
    } else {
        format!("{v}")
    }
}

/// A time `k·dt` as CommonRoad writes decimals (6 digits: `0.3`, not `0.30000000000000004`).
pub(crate) fn time(seconds: f64) -> String {
    commonroad::xml::format_decimal(seconds).unwrap_or_else(|| "0.0".to_string())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_times_and_escaping() {
        assert_eq!(num(-0.0), "0");
        assert_eq!(num(0.1 + 0.2), "0.30000000000000004");
        assert_eq!(num(1e-7), "0.0000001");
        assert_eq!(time(3.0 * 0.1), "0.3");
        assert_eq!(time(12.0), "12.0");
        assert_eq!(time(-0.0000000001), "0.0");
        let d = document(&El::new("A").attr("v", "a<\"b\"\n&\u{1}").child(El::new("B")));
        assert_eq!(d, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<A v=\"a&lt;&quot;b&quot;&#10;&amp;\u{FFFD}\">\n  <B/>\n</A>\n");
    }
}
