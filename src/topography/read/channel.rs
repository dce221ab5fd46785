//! The channel of a multi-channel file: the one the caller names (by name,
//! case-insensitive, or by index from 0), else the first height channel.

/// The index of the channel to read among `channels` (name, whether it
/// holds heights), or an error naming the channels there are.
///
/// `wanted` is matched by name first, so a channel named `"1"` is found by
/// its name; a number that names no channel is its index.
pub(crate) fn choose(channels: &[(&str, bool)], wanted: Option<&str>) -> Result<usize, String> {
    let names = || {
        channels
            .iter()
            .enumerate()
            .map(|(i, (n, _))| format!("{i}: \"{n}\""))
            .collect::<Vec<_>>()
            .join(", ")
    };
    match wanted {
        Some(w) => channels
            .iter()
            .position(|(n, _)| n.eq_ignore_ascii_case(w.trim()))
            .or_else(|| {
                w.trim()
                    .parse::<usize>()
                    .ok()
                    .filter(|&i| i < channels.len())
            })
            .ok_or_else(|| format!("no channel \"{w}\": the file has {}", names())),
        None => channels.iter().position(|&(_, h)| h).ok_or_else(|| {
            if channels.is_empty() {
                "the file has no data channel".to_string()
            } else {
                format!(
                    "no height channel among {}: choose one by name or index (channel)",
                    names()
                )
            }
        }),
    }
}

#[cfg(test)]
mod tests {
    use super::choose;

    #[test]
    fn by_name_index_or_first_height() {
        let c = [("Amplitude", false), ("Height", true), ("1", false)];
        assert_eq!(choose(&c, None), Ok(1));
        assert_eq!(choose(&c, Some("amplitude")), Ok(0));
        assert_eq!(choose(&c, Some("1")), Ok(2));
        assert_eq!(choose(&c, Some("0")), Ok(0));
        let e = choose(&c, Some("Phase")).unwrap_err();
        assert!(
            e.contains("no channel \"Phase\"") && e.contains("0: \"Amplitude\""),
            "{e}"
        );
        assert!(choose(&c, Some("3")).is_err());
        let e = choose(&c[..1], None).unwrap_err();
        assert!(
            e.contains("no height channel among 0: \"Amplitude\""),
            "{e}"
        );
        assert!(choose(&[], None).unwrap_err().contains("no data channel"));
    }
}
