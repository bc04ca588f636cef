//! The report's walk against measured gait: `summary.md`'s "Against measured gait" section
//! and the `normative_*` keys appended to `summary.json`. Both come from the comparison
//! `gaitlab compare` prints, run on the report's own recording (one walk, the same figures).

use super::metrics::Summary;
use crate::analysis::Run;
use crate::normative::{self, Comparison, CurveComparison, References};
use serde::Serialize;
use std::fmt::Write as _;
use std::path::Path;

/// The report's walk (`cycles` of the config named `name`) against the built-in reference.
pub(super) fn compare(name: &str, cycles: u32, run: &Run, summary: &Summary) -> crate::Result<Comparison> {
    normative::compare_recorded(Path::new(name), cycles, run, summary, References::built_in())
}

/// `summary.json`: the interface's keys as they always were, then the comparison's headline
/// figures (new keys go at the end). The snapshot files read [`super::metrics::LABELS`], not
/// this, so they do not change.
#[derive(Serialize)]
pub(super) struct SummaryJson<'a> {
    #[serde(flatten)]
    summary: &'a Summary,
    normative_hip_rms_deg: f64,
    normative_knee_rms_deg: f64,
    normative_ankle_rms_deg: f64,
    normative_hip_r: f64,
    normative_knee_r: f64,
    normative_ankle_r: f64,
    /// The part of the walk the figures are measured on, where it is not every cycle after
    /// start-up (a schedule's plateau, the cycles on stairs or a slope): as compare and the
    /// snapshot name it.
    #[serde(skip_serializing_if = "Option::is_none")]
    steady_part: Option<String>,
}

impl<'a> SummaryJson<'a> {
    pub(super) fn new(summary: &'a Summary, c: &Comparison) -> Self {
        let curve = |stem: &str| c.curves.iter().find(|k| k.curve == stem);
        let rms = |stem: &str| curve(stem).map_or(f64::NAN, |k| k.rms_deg);
        let r = |stem: &str| curve(stem).map_or(f64::NAN, |k| k.pearson_r);
        SummaryJson {
            summary,
            normative_hip_rms_deg: rms("hip_flex"),
            normative_knee_rms_deg: rms("knee_flex"),
            normative_ankle_rms_deg: rms("ankle_dorsi"),
            normative_hip_r: r("hip_flex"),
            normative_knee_r: r("knee_flex"),
            normative_ankle_r: r("ankle_dorsi"),
            steady_part: c.steady_part.clone(),
        }
    }
}

/// How the table names each compared curve.
fn label(stem: &str) -> &str {
    match stem {
        "hip_flex" => "hip flexion",
        "knee_flex" => "knee flexion",
        "ankle_dorsi" => "ankle dorsiflexion",
        "pelvis_tilt_ant" => "pelvic tilt, shape (means removed)",
        "pelvis_obliq_up" => "pelvic obliquity, right up",
        "pelvis_rot_fwd" => "pelvic rotation, right forward",
        other => other,
    }
}

/// The "Against measured gait" section: which walk, the reference and both speeds, then a
/// row per curve. Figures to two decimals (r to three), so that they read back as
/// `gaitlab compare --json` gives them.
pub(super) fn section(md: &mut String, name: &str, compared: bool, c: &Comparison) {
    let _ = write!(
        md,
        "\n## Against measured gait\n\n`{name}` at {:.3} m/s against {}, {}, over the mean \
         steady right gait cycle every 2 % (as `gaitlab compare` gives it).{} Difference = walk − \
         reference; r: Pearson r of the two mean curves (the shape, blind to offset and scale); \
         outside ±1 / ±2 SD: share of the cycle beyond the reference's mean ± 1 / 2 SD; range of \
         motion difference: the walk's less the reference's; extremes as value @ % of the cycle. \
         Pelvic tilt is compared as a shape (both means removed): the measured tilt carries an \
         offset of about 10° that depends on the marker model. The plots `joints` and `pelvis` \
         draw the reference's band.\n\n\
         | curve | RMS (deg) | r | outside ±1 SD (%) | outside ±2 SD (%) | range of motion difference (deg) | walk max | reference max | walk min | reference min |\n\
         |---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n",
        c.speed_mps,
        normative::BUILT_IN_SOURCE,
        c.reference_blocks(),
        compared_note(name, compared, c),
    );
    for k in &c.curves {
        row(md, k);
    }
    spatiotemporal(md, c);
}

