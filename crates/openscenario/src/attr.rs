//! Typed, parameter-resolved access to the attributes and children of an element.

use crate::error::{Diagnostic, Error, ErrorKind, Location};
use crate::esmini_fallback;
use crate::params::{positioned, resolve_in_scope, Scope};
use crate::references::ReferenceSite;
use crate::xml::{Elem, Pos};
use std::cell::RefCell;
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

/// What a reading records beside the model: where each reference was written (so that a
/// name that refers to nothing is reported at its own attribute) and the values the standard
/// forbids but esmini reads in its own way (problems: errors unless `--lenient`).
#[derive(Default)]
pub(crate) struct Record {
    pub sites: RefCell<Vec<ReferenceSite>>,
    pub problems: RefCell<Vec<Diagnostic>>,
    /// The scenario's `revMinor` once its FileHeader is read: some defaults depend on it.
    pub rev_minor: std::cell::Cell<Option<u32>>,
}

/// Where we are: the file being read, the parameters in scope and the reading's record.
pub(crate) struct Cx<'s> {
    pub file: Arc<Path>,
    pub scope: &'s Scope<'s>,
    pub record: &'s Record,
}

impl<'s> Cx<'s> {
    pub(crate) fn new(file: Arc<Path>, scope: &'s Scope<'s>, record: &'s Record) -> Self {
        Cx { file, scope, record }
    }

