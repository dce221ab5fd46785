//! Closed sets of names: the enums whose values a scene file, a
//! command-line flag or a Python keyword spells as one word (`periodic`,
//! `hann`, `rad/s`).
//!
//! Each such enum implements [`Named`]: one table, next to the enum, gives
//! every value its name and a one-line description, and the set a name and
//! a description of its own. Serde reads and writes the value by that name
//! (as serde's derive with `rename` would, with the same error text),
//! `Display` prints it, and the front-ends build from the same table what
//! they need of a closed set (the scene's JSON Schema with one description
//! per value, the command line's possible values, Python's keywords), so
//! that no value is spelled twice and a new value reaches every front-end
//! at once. Each such type also has an inherent `name()`, callable without
//! the trait in scope.
//!
//! The sets of the optional modules (the BEM's [`Boundary`],
//! [`Connectivity`] and [`LawKind`], a measured surface's [`Detrend`] and
//! [`Window`]) are declared here, at every feature setting, so that a scene
//! names them in every build; their modules re-export them.
//!
//! # Examples
//! ```
//! use persson::adhesion::AreaEnhancement;
//! use persson::names::Named;
//!
//! assert_eq!(AreaEnhancement::None.name(), "none");
//! assert_eq!(AreaEnhancement::from_name("slopes"), Some(AreaEnhancement::Slopes));
//! assert_eq!(serde_json::to_string(&AreaEnhancement::Slopes).unwrap(), "\"slopes\"");
//! let e = serde_json::from_str::<AreaEnhancement>("\"sloped\"").unwrap_err();
//! assert_eq!(
//!     e.to_string(),
//!     "unknown variant `sloped`, expected `slopes` or `none` at line 1 column 8"
//! );
//! ```

use std::fmt;
use std::marker::PhantomData;

mod sets;
pub use sets::{Boundary, Connectivity, Detrend, LawKind, Window};

use serde::de::{
    self, DeserializeSeed, Deserializer, EnumAccess, Unexpected, VariantAccess, Visitor,
};
use serde::Serializer;

/// A closed set of values, each spelled as one name.
///
/// Implemented with the crate's `named!` macro, which also gives the type
/// serde by name and `Display` from the same table, and fails to compile
/// when the table misses a variant.
pub trait Named: Copy + PartialEq + Sized + 'static {
    /// The set's name in snake_case (`boundary`, `frequency_unit`): the key
    /// it is usually given under. The front-ends name the set after it (the
    /// JSON Schema's `BoundaryName`).
    const SET: &'static str;
    /// What the set chooses, in one line.
    const DESCRIPTION: &'static str;
    /// Every value with its name and a one-line description, in order.
    const VALUES: &'static [(Self, &'static str, &'static str)];

    /// The name, as in scene files, on the command line and in Python.
    fn name(self) -> &'static str {
        row(self).1
    }

    /// One line on the value (the scene schema's, and `--help`'s).
    fn description(self) -> &'static str {
        row(self).2
    }

    /// The value named `name` (names are case-sensitive).
    fn from_name(name: &str) -> Option<Self> {
        Self::VALUES.iter().find(|v| v.1 == name).map(|v| v.0)
    }

    /// Every name, in order.
    fn names() -> impl Iterator<Item = &'static str> {
        Self::VALUES.iter().map(|v| v.1)
    }
}

/// The table's row of `value` (`named!` checks that every variant has one;
/// an empty name and description otherwise).
fn row<T: Named>(value: T) -> (T, &'static str, &'static str) {
    T::VALUES
        .iter()
        .copied()
        .find(|v| v.0 == value)
        .unwrap_or((value, "", ""))
}

/// Serde's `Serialize` of a [`Named`] value: the unit variant `ty::name`
/// (a string in JSON), as derived.
///
/// # Errors
/// The serializer's.
#[doc(hidden)]
pub fn serialize<T: Named, S: Serializer>(
    value: T,
    ty: &'static str,
    s: S,
) -> Result<S::Ok, S::Error> {
    let index = T::VALUES.iter().position(|v| v.0 == value).unwrap_or(0);
    s.serialize_unit_variant(ty, index as u32, value.name())
}

/// Serde's `Deserialize` of a [`Named`] value: a unit variant by name, with
/// the derive's error for another name (``unknown variant `x`, expected
/// `a` or `b` ``).
///
/// # Errors
/// Another name, or not a unit variant.
#[doc(hidden)]
pub(crate) fn deserialize<'de, T: Named, D: Deserializer<'de>>(
    d: D,
    ty: &'static str,
    names: &'static [&'static str],
) -> Result<T, D::Error> {
    d.deserialize_enum(
        ty,
        names,
        ByName {
            ty,
            names,
            value: PhantomData::<T>,
        },
    )
}

/// The visitor of a unit variant of `ty` (the enum) and of its name (the
/// variant identifier).
struct ByName<T> {
    ty: &'static str,
    names: &'static [&'static str],
    value: PhantomData<T>,
}

impl<T> Clone for ByName<T> {
    fn clone(&self) -> Self {
        *self
    }
}

impl<T> Copy for ByName<T> {}

impl<'de, T: Named> Visitor<'de> for ByName<T> {
    type Value = T;

    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "enum {}", self.ty)
    }

    fn visit_enum<A: EnumAccess<'de>>(self, data: A) -> Result<T, A::Error> {
        let (value, variant) = data.variant_seed(Identifier(self))?;
        variant.unit_variant()?;
        Ok(value)
    }
}

