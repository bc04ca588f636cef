//! A walk against measured human gait: the walk's mean joint curves over the right gait cycle
//! set beside a normative reference (mean and between-subject SD every 1 % of the cycle) at
//! the walk's own speed.
//!
//! The built-in references are `data/normative/joint_angles_by_speed.csv` (Fukuchi, Fukuchi &
//! Duarte 2018, CC BY 4.0; source, licence and derivation beside it): young adults' treadmill
//! trials in six speed blocks, 0.58 to 1.80 m/s, read at the walk's speed by linear
//! interpolation between the two blocks around it. Joint curves change with speed as much as
//! with anything a config sets (the knee's loading flexion goes from 8° at 0.8 m/s to 20° at
//! 1.6), so a norm at another speed would blame the walk for the reference's pace. A user's
//! file with the same columns, one speed block or several, can replace them. Pelvic tilt is
//! compared as a shape (both means removed): the measured tilt carries a ~10° offset that
//! depends on the marker model, the walk's tilt is a swing about its posture.
//!
//! The walk's cadence and stride are set beside norms for its own speed
//! (`data/normative/spatiotemporal_by_speed.csv`, the same dataset's treadmill trials at 40–115 %
//! of comfortable speed), interpolated the same way, and its pelvis's vertical range beside the
//! same adults' measured one ([`PelvisNorms`]).

mod blocks;
mod legs;
mod pelvis;

use blocks::{blocks_used, bracket, parse_rows};

pub use legs::{LegAngles, pelvis_range_through_legs};
pub use pelvis::{PELVIS_NORMS_SOURCE, PelvisAtSpeed, PelvisNorms};

use crate::analysis::Run;
use crate::error::{Error, Result};
use crate::model::body::BodyDims;
use crate::model::params::WalkParams;
use crate::report::metrics::Summary;
use crate::snapshot::measure;
use std::path::Path;

/// How the built-in references are named in tables and files.
pub const BUILT_IN_SOURCE: &str = "Fukuchi, Fukuchi & Duarte 2018 (young adults, treadmill, by speed, CC BY 4.0)";

/// The built-in references' text: six speed blocks, 0.58 to 1.80 m/s.
pub const BUILT_IN: &str = include_str!("../../data/normative/joint_angles_by_speed.csv");

/// How the built-in spatiotemporal norms are named.
pub const SPEED_NORMS_SOURCE: &str =
    "Fukuchi, Fukuchi & Duarte 2018 (22 young adults, treadmill at 40-115 % of comfortable speed, CC BY 4.0)";

/// The built-in spatiotemporal norms by speed: `data/normative/spatiotemporal_by_speed.csv`
/// (source, licence and derivation beside it).
pub const BUILT_IN_SPEED_NORMS: &str = include_str!("../../data/normative/spatiotemporal_by_speed.csv");

/// Said beside the comparison of a walk off level ground.
pub const OFF_LEVEL_NOTE: &str = "the walk is not on level ground and the norms are level treadmill walking: the differences include what the terrain asks of the legs";

/// The curves compared: (reference column stem, the walk's curve, compared as a shape).
const COMPARED: [(&str, &str, bool); 6] = [
    ("hip_flex", "hip_flex_r_deg", false),
    ("knee_flex", "knee_flex_r_deg", false),
    ("ankle_dorsi", "ankle_dorsi_r_deg", false),
    ("pelvis_tilt_ant", "pelvis_tilt_deg", true),
    ("pelvis_obliq_up", "pelvis_obliquity_deg", false),
    ("pelvis_rot_fwd", "pelvis_rotation_deg", false),
];

/// A normative reference at one speed: per curve stem, mean and SD at 0..=100 % of the cycle.
#[derive(Clone, Debug, PartialEq)]
pub struct Reference {
    /// The reference's walking speed (m/s): its block's, or the speed it was interpolated at.
    pub speed_mps: f64,
    /// The speeds of the blocks it came from (m/s), equal when one block was taken.
    pub blocks_mps: (f64, f64),
    /// (stem, mean, sd), 101 points each.
    pub curves: Vec<(String, Vec<f64>, Vec<f64>)>,
}

