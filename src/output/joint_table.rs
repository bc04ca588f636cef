//! The joint table (interface "Joint table"): one CSV row a frame, fixed columns, fixed
//! decimals, so the same config gives the same bytes on every run and platform.

use crate::model::walk::frame::Frame;
use std::fmt::Write as _;
use std::io::{self, Write};

/// The columns, in order.
pub(crate) const COLUMNS: &[&str] = &[
    "frame",
    "time_s",
    "phase_r",
    "phase_l",
    "support",
    "pelvis_x",
    "pelvis_y",
    "pelvis_z",
    "pelvis_tilt_deg",
    "pelvis_obliquity_deg",
    "pelvis_rotation_deg",
    "hip_flex_r_deg",
    "hip_abd_r_deg",
    "knee_flex_r_deg",
    "ankle_dorsi_r_deg",
    "hip_flex_l_deg",
    "hip_abd_l_deg",
    "knee_flex_l_deg",
    "ankle_dorsi_l_deg",
    "heel_r_x",
    "heel_r_y",
    "heel_r_z",
    "toe_r_x",
    "toe_r_y",
    "toe_r_z",
    "heel_l_x",
    "heel_l_y",
    "heel_l_z",
    "toe_l_x",
    "toe_l_y",
    "toe_l_z",
    "shoulder_flex_r_deg",
    "elbow_flex_r_deg",
    "shoulder_flex_l_deg",
    "elbow_flex_l_deg",
    "terrain_y_under_heel_r",
    "terrain_y_under_heel_l",
];

/// Appends `x` with `decimals` places (at most 6), rounded half away from zero from the
/// binary value; a value that rounds to zero is written without a minus sign so −0.0000 and
/// 0.0000 cannot differ between runs. Integer arithmetic instead of `format!("{:.6}")`, whose
/// cost per number made the CSV the bottleneck (benches/README.md, "Walk model").
fn push_fixed(line: &mut String, x: f64, decimals: usize) {
    const POW: [f64; 7] = [1.0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6];
    let scaled = (x * POW[decimals]).round();
    if !scaled.is_finite() || scaled.abs() >= 9.0e15 {
        let _ = write!(line, "{x:.decimals$}");
        return;
    }
    let mut n = scaled as i64;
    if n < 0 {
        line.push('-');
        n = -n;
    }
    let unit = 10i64.pow(decimals as u32);
    let _ = write!(line, "{}", n / unit);
    if decimals > 0 {
        let frac = n % unit;
        let _ = write!(line, ".{frac:0decimals$}");
    }
}

/// Writes the header line.
pub(crate) fn write_header(out: &mut dyn Write) -> io::Result<()> {
    writeln!(out, "{}", COLUMNS.join(","))
}

/// Formats one frame's row (positions to the µm, angles to 1e-4°) into `line`, no newline.
pub fn format_row(f: &Frame, line: &mut String) {
    line.clear();
    let _ = write!(line, "{}", f.frame);
    let (r, l) = (&f.legs[0], &f.legs[1]);
    let pos = 6;
    let ang = 4;
    let cell = |line: &mut String, x: f64, d: usize| {
        line.push(',');
        push_fixed(line, x, d);
    };
    cell(line, f.time_s, pos);
    cell(line, r.phase, pos);
    cell(line, l.phase, pos);
    line.push(',');
    line.push_str(f.support.name());
    for v in [f.pelvis.x, f.pelvis.y, f.pelvis.z] {
        cell(line, v, pos);
    }
    for v in [f.pelvis_tilt_deg, f.pelvis_obliquity_deg, f.pelvis_rotation_deg] {
        cell(line, v, ang);
    }
    for leg in [r, l] {
        for v in [leg.hip_flex_deg, leg.hip_abd_deg, leg.knee_flex_deg, leg.ankle_dorsi_deg] {
            cell(line, v, ang);
        }
    }
    for leg in [r, l] {
        for v in [leg.heel.x, leg.heel.y, leg.heel.z, leg.toe.x, leg.toe.y, leg.toe.z] {
            cell(line, v, pos);
        }
    }
    for leg in [r, l] {
        cell(line, leg.shoulder_flex_deg, ang);
        cell(line, leg.elbow_flex_deg, ang);
    }
    cell(line, r.ground_under_heel, pos);
    cell(line, l.ground_under_heel, pos);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn negative_zero_is_written_as_zero() {
        let mut s = String::new();
        push_fixed(&mut s, -0.00001, 4);
        assert_eq!(s, "0.0000");
        s.clear();
        push_fixed(&mut s, -0.5, 2);
        assert_eq!(s, "-0.50");
    }
}
