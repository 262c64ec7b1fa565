//! Whether a typed case holds a value that is not a number (NaN or ±inf).
//!
//! A deck cannot give one (the reader refuses numbers beyond double precision), but a case
//! built or edited in code can. The search walks the case's serialized form, so every number
//! of every input structure is seen, including fields added later, without a list to keep.
//! It stops at the first such value and allocates nothing; naming the values is
//! [`super::Case::values_not_numbers`]'s work, done only when there is one.

use serde::ser::{self, Serialize, Serializer};

use super::Case;

/// The case's fields that are derived from its input, not input: the flight conditions are
/// derived from `flight` and checked where they are derived.
const DERIVED_FIELDS: [&str; 1] = ["conditions"];

/// Whether any input number of `case` is NaN or infinite.
pub(super) fn holds_value_not_a_number(case: &Case) -> bool {
    case.serialize(Finder).is_err()
}

/// Why the walk stopped: a value that is not a number (the only "error").
#[derive(Debug)]
struct NotANumber;

impl std::fmt::Display for NotANumber {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("a value that is not a number")
    }
}

impl std::error::Error for NotANumber {}

impl ser::Error for NotANumber {
    fn custom<T: std::fmt::Display>(_: T) -> Self {
        NotANumber
    }
}

/// The serializer that checks numbers and writes nothing.
#[derive(Clone, Copy)]
struct Finder;

/// A struct's, sequence's or map's members, walked by [`Finder`].
struct Members {
    /// The field names skipped (the case's derived fields; none elsewhere).
    skip: &'static [&'static str],
}

type Walked = Result<(), NotANumber>;

fn finite(v: f64) -> Walked {
    if v.is_finite() {
        Ok(())
    } else {
        Err(NotANumber)
    }
}

const NOTHING: Members = Members { skip: &[] };

impl Serializer for Finder {
    type Ok = ();
    type Error = NotANumber;
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
    fn serialize_bool(self, _: bool) -> Walked {
        Ok(())
    }
    fn serialize_i8(self, _: i8) -> Walked {
        Ok(())
    }
    fn serialize_i16(self, _: i16) -> Walked {
        Ok(())
    }
    fn serialize_i32(self, _: i32) -> Walked {
        Ok(())
    }
    fn serialize_i64(self, _: i64) -> Walked {
        Ok(())
    }
    fn serialize_u8(self, _: u8) -> Walked {
        Ok(())
    }
    fn serialize_u16(self, _: u16) -> Walked {
        Ok(())
    }
    fn serialize_u32(self, _: u32) -> Walked {
        Ok(())
    }
    fn serialize_u64(self, _: u64) -> Walked {
        Ok(())
    }
    fn serialize_char(self, _: char) -> Walked {
        Ok(())
    }
    fn serialize_str(self, _: &str) -> Walked {
        Ok(())
    }
    fn serialize_bytes(self, _: &[u8]) -> Walked {
        Ok(())
    }
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
    fn serialize_seq(self, _: Option<usize>) -> Result<Members, NotANumber> {
        Ok(NOTHING)
    }
    fn serialize_tuple(self, _: usize) -> Result<Members, NotANumber> {
        Ok(NOTHING)
    }
    fn serialize_tuple_struct(self, _: &'static str, _: usize) -> Result<Members, NotANumber> {
        Ok(NOTHING)
    }
    fn serialize_tuple_variant(
        self,
        _: &'static str,
        _: u32,
        _: &'static str,
        _: usize,
    ) -> Result<Members, NotANumber> {
        Ok(NOTHING)
    }
    fn serialize_map(self, _: Option<usize>) -> Result<Members, NotANumber> {
        Ok(NOTHING)
    }
    fn serialize_struct(self, name: &'static str, _: usize) -> Result<Members, NotANumber> {
        Ok(if name == "Case" {
            Members {
                skip: &DERIVED_FIELDS,
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
    ) -> Result<Members, NotANumber> {
        Ok(NOTHING)
    }
}

impl ser::SerializeSeq for Members {
    type Ok = ();
    type Error = NotANumber;
    fn serialize_element<T: ?Sized + Serialize>(&mut self, value: &T) -> Walked {
        value.serialize(Finder)
    }
    fn end(self) -> Walked {
        Ok(())
    }
}

impl ser::SerializeTuple for Members {
    type Ok = ();
    type Error = NotANumber;
    fn serialize_element<T: ?Sized + Serialize>(&mut self, value: &T) -> Walked {
        value.serialize(Finder)
    }
    fn end(self) -> Walked {
        Ok(())
    }
}

impl ser::SerializeTupleStruct for Members {
    type Ok = ();
    type Error = NotANumber;
    fn serialize_field<T: ?Sized + Serialize>(&mut self, value: &T) -> Walked {
        value.serialize(Finder)
    }
    fn end(self) -> Walked {
        Ok(())
    }
}

impl ser::SerializeTupleVariant for Members {
    type Ok = ();
    type Error = NotANumber;
    fn serialize_field<T: ?Sized + Serialize>(&mut self, value: &T) -> Walked {
        value.serialize(Finder)
    }
    fn end(self) -> Walked {
        Ok(())
    }
}

impl ser::SerializeMap for Members {
    type Ok = ();
    type Error = NotANumber;
    fn serialize_key<T: ?Sized + Serialize>(&mut self, key: &T) -> Walked {
        key.serialize(Finder)
    }
    fn serialize_value<T: ?Sized + Serialize>(&mut self, value: &T) -> Walked {
        value.serialize(Finder)
    }
    fn end(self) -> Walked {
        Ok(())
    }
}

impl ser::SerializeStruct for Members {
    type Ok = ();
    type Error = NotANumber;
    fn serialize_field<T: ?Sized + Serialize>(&mut self, key: &'static str, value: &T) -> Walked {
        if self.skip.contains(&key) {
            return Ok(());
        }
        value.serialize(Finder)
    }
    fn end(self) -> Walked {
        Ok(())
    }
}

impl ser::SerializeStructVariant for Members {
    type Ok = ();
    type Error = NotANumber;
    fn serialize_field<T: ?Sized + Serialize>(&mut self, _: &'static str, value: &T) -> Walked {
        value.serialize(Finder)
    }
    fn end(self) -> Walked {
        Ok(())
    }
}