    /// The same file and record with the parameters of `scope` (an entry's own declarations).
    pub(crate) fn scoped<'a>(&'a self, scope: &'a Scope<'a>) -> Cx<'a> {
        Cx { file: self.file.clone(), scope, record: self.record }
    }

    /// Another file (a catalog's) with `scope`, recording into the same record.
    pub(crate) fn in_file<'a>(&'a self, file: Arc<Path>, scope: &'a Scope<'a>) -> Cx<'a> {
        Cx { file, scope, record: self.record }
    }

    fn problem(&self, pos: Pos, message: String) {
        self.record.problems.borrow_mut().push(Diagnostic { location: self.loc(pos), message });
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
        self.opt_conv_or(e, name, conv, |_| None)
    }

    /// Like [`Cx::opt_conv`]; where `conv` fails, `fallback` may give what esmini reads instead
    /// (its value and how to say it), which is then a problem rather than an error.
    fn opt_conv_or<T>(
        &self,
        e: &Elem,
        name: &str,
        conv: impl Fn(&str) -> Result<T, String>,
        fallback: impl Fn(&str) -> Option<(T, String)>,
    ) -> Result<Option<T>, Error> {
        let Some(a) = e.attr(name) else { return Ok(None) };
        let text = resolve_in_scope(&a.value, self.scope).map_err(|err| positioned(&self.file, a.pos, err))?;
        match conv(&text) {
            Ok(v) => Ok(Some(v)),
            Err(expected) => {
                let shown = if text == a.value { format!("'{text}'") } else { format!("'{text}' (from '{}')", a.value) };
                let message = format!("attribute '{name}' of <{}>: expected {expected}, found {shown}", e.name);
                // An expression's text is not what esmini converts (it stops on an expression it
                // cannot evaluate), so only a literal or a parameter's value falls back.
                match fallback(&text).filter(|_| !a.value.trim_start().starts_with("${")) {
                    Some((v, read_as)) => {
                        self.problem(a.pos, format!("{message}; esmini reads it as {read_as}"));
                        Ok(Some(v))
                    }
                    None => Err(self.err(ErrorKind::Value, a.pos, message)),
                }
            }
        }
    }

    /// A number; text that is not one is read as esmini reads it (C's `atof`: its leading
    /// number, else 0), a problem.
    pub(crate) fn opt_f64(&self, e: &Elem, name: &str) -> Result<Option<f64>, Error> {
        self.opt_conv_or(e, name, parse_f64, |t| {
            let v = esmini_fallback::atof(t);
            // an infinite or NaN reading is nothing a run can go on with: it stays an error
            v.is_finite().then(|| (v, format!("{v}")))
        })
    }

    /// An optional number under `name`, else under `old_name`, the attribute's name in an
    /// earlier version of the standard (Sun's `illuminance` was `intensity` in OpenSCENARIO 1.0).
    pub(crate) fn opt_f64_renamed(&self, e: &Elem, name: &str, old_name: &str) -> Result<Option<f64>, Error> {
        match self.opt_f64(e, name)? {
            Some(v) => Ok(Some(v)),
            None => self.opt_f64(e, old_name),
        }
    }

    /// A number esmini reads with `std::stof`, which stops on text that is not one: no fallback.
    pub(crate) fn f64_exact(&self, e: &Elem, name: &str) -> Result<f64, Error> {
        self.opt_conv(e, name, parse_f64)?.ok_or_else(|| self.missing(e, name))
    }
    pub(crate) fn f64(&self, e: &Elem, name: &str) -> Result<f64, Error> {
        self.opt_f64(e, name)?.ok_or_else(|| self.missing(e, name))
    }
    pub(crate) fn f64_or(&self, e: &Elem, name: &str, default: f64) -> Result<f64, Error> {
        Ok(self.opt_f64(e, name)?.unwrap_or(default))
    }
    /// An integer; text that is not one is read as esmini reads it (C's `atoi`), a problem.
    pub(crate) fn opt_i64(&self, e: &Elem, name: &str) -> Result<Option<i64>, Error> {
        self.opt_conv_or(e, name, parse_i64, |t| {
            let v = esmini_fallback::atoi(t);
            Some((v, v.to_string()))
        })
    }
    pub(crate) fn i64(&self, e: &Elem, name: &str) -> Result<i64, Error> {
        self.opt_i64(e, name)?.ok_or_else(|| self.missing(e, name))
    }
    pub(crate) fn opt_u32(&self, e: &Elem, name: &str) -> Result<Option<u32>, Error> {
        self.opt_conv_or(
            e,
            name,
            |s| parse_i64(s).and_then(|v| u32::try_from(v).map_err(|_| "an unsigned integer".to_string())),
            |t| u32::try_from(esmini_fallback::atoi(t)).ok().map(|v| (v, v.to_string())),
        )
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
        let value = raw.value.trim().trim_start_matches('$').to_string();
        self.site(name, &value, raw.pos);
        Ok(value)
    }

    /// The resolved value of a required attribute that names something elsewhere (an entity, a
    /// road, a storyboard element, …), its position kept for the checks of what it names.
    pub(crate) fn reference(&self, e: &Elem, name: &str) -> Result<String, Error> {
        self.opt_reference(e, name)?.ok_or_else(|| self.missing(e, name))
    }

    /// Like [`Cx::reference`] for an optional attribute.
    pub(crate) fn opt_reference(&self, e: &Elem, name: &str) -> Result<Option<String>, Error> {
        let value = self.opt_text(e, name)?;
        if let (Some(v), Some(a)) = (&value, e.attr(name)) {
            self.site(name, v, a.pos);
        }
        Ok(value)
    }

    /// Keeps where `attribute` (a reference whose resolved value is `value`) was written.
    pub(crate) fn site(&self, attribute: &str, value: &str, pos: Pos) {
        self.record.sites.borrow_mut().push(ReferenceSite { attribute: attribute.to_string(), value: value.to_string(), location: self.loc(pos) });
    }

    /// An enumeration value that esmini compares exactly and replaces by `default` when it does
    /// not know it (vehicle and pedestrian categories): such a value is a problem, read as esmini
    /// reads it.
    pub(crate) fn enum_or_esmini_default<T: XmlEnum>(&self, e: &Elem, name: &str, default: T) -> Result<T, Error> {
        let a = e.attr(name).ok_or_else(|| self.missing(e, name))?;
        let text = resolve_in_scope(&a.value, self.scope).map_err(|err| positioned(&self.file, a.pos, err))?;
        match T::from_xml(text.trim()) {
            Some(v) => Ok(v),
            None => {
                let shown = if text == a.value { format!("'{text}'") } else { format!("'{text}' (from '{}')", a.value) };
                self.problem(
                    a.pos,
                    format!(
                        "attribute '{name}' of <{}>: expected one of {}, found {shown}; esmini reads it as its default, {}",
                        e.name,
                        T::NAMES.join(", "),
                        default.xml_name()
                    ),
                );
                Ok(default)
            }
        }
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