/// The variant identifier: a name, or (non-self-describing formats) an index.
struct Identifier<T>(ByName<T>);

impl<'de, T: Named> DeserializeSeed<'de> for Identifier<T> {
    type Value = T;

    fn deserialize<D: Deserializer<'de>>(self, d: D) -> Result<T, D::Error> {
        d.deserialize_identifier(self)
    }
}

impl<'de, T: Named> Visitor<'de> for Identifier<T> {
    type Value = T;

    fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("variant identifier")
    }

    fn visit_u64<E: de::Error>(self, v: u64) -> Result<T, E> {
        usize::try_from(v)
            .ok()
            .and_then(|i| T::VALUES.get(i))
            .map(|r| r.0)
            .ok_or_else(|| {
                let want = format!("variant index 0 <= i < {}", T::VALUES.len());
                E::invalid_value(Unexpected::Unsigned(v), &want.as_str())
            })
    }

    fn visit_str<E: de::Error>(self, v: &str) -> Result<T, E> {
        T::from_name(v).ok_or_else(|| E::unknown_variant(v, self.0.names))
    }

    fn visit_bytes<E: de::Error>(self, v: &[u8]) -> Result<T, E> {
        match std::str::from_utf8(v) {
            Ok(s) => self.visit_str(s),
            Err(_) => Err(E::unknown_variant(
                &String::from_utf8_lossy(v),
                self.0.names,
            )),
        }
    }
}

/// Implements [`Named`] for a fieldless enum from its table (`Variant =
/// "name": "description"`), with serde by name and `Display`; a variant
/// missing from the table is a compile error.
macro_rules! named {
    (
        $ty:ident, $set:literal, $description:literal {
            $($v:ident = $name:literal: $text:literal),+ $(,)?
        }
    ) => {
        impl $crate::names::Named for $ty {
            const SET: &'static str = $set;
            const DESCRIPTION: &'static str = $description;
            const VALUES: &'static [(Self, &'static str, &'static str)] =
                &[$(($ty::$v, $name, $text)),+];
        }

        // Every variant is in the table: a new one fails to compile here.
        const _: fn($ty) = |v| match v {
            $($ty::$v => ()),+
        };

        impl serde::Serialize for $ty {
            fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
                $crate::names::serialize(*self, stringify!($ty), s)
            }
        }

        impl<'de> serde::Deserialize<'de> for $ty {
            fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
                $crate::names::deserialize(d, stringify!($ty), &[$($name),+])
            }
        }

        impl $ty {
            /// The name, as in scene files, on the command line and in
            /// Python ([`Named::name`](crate::names::Named::name), callable
            /// without the trait in scope).
            pub fn name(self) -> &'static str {
                <Self as $crate::names::Named>::name(self)
            }
        }

        impl std::fmt::Display for $ty {
            fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
                f.write_str($crate::names::Named::name(*self))
            }
        }
    };
}

pub(crate) use named;

#[cfg(test)]
mod tests {
    use super::*;

    #[derive(Debug, Clone, Copy, PartialEq)]
    enum Colour {
        Red,
        DarkBlue,
        Green,
    }

    named! {
        Colour, "colour", "A colour." {
            Red = "red": "Red.",
            DarkBlue = "dark-blue": "Dark blue.",
            Green = "green": "Green.",
        }
    }

    #[derive(serde::Serialize, serde::Deserialize, Debug, PartialEq)]
    enum Derived {
        #[serde(rename = "red")]
        Red,
        #[serde(rename = "dark-blue")]
        DarkBlue,
        #[serde(rename = "green")]
        Green,
    }

    /// Names, serde and its errors are those of the derive with `rename`.
    #[test]
    fn serde_by_name_is_the_derive() {
        for (c, d) in [
            (Colour::Red, Derived::Red),
            (Colour::DarkBlue, Derived::DarkBlue),
            (Colour::Green, Derived::Green),
        ] {
            let s = serde_json::to_string(&c).unwrap();
            assert_eq!(s, serde_json::to_string(&d).unwrap());
            assert_eq!(s, format!("\"{c}\""));
            assert_eq!(serde_json::from_str::<Colour>(&s).unwrap(), c);
            assert_eq!(Colour::from_name(c.name()), Some(c));
            let v = serde_json::Value::String(c.name().into());
            assert_eq!(serde_json::from_value::<Colour>(v).unwrap(), c);
        }
        for bad in ["\"blue\"", "\"Red\"", "3", "{\"red\": 1}", "null"] {
            let want = serde_json::from_str::<Derived>(bad)
                .unwrap_err()
                .to_string();
            let got = serde_json::from_str::<Colour>(bad).unwrap_err().to_string();
            assert_eq!(got, want, "{bad}");
        }
        let bad = serde_json::Value::String("blue".into());
        assert_eq!(
            serde_json::from_value::<Colour>(bad.clone())
                .unwrap_err()
                .to_string(),
            serde_json::from_value::<Derived>(bad)
                .unwrap_err()
                .to_string()
        );
        assert_eq!(Colour::DarkBlue.description(), "Dark blue.");
        assert_eq!(
            Colour::names().collect::<Vec<_>>(),
            ["red", "dark-blue", "green"]
        );
    }
}
