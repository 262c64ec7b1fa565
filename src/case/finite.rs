//! Whether a typed case holds a value that is not a number (NaN or ±inf).
//!
//! A deck cannot give one (the reader refuses numbers beyond double precision), but a case
//! built or edited in code can. The search walks the case's serialized form, so every number
//! of every input structure is seen, including fields added later, without a list to keep.
//! It stops at the first such value and allocates nothing until then; naming the values by
//! namelist and variable is [`super::Case::values_not_numbers`]'s work, done only when there
//! is one.

use serde::ser::{self, Serialize, Serializer};

use super::Case;

/// The case's fields that are derived from its input, not input: the flight conditions are
/// derived from `flight` and checked where they are derived.
const DERIVED_FIELDS: [&str; 1] = ["conditions"];

/// The first input number of `case` that is NaN or infinite, if any: the path of its field
/// in the case (`synthesis.zcg`, `body.r[2]`; a map's entry by its key, `sections{CANARD}`) and
/// its value.
pub(super) fn first_value_not_a_number(case: &Case) -> Option<(String, f64)> {
    case.serialize(Finder)
        .err()
        .map(|e| (e.path.unwrap_or_default(), e.value))
}

/// Why the walk stopped: a value that is not a number (the only "error"), and where, written
/// as the walk returns through the fields that hold it.
#[derive(Debug)]
struct Found {
    value: f64,
    /// None at the value itself; the field path above it as it is returned.
    path: Option<String>,
}

impl Found {
    /// The same value, one field further out (`.name`, `[index]`, `{entry}`).
    fn inside(self, step: std::fmt::Arguments) -> Found {
        let path = match self.path {
            Some(below) if below.starts_with('[') || below.starts_with('{') => {
                format!("{step}{below}")
            }
            Some(below) => format!("{step}.{below}"),
            None => step.to_string(),
        };
        Found {
            value: self.value,
            path: Some(path),
        }
    }
}

impl std::fmt::Display for Found {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{} = {}", self.path.as_deref().unwrap_or(""), self.value)
    }
}

impl std::error::Error for Found {}

impl ser::Error for Found {
    /// A structure that cannot be walked (none of the case's: they all serialize) is taken
    /// as holding a value that is not a number, so that it is looked at.
    fn custom<T: std::fmt::Display>(why: T) -> Self {
        Found {
            value: f64::NAN,
            path: Some(format!("(not walked: {why})")),
        }
    }
}

/// The serializer that checks numbers and writes nothing.
#[derive(Clone, Copy)]
struct Finder;

/// A struct's, sequence's or map's members, walked by [`Finder`].
struct Members {
    /// The field names skipped (the case's derived fields; none elsewhere).
    skip: &'static [&'static str],
    /// The members walked so far.
    count: usize,
}

impl Members {
    /// Walks a named field, naming it when the value is not a number.
    fn field<T: ?Sized + Serialize>(key: &'static str, value: &T) -> Walked {
        value
            .serialize(Finder)
            .map_err(|e| e.inside(format_args!("{key}")))
    }

    /// Walks the next member, naming it by its place when the value is not a number.
    fn element<T: ?Sized + Serialize>(&mut self, value: &T, brackets: bool) -> Walked {
        let k = self.count;
        self.count += 1;
        value.serialize(Finder).map_err(|e| {
            if brackets {
                e.inside(format_args!("[{k}]"))
            } else {
                e.inside(format_args!("{{{k}}}"))
            }
        })
    }
}

type Walked = Result<(), Found>;

fn finite(v: f64) -> Walked {
    if v.is_finite() {
        Ok(())
    } else {
        Err(Found {
            value: v,
            path: None,
        })
    }
}

const NOTHING: Members = Members {
    skip: &[],
    count: 0,
};

/// Serializer methods for values that hold no number: nothing to check.
macro_rules! ignored {
    ($($method:ident: $ty:ty),* $(,)?) => {$(
        fn $method(self, _: $ty) -> Walked {
            Ok(())
        }
    )*};
}

impl Serializer for Finder {
    type Ok = ();
    type Error = Found;
    type SerializeSeq = Members;
    type SerializeTuple = Members;
    type SerializeTupleStruct = Members;
    type SerializeTupleVariant = Members;
    type SerializeMap = Members;
    type SerializeStruct = Members;
    type SerializeStructVariant = Members;

