//! The presets: the config files in `configs/`, embedded in the binary. The first line of
//! each is `# preset: <description>`.

use crate::config::{ConfigErrors, parse_str};
use crate::model::params::WalkParams;

/// Every preset: (name, file text). `default` is what the lab opens without a config.
pub static PRESETS: &[(&str, &str)] = &[
    ("default", include_str!("../../configs/default.toml")),
    ("stroll", include_str!("../../configs/stroll.toml")),
    ("brisk", include_str!("../../configs/brisk.toml")),
    ("elderly", include_str!("../../configs/elderly.toml")),
    ("wide_sway", include_str!("../../configs/wide_sway.toml")),
    ("long_stride", include_str!("../../configs/long_stride.toml")),
    ("stairs_up", include_str!("../../configs/stairs_up.toml")),
    ("stairs_down", include_str!("../../configs/stairs_down.toml")),
    ("slope_up", include_str!("../../configs/slope_up.toml")),
    ("slope_down", include_str!("../../configs/slope_down.toml")),
    ("rough", include_str!("../../configs/rough.toml")),
    ("pace", include_str!("../../configs/pace.toml")),
    ("start_stop", include_str!("../../configs/start_stop.toml")),
];

/// What the default preset is. `configs/default.toml` is `gaitlab init`'s output, which
/// writes this line first, so the description cannot come from the file itself.
pub(crate) const DEFAULT_DESCRIPTION: &str = "normal adult walk at 1.3 m/s on level ground";

/// The description line of a preset's text.
#[must_use]
pub(crate) fn description(text: &str) -> &str {
    text.lines().next().and_then(|l| l.strip_prefix("# preset:")).map_or("", str::trim)
}

/// The text of preset `name`.
#[must_use]
pub fn text(name: &str) -> Option<&'static str> {
    PRESETS.iter().find(|(n, _)| *n == name).map(|(_, t)| *t)
}

/// The parameters of preset `name`.
pub fn params(name: &str) -> Option<Result<WalkParams, ConfigErrors>> {
    text(name).map(|t| parse_str(t, &format!("configs/{name}.toml")))
}

/// The embedded default config's text (the same bytes as `configs/default.toml`).
#[must_use]
pub fn default_text() -> &'static str {
    PRESETS[0].1
}
