//! The macro that turns the list of studies into everything that
//! enumerates them.

/// `studies! { /// doc
/// key: Type, … }`: from the list of studies (each a [`Study`](crate::study::Study)
/// whose `KEY` is `key`), the scene's `Outputs` (one optional spec per
/// study, documented by the list's doc comment), the `SceneReport` (one
/// optional report per study, serialized in the list's order), the
/// dispatcher `Outputs::run`, the warnings, the tables and the files.
macro_rules! studies {
    ($( $(#[doc = $doc:literal])* $key:ident : $study:ty ),+ $(,)?) => {
        /// The outputs a scene asks for; absent ones are not computed.
        #[derive(Debug, Clone, Default, serde::Deserialize, serde::Serialize, schemars::JsonSchema)]
        #[serde(deny_unknown_fields)]
        pub struct Outputs {
            $(
                $(#[doc = $doc])*
                #[serde(default, skip_serializing_if = "Option::is_none")]
                pub $key: Option<<$study as $crate::study::Study>::Spec>,
            )+
        }

        /// What a scene computed: one entry per output asked for.
        #[derive(Debug, Clone, Default, PartialEq)]
        #[non_exhaustive]
        pub struct SceneReport {
            /// The scene's name.
            pub name: Option<String>,
            /// The scene's description.
            pub description: Option<String>,
            $(
                $(#[doc = $doc])*
                pub $key: Option<<$study as $crate::study::Study>::Report>,
            )+
            /// Remarks on the input (never a change of a number); the CLI
            /// prints them on stderr and in the top-level `warnings` of `--json`.
            pub warnings: Vec<$crate::warning::Warning>,
        }

        $(
            const _: () = assert!(
                $crate::study::same(<$study as $crate::study::Study>::KEY, stringify!($key)),
                concat!("the study on the line `", stringify!($key), "` has another KEY"),
            );
        )+

        impl Outputs {
            /// Whether the scene asks for nothing.
            pub fn is_empty(&self) -> bool {
                true $(&& self.$key.is_none())+
            }

            /// What the asked outputs read of the scene's inputs.
            pub fn reads(&self, inputs: &$crate::study::Inputs<'_>) -> $crate::study::Reads {
                let mut r = $crate::study::Reads::NOTHING;
                $(
                    if let Some(s) = &self.$key {
                        r = r.or(<$study as $crate::study::Study>::reads(s, inputs));
                    }
                )+
                r
            }

            /// Compute every asked output into `report`, in the list's
            /// order; an error names its field under `outputs.<key>.`.
            ///
            /// # Errors
            /// The first failed output's.
            pub fn run(
                &self,
                ctx: &$crate::study::Context<'_>,
                report: &mut SceneReport,
            ) -> persson::error::Result<()> {
                $(
                    if let Some(s) = &self.$key {
                        report.$key = Some(
                            <$study as $crate::study::Study>::run(ctx, s).map_err(|e| {
                                $crate::naming::prefix(
                                    concat!("outputs.", stringify!($key), "."),
                                    e,
                                )
                            })?,
                        );
                    }
                )+
                Ok(())
            }

            /// Every file the outputs ask to write, relative to the scene's folder.
            pub fn files(&self) -> Vec<$crate::study::OutFile> {
                let mut out = Vec::new();
                $(
                    if let Some(s) = &self.$key {
                        out.extend(<$study as $crate::study::Study>::files(s));
                    }
                )+
                out
            }

            /// Stage the files of [`Outputs::files`] into `out`, from `report`.
            ///
            /// # Errors
            /// A figure that cannot be drawn; a file that cannot be staged.
            pub fn write(
                &self,
                report: &SceneReport,
                ctx: &$crate::study::Context<'_>,
                dir: &std::path::Path,
                out: &mut $crate::output::Files,
            ) -> persson::error::Result<()> {
                $(
                    if let (Some(s), Some(r)) = (&self.$key, &report.$key) {
                        <$study as $crate::study::Study>::write(s, r, ctx, dir, out)?;
                    }
                )+
                Ok(())
            }
        }

        impl SceneReport {
            /// Gather the warnings of every output into the scene's, once each.
            pub(crate) fn collect_warnings(&mut self) {
                let mut all = std::mem::take(&mut self.warnings);
                $(
                    if let Some(r) = &self.$key {
                        for w in <$study as $crate::study::Study>::warnings(r) {
                            $crate::warning::push(&mut all, Some(w));
                        }
                    }
                )+
                self.warnings = all;
            }
        }

        impl $crate::table::Tabulate for SceneReport {
            fn tables(&self) -> Vec<$crate::table::Table> {
                let mut out = Vec::new();
                $(
                    if let Some(r) = &self.$key {
                        out.extend(r.tables());
                    }
                )+
                out
            }
        }

        impl serde::Serialize for SceneReport {
            fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
                use serde::ser::SerializeMap;
                let mut map = serializer.serialize_map(None)?;
                if let Some(n) = &self.name {
                    map.serialize_entry("name", n)?;
                }
                if let Some(d) = &self.description {
                    map.serialize_entry("description", d)?;
                }
                $(
                    if let Some(r) = &self.$key {
                        <$study as $crate::study::Study>::entries(r, &mut map)?;
                    }
                )+
                map.end()
            }
        }
    };
}

pub(crate) use studies;