    fn serialize_f64(self, v: f64) -> Walked {
        finite(v)
    }
    fn serialize_f32(self, v: f32) -> Walked {
        finite(f64::from(v))
    }
    ignored!(
        serialize_bool: bool,
        serialize_i8: i8,
        serialize_i16: i16,
        serialize_i32: i32,
        serialize_i64: i64,
        serialize_u8: u8,
        serialize_u16: u16,
        serialize_u32: u32,
        serialize_u64: u64,
        serialize_char: char,
        serialize_str: &str,
        serialize_bytes: &[u8],
    );
    fn serialize_none(self) -> Walked {
        Ok(())
    }
    fn serialize_some<T: ?Sized + Serialize>(self, value: &T) -> Walked {
        value.serialize(self)
    }
    fn serialize_unit(self) -> Walked {
        Ok(())
    }
    fn serialize_unit_struct(self, _: &'static str) -> Walked {
        Ok(())
    }
    fn serialize_unit_variant(self, _: &'static str, _: u32, _: &'static str) -> Walked {
        Ok(())
    }
    fn serialize_newtype_struct<T: ?Sized + Serialize>(self, _: &'static str, value: &T) -> Walked {
        value.serialize(self)
    }
    fn serialize_newtype_variant<T: ?Sized + Serialize>(
        self,
        _: &'static str,
        _: u32,
        _: &'static str,
        value: &T,
    ) -> Walked {
        value.serialize(self)
    }
    fn serialize_seq(self, _: Option<usize>) -> Result<Members, Found> {
        Ok(NOTHING)
    }
    fn serialize_tuple(self, _: usize) -> Result<Members, Found> {
        Ok(NOTHING)
    }
    fn serialize_tuple_struct(self, _: &'static str, _: usize) -> Result<Members, Found> {
        Ok(NOTHING)
    }
    fn serialize_tuple_variant(
        self,
        _: &'static str,
        _: u32,
        _: &'static str,
        _: usize,
    ) -> Result<Members, Found> {
        Ok(NOTHING)
    }
    fn serialize_map(self, _: Option<usize>) -> Result<Members, Found> {
        Ok(NOTHING)
    }
    fn serialize_struct(self, name: &'static str, _: usize) -> Result<Members, Found> {
        Ok(if name == "Case" {
            Members {
                skip: &DERIVED_FIELDS,
                count: 0,
            }
        } else {
            NOTHING
        })
    }
    fn serialize_struct_variant(
        self,
        _: &'static str,
        _: u32,
        _: &'static str,
        _: usize,
    ) -> Result<Members, Found> {
        Ok(NOTHING)
    }
}

/// The members of a sequence, a tuple and a tuple struct or variant: walked in order, named
/// by their place.
macro_rules! elements {
    ($($trait:ident :: $method:ident),*) => {$(
        impl ser::$trait for Members {
            type Ok = ();
            type Error = Found;
            fn $method<T: ?Sized + Serialize>(&mut self, value: &T) -> Walked {
                self.element(value, true)
            }
            fn end(self) -> Walked {
                Ok(())
            }
        }
    )*};
}

elements!(
    SerializeSeq::serialize_element,
    SerializeTuple::serialize_element,
    SerializeTupleStruct::serialize_field,
    SerializeTupleVariant::serialize_field
);

impl ser::SerializeMap for Members {
    type Ok = ();
    type Error = Found;
    fn serialize_key<T: ?Sized + Serialize>(&mut self, key: &T) -> Walked {
        key.serialize(Finder)
    }
    fn serialize_value<T: ?Sized + Serialize>(&mut self, value: &T) -> Walked {
        self.element(value, false)
    }
    /// An entry whose key is text is named by its key (`sections{CANARD}`), others by place.
    fn serialize_entry<K: ?Sized + Serialize, V: ?Sized + Serialize>(
        &mut self,
        key: &K,
        value: &V,
    ) -> Walked {
        key.serialize(Finder)?;
        let place = self.count;
        self.count += 1;
        value
            .serialize(Finder)
            .map_err(|e| match serde_json::to_value(key) {
                Ok(serde_json::Value::String(name)) => e.inside(format_args!("{{{name}}}")),
                _ => e.inside(format_args!("{{{place}}}")),
            })
    }
    fn end(self) -> Walked {
        Ok(())
    }
}

impl ser::SerializeStruct for Members {
    type Ok = ();
    type Error = Found;
    fn serialize_field<T: ?Sized + Serialize>(&mut self, key: &'static str, value: &T) -> Walked {
        if self.skip.contains(&key) {
            return Ok(());
        }
        Members::field(key, value)
    }
    fn end(self) -> Walked {
        Ok(())
    }
}

impl ser::SerializeStructVariant for Members {
    type Ok = ();
    type Error = Found;
    fn serialize_field<T: ?Sized + Serialize>(&mut self, key: &'static str, value: &T) -> Walked {
        Members::field(key, value)
    }
    fn end(self) -> Walked {
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::case::{Body, SectionInput, Synthesis};

    #[test]
    fn the_first_value_not_a_number_is_named_by_its_field() {
        let mut case = Case::new();
        assert_eq!(first_value_not_a_number(&case), None);
        case.body = Some(Body {
            x: vec![0.0, 1.0, 2.0],
            r: vec![0.0, 0.1, f64::INFINITY],
            ..Body::default()
        });
        let (path, value) = first_value_not_a_number(&case).unwrap();
        assert_eq!((path.as_str(), value), ("body.r[2]", f64::INFINITY));

        case.body = None;
        case.synthesis = Some(Synthesis {
            scale: Some(f64::NAN),
            ..Synthesis::default()
        });
        let (path, value) = first_value_not_a_number(&case).unwrap();
        assert_eq!(path, "synthesis.scale");
        assert!(value.is_nan());

        case.synthesis = None;
        let mut section = SectionInput::default();
        section.scalars.insert("TOVC".into(), 0.12);
        section.scalars.insert("XOVC".into(), f64::NEG_INFINITY);
        case.sections.insert("WING".into(), section);
        let (path, _) = first_value_not_a_number(&case).unwrap();
        assert_eq!(
            path, "sections{WING}.scalars{XOVC}",
            "map entries by their keys"
        );
    }

    /// The flight conditions are derived from the flight input and checked where they are
    /// derived: the walk leaves them.
    #[test]
    fn derived_conditions_are_not_input() {
        let mut case = Case::new();
        case.flight = Some(crate::case::FlightInput {
            mach: vec![0.2],
            altitude: vec![0.0],
            alpha_deg: vec![0.0],
            ..Default::default()
        });
        case.prepare();
        let mut condition = case.conditions[0].clone();
        condition.mach = f64::NAN;
        case.conditions.push(condition);
        assert_eq!(first_value_not_a_number(&case), None);
    }
}
