//! Writes a complete, commented config (`gaitlab init`): every key with its doc line, unit
//! and valid range; derived keys commented out with the value they derive to.

use crate::config::schema::{GROUPS, Kind, PARAMS, Value};
use crate::model::gait_curves::CurveName;
use crate::model::params::{Resolved, WalkParams};
use crate::model::schedule::{PaceAction, PaceEntry, PaceTrigger};

/// A number as TOML writes it: always with a decimal point, at most 4 decimals.
#[must_use]
pub(crate) fn toml_number(x: f64) -> String {
    let rounded = (x * 1e4).round() / 1e4;
    let rounded = if rounded == 0.0 { 0.0 } else { rounded };
    if rounded.fract() == 0.0 { format!("{rounded:.1}") } else { format!("{rounded}") }
}

/// The commented-out line a derived key is shown as (no newline): `# name = value  # derived`.
/// `config::edit` finds these lines by this form to show a written walk's values.
#[must_use]
pub(crate) fn derived_comment(name: &str, value: &str) -> String {
    format!("# {name} = {value}  # derived")
}

/// What a derived key resolves to, in the key's unit.
#[must_use]
pub(crate) fn derived_value(key: &str, p: &WalkParams, r: &Resolved) -> Option<f64> {
    let d = &r.dims;
    let deg = f64::to_degrees;
    // The sway-scaled keys are shown before the knob, as they are written: at sway 0 the walk's
    // ranges are 0 and say nothing of the key (the lab read `obliquity_range_deg 0.0` there),
    // so the walk is resolved again at sway 1.
    let unswayed = |x: f64, of: fn(&Resolved) -> f64| {
        if p.walk.sway > 0.0 {
            x / p.walk.sway
        } else {
            let mut at_one = p.clone();
            at_one.walk.sway = 1.0;
            of(&at_one.resolve())
        }
    };
    Some(match key {
        "body.thigh_m" => d.thigh,
        "body.shank_m" => d.shank,
        "body.ankle_height_m" => d.ankle_height,
        "body.foot_length_m" => d.foot_length,
        "body.upper_arm_m" => d.upper_arm,
        "body.forearm_m" => d.forearm,
        "body.hand_m" => d.hand,
        "body.hip_width_m" => d.hip_width,
        "body.shoulder_width_m" => d.shoulder_width,
        "body.trunk_m" => d.trunk,
        "walk.stride_m" => r.stride_m,
        "walk.cadence_spm" => 120.0 / r.cycle_s,
        "walk.step_width_m" => r.step_width_m,
        "pelvis.rotation_range_deg" => deg(r.rotation_range),
        "pelvis.obliquity_range_deg" => unswayed(deg(r.obliquity_range), |r| r.obliquity_range.to_degrees()),
        "pelvis.vertical_range_cm" => r.vertical_range * 100.0,
        "pelvis.lateral_range_cm" => unswayed(r.lateral_range * 100.0, |r| r.lateral_range * 100.0),
        "pelvis.midstance_drop_cm" => r.midstance_drop * 100.0,
        "pelvis.midstance_offset_cm" => r.midstance_offset * 100.0,
        "pelvis.stance_rise" => r.stance_rise,
        "legs.toe_off" => r.toe_off,
        "legs.heel_rise" => r.heel_rise,
        "legs.heel_pad_mm" => r.heel_pad * 1000.0,
        "arms.shoulder_range_deg" => deg(r.shoulder_range),
        "arms.elbow_range_deg" => deg(r.elbow_range),
        _ => return None,
    })
}

/// The value of a key as TOML text (`None` for a derived key that is not set).
#[must_use]
pub fn value_text(value: &Value) -> Option<String> {
    match value {
        Value::Real(x) => Some(toml_number(*x)),
        Value::Int(n) => Some(n.to_string()),
        Value::Word(w) => Some(format!("\"{w}\"")),
        Value::Bool(b) => Some(b.to_string()),
        Value::Auto => None,
    }
}

