//! A study's flags, derived from its spec: one declaration (the spec's
//! fields, their doc comments and serde defaults) gives the scene's schema
//! and these flags alike.
//!
//! [`SpecArgs<T>`] reads the JSON Schema of the spec `T` (the one the scene
//! schema is generated from) and declares one flag per field:
//!
//! | field's schema | flag |
//! |---|---|
//! | number | `--field X`, a plain SI number ([`super::number::number`]) |
//! | integer | `--field N` ([`super::number::count`]); a 64-bit one, a seed ([`super::number::seed`]) |
//! | array of numbers | `--field X,Y,…`, repeatable |
//! | array of integers | `--field N,M,…`, repeatable |
//! | boolean | `--field`, a switch |
//! | one of named values | `--field NAME`, the values and their descriptions listed |
//! | string named `plot` or `plot_*`, or listed in [`SpecFlags::OUTPUTS`] | `--field FILE.svg\|png` (or the listed value name), an output file ([`super::files`]) |
//! | other string | `--field TEXT` |
//! | object, array of objects | none: the command declares it ([`SpecFlags::OWN`]); building the command line panics otherwise, which its test finds |
//!
//! The flag is the field's name in kebab case (`yield_stress` →
//! `--yield-stress`); its argument id is the field's name, which is what
//! [`super::blame`] matches errors by. Its help is the field's description;
//! its default, the schema's. A command renames a field's flag or keeps a
//! field for its own flags with [`SpecFlags`]. The values given are handed
//! to the spec's serde `Deserialize`, exactly as a scene's would be: the
//! command line and a scene cannot accept different values.

use std::collections::BTreeMap;
use std::marker::PhantomData;

use clap::{Arg, ArgAction, ArgMatches, Command};
use schemars::JsonSchema;
use serde::de::{self, DeserializeOwned, IntoDeserializer, Visitor};
use serde_json::Value;

use super::files::{out_file, OutFile};
use super::number::{count, number};

/// How a command maps a spec's fields onto flags (module docs).
pub trait SpecFlags: JsonSchema + DeserializeOwned {
    /// Fields the command fills itself (shared flags, the example's values):
    /// no flag is derived for them.
    const OWN: &'static [&'static str] = &[];
    /// Fields whose flag has another name: (field, flag).
    const RENAMED: &'static [(&'static str, &'static str)] = &[];
    /// Further names a flag answers to: (field, alias).
    const ALIASES: &'static [(&'static str, &'static str)] = &[];
    /// Fields whose argument id is not their name: (field, id). For specs
    /// flattened side by side whose fields share a name (`plot`); the id is
    /// what [`super::blame`] matches an error's field by.
    const IDS: &'static [(&'static str, &'static str)] = &[];
    /// Fields that name a file the study writes, other than its figures
    /// (`plot`, `plot_*`): (field, value name with its extensions).
    const OUTPUTS: &'static [(&'static str, &'static str)] = &[];
}

/// The flags of the spec `T` (module docs); [`SpecArgs::spec`] builds it.
#[derive(Debug, Clone)]
pub struct SpecArgs<T> {
    given: BTreeMap<String, Given>,
    spec: PhantomData<fn() -> T>,
}

impl<T: SpecFlags> SpecArgs<T> {
    /// Whether a flag gave the field `name` (or its schema has a default).
    pub fn has(&self, name: &str) -> bool {
        self.given.contains_key(name)
    }

    /// Give the field `name` the value `v` (a number, numbers, a count or a
    /// name) unless a flag gave it: the built-in example's values, what a
    /// command's own flags imply.
    pub fn or(&mut self, name: &str, v: impl Into<Given>) -> &mut Self {
        self.given.entry(name.into()).or_insert(v.into());
        self
    }

    /// The spec, from the flags given and what the command set. A required
    /// field nobody gave is an error naming its flag.
    pub fn spec(&self) -> anyhow::Result<T> {
        for field in required::<T>() {
            if !self.given.contains_key(&field) {
                let words = field.replace('_', " ");
                anyhow::bail!("no {words}: give {} X", flag_of::<T>(&field));
            }
        }
        let map = de::value::MapDeserializer::new(self.given.clone().into_iter());
        T::deserialize(map).map_err(|e: de::value::Error| anyhow::anyhow!("{e}"))
    }
}