impl Reference {
    /// Where the curves came from, in words, as [`NormsAtSpeed::blocks_used`] says it.
    #[must_use]
    pub fn blocks_used(&self, walk_speed_mps: f64) -> String {
        blocks_used(walk_speed_mps, self.blocks_mps)
    }
}

/// Normative references at one or more speeds, slowest first: the built-in file has five
/// speed blocks (0.80 to 1.80 m/s), a user's file may have one.
#[derive(Clone, Debug, PartialEq)]
pub struct References {
    /// The blocks, speeds strictly rising.
    pub blocks: Vec<Reference>,
}

impl References {
    /// The built-in references, parsed once for the process (a test checks that they parse):
    /// a report reads them for its summary and three plots, the lab whenever the pace changes.
    #[must_use]
    pub fn built_in() -> &'static References {
        static BUILT: std::sync::OnceLock<References> = std::sync::OnceLock::new();
        BUILT.get_or_init(|| References::parse(BUILT_IN, "built-in reference").expect("the built-in reference parses"))
    }

    /// Parses the built-in file's format: `#` comments, a header, then 101 rows (0 to 100 %
    /// of the cycle) per speed block, a block's rows sharing their `speed_m_s`, speeds rising.
    pub fn parse(text: &str, label: &str) -> Result<References> {
        let bad = |line: usize, message: String| Error::Usage(format!("{label}:{line}: {message}"));
        let mut rows = text.lines().enumerate().filter(|(_, l)| !l.trim().is_empty() && !l.starts_with('#'));
        let (header_line, header) = rows.next().ok_or_else(|| bad(1, "no header".into()))?;
        let columns: Vec<&str> = header.split(',').map(str::trim).collect();
        let column = |name: &str| {
            columns
                .iter()
                .position(|c| *c == name)
                .ok_or_else(|| bad(header_line + 1, format!("no column `{name}` (columns: {})", columns.join(", "))))
        };
        let speed = column("speed_m_s")?;
        let pct = column("pct_cycle")?;
        let mut stems = Vec::new();
        for (stem, _, _) in COMPARED {
            stems.push((stem, column(&format!("{stem}_mean_deg"))?, column(&format!("{stem}_sd_deg"))?));
        }
        // (first line of the block, its rows)
        let mut tables: Vec<(usize, Vec<Vec<f64>>)> = Vec::new();
        for (n, line) in rows {
            let fields: Vec<&str> = line.split(',').map(str::trim).collect();
            if fields.len() != columns.len() {
                return Err(bad(n + 1, format!("{} values; expected {}, one per column", fields.len(), columns.len())));
            }
            let mut values = Vec::with_capacity(fields.len());
            for (field, name) in fields.iter().zip(&columns) {
                match field.parse::<f64>() {
                    Ok(v) if v.is_finite() => values.push(v),
                    _ => return Err(bad(n + 1, format!("`{name}` is `{field}`, not a finite number"))),
                }
            }
            if let Some(&(stem, _, sd)) = stems.iter().find(|&&(_, _, sd)| values[sd] < 0.0) {
                return Err(bad(n + 1, format!("`{stem}_sd_deg` is {}; an SD is 0 or more", values[sd])));
            }
            if values[speed] <= 0.0 {
                return Err(bad(n + 1, format!("`speed_m_s` is {}; a walking speed is above 0", values[speed])));
            }
            match tables.last_mut() {
                Some((_, table)) if table[0][speed] == values[speed] => table.push(values),
                Some((_, table)) if table[0][speed] > values[speed] => {
                    return Err(bad(n + 1, "speed blocks must come slowest first (speed_m_s rising)".into()));
                }
                _ => tables.push((n + 1, vec![values])),
            }
        }
        if tables.is_empty() {
            return Err(bad(header_line + 1, "0 rows; expected 101 (0 to 100 % of the cycle)".into()));
        }
        let mut blocks = Vec::new();
        for (line, table) in tables {
            // The rows must be the cycle's percents in order: a block's rows read by position.
            if let Some(i) = (0..table.len()).find(|&i| table[i][pct] != i as f64) {
                return Err(bad(
                    line + i,
                    format!("`pct_cycle` is {}; a block's rows run 0, 1, ... 100 in order", table[i][pct]),
                ));
            }
            if table.len() != 101 {
                return Err(bad(
                    line,
                    format!("{} rows at {} m/s; expected 101 (0 to 100 % of the cycle)", table.len(), table[0][speed]),
                ));
            }
            let curves = stems
                .iter()
                .map(|&(stem, m, s)| {
                    (stem.to_string(), table.iter().map(|r| r[m]).collect(), table.iter().map(|r| r[s]).collect())
                })
                .collect();
            let v = table[0][speed];
            blocks.push(Reference { speed_mps: v, blocks_mps: (v, v), curves });
        }
        Ok(References { blocks })
    }

    /// The reference at `speed_mps`: means and SDs interpolated linearly between the two
    /// blocks around it, or the end block beyond either end (never extrapolated).
    #[must_use]
    pub fn at(&self, speed_mps: f64) -> Reference {
        let speeds: Vec<f64> = self.blocks.iter().map(|b| b.speed_mps).collect();
        let (lo, hi, t) = bracket(&speeds, speed_mps);
        let (a, b) = (&self.blocks[lo], &self.blocks[hi]);
        let mix = |x: &[f64], y: &[f64]| x.iter().zip(y).map(|(x, y)| x + t * (y - x)).collect::<Vec<f64>>();
        let curves = a
            .curves
            .iter()
            .zip(&b.curves)
            .map(|((stem, m0, s0), (_, m1, s1))| (stem.clone(), mix(m0, m1), mix(s0, s1)))
            .collect();
        Reference {
            speed_mps: a.speed_mps + t * (b.speed_mps - a.speed_mps),
            blocks_mps: (a.speed_mps, b.speed_mps),
            curves,
        }
    }
}