/// What the table is of, beyond the walk's name: the steady part compared (a walk whose pace
/// changed, or the cycles on its stairs or slope), and that compared walks are not in it.
fn compared_note(name: &str, compared: bool, c: &Comparison) -> String {
    let mut note = String::new();
    if let Some(part) = &c.steady_part {
        if part.contains("plateau") {
            let _ = write!(note, " The walk's pace changed: compared on its steady part, {part} (see *Pace*).");
        } else {
            let _ = write!(note, " Compared on {part}.");
        }
    }
    if !c.level_ground {
        let mut off_level = normative::OFF_LEVEL_NOTE.to_string();
        off_level[..1].make_ascii_uppercase();
        let _ = write!(note, " {off_level}.");
    }
    if compared {
        let _ = write!(note, " The table is for `{name}`, the report's own walk, not the compared ones.");
    }
    note
}

/// The walk's cadence and stride beside the norms at its own speed (the figures
/// `gaitlab compare` prints above its table).
fn spatiotemporal(md: &mut String, c: &Comparison) {
    let n = &c.spatiotemporal_norms;
    let _ = write!(
        md,
        "\nSpatiotemporal figures against {} at the walk's {:.3} m/s ({}):\n\n\
         | figure | walk | norm, mean ± SD | walk − norm (SD) |\n|---|---:|---:|---:|\n",
        normative::SPEED_NORMS_SOURCE,
        n.speed_mps,
        n.blocks_used()
    );
    let [(_, cadence), (_, stride), (_, stance)] = c.spatiotemporal;
    for (name, walk, (mean, sd), digits) in
        [("cadence (steps/min)", cadence, n.cadence_spm, 1), ("stride length (m)", stride, n.stride_length_m, 3)]
    {
        let _ =
            writeln!(md, "| {name} | {walk:.digits$} | {mean:.digits$} ± {sd:.digits$} | {:+.2} |", (walk - mean) / sd);
    }
    let _ = writeln!(md, "| stance (%) | {stance:.1} | no norm by speed | |");
    let p = &c.pelvis_norms;
    let (mean, sd) = p.vertical_range_cm;
    let walk = c.pelvis_vertical_range_cm;
    let score = if c.level_ground { format!("{:+.2}", (walk - mean) / sd) } else { "off level ground".to_string() };
    let _ = writeln!(md, "| pelvis vertical range (cm)¹ | {walk:.2} | {mean:.2} ± {sd:.2} | {score} |");
    let _ = writeln!(
        md,
        "\n¹ Against {} ({}): the centre of the four pelvis markers, per step.",
        normative::PELVIS_NORMS_SOURCE,
        p.blocks_used()
    );
    if let Some(sentence) = normative::through_legs_sentence(c) {
        let _ = writeln!(md, "\n{}{}.", sentence[..1].to_uppercase(), &sentence[1..]);
    }
}

fn row(md: &mut String, k: &CurveComparison) {
    let at = |(v, p): (f64, f64)| format!("{v:.2} @ {p:.0}");
    let _ = writeln!(
        md,
        "| {} (`{}`) | {:.2} | {:.3} | {:.2} | {:.2} | {:+.2} | {} | {} | {} | {} |",
        label(&k.curve),
        k.curve,
        k.rms_deg,
        k.pearson_r,
        k.outside_1sd_pct,
        k.outside_2sd_pct,
        k.range_difference_deg,
        at(k.walk_max),
        at(k.reference_max),
        at(k.walk_min),
        at(k.reference_min)
    );
}
