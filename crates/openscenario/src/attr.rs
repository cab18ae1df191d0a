//! Typed, parameter-resolved access to the attributes and children of an element.

use crate::error::{Error, ErrorKind, Location};
use crate::params::{positioned, resolve_in_scope, Scope};
use crate::xml::{Elem, Pos};
use std::path::Path;
use std::sync::Arc;

/// An enumeration of the schema with its XML spellings.
pub trait XmlEnum: Sized + Copy {
    const NAMES: &'static [&'static str];
    fn from_xml(s: &str) -> Option<Self>;
    /// The canonical (latest) XML spelling.
    fn xml_name(self) -> &'static str;
}

/// Exact spelling first; then case-insensitively (files in the wild vary in case).
pub(crate) fn parse_enum<T: XmlEnum>(s: &str) -> Option<T> {
    let s = s.trim();
    T::from_xml(s).or_else(|| T::NAMES.iter().find(|n| n.eq_ignore_ascii_case(s)).and_then(|n| T::from_xml(n)))
}

/// Defines a schema enumeration with its XML spellings (first spelling is canonical).
#[macro_export]
#[doc(hidden)]
macro_rules! xml_enum {
    ($(#[$m:meta])* $name:ident { $($(#[$vm:meta])* $variant:ident = $first:literal $(| $alt:literal)*),* $(,)? }) => {
        $(#[$m])*
        #[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash, serde::Serialize)]
        pub enum $name { $($(#[$vm])* $variant),* }
        impl $crate::attr::XmlEnum for $name {
            const NAMES: &'static [&'static str] = &[$($first $(, $alt)*),*];
            fn from_xml(s: &str) -> Option<Self> {
                match s { $($first $(| $alt)* => Some(Self::$variant),)* _ => None }
            }
            fn xml_name(self) -> &'static str {
                match self { $(Self::$variant => $first,)* }
            }
        }
        impl std::fmt::Display for $name {
            fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
                f.write_str($crate::attr::XmlEnum::xml_name(*self))
            }
        }
    };
}

/// Where we are: the file being read and the parameters in scope.
pub(crate) struct Cx<'s> {
    pub file: Arc<Path>,
    pub scope: &'s Scope<'s>,
}

impl<'s> Cx<'s> {
    pub(crate) fn new(file: Arc<Path>, scope: &'s Scope<'s>) -> Self {
        Cx { file, scope }
    }

    pub(crate) fn loc(&self, pos: Pos) -> Location {
        Location { file: self.file.clone(), line: pos.line, col: pos.col }
    }

    pub(crate) fn err(&self, kind: ErrorKind, pos: Pos, message: impl Into<String>) -> Error {
        Error::new(kind, self.loc(pos), message)
    }

    /// The required child `name` of `e`.
    pub(crate) fn child<'e>(&self, e: &'e Elem, name: &str) -> Result<&'e Elem, Error> {
        e.child(name).ok_or_else(|| self.err(ErrorKind::Structure, e.pos, format!("{} needs a child element <{name}>", e.name)))
    }

    /// The first child of a schema choice, which must exist.
    pub(crate) fn choice<'e>(&self, e: &'e Elem, what: &str) -> Result<&'e Elem, Error> {
        e.first_child().ok_or_else(|| self.err(ErrorKind::Structure, e.pos, format!("{} needs a child element ({what})", e.name)))
    }

    pub(crate) fn unexpected(&self, e: &Elem, parent: &str, expected: &str) -> Error {
        self.err(ErrorKind::Structure, e.pos, format!("unexpected element <{}> in {parent}, expected one of {expected}", e.name))
    }

    /// The resolved value of an optional attribute.
    pub(crate) fn opt_text(&self, e: &Elem, name: &str) -> Result<Option<String>, Error> {
        match e.attr(name) {
            None => Ok(None),
            Some(a) => resolve_in_scope(&a.value, self.scope).map(Some).map_err(|err| positioned(&self.file, a.pos, err)),
        }
    }

    fn missing(&self, e: &Elem, name: &str) -> Error {
        self.err(ErrorKind::Structure, e.pos, format!("<{}> needs a '{name}' attribute", e.name))
    }

    pub(crate) fn text(&self, e: &Elem, name: &str) -> Result<String, Error> {
        self.opt_text(e, name)?.ok_or_else(|| self.missing(e, name))
    }

    /// An optional attribute resolved and converted by `conv` (message says what was expected).
    fn opt_conv<T>(&self, e: &Elem, name: &str, conv: impl Fn(&str) -> Result<T, String>) -> Result<Option<T>, Error> {
        let Some(a) = e.attr(name) else { return Ok(None) };
        let text = resolve_in_scope(&a.value, self.scope).map_err(|err| positioned(&self.file, a.pos, err))?;
        conv(&text).map(Some).map_err(|expected| {
            let shown = if text == a.value { format!("'{text}'") } else { format!("'{text}' (from '{}')", a.value) };
            self.err(ErrorKind::Value, a.pos, format!("attribute '{name}' of <{}>: expected {expected}, found {shown}", e.name))
        })
    }

    pub(crate) fn opt_f64(&self, e: &Elem, name: &str) -> Result<Option<f64>, Error> {
        self.opt_conv(e, name, parse_f64)
    }
    pub(crate) fn f64(&self, e: &Elem, name: &str) -> Result<f64, Error> {
        self.opt_f64(e, name)?.ok_or_else(|| self.missing(e, name))
    }
    pub(crate) fn f64_or(&self, e: &Elem, name: &str, default: f64) -> Result<f64, Error> {
        Ok(self.opt_f64(e, name)?.unwrap_or(default))
    }
    pub(crate) fn opt_i64(&self, e: &Elem, name: &str) -> Result<Option<i64>, Error> {
        self.opt_conv(e, name, parse_i64)
    }
    pub(crate) fn i64(&self, e: &Elem, name: &str) -> Result<i64, Error> {
        self.opt_i64(e, name)?.ok_or_else(|| self.missing(e, name))
    }
    pub(crate) fn opt_u32(&self, e: &Elem, name: &str) -> Result<Option<u32>, Error> {
        self.opt_conv(e, name, |s| parse_i64(s).and_then(|v| u32::try_from(v).map_err(|_| "an unsigned integer".to_string())))
    }
    pub(crate) fn u32_or(&self, e: &Elem, name: &str, default: u32) -> Result<u32, Error> {
        Ok(self.opt_u32(e, name)?.unwrap_or(default))
    }
    pub(crate) fn opt_bool(&self, e: &Elem, name: &str) -> Result<Option<bool>, Error> {
        self.opt_conv(e, name, parse_bool)
    }
    pub(crate) fn bool(&self, e: &Elem, name: &str) -> Result<bool, Error> {
        self.opt_bool(e, name)?.ok_or_else(|| self.missing(e, name))
    }
    pub(crate) fn bool_or(&self, e: &Elem, name: &str, default: bool) -> Result<bool, Error> {
        Ok(self.opt_bool(e, name)?.unwrap_or(default))
    }
    pub(crate) fn opt_enum<T: XmlEnum>(&self, e: &Elem, name: &str) -> Result<Option<T>, Error> {
        self.opt_conv(e, name, |s| parse_enum::<T>(s).ok_or_else(|| format!("one of {}", T::NAMES.join(", "))))
    }
    pub(crate) fn enum_<T: XmlEnum>(&self, e: &Elem, name: &str) -> Result<T, Error> {
        self.opt_enum(e, name)?.ok_or_else(|| self.missing(e, name))
    }
    /// A reference to a named thing; tolerates a leading `$` as esmini does for `parameterRef="$X"`.
    pub(crate) fn name_ref(&self, e: &Elem, name: &str) -> Result<String, Error> {
        let raw = e.attr(name).ok_or_else(|| self.missing(e, name))?;
        Ok(raw.value.trim().trim_start_matches('$').to_string())
    }
}

pub(crate) fn parse_f64(s: &str) -> Result<f64, String> {
    let t = s.trim();
    match t.parse::<f64>() {
        Ok(v) if !v.is_nan() => Ok(v),
        _ => Err("a number".to_string()),
    }
}

pub(crate) fn parse_i64(s: &str) -> Result<i64, String> {
    let t = s.trim();
    if let Ok(v) = t.parse::<i64>() {
        return Ok(v);
    }
    // An integral value written as a decimal ("3.0", or an expression result) is accepted.
    match t.parse::<f64>() {
        Ok(v) if v.fract() == 0.0 && v.abs() < 9.0e15 => Ok(v as i64),
        _ => Err("an integer".to_string()),
    }
}

pub(crate) fn parse_bool(s: &str) -> Result<bool, String> {
    match s.trim() {
        "true" | "1" | "True" | "TRUE" => Ok(true),
        "false" | "0" | "False" | "FALSE" => Ok(false),
        _ => Err("true or false".to_string()),
    }
}