/// One speed block of spatiotemporal norms: mean and between-subject SD.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SpeedBlock {
    /// The block's mean walking speed (m/s).
    pub speed_mps: f64,
    /// Cadence (steps/min): mean, SD.
    pub cadence_spm: (f64, f64),
    /// Stride length, heel strike to heel strike of one foot (m): mean, SD.
    pub stride_length_m: (f64, f64),
}

/// Spatiotemporal norms at several speeds, slowest first.
#[derive(Clone, Debug, PartialEq)]
pub struct SpeedNorms {
    /// The blocks, speeds strictly rising.
    pub blocks: Vec<SpeedBlock>,
}

/// The norms at one walk's speed, and which blocks they came from.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct NormsAtSpeed {
    /// The speed asked for (m/s).
    pub speed_mps: f64,
    /// The speeds of the blocks interpolated between (m/s); equal when one block was taken
    /// (the speed is at or beyond the data's ends).
    pub from_block_mps: f64,
    /// See `from_block_mps`.
    pub to_block_mps: f64,
    /// Cadence norm (steps/min): mean, SD.
    pub cadence_spm: (f64, f64),
    /// Stride length norm (m): mean, SD.
    pub stride_length_m: (f64, f64),
}

impl SpeedNorms {
    /// The built-in table, parsed (a test checks that it does).
    #[must_use]
    pub fn built_in() -> SpeedNorms {
        SpeedNorms::parse(BUILT_IN_SPEED_NORMS, "built-in speed norms").expect("the built-in table parses")
    }

    /// Parses the built-in file's format: `#` comments, a header, one row a speed block.
    pub fn parse(text: &str, label: &str) -> Result<SpeedNorms> {
        let wanted = ["speed_m_s", "cadence_mean_spm", "cadence_sd_spm", "stride_length_mean_m", "stride_length_sd_m"];
        let blocks = parse_rows(text, label, &wanted)?
            .into_iter()
            .map(|v| SpeedBlock { speed_mps: v[0], cadence_spm: (v[1], v[2]), stride_length_m: (v[3], v[4]) })
            .collect();
        Ok(SpeedNorms { blocks })
    }

