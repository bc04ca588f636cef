//! `gaitlab compare`: the walk's joint curves against measured human gait, as a table or JSON
//! lines.

use super::common::stdout_written;
use crate::config;
use crate::error::Result;
use crate::normative::{self, Comparison};
use std::io::{self, Write};
use std::path::Path;

pub(super) fn run(path: &Path, reference: Option<&Path>, json: bool, sets: &[String]) -> Result<()> {
    let params = config::load(path, sets)?;
    let (reference, source) = super::common::references(reference)?;
    let comparison = normative::compare(path, &params, &reference)?;
    let stdout = io::stdout();
    let mut out = io::BufWriter::new(stdout.lock());
    let written =
        if json { write_json(&mut out, &comparison) } else { write_table(&mut out, path, &source, &comparison) };
    stdout_written(written.and_then(|()| out.flush()))
}

/// The walk's spatiotemporal figures and pelvis vertical range beside the norms at its speed:
/// the comment lines above the table.
fn write_figures(out: &mut dyn Write, c: &Comparison) -> io::Result<()> {
    let [(_, cadence), (_, stride), (_, stance)] = c.spatiotemporal;
    writeln!(out, "# the walk: cadence {cadence:.1} steps/min, stride {stride:.3} m, stance {stance:.1} %")?;
    let n = &c.spatiotemporal_norms;
    let (cad_z, stride_z) = (sd_units(cadence, n.cadence_spm), sd_units(stride, n.stride_length_m));
    writeln!(
        out,
        "# norms at {:.3} m/s ({}; {}): cadence {:.1} +- {:.1} steps/min (walk {cad_z:+.2} SD), stride {:.3} +- {:.3} m (walk {stride_z:+.2} SD); no stance norm by speed",
        n.speed_mps,
        normative::SPEED_NORMS_SOURCE,
        n.blocks_used(),
        n.cadence_spm.0,
        n.cadence_spm.1,
        n.stride_length_m.0,
        n.stride_length_m.1
    )?;
    let p = &c.pelvis_norms;
    // Off level ground the walk's range is mostly the climb's profile: no score against people
    // walking on the level (stairs_down read +35 SD).
    let score = if c.level_ground {
        format!("walk {:+.2} SD", sd_units(c.pelvis_vertical_range_cm, p.vertical_range_cm))
    } else {
        "no SD score: they walked on level ground".to_string()
    };
    writeln!(
        out,
        "# pelvis vertical range: walk {:.2} cm; people at {:.3} m/s ({}; {}): {:.2} +- {:.2} cm ({score})",
        c.pelvis_vertical_range_cm,
        p.speed_mps,
        normative::PELVIS_NORMS_SOURCE,
        p.blocks_used(),
        p.vertical_range_cm.0,
        p.vertical_range_cm.1,
    )?;
    if let Some(sentence) = normative::through_legs_sentence(c) {
        writeln!(out, "# {sentence}")?;
    }
    Ok(())
}

fn write_table(out: &mut dyn Write, path: &Path, source: &str, c: &Comparison) -> io::Result<()> {
    writeln!(
        out,
        "# {} at {:.3} m/s against {source}, {}; right gait cycle, every 2 %",
        path.display(),
        c.speed_mps,
        c.reference_blocks()
    )?;
    if !c.level_ground {
        writeln!(out, "# {}", normative::OFF_LEVEL_NOTE)?;
    }
    if let Some(part) = &c.steady_part {
        // A part on stairs or a slope says why itself; a pace plateau's reason is said here.
        let why = if part.contains("plateau") {
            " (the pace changed: the plateau with the most whole gait cycles; speed changes, stopping and standing left out)"
        } else {
            ""
        };
        writeln!(out, "# steady part compared: {part}{why}")?;
    }
    write_figures(out, c)?;
    writeln!(
        out,
        "# deviation = walk - reference; r = Pearson r of the shapes; out1/out2 = share of the cycle beyond mean +- 1/2 SD; rom = range of motion difference; * shape only (means removed)"
    )?;
    writeln!(
        out,
        "{:<17} {:>7} {:>6} {:>8} {:>5} {:>5} {:>5} {:>7}  {:>15} {:>15}  {:>15} {:>15}",
        "curve",
        "rms_deg",
        "r",
        "max_dev",
        "at_%",
        "out1%",
        "out2%",
        "rom_deg",
        "walk max @%",
        "ref max @%",
        "walk min @%",
        "ref min @%"
    )?;
    let at = |(v, p): (f64, f64)| format!("{v:.1} @{p:.0}");
    for k in &c.curves {
        let name = if k.shape_only { format!("{}*", k.curve) } else { k.curve.clone() };
        writeln!(
            out,
            "{name:<17} {:>7.2} {:>6.3} {:>8.2} {:>5.0} {:>5.0} {:>5.0} {:>+7.1}  {:>15} {:>15}  {:>15} {:>15}",
            k.rms_deg,
            k.pearson_r,
            k.max_deviation_deg,
            k.at_pct,
            k.outside_1sd_pct,
            k.outside_2sd_pct,
            k.range_difference_deg,
            at(k.walk_max),
            at(k.reference_max),
            at(k.walk_min),
            at(k.reference_min)
        )?;
    }
    Ok(())
}

/// How many of the norm's SDs the walk's figure lies from its mean (+: above).
fn sd_units(walk: f64, (mean, sd): (f64, f64)) -> f64 {
    (walk - mean) / sd
}

fn write_json(out: &mut dyn Write, c: &Comparison) -> io::Result<()> {
    for k in &c.curves {
        let mut line = serde_json::to_value(k).map_err(io::Error::other)?;
        line["speed_mps"] = c.speed_mps.into();
        line["reference_speed_mps"] = c.reference_speed_mps.into();
        line["reference_from_block_mps"] = c.reference_blocks_mps.0.into();
        line["reference_to_block_mps"] = c.reference_blocks_mps.1.into();
        line["level_ground"] = c.level_ground.into();
        for (key, value) in c.spatiotemporal {
            line[key] = value.into();
        }
        let n = &c.spatiotemporal_norms;
        line["norm_from_block_mps"] = n.from_block_mps.into();
        line["norm_to_block_mps"] = n.to_block_mps.into();
        line["cadence_norm_spm"] = n.cadence_spm.0.into();
        line["cadence_norm_sd_spm"] = n.cadence_spm.1.into();
        line["stride_length_norm_m"] = n.stride_length_m.0.into();
        line["stride_length_norm_sd_m"] = n.stride_length_m.1.into();
        let p = &c.pelvis_norms;
        line["pelvis_vertical_range_cm"] = c.pelvis_vertical_range_cm.into();
        line["pelvis_vertical_range_norm_cm"] = p.vertical_range_cm.0.into();
        line["pelvis_vertical_range_norm_sd_cm"] = p.vertical_range_cm.1.into();
        line["pelvis_norm_from_block_mps"] = p.from_block_mps.into();
        line["pelvis_norm_to_block_mps"] = p.to_block_mps.into();
        if let Some((people, walk)) = c.pelvis_range_through_legs_cm {
            line["pelvis_vertical_range_legs_norm_cm"] = people.into();
            line["pelvis_vertical_range_legs_walk_cm"] = walk.into();
        }
        if let Some(part) = &c.steady_part {
            line["steady_part"] = part.as_str().into();
        }
        writeln!(out, "{line}")?;
    }
    Ok(())
}