/// `--flag` of the field `field`.
fn flag_of<T: SpecFlags>(field: &str) -> String {
    let long = T::RENAMED
        .iter()
        .find(|(f, _)| *f == field)
        .map_or_else(|| field.replace('_', "-"), |(_, l)| l.to_string());
    format!("--{long}")
}

/// What one field's flag takes (module docs' table).
#[derive(Debug, Clone, PartialEq)]
enum Kind {
    Number,
    Count,
    Seed,
    Numbers,
    Counts,
    Switch,
    Choice(Vec<(String, String)>),
    /// An output file, with its value name (`FILE.svg|png`).
    Output(&'static str),
    Text,
}

/// One field of the spec: its name, argument id, kind, description and
/// default.
struct Field {
    name: String,
    id: String,
    kind: Kind,
    help: String,
    default: Option<String>,
}

/// The spec's JSON Schema (the definitions it refers to under `$defs`).
fn schema<T: JsonSchema>() -> Value {
    schemars::schema_for!(T).to_value()
}

/// The fields of `T` that are not the command's own, in the schema's
/// (alphabetical) order.
fn fields<T: SpecFlags>() -> Vec<Field> {
    let root = schema::<T>();
    let Some(props) = root.get("properties").and_then(Value::as_object) else {
        return Vec::new();
    };
    props
        .iter()
        .filter(|(name, _)| !T::OWN.contains(&name.as_str()))
        .map(|(name, p)| Field {
            id: T::IDS
                .iter()
                .find(|(f, _)| f == name)
                .map_or_else(|| name.clone(), |(_, id)| id.to_string()),
            kind: kind::<T>(name, p, &root),
            help: one_line(p.get("description").and_then(Value::as_str).unwrap_or("")),
            default: p.get("default").and_then(|d| match d {
                Value::String(s) => Some(s.clone()),
                Value::Number(n) => Some(n.to_string()),
                _ => None,
            }),
            name: name.clone(),
        })
        .collect()
}

/// The fields of `T` its schema requires.
fn required<T: JsonSchema>() -> Vec<String> {
    schema::<T>()
        .get("required")
        .and_then(Value::as_array)
        .map(|r| {
            r.iter()
                .filter_map(|v| v.as_str().map(String::from))
                .collect()
        })
        .unwrap_or_default()
}

/// A description on one line (doc comments wrap), without the closing
/// full stop, as every flag's help is written.
fn one_line(s: &str) -> String {
    let line = s.split_whitespace().collect::<Vec<_>>().join(" ");
    line.strip_suffix('.').map_or(line.clone(), String::from)
}

/// `p` itself, or the definition its `$ref` names; an optional value's
/// non-null branch.
fn resolve<'a>(p: &'a Value, root: &'a Value) -> &'a Value {
    if let Some(r) = p.get("$ref").and_then(Value::as_str) {
        let name = r.rsplit('/').next().unwrap_or(r);
        if let Some(d) = root.get("$defs").and_then(|d| d.get(name)) {
            return resolve(d, root);
        }
    }
    if let Some(branches) = p.get("anyOf").and_then(Value::as_array) {
        if let Some(b) = branches
            .iter()
            .find(|b| b.get("type").and_then(Value::as_str) != Some("null"))
        {
            return resolve(b, root);
        }
    }
    p
}

/// The schema's type of `p`, without `null`.
fn type_of(p: &Value) -> Option<&str> {
    match p.get("type")? {
        Value::String(s) => Some(s),
        Value::Array(a) => a.iter().filter_map(Value::as_str).find(|t| *t != "null"),
        _ => None,
    }
}

/// What the flag of the field `name` with schema `p` takes.
fn kind<T: SpecFlags>(name: &str, p: &Value, root: &Value) -> Kind {
    let p = resolve(p, root);
    if let Some(choices) = p.get("oneOf").and_then(Value::as_array) {
        let named = choices
            .iter()
            .filter_map(|c| {
                let v = c.get("const").or_else(|| c.get("enum")?.get(0))?.as_str()?;
                let help = c.get("description").and_then(Value::as_str).unwrap_or("");
                Some((v.to_string(), one_line(help)))
            })
            .collect();
        return Kind::Choice(named);
    }
    if let Some(values) = p.get("enum").and_then(Value::as_array) {
        let named = values
            .iter()
            .filter_map(|v| Some((v.as_str()?.to_string(), String::new())))
            .collect();
        return Kind::Choice(named);
    }
    let output = T::OUTPUTS.iter().find(|(f, _)| *f == name).map(|(_, v)| *v);
    let plot = name == "plot" || name.starts_with("plot_");
    let items = p.get("items").map(|i| type_of(resolve(i, root)));
    match type_of(p) {
        Some("number") => Kind::Number,
        Some("integer") if p.get("format").and_then(Value::as_str) == Some("uint64") => Kind::Seed,
        Some("integer") => Kind::Count,
        Some("boolean") => Kind::Switch,
        Some("array") if items == Some(Some("number")) => Kind::Numbers,
        Some("array") if items == Some(Some("integer")) => Kind::Counts,
        Some("string") => match output {
            Some(value_name) => Kind::Output(value_name),
            None if plot => Kind::Output("FILE.svg|png"),
            None => Kind::Text,
        },
        // A list of objects, a nested object: no flag says it; the command
        // declares its own (`SpecFlags::OWN`). The command line is built,
        // and this found, by the test `the_command_line_is_consistent`.
        other => panic!(
            "{}: field `{name}` ({}) has no derived flag: list it in SpecFlags::OWN",
            std::any::type_name::<T>(),
            other.unwrap_or("untyped")
        ),
    }
}

/// The flag of one field (module docs' table).
fn arg<T: SpecFlags>(f: &Field) -> Arg {
    let long = flag_of::<T>(&f.name)[2..].to_string();
    let mut a = Arg::new(f.id.clone())
        .long(long.clone())
        .help(f.help.clone());
    for (_, alias) in T::ALIASES.iter().filter(|(field, _)| *field == f.name) {
        a = a.alias(*alias);
    }
    let value_name = long.replace('-', "_").to_uppercase();
    a = match &f.kind {
        Kind::Number => a.value_parser(number).allow_hyphen_values(true),
        Kind::Count => a.value_parser(count).allow_hyphen_values(true),
        Kind::Seed => a
            .value_parser(super::number::seed)
            .allow_hyphen_values(true),
        Kind::Numbers => a
            .value_parser(number)
            .allow_hyphen_values(true)
            .value_delimiter(',')
            .action(ArgAction::Append),
        Kind::Counts => a
            .value_parser(count)
            .allow_hyphen_values(true)
            .value_delimiter(',')
            .action(ArgAction::Append),
        Kind::Switch => return a.action(ArgAction::SetTrue),
        Kind::Choice(named) => {
            a.value_parser(clap::builder::PossibleValuesParser::new(named.iter().map(
                |(v, h)| clap::builder::PossibleValue::new(v.clone()).help(h.clone()),
            )))
        }
        Kind::Output(name) => a.value_parser(out_file).value_name(*name),
        Kind::Text => a,
    };
    if !matches!(f.kind, Kind::Output(_)) {
        a = a.value_name(value_name);
    }
    // A default the help already states is not repeated by clap.
    match &f.default {
        Some(d) if !f.help.contains("default") => a.default_value(d.clone()),
        _ => a,
    }
}

/// One field's value as given: what serde reads it as.
#[derive(Debug, Clone, PartialEq)]
pub enum Given {
    Number(f64),
    Count(u64),
    Numbers(Vec<f64>),
    Counts(Vec<u64>),
    Switch(bool),
    Text(String),
}

impl Given {
    /// The value of the field `f` in `m`, if any.
    fn read(f: &Field, m: &ArgMatches) -> Result<Option<Given>, clap::Error> {
        let id = f.id.as_str();
        let raw = |msg: String| clap::Error::raw(clap::error::ErrorKind::InvalidValue, msg + "\n");
        let typed = |e: clap::parser::MatchesError| raw(format!("--{id}: {e}"));
        Ok(match &f.kind {
            Kind::Number => m
                .try_get_one::<f64>(id)
                .map_err(typed)?
                .map(|v| Given::Number(*v)),
            Kind::Count => {
                let n = m.try_get_one::<usize>(id).map_err(typed)?;
                n.map(|v| Given::Count(*v as u64))
            }
            Kind::Seed => m
                .try_get_one::<u64>(id)
                .map_err(typed)?
                .map(|v| Given::Count(*v)),
            Kind::Numbers => m
                .try_get_many::<f64>(id)
                .map_err(typed)?
                .map(|v| Given::Numbers(v.copied().collect())),
            Kind::Counts => m
                .try_get_many::<usize>(id)
                .map_err(typed)?
                .map(|v| Given::Counts(v.map(|n| *n as u64).collect())),
            Kind::Switch => m
                .try_get_one::<bool>(id)
                .map_err(typed)?
                .filter(|on| **on)
                .map(|on| Given::Switch(*on)),
            Kind::Choice(_) | Kind::Text => m
                .try_get_one::<String>(id)
                .map_err(typed)?
                .map(|v| Given::Text(v.clone())),
            Kind::Output(_) => match m.try_get_one::<OutFile>(id).map_err(typed)? {
                Some(p) => {
                    let s = p
                        .to_str()
                        .ok_or_else(|| raw(format!("--{id}: a file name that is not UTF-8")))?;
                    Some(Given::Text(s.to_string()))
                }
                None => None,
            },
        })
    }
}

impl From<f64> for Given {
    fn from(v: f64) -> Self {
        Given::Number(v)
    }
}

impl From<&str> for Given {
    fn from(s: &str) -> Self {
        Given::Text(s.to_string())
    }
}

impl From<Vec<f64>> for Given {
    fn from(v: Vec<f64>) -> Self {
        Given::Numbers(v)
    }
}

impl From<usize> for Given {
    fn from(n: usize) -> Self {
        Given::Count(n as u64)
    }
}

impl<'de> IntoDeserializer<'de, de::value::Error> for Given {
    type Deserializer = Self;
    fn into_deserializer(self) -> Self {
        self
    }
}

impl<'de> de::Deserializer<'de> for Given {
    type Error = de::value::Error;

