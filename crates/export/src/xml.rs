//! A small element tree for the OpenSCENARIO document and its writer: attributes in the order
//! they were added, two-space indentation, escaped values, and numbers in their shortest
//! round-trip form (never an exponent, never `-0`), so that the same scenario gives the same
//! bytes and every coordinate is written exactly.

/// An element: name, attributes in order, children in order.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct El {
    name: &'static str,
    attrs: Vec<(&'static str, String)>,
    children: Vec<El>,
}

impl El {
    pub fn new(name: &'static str) -> Self {
        Self { name, attrs: Vec::new(), children: Vec::new() }
    }

    /// Adds an attribute.
    pub fn attr(mut self, key: &'static str, value: impl Into<String>) -> Self {
        self.attrs.push((key, value.into()));
        self
    }

    /// Adds a numeric attribute.
    pub fn num(self, key: &'static str, value: f64) -> Self {
        self.attr(key, num(value))
    }

    /// Adds a child.
    pub fn child(mut self, c: El) -> Self {
        self.children.push(c);
        self
    }

    /// Adds a child when there is one.
    pub fn child_opt(mut self, c: Option<El>) -> Self {
        self.children.extend(c);
        self
    }

    /// Adds children.
    pub fn children(mut self, cs: impl IntoIterator<Item = El>) -> Self {
        self.children.extend(cs);
        self
    }

    /// Adds a child in place.
    pub fn push(&mut self, c: El) {
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

/// Escapes an attribute value. Line breaks and tabs are written as character references so a
/// reader's attribute-value normalisation keeps them.
fn escape_into(out: &mut String, s: &str) {
    for c in s.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\n' => out.push_str("&#10;"),
            '\r' => out.push_str("&#13;"),
            '\t' => out.push_str("&#9;"),
            // characters XML 1.0 cannot hold at all
            c if (c as u32) < 0x20 => out.push('\u{FFFD}'),
            c => out.push(c),
        }
    }
}

/// A number in its shortest round-trip form; `-0` is `0`. The caller has checked it is finite.
pub(crate) fn num(v: f64) -> String {
    if v == 0.0 {
        "0".to_string()
    } else {
        format!("{v}")
    }
}

/// A time `k·dt` rounded to the nanosecond (`0.3`, not `0.30000000000000004`).
pub(crate) fn time(seconds: f64) -> String {
    let mut s = format!("{seconds:.9}");
    while s.ends_with('0') {
        s.pop();
    }
    if s.ends_with('.') {
        s.pop();
    }
    if s == "-0" {
        s = "0".to_string();
    }
    s
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
        assert_eq!(time(12.0), "12");
        assert_eq!(time(-0.0000000001), "0");
        let d = document(&El::new("A").attr("v", "a<\"b\"\n&").child(El::new("B")));
        assert_eq!(d, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<A v=\"a&lt;&quot;b&quot;&#10;&amp;\">\n  <B/>\n</A>\n");
    }
}
