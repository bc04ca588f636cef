//! User text as error messages show it: on one line, control characters escaped, cut to a
//! readable length with an ellipsis. A config can hold a megabyte-long string, key or number
//! literal, or a key with a newline in it (`"a\nb" = 1`); none of that may reach stderr as is.

/// Most characters of user text (a value, a key) that a message echoes.
pub(crate) const ECHO_CHARS: usize = 80;

/// Most characters of a message (after the place); with the key, a line stays within about
/// 300 characters. Lists in messages give way to a pointer to `gaitlab init` beyond it, and
/// every message is cut to it as a safety net.
pub(crate) const MESSAGE_CHARS: usize = 250;

/// The escape of `c` if it must not be shown as is: line breaks, tabs, other control
/// characters and the bidirectional overrides that can make a line read differently from
/// what it holds.
fn escape(c: char) -> Option<String> {
    match c {
        '\n' => Some("\\n".into()),
        '\r' => Some("\\r".into()),
        '\t' => Some("\\t".into()),
        c if c.is_control() || matches!(c, '\u{202a}'..='\u{202e}' | '\u{2066}'..='\u{2069}' | '\u{feff}') => {
            Some(format!("\\u{:04X}", u32::from(c)))
        }
        _ => None,
    }
}

/// `s` with control characters escaped (as TOML writes them: `\n`, `\u001B`), cut to at most
/// `max` characters, the last of them an ellipsis when anything was cut.
#[must_use]
pub(crate) fn clip(s: &str, max: usize) -> String {
    clip_pieces(s.chars().map(|c| escape(c).unwrap_or_else(|| c.to_string())), max)
}

/// Joins `pieces` (each a character or its escape, never split) up to `max` characters.
fn clip_pieces(pieces: impl Iterator<Item = String>, max: usize) -> String {
    let mut out = String::new();
    let mut shown = 0;
    let mut pieces = pieces.peekable();
    while let Some(piece) = pieces.next() {
        let n = piece.chars().count();
        let room = if pieces.peek().is_some() { max.saturating_sub(1) } else { max };
        if shown + n > room {
            out.push('…');
            return out;
        }
        out.push_str(&piece);
        shown += n;
    }
    out
}

/// User text echoed bare (a key, a number literal): [`clip`] to [`ECHO_CHARS`].
#[must_use]
pub(crate) fn echo(s: &str) -> String {
    clip(s, ECHO_CHARS)
}

/// A user string echoed in double quotes, `"` and `\` escaped as TOML writes them, cut to
/// [`ECHO_CHARS`] inside the quotes.
#[must_use]
pub(crate) fn quoted(s: &str) -> String {
    let pieces = s.chars().map(|c| match c {
        '"' => "\\\"".to_string(),
        '\\' => "\\\\".to_string(),
        c => escape(c).unwrap_or_else(|| c.to_string()),
    });
    format!("\"{}\"", clip_pieces(pieces, ECHO_CHARS))
}

/// A number as a message shows it: as Rust prints it when that is short, else to six
/// significant digits, in exponent form outside 1e-4..1e15 (`1e308`, not 309 digits). A value
/// the lab computed (a dragged control point) read `-1.0119047619048305e-2` and pushed the
/// reason off an 80-column line; now `-0.010119`.
#[must_use]
pub fn number(x: f64) -> String {
    let plain = format!("{x}");
    if plain.len() <= 16 {
        return plain;
    }
    let trim =
        |s: &str| if s.contains('.') { s.trim_end_matches('0').trim_end_matches('.').to_string() } else { s.into() };
    let magnitude = x.abs();
    if (1e-4..1e15).contains(&magnitude) {
        let decimals = (5 - magnitude.log10().floor() as i32).max(0) as usize;
        trim(&format!("{x:.decimals$}"))
    } else {
        let text = format!("{x:.5e}");
        let (mantissa, exponent) = text.split_once('e').expect("exponent form");
        format!("{}e{exponent}", trim(mantissa))
    }
}

/// "a" or "an" before `word`.
#[must_use]
pub(crate) fn article(word: &str) -> &'static str {
    if word.starts_with(['a', 'e', 'i', 'o', 'u']) { "an" } else { "a" }
}

/// `(what: a, b, c)` when that fits in `room` characters, else a pointer to `gaitlab init`,
/// which lists everything with its range.
#[must_use]
pub(crate) fn listing(what: &str, items: &[&str], room: usize) -> String {
    let full = format!("({what}: {})", items.join(", "));
    if items.is_empty() {
        String::new()
    } else if full.chars().count() <= room {
        full
    } else {
        format!("({} {what}; `gaitlab init` lists them all)", items.len())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn short_text_is_kept_and_long_text_cut_to_the_limit_with_an_ellipsis() {
        assert_eq!(echo("walk.speed_mps"), "walk.speed_mps");
        let exact = "k".repeat(ECHO_CHARS);
        assert_eq!(echo(&exact), exact);
        let cut = echo(&"k".repeat(1_000_000));
        assert_eq!(cut.chars().count(), ECHO_CHARS);
        assert_eq!(cut, format!("{}…", "k".repeat(ECHO_CHARS - 1)));
        // Characters, not bytes: a cut never splits one.
        assert_eq!(echo(&"é".repeat(200)).chars().count(), ECHO_CHARS);
    }

    #[test]
    fn control_characters_are_escaped_and_escapes_are_never_split() {
        assert_eq!(echo("a\nb\tc\r\u{1b}[31m\u{202e}"), "a\\nb\\tc\\r\\u001B[31m\\u202E");
        let cut = echo(&format!("{}\u{1b}xyz", "k".repeat(ECHO_CHARS - 4)));
        assert_eq!(cut, format!("{}…", "k".repeat(ECHO_CHARS - 4)));
    }

    #[test]
    fn quoted_strings_escape_quotes_and_stay_short() {
        assert_eq!(quoted("fast"), "\"fast\"");
        assert_eq!(quoted("a\"b\\c"), "\"a\\\"b\\\\c\"");
        let q = quoted(&"x".repeat(1_000_000));
        assert_eq!(q.chars().count(), ECHO_CHARS + 2);
        assert!(q.ends_with("…\""), "{q}");
    }

    #[test]
    fn numbers_are_short() {
        assert_eq!(number(1.25), "1.25");
        assert_eq!(number(1e308), "1e308");
        assert_eq!(number(1e-308), "1e-308");
        assert_eq!(number(-0.0), "-0");
        // Values the lab computes, at six significant digits.
        assert_eq!(number(-1.0119047619048305e-2), "-0.010119");
        assert_eq!(number(1.0041666666666669), "1.00417");
        assert_eq!(number(3.3333333333333326e-2), "0.0333333");
        assert_eq!(number(123456.78901234567), "123457");
        assert_eq!(number(1.2345678901234567e-7), "1.23457e-7");
    }

    #[test]
    fn listings_fall_back_to_a_pointer_when_long() {
        assert_eq!(listing("keys of [walk]", &["a", "b"], 100), "(keys of [walk]: a, b)");
        assert_eq!(listing("keys of [ik]", &["abcdef"; 30], 100), "(30 keys of [ik]; `gaitlab init` lists them all)");
        assert_eq!(listing("keys of [x]", &[], 100), "");
    }
}