    fn deserialize_any<V: Visitor<'de>>(self, v: V) -> Result<V::Value, Self::Error> {
        match self {
            Given::Number(x) => v.visit_f64(x),
            Given::Count(n) => v.visit_u64(n),
            Given::Numbers(xs) => v.visit_seq(de::value::SeqDeserializer::new(xs.into_iter())),
            Given::Counts(ns) => v.visit_seq(de::value::SeqDeserializer::new(ns.into_iter())),
            Given::Switch(b) => v.visit_bool(b),
            Given::Text(s) => v.visit_string(s),
        }
    }

    fn deserialize_option<V: Visitor<'de>>(self, v: V) -> Result<V::Value, Self::Error> {
        v.visit_some(self)
    }

    /// A named value (`--theory xu`) is a unit variant, as in JSON.
    fn deserialize_enum<V: Visitor<'de>>(
        self,
        name: &'static str,
        variants: &'static [&'static str],
        v: V,
    ) -> Result<V::Value, Self::Error> {
        match self {
            Given::Text(s) => v.visit_enum(de::value::StringDeserializer::new(s)),
            other => other.deserialize_any(v).map_err(|_| {
                de::Error::custom(format_args!("expected one of {variants:?} for {name}"))
            }),
        }
    }

    serde::forward_to_deserialize_any! {
        bool i8 i16 i32 i64 i128 u8 u16 u32 u64 u128 f32 f64 char str string
        bytes byte_buf unit unit_struct newtype_struct seq tuple
        tuple_struct map struct identifier ignored_any
    }
}