    /// The norms at `speed_mps`: linear interpolation (means and SDs) between the two blocks
    /// around it, or the end block beyond either end (never extrapolated).
    #[must_use]
    pub fn at(&self, speed_mps: f64) -> NormsAtSpeed {
        let speeds: Vec<f64> = self.blocks.iter().map(|b| b.speed_mps).collect();
        let (lo, hi, t) = bracket(&speeds, speed_mps);
        let (lo, hi) = (self.blocks[lo], self.blocks[hi]);
        let mix = |a: (f64, f64), b: (f64, f64)| (a.0 + t * (b.0 - a.0), a.1 + t * (b.1 - a.1));
        NormsAtSpeed {
            speed_mps,
            from_block_mps: lo.speed_mps,
            to_block_mps: hi.speed_mps,
            cadence_spm: mix(lo.cadence_spm, hi.cadence_spm),
            stride_length_m: mix(lo.stride_length_m, hi.stride_length_m),
        }
    }
}

impl NormsAtSpeed {
    /// Where the norms came from, in words: "the 1.232 m/s block", "between the 1.232 and
    /// 1.417 m/s blocks", or "the 1.417 m/s block, the fastest (the walk is faster)".
    #[must_use]
    pub fn blocks_used(&self) -> String {
        blocks_used(self.speed_mps, (self.from_block_mps, self.to_block_mps))
    }
}

impl Comparison {
    /// Which speed blocks the reference came from, in words ([`Reference::blocks_used`]).
    #[must_use]
    pub fn reference_blocks(&self) -> String {
        blocks_used(self.speed_mps, self.reference_blocks_mps)
    }
}

/// One curve of the walk against the reference.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct CurveComparison {
    /// The reference's name for it.
    pub curve: String,
    /// Compared as a shape (both means removed).
    pub shape_only: bool,
    /// Root-mean-square difference over the cycle (deg).
    pub rms_deg: f64,
    /// Largest difference, walk minus reference (deg), and where (% of the cycle).
    pub max_deviation_deg: f64,
    /// Where the largest difference is (% of the cycle).
    pub at_pct: f64,
    /// Share of the cycle where the walk is outside the reference's mean ± 1 SD (%).
    pub outside_1sd_pct: f64,
    /// Share of the cycle where the walk is outside the reference's mean ± 2 SD (%).
    pub outside_2sd_pct: f64,
    /// Pearson correlation of the walk's curve with the reference mean: the shape alone,
    /// blind to offset and scale (1: the same shape).
    pub pearson_r: f64,
    /// The walk's range of motion less the reference's (deg).
    pub range_difference_deg: f64,
    /// The walk's and the reference's largest value and where (deg, %).
    pub walk_max: (f64, f64),
    /// See `walk_max`.
    pub reference_max: (f64, f64),
    /// The walk's and the reference's smallest value and where (deg, %).
    pub walk_min: (f64, f64),
    /// See `walk_min`.
    pub reference_min: (f64, f64),
}

