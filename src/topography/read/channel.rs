//! The channel of a multi-channel file: the one the caller names (by name,
//! case-insensitive, or by index from 0), else the first height channel.

use std::borrow::Cow;

/// How many channels an error lists; the others are counted.
const LISTED: usize = 20;

/// The index of the channel to read among `channels` (name, whether it
/// holds heights), or an error naming the channels there are.
///
/// `wanted` is matched by name first, so a channel named `"1"` is found by
/// its name; a number that names no channel is its index.
pub(crate) fn choose(channels: &[(&str, bool)], wanted: Option<&str>) -> Result<usize, String> {
    choose_among(
        channels.len(),
        |i| Cow::Borrowed(channels[i].0),
        |i| channels[i].1,
        wanted,
    )
}

/// [`choose`] among `n` channels whose names and kinds are made on demand
/// (`name(i)`, `height(i)`), so that a file of many channels costs no
/// list of them.
pub(crate) fn choose_among<'n>(
    n: usize,
    name: impl Fn(usize) -> Cow<'n, str>,
    height: impl Fn(usize) -> bool,
    wanted: Option<&str>,
) -> Result<usize, String> {
    let names = || {
        let mut s = (0..n.min(LISTED))
            .map(|i| format!("{i}: \"{}\"", name(i)))
            .collect::<Vec<_>>()
            .join(", ");
        if n > LISTED {
            s.push_str(&format!(" … and {} more", n - LISTED));
        }
        s
    };
    match wanted {
        Some(w) => (0..n)
            .position(|i| name(i).eq_ignore_ascii_case(w.trim()))
            .or_else(|| w.trim().parse::<usize>().ok().filter(|&i| i < n))
            .ok_or_else(|| format!("no channel \"{w}\": the file has {}", names())),
        None => (0..n).position(height).ok_or_else(|| {
            if n == 0 {
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

    #[test]
    fn long_lists_are_cut() {
        let names: Vec<String> = (0..1000).map(|i| format!("c{i}")).collect();
        let c: Vec<(&str, bool)> = names.iter().map(|n| (n.as_str(), false)).collect();
        let e = choose(&c, Some("nope")).unwrap_err();
        assert!(e.contains("19: \"c19\" … and 980 more"), "{e}");
        assert!(!e.contains("c20"), "{e}");
        let e = choose(&c, None).unwrap_err();
        assert!(e.contains("… and 980 more"), "{e}");
        assert_eq!(choose(&c, Some("C999")), Ok(999));
    }
}