impl<T: SpecFlags> clap::FromArgMatches for SpecArgs<T> {
    fn from_arg_matches(m: &ArgMatches) -> Result<Self, clap::Error> {
        let mut given = BTreeMap::new();
        for f in fields::<T>() {
            if let Some(v) = Given::read(&f, m)? {
                given.insert(f.name, v);
            }
        }
        Ok(SpecArgs {
            given,
            spec: PhantomData,
        })
    }

    fn update_from_arg_matches(&mut self, m: &ArgMatches) -> Result<(), clap::Error> {
        *self = Self::from_arg_matches(m)?;
        Ok(())
    }
}

impl<T: SpecFlags> clap::Args for SpecArgs<T> {
    fn augment_args(cmd: Command) -> Command {
        fields::<T>().iter().fold(cmd, |c, f| c.arg(arg::<T>(f)))
    }

    fn augment_args_for_update(cmd: Command) -> Command {
        Self::augment_args(cmd)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::{Args as _, FromArgMatches as _};
    use persson_studies::scene::{AreaOutput, MagnificationOutput};

    /// The spec `T` a command line of its derived flags gives.
    fn parse<T: SpecFlags>(line: &[&str]) -> anyhow::Result<T> {
        let cmd = SpecArgs::<T>::augment_args(Command::new("t").no_binary_name(true));
        let m = cmd.try_get_matches_from(line)?;
        SpecArgs::<T>::from_arg_matches(&m)?.spec()
    }

    /// The spec a scene's JSON gives.
    fn scene<T: DeserializeOwned>(json: &str) -> T {
        serde_json::from_str(json).expect("a valid scene section")
    }

    #[test]
    fn flags_give_the_spec_a_scene_gives() {
        let flags: AreaOutput = parse(&[
            "--zeta",
            "100",
            "--theory",
            "wang-muser",
            "--gamma",
            "0.5",
            "--plot",
            "a.svg",
        ])
        .unwrap();
        let json: AreaOutput =
            scene(r#"{"zeta": 100, "theory": "wang-muser", "gamma": 0.5, "plot": "a.svg"}"#);
        assert_eq!(
            serde_json::to_value(&flags).unwrap(),
            serde_json::to_value(&json).unwrap()
        );
        // Nothing given: the scene's defaults, not the command line's own.
        let (flags, json): (MagnificationOutput, MagnificationOutput) = (
            parse(&["--pressure", "1e6"]).unwrap(),
            scene(r#"{"nominal_pressure": 1e6}"#),
        );
        assert_eq!(flags.points, json.points);
        assert_eq!(flags.points, 41);
        let zeta: MagnificationOutput =
            parse(&["--pressure", "1", "--zeta", "1,2", "--zeta", "4"]).unwrap();
        assert_eq!(zeta.zeta, [1.0, 2.0, 4.0]);
    }

    #[test]
    fn values_json_cannot_hold_reach_the_spec() {
        // -inf is kept (and refused by the study's range check), not dropped.
        let s: AreaOutput = parse(&["--yield-stress", "-inf", "--tolerance", "1e-3"]).unwrap();
        assert_eq!(s.yield_stress, Some(f64::NEG_INFINITY));
        assert_eq!(s.tolerance, Some(1e-3));
        let alias: AreaOutput = parse(&["--theory-tolerance", "1e-4"]).unwrap();
        assert_eq!(alias.tolerance, Some(1e-4));
    }

    #[test]
    fn seeds_and_output_files() {
        use persson_studies::surrogates::SurrogatesOutput;
        let s: SurrogatesOutput = parse(&[
            "--seed",
            "18446744073709551615",
            "--surfaces",
            "s.npy",
            "--kind",
            "amplitude-adjusted",
        ])
        .unwrap();
        assert_eq!(s.seed, Some(u64::MAX));
        assert_eq!(s.surfaces.as_deref(), Some(std::path::Path::new("s.npy")));
        let cmd = SpecArgs::<SurrogatesOutput>::augment_args(Command::new("t"));
        let names = |id: &str| {
            let a = cmd.get_arguments().find(|a| a.get_id() == id).unwrap();
            a.get_value_names().unwrap()[0].to_string()
        };
        assert_eq!(names("surfaces"), "FILE.npy");
        assert_eq!(names("plot_distribution"), "FILE.svg|png");
        assert!(parse::<SurrogatesOutput>(&["--seed", "-1"]).is_err());
    }

    /// A spec with a nested object the command did not declare its own.
    #[derive(serde::Deserialize, schemars::JsonSchema)]
    #[allow(dead_code)]
    struct Nested {
        inner: Option<MagnificationOutput>,
    }
    impl SpecFlags for Nested {}

    #[test]
    #[should_panic(
        expected = "field `inner` (object) has no derived flag: list it in SpecFlags::OWN"
    )]
    fn a_field_no_flag_can_say_must_be_the_commands_own() {
        SpecArgs::<Nested>::augment_args(Command::new("t"));
    }

    #[test]
    fn bad_values_name_their_flag() {
        let err = |line: &[&str]| parse::<MagnificationOutput>(line).unwrap_err().to_string();
        assert_eq!(err(&[]), "no nominal pressure: give --pressure X");
        assert!(
            err(&["--pressure", "1MPa"]).contains("1e6"),
            "{}",
            err(&["--pressure", "1MPa"])
        );
        let theory = parse::<AreaOutput>(&["--theory", "persson"])
            .unwrap_err()
            .to_string();
        assert!(
            theory.contains("'persson'") && theory.contains("yang-persson"),
            "{theory}"
        );
        let points = err(&["--pressure", "1", "--points", "2.5"]);
        assert!(points.contains("--points"), "{points}");
    }
}