/// A walk against a reference.
#[derive(Clone, Debug, PartialEq)]
pub struct Comparison {
    /// The walk's speed (m/s).
    pub speed_mps: f64,
    /// The reference's speed (m/s): the walk's, inside the references' speeds.
    pub reference_speed_mps: f64,
    /// The speeds of the reference blocks it came from (m/s), equal when one was taken.
    pub reference_blocks_mps: (f64, f64),
    /// Curve by curve.
    pub curves: Vec<CurveComparison>,
    /// The walk's spatiotemporal figures, as the report's summary measures them: cadence
    /// (steps/min), stride length (m), stance (% of the cycle); cadence and stride are set
    /// beside `spatiotemporal_norms`.
    pub spatiotemporal: [(&'static str, f64); 3],
    /// Cadence and stride norms at the walk's speed (the built-in table by speed; no stance
    /// norm by speed is available).
    pub spatiotemporal_norms: NormsAtSpeed,
    /// The walk's pelvis vertical range (cm, the report's `pelvis_vertical_range_cm`), set
    /// beside `pelvis_norms`.
    pub pelvis_vertical_range_cm: f64,
    /// People's pelvis vertical range at the walk's speed.
    pub pelvis_norms: PelvisAtSpeed,
    /// The pelvis vertical range (cm) that the reference's mean angles and the walk's own give
    /// through the walk's legs ([`pelvis_range_through_legs`]): what the joint curves alone
    /// account for. `None` off level ground, where the chain does not stand, where the body is
    /// not known ([`compare_measured`]) or a curve is missing (never NaN).
    pub pelvis_range_through_legs_cm: Option<(f64, f64)>,
    /// The walk was on level ground, as the norms' treadmill walking was; false on stairs,
    /// slopes and rough ground, where the differences include what the terrain asks.
    pub level_ground: bool,
    /// The part of the walk compared, for a walk that was not steady throughout (its pace
    /// changed or it stopped): the plateau the snapshot measured
    /// ([`crate::report::metrics::steady_window`]); `None` for a walk steady throughout.
    pub steady_part: Option<String>,
}

fn extreme(points: &[(f64, f64)], larger: bool) -> (f64, f64) {
    let pick = |a: (f64, f64), b: (f64, f64)| if (b.0 > a.0) == larger && b.0 != a.0 { b } else { a };
    points.iter().copied().fold(points[0], pick)
}

/// Pearson's r of two equally long series; 0 when either is flat (no shape to correlate).
fn pearson(a: &[f64], b: &[f64]) -> f64 {
    let n = a.len() as f64;
    let (ma, mb) = (a.iter().sum::<f64>() / n, b.iter().sum::<f64>() / n);
    let (mut sab, mut saa, mut sbb) = (0.0, 0.0, 0.0);
    for (x, y) in a.iter().zip(b) {
        sab += (x - ma) * (y - mb);
        saa += (x - ma) * (x - ma);
        sbb += (y - mb) * (y - mb);
    }
    if saa == 0.0 || sbb == 0.0 { 0.0 } else { sab / (saa * sbb).sqrt() }
}

fn range(v: &[f64]) -> f64 {
    v.iter().copied().fold(f64::NEG_INFINITY, f64::max) - v.iter().copied().fold(f64::INFINITY, f64::min)
}

/// Walks `params` (the config at `path`) for its `sim.cycles` and compares it with `reference`
/// every 2 % of the right gait cycle.
pub fn compare(path: &Path, params: &WalkParams, reference: &References) -> Result<Comparison> {
    let walk = measure::measure(path, params)?;
    let mut c = compare_measured(&walk, reference);
    c.level_ground = params.terrain.kind().is_level();
    if c.level_ground {
        c.pelvis_range_through_legs_cm = through_legs(&walk, &reference.at(c.speed_mps), &params.resolve().dims);
    }
    Ok(c)
}

/// A walk already recorded and summarised (the report's: `cycles` of the config at `path`)
/// against `reference`, measured and compared exactly as [`compare`] does.
pub fn compare_recorded(
    path: &Path,
    cycles: u32,
    run: &Run,
    summary: &Summary,
    reference: &References,
) -> Result<Comparison> {
    let walk = measure::recorded(path, cycles, run, summary)?;
    let mut c = compare_measured(&walk, reference);
    c.level_ground = run.terrain.kind().is_level();
    if c.level_ground {
        let dims = &run.gait.resolved().dims;
        c.pelvis_range_through_legs_cm = through_legs(&walk, &reference.at(c.speed_mps), dims);
    }
    Ok(c)
}

/// The pelvis range the joint curves alone give, people's and the walk's, as `compare` and the
/// report's summary say it; `None` where it was not measured (off level ground, or no body).
#[must_use]
pub fn through_legs_sentence(c: &Comparison) -> Option<String> {
    let (people, walk) = c.pelvis_range_through_legs_cm?;
    Some(format!(
        "the joint curves alone, put through this body's legs (sagittal chain, pelvic obliquity, rigid feet): the reference's mean angles would give the pelvis a vertical range of {people:.2} cm, the walk's own angles {walk:.2} cm; where the two are close, closer joint curves cannot raise the walk's pelvis"
    ))
}

/// The pelvis range `reference`'s mean angles and `walk`'s own give through the legs of
/// `dims` (level ground only: the chain stands on flat ground); `None` where a curve is missing.
fn through_legs(walk: &measure::Snapshot, reference: &Reference, dims: &BodyDims) -> Option<(f64, f64)> {
    let ours = |name: &str| walk.curves.iter().find(|(n, _)| n == name).map_or(&[][..], |c| c.1.as_slice());
    let theirs = |stem: &str| reference.curves.iter().find(|c| c.0 == stem).map_or(&[][..], |c| c.1.as_slice());
    let people = LegAngles {
        hip_flex: theirs("hip_flex"),
        knee_flex: theirs("knee_flex"),
        ankle_dorsi: theirs("ankle_dorsi"),
        pelvis_tilt: theirs("pelvis_tilt_ant"),
        pelvis_obliquity: theirs("pelvis_obliq_up"),
    };
    let walked = LegAngles {
        hip_flex: ours("hip_flex_r_deg"),
        knee_flex: ours("knee_flex_r_deg"),
        ankle_dorsi: ours("ankle_dorsi_r_deg"),
        pelvis_tilt: ours("pelvis_tilt_deg"),
        pelvis_obliquity: ours("pelvis_obliquity_deg"),
    };
    let (people, walked) = (pelvis_range_through_legs(&people, dims), pelvis_range_through_legs(&walked, dims));
    (people.is_finite() && walked.is_finite()).then_some((people, walked))
}

/// A walk already measured against `references` at the speed it walked (the fit measures
/// once for this and for its constraints).
#[must_use]
pub fn compare_measured(walk: &measure::Snapshot, references: &References) -> Comparison {
    let speed_mps = walk.summary.iter().find(|(k, _)| k == "speed_mps").map_or(f64::NAN, |(_, v)| *v);
    let reference = &references.at(speed_mps);
    let mut curves = Vec::new();
    for ((stem, name, shape_only), (_, mean, sd)) in COMPARED.iter().zip(&reference.curves) {
        let ours = &walk.curves.iter().find(|(n, _)| n == name).expect("a measured curve").1;
        // The walk's points are every 2 %: the reference's rows 0, 2, … 100.
        let theirs: Vec<(f64, f64)> = (0..ours.len()).map(|i| (mean[2 * i], sd[2 * i])).collect();
        let offset = |v: &[f64]| if *shape_only { v.iter().sum::<f64>() / v.len() as f64 } else { 0.0 };
        let (ours_off, theirs_off) = (offset(ours), offset(&theirs.iter().map(|t| t.0).collect::<Vec<_>>()));
        let diffs: Vec<f64> = ours.iter().zip(&theirs).map(|(o, t)| (o - ours_off) - (t.0 - theirs_off)).collect();
        let rms_deg = (diffs.iter().map(|d| d * d).sum::<f64>() / diffs.len() as f64).sqrt();
        let (at, max_dev) =
            diffs.iter().enumerate().fold((0, 0.0_f64), |a, (i, d)| if d.abs() > a.1.abs() { (i, *d) } else { a });
        let outside = |k: f64| diffs.iter().zip(&theirs).filter(|(d, t)| d.abs() > k * t.1).count();
        let theirs_mean: Vec<f64> = theirs.iter().map(|t| t.0).collect();
        let pct = |i: usize| 2.0 * i as f64;
        // Extremes as compared: a shape's without its mean.
        let ours_pts: Vec<(f64, f64)> = ours.iter().enumerate().map(|(i, v)| (v - ours_off, pct(i))).collect();
        let theirs_pts: Vec<(f64, f64)> = theirs.iter().enumerate().map(|(i, t)| (t.0 - theirs_off, pct(i))).collect();
        curves.push(CurveComparison {
            curve: (*stem).to_string(),
            shape_only: *shape_only,
            rms_deg,
            max_deviation_deg: max_dev,
            at_pct: pct(at),
            outside_1sd_pct: 100.0 * outside(1.0) as f64 / diffs.len() as f64,
            outside_2sd_pct: 100.0 * outside(2.0) as f64 / diffs.len() as f64,
            pearson_r: pearson(ours, &theirs_mean),
            range_difference_deg: range(ours) - range(&theirs_mean),
            walk_max: extreme(&ours_pts, true),
            reference_max: extreme(&theirs_pts, true),
            walk_min: extreme(&ours_pts, false),
            reference_min: extreme(&theirs_pts, false),
        });
    }
    let figure = |key: &str| walk.summary.iter().find(|(k, _)| k == key).map_or(f64::NAN, |(_, v)| *v);
    let spatiotemporal = [
        ("cadence_spm", figure("cadence_spm")),
        ("stride_length_m", figure("stride_length_m")),
        ("stance_pct", figure("stance_pct")),
    ];
    let spatiotemporal_norms = SpeedNorms::built_in().at(speed_mps);
    Comparison {
        pelvis_vertical_range_cm: figure("pelvis_vertical_range_cm"),
        pelvis_norms: PelvisNorms::built_in().at(speed_mps),
        pelvis_range_through_legs_cm: None,
        speed_mps,
        reference_speed_mps: reference.speed_mps,
        reference_blocks_mps: reference.blocks_mps,
        curves,
        spatiotemporal,
        spatiotemporal_norms,
        level_ground: true,
        steady_part: walk.steady_part.clone(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::body::{BALL_FRACTION, BodyDims, HEEL_FRACTION, Sex};

    /// Hip height over the ground (m) when the reference's mean angles at `pct` % are put
    /// through a 1.75 m body's leg with the heel `heel_back` of the foot behind the ankle,
    /// standing on whichever of heel and ball is lower.
    fn hip_height(r: &Reference, pct: usize, heel_back: f64) -> f64 {
        let d = BodyDims::from_height(1.75, Sex::Male);
        let mean = |stem: &str| r.curves.iter().find(|c| c.0 == stem).unwrap().1[pct % 100].to_radians();
        let thigh = mean("hip_flex") - mean("pelvis_tilt_ant");
        let shank = thigh - mean("knee_flex");
        let pitch = shank + mean("ankle_dorsi");
        let below = |x: f64| -(x * pitch.sin() - d.ankle_height * pitch.cos());
        let ankle_above_contact =
            below(-heel_back * d.foot_length).max(below((BALL_FRACTION - heel_back) * d.foot_length));
        d.thigh * thigh.cos() + d.shank * shank.cos() + ankle_above_contact
    }

    #[test]
    fn the_norms_put_both_feet_down_at_heel_strike_with_the_heel_behind_the_ankle() {
        // Why HEEL_FRACTION is what it is: at heel strike the leading leg stands on its heel
        // and the trailing one (half a cycle on) on its ball; the same pelvis must sit on both.
        // The comfortable-speed file the constant was set on.
        let r = References::parse(COMFORTABLE, "comfortable").unwrap().at(1.245);
        let gap = |heel_back: f64| (hip_height(&r, 0, heel_back) - hip_height(&r, 50, heel_back)).abs();
        assert!(gap(HEEL_FRACTION) < 0.011, "{}", gap(HEEL_FRACTION));
        assert!(gap(0.0) > 0.03, "a heel under the ankle: {}", gap(0.0));
    }

    #[test]
    fn the_built_in_references_have_six_speed_blocks_and_are_read_at_the_walks_speed() {
        let refs = References::built_in();
        let speeds: Vec<f64> = refs.blocks.iter().map(|b| b.speed_mps).collect();
        assert_eq!(speeds.len(), 6);
        assert!(speeds.windows(2).all(|w| w[0] < w[1]) && (0.55..0.62).contains(&speeds[0]), "{speeds:?}");
        assert!((1.55..1.65).contains(&speeds[4]) && (1.75..1.85).contains(&speeds[5]), "{speeds:?}");
        for b in &refs.blocks {
            assert_eq!(b.curves.len(), 6);
            assert!(b.curves.iter().all(|(_, m, s)| m.len() == 101 && s.len() == 101));
        }
        let knee = |r: &Reference| r.curves[1].1.clone();
        // Loading-response knee flexion grows with speed (Fukuchi 2018, fig. 5): by 1.9° from the
        // 0.583 to the 0.796 m/s block, 3.0-5.2° a block above.
        let loading = |r: &Reference| knee(r)[..30].iter().copied().fold(f64::MIN, f64::max);
        assert!(refs.blocks.windows(2).all(|w| loading(&w[1]) > loading(&w[0]) + 1.5));
        // Between two blocks: the linear mix; at or beyond an end: the end block itself.
        let mid = refs.at(0.5 * (speeds[1] + speeds[2]));
        assert!((knee(&mid)[74] - 0.5 * (knee(&refs.blocks[1])[74] + knee(&refs.blocks[2])[74])).abs() < 1e-9);
        assert_eq!(mid.blocks_mps, (speeds[1], speeds[2]));
        assert_eq!(refs.at(0.3).curves, refs.blocks[0].curves);
        assert_eq!(refs.at(2.5).curves, refs.blocks[5].curves);
        assert_eq!(refs.at(2.5).speed_mps, speeds[5]);
        assert_eq!(
            refs.at(2.5).blocks_used(2.5),
            format!("the {:.3} m/s block, the fastest (the walk is faster; not extrapolated)", speeds[5])
        );
        assert_eq!(refs.at(f64::NAN).curves, refs.blocks[0].curves);
    }

    #[test]
    fn a_bad_reference_file_is_located_by_line() {
        let one_block = References::parse(COMFORTABLE, "comfortable").unwrap();
        assert_eq!(one_block.blocks.len(), 1);
        assert!((one_block.at(0.8).speed_mps - 1.245).abs() < 1e-9);
        assert!((one_block.blocks[0].curves[1].1[74] - 62.26).abs() < 1e-9);
        let e = References::parse("pct_cycle,speed_m_s\n0,1\n", "mine.csv").unwrap_err().to_string();
        assert!(e.starts_with("mine.csv:") && e.contains("no column `hip_flex_mean_deg`"), "{e}");
        let mut bad = COMFORTABLE.replace("hip_flex_sd_deg", "hip_sd");
        assert!(References::parse(&bad, "x.csv").unwrap_err().to_string().contains("no column `hip_flex_sd_deg`"));
        bad = COMFORTABLE.replacen("0,1.245,29.87", "0,1.245,nan", 1);
        let e = References::parse(&bad, "x.csv").unwrap_err().to_string();
        assert!(e.contains("`hip_flex_mean_deg` is `nan`, not a finite number"), "{e}");
        // Rows out of order, a negative SD, a speed of 0: each refused at its line.
        let row = |pct: usize| COMFORTABLE.lines().find(|l| l.starts_with(&format!("{pct},"))).unwrap().to_string();
        let (r3, r4) = (row(3), row(4));
        bad = COMFORTABLE.replacen(&r3, "SWAP", 1).replacen(&r4, &r3, 1).replacen("SWAP", &r4, 1);
        let e = References::parse(&bad, "x.csv").unwrap_err().to_string();
        assert!(e.contains("`pct_cycle` is 4; a block's rows run 0, 1, ... 100 in order"), "{e}");
        let header_line = COMFORTABLE.lines().position(|l| l.starts_with("pct_cycle")).unwrap();
        assert!(e.starts_with(&format!("x.csv:{}:", header_line + 5)), "{e}");
        let fields: Vec<&str> = r3.split(',').collect();
        let negative_sd = format!("{},{},{},-{}", fields[0], fields[1], fields[2], fields[3..].join(","));
        bad = COMFORTABLE.replacen(&r3, &negative_sd, 1);
        let e = References::parse(&bad, "x.csv").unwrap_err().to_string();
        assert!(e.contains("`hip_flex_sd_deg` is -") && e.contains("an SD is 0 or more"), "{e}");
        bad = COMFORTABLE.replace(",1.245,", ",0,");
        let e = References::parse(&bad, "x.csv").unwrap_err().to_string();
        assert!(e.contains("`speed_m_s` is 0; a walking speed is above 0"), "{e}");
        // A block one row short (its 100 % row gone), and blocks out of order, name their first
        // line.
        let lines: Vec<&str> = BUILT_IN.lines().collect();
        let first_row = lines.iter().position(|l| l.starts_with("0,")).unwrap();
        let short: String =
            lines.iter().enumerate().filter(|(i, _)| *i != first_row + 100).map(|(_, l)| format!("{l}\n")).collect();
        let e = References::parse(&short, "s.csv").unwrap_err().to_string();
        assert!(e.starts_with(&format!("s.csv:{}:", first_row + 1)) && e.contains("100 rows at"), "{e}");
        let header = lines[first_row - 1];
        let swapped = format!(
            "{header}\n{}\n{}\n",
            lines[first_row + 101..first_row + 202].join("\n"),
            lines[first_row..first_row + 101].join("\n")
        );
        let e = References::parse(&swapped, "o.csv").unwrap_err().to_string();
        assert!(e.starts_with("o.csv:103:") && e.contains("slowest first"), "{e}");
    }

    /// The comfortable-speed reference (T05 only), which a user can pass with `--reference`.
    const COMFORTABLE: &str = include_str!("../../data/normative/normative_adult_walking.csv");
}
