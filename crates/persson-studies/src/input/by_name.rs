//! The numerics' closed sets ([`Named`]: boundary, window, cohesive law, …)
//! in the front-ends, generated from their one table of names.
//!
//! A scene field keeps the numerics' type, which serde reads and writes by
//! name. What the numerics cannot derive (the orphan rule, and no schemars
//! or clap in the numerics) is here:
//! - the JSON Schema: [`ByName<T>`], named `<Set>Name` after
//!   [`Named::SET`] (`BoundaryName`), a `oneOf` of one `const` per value
//!   with its description; a field says `#[schemars(with =
//!   "Option<ByName<Boundary>>")]`;
//! - (feature `clap`) the command line's value parser [`by_name`], which
//!   lists the names as possible values with their descriptions in
//!   `--help`, and rejects another name with clap's own error (the possible
//!   values and a similar one): `#[arg(long, value_parser = by_name::<Window>())]`.
//!
//! Python reads a keyword by serde ([`Named`]'s error text).

use std::borrow::Cow;
use std::marker::PhantomData;

use persson::names::Named;
use schemars::{json_schema, JsonSchema, Schema, SchemaGenerator};

/// The JSON Schema of the closed set `T`, for `#[schemars(with = …)]`.
pub struct ByName<T>(PhantomData<T>);

impl<T: Named> JsonSchema for ByName<T> {
    fn schema_name() -> Cow<'static, str> {
        format!("{}Name", upper_camel(T::SET)).into()
    }

    fn json_schema(_: &mut SchemaGenerator) -> Schema {
        let one_of: Vec<_> = T::VALUES
            .iter()
            .map(|&(_, name, description)| {
                serde_json::json!({"description": description, "type": "string", "const": name})
            })
            .collect();
        json_schema!({"description": T::DESCRIPTION, "oneOf": one_of})
    }
}

/// `frequency_unit` → `FrequencyUnit`.
fn upper_camel(snake: &str) -> String {
    snake
        .split('_')
        .flat_map(|w| {
            let mut c = w.chars();
            c.next()
                .map(|f| f.to_uppercase().chain(c).collect::<String>())
        })
        .collect()
}

#[cfg(feature = "clap")]
pub use parser::{by_name, NameParser};

#[cfg(feature = "clap")]
mod parser {
    use std::ffi::OsStr;
    use std::marker::PhantomData;

    use clap::builder::{PossibleValue, PossibleValuesParser, TypedValueParser};
    use persson::names::Named;

    /// The command line's parser of the closed set `T` ([`by_name`]).
    #[derive(Debug)]
    pub struct NameParser<T>(PhantomData<T>);

    impl<T> Clone for NameParser<T> {
        fn clone(&self) -> Self {
            NameParser(PhantomData)
        }
    }

    /// The value parser of a flag taking a value of `T` by name: the names
    /// are its possible values, each with its description (without the
    /// final period, as clap's derive shows a doc comment).
    pub fn by_name<T: Named + Send + Sync>() -> NameParser<T> {
        NameParser(PhantomData)
    }

    fn possible_values<T: Named>() -> impl Iterator<Item = PossibleValue> {
        T::VALUES.iter().map(|&(_, name, description)| {
            let help = description.strip_suffix('.').filter(|h| !h.ends_with('.'));
            PossibleValue::new(name).help(help.unwrap_or(description))
        })
    }

    impl<T: Named + Send + Sync> TypedValueParser for NameParser<T> {
        type Value = T;

        fn parse_ref(
            &self,
            cmd: &clap::Command,
            arg: Option<&clap::Arg>,
            value: &OsStr,
        ) -> Result<T, clap::Error> {
            let name =
                PossibleValuesParser::new(possible_values::<T>()).parse_ref(cmd, arg, value)?;
            // The possible values are T's names: no other passes the parser.
            T::from_name(&name)
                .ok_or_else(|| clap::Error::new(clap::error::ErrorKind::InvalidValue).with_cmd(cmd))
        }

        fn possible_values(&self) -> Option<Box<dyn Iterator<Item = PossibleValue> + '_>> {
            Some(Box::new(possible_values::<T>()))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn set_names_are_upper_camel() {
        assert_eq!(upper_camel("frequency_unit"), "FrequencyUnit");
        assert_eq!(upper_camel("boundary"), "Boundary");
    }
}
