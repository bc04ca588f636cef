//! Saving the lab's edits into the user's TOML: only the edited keys change, comments and
//! layout stay (toml_edit), and the file is replaced by the output rule (atomically, keeping its mode; see
//! [`crate::output`]).

use crate::model::params::WalkParams;
use crate::output::write_atomic;
use std::path::Path;

/// Writes `params`' values of `keys` (and any changed curve overrides) into `source_text`
/// and saves the result at `path`. Returns the text written.
pub fn save(path: &Path, source_text: &str, params: &WalkParams, keys: &[&str]) -> Result<String, String> {
    let text = edited_text(source_text, params, keys)?;
    write_atomic(path, |out| out.write_all(text.as_bytes())).map_err(|e| e.to_string())?;
    Ok(text)
}

pub use crate::config::edit::edited_text;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn only_edited_keys_change_and_comments_stay() {
        let source = "# my walk\n[walk]\n# how fast\nspeed_mps = 1.3 # brisk-ish\nsway = 1.0\n";
        let mut params = crate::config::load_text(source, "t", &[]).unwrap();
        params.walk.speed_mps = 1.45;
        params.pelvis.tilt_range_deg = 4.0;
        let text = edited_text(source, &params, &["walk.speed_mps", "pelvis.tilt_range_deg"]).unwrap();
        assert_eq!(
            text,
            "# my walk\n[walk]\n# how fast\nspeed_mps = 1.45 # brisk-ish\nsway = 1.0\n\n[pelvis]\ntilt_range_deg = 4.0\n"
        );
        let back = crate::config::load_text(&text, "t", &[]).unwrap();
        assert_eq!(back, params);
    }

    #[test]
    fn a_derived_key_set_back_to_derived_leaves_the_file() {
        let source = "[walk]\nstride_m = 1.5\nspeed_mps = 1.3\n";
        let mut params = crate::config::load_text(source, "t", &[]).unwrap();
        params.walk.stride_m = None;
        assert_eq!(edited_text(source, &params, &["walk.stride_m"]).unwrap(), "[walk]\nspeed_mps = 1.3\n");
    }
}