/// The whole config for `params`, headed by `title` (one comment line).
#[must_use]
pub fn render(params: &WalkParams, title: &str) -> String {
    let r = params.resolve();
    let mut out = String::new();
    out.push_str(&format!("# {title}\n"));
    out.push_str("#\n# A gaitlab config. Every key is optional: a missing key takes its default. Keys shown\n");
    out.push_str("# commented out are derived from walk.speed_mps, walk.sway and body.height_m; set one\n");
    out.push_str("# to override the derivation for that key alone. Units are SI unless the name says\n");
    out.push_str("# otherwise (_deg, _cm, _pct); phases are fractions of the gait cycle from heel strike.\n");
    for group in GROUPS.iter().filter(|g| **g != "curves") {
        out.push_str(&format!("\n[{group}]\n"));
        for spec in PARAMS.iter().filter(|p| p.group() == *group) {
            let unit = if spec.unit.is_empty() { String::new() } else { format!(" [{}]", spec.unit) };
            out.push_str(&format!("# {}{unit}. Valid: {}.\n", spec.doc, spec.valid_range()));
            match value_text(&(spec.get)(params)) {
                Some(v) => out.push_str(&format!("{} = {v}\n", spec.name())),
                None => {
                    let derived = derived_value(spec.key, params, &r).map_or("?".into(), toml_number);
                    let auto = matches!(spec.kind, Kind::Real { auto: true, .. });
                    debug_assert!(auto);
                    out.push_str(&derived_comment(spec.name(), &derived));
                    out.push('\n');
                }
            }
        }
        if *group == "walk" {
            out.push_str(SCHEDULE_DOC);
        }
    }
    out.push_str("\n# [curves.<name>] replaces a curve's control points: points = [[x, y], ...], 3n+1 of\n");
    out.push_str("# them, x from 0 to 1 and increasing; cycle curves must end where they start, and the\n");
    out.push_str("# forward progress curves (pelvis_forward_ds_ms, pelvis_forward_ms_ds, swing_forward) never\n");
    out.push_str("# go back.\n# Curves: ");
    let names: Vec<&str> = CurveName::ALL.iter().map(|c| c.key()).collect();
    out.push_str(&names.join(", "));
    out.push_str(".\n# The defaults of heel_rise, swing_forward, swing_heel_height and pelvis_vertical depend on\n");
    out.push_str("# the speed (drawn at 0.8, 1.3 and 1.6 m/s and blended between); a [curves] entry holds at\n");
    out.push_str("# every speed. The default pelvis_vertical_ds_ms starts slowly where the heel pad is whole\n");
    out.push_str("# (legs.heel_pad_mm, on flat ground) and quickly where there is none, blended between.\n");
    out.push_str(
        "# Example, the default heel-rise curve at 1.3 m/s (foot-ground angle in degrees for a 1.8 m stride):\n",
    );
    out.push_str("# [curves.heel_rise]\n# points = [");
    let pts: Vec<String> = CurveName::HeelRise
        .default_curve()
        .points()
        .iter()
        .map(|p| format!("[{}, {}]", toml_number(p.x), toml_number(p.y)))
        .collect();
    out.push_str(&pts.join(", "));
    out.push_str("]\n");
    for (name, points) in &params.curves {
        out.push_str(&format!("\n[curves.{name}]\npoints = ["));
        let pts: Vec<String> =
            points.iter().map(|(x, y)| format!("[{}, {}]", toml_number(*x), toml_number(*y))).collect();
        out.push_str(&pts.join(", "));
        out.push_str("]\n");
    }
    for entry in &params.schedule {
        out.push_str(&schedule_entry(entry));
    }
    out
}

/// What `gaitlab init` says of `[[walk.schedule]]` (under `[walk]`).
const SCHEDULE_DOC: &str = "\
# [[walk.schedule]] changes the pace while walking; none by default (one steady speed).
# Each entry: when, time_s (0 to 86400 s) or distance_m (0 to 100000 m, pelvis travel),
# and what, speed_mps (0.4 to 2 m/s, reached over the next two steps) or stop = true (a
# braking step, the trailing foot closes beside it, the body settles to standing) or
# start = true (with time_s: sets off from standing; as the first entry the walk begins
# standing, feet side by side). Entries fire in file order. Example:
# [[walk.schedule]]
# time_s = 4.0
# speed_mps = 1.6
";

/// One schedule entry as a `[[walk.schedule]]` table.
fn schedule_entry(entry: &PaceEntry) -> String {
    let when = match entry.trigger {
        PaceTrigger::TimeS(t) => format!("time_s = {}", toml_number(t)),
        PaceTrigger::DistanceM(d) => format!("distance_m = {}", toml_number(d)),
    };
    let what = match entry.action {
        PaceAction::Speed(v) => format!("speed_mps = {}", toml_number(v)),
        PaceAction::Stop => "stop = true".to_string(),
        PaceAction::Start => "start = true".to_string(),
    };
    format!("\n[[walk.schedule]]\n{when}\n{what}\n")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sway_scaled_keys_are_shown_before_the_knob_even_at_sway_0() {
        let at = |sway: f64| {
            let mut p = WalkParams::default();
            p.walk.sway = sway;
            let r = p.resolve();
            ["pelvis.obliquity_range_deg", "pelvis.lateral_range_cm"].map(|k| derived_value(k, &p, &r).unwrap())
        };
        let one = at(1.0);
        // 12.05 deg and 4.836 cm at 1.3 m/s, whatever the knob.
        assert!((one[0] - 12.05).abs() < 1e-9 && (one[1] - 4.836).abs() < 1e-9, "{one:?}");
        for sway in [0.0, 0.5, 2.0] {
            let shown = at(sway);
            assert!((shown[0] - one[0]).abs() < 1e-9 && (shown[1] - one[1]).abs() < 1e-9, "sway {sway}: {shown:?}");
        }
    }
}
