//! Gait metrics of a simulated walk, computed from its frames (never from the parameters).
//!
//! Definitions, as `summary.json` reports them:
//! - **steady state**: from the second right heel strike (the first cycle is start-up) to the
//!   last right heel strike of the run; every figure except the health checks is taken over
//!   these complete cycles. A walk whose pace changed or that stopped (`[[walk.schedule]]`)
//!   is measured on one plateau only, its whole cycles: the plateau with the most of them
//!   ([`steady_window`], [`crate::analysis::steady`]); speed changes, the stop and standing
//!   are never averaged in. There stride and step width come from the heels at the
//!   plateau's heel strikes.
//! - **speed**: pelvis travel over the steady window divided by its duration.
//! - **cycle, cadence**: mean right heel strike to right heel strike time; cadence = 120/cycle.
//! - **stride length**: mean forward distance between consecutive right heel strikes'
//!   footfalls (heel positions); **step width**: mean lateral distance between consecutive
//!   footfalls of opposite feet.
//! - **stance %**: frames in which a leg is in loading response, midstance or heel rise, over
//!   all frames, averaged over both legs; **double support %**: frames with both feet down.
//! - **ranges** (pelvis, shoulder, elbow): max − min within each steady cycle, averaged over
//!   the cycles (on stairs or slopes a range over the whole walk would measure the climb);
//!   the pelvis's vertical range is taken after removing the straight line from the cycle's
//!   first to its last frame, so on a climb it is the bob, not the height gained.
//! - **peaks** (hip, knee, ankle): extremes over all steady frames of both legs; knee stance
//!   and swing peaks are split by the leg's phase. Extension and plantarflexion are reported
//!   as positive numbers.
//! - **clearance**: toe tip (or heel) height above the ground directly below it; the
//!   minimum toe clearance is the lowest point of mid-swing (swing phase 0.7–0.9 of the
//!   cycle, where the foot passes the stance foot), so the toe leaving and touching the
//!   ground does not count; the maximum heel clearance is the highest over the whole swing.
//!   Over uneven ground "below" follows the terrain under each point at that frame.
//! - **foot skate, penetration, reach failures, non-finite values**: the walk model's health
//!   checks ([`crate::analysis::checks`]) over every frame, start-up included.
//! - **optimiser**: steps decided in the steady window (their toe-off after its first frame and
//!   by its last), the mean chosen cost, and the steps
//!   where no candidate was feasible; `optimiser_fixed_rule_mean_cost` gives the fixed rule's
//!   cost on the same steps for comparison.

use crate::analysis::{self, Run};
use crate::model::body::Side;
use crate::model::walk::frame::{Frame, LegFrame, Support};
use crate::model::walk::leg::LegPhase;
use serde::Serialize;

/// The figures of `summary.json`, in the interface's order.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[allow(missing_docs)]
pub struct Summary {
    pub speed_mps: f64,
    pub cadence_spm: f64,
    pub stride_length_m: f64,
    pub step_width_m: f64,
    pub cycle_s: f64,
    pub stance_pct: f64,
    pub double_support_pct: f64,
    pub pelvis_vertical_range_cm: f64,
    pub pelvis_lateral_range_cm: f64,
    pub pelvis_tilt_range_deg: f64,
    pub pelvis_obliquity_range_deg: f64,
    pub pelvis_rotation_range_deg: f64,
    pub hip_flex_max_deg: f64,
    pub hip_ext_max_deg: f64,
    pub knee_flex_max_stance_deg: f64,
    pub knee_flex_max_swing_deg: f64,
    pub ankle_dorsi_max_deg: f64,
    pub ankle_plantar_max_deg: f64,
    pub shoulder_flex_range_deg: f64,
    pub elbow_flex_range_deg: f64,
    pub min_toe_clearance_cm: f64,
    pub max_heel_clearance_cm: f64,
    pub foot_skate_mm: f64,
    pub terrain_penetration_mm: f64,
    pub reach_failures: u64,
    pub non_finite_values: u64,
    pub optimiser_steps: u64,
    pub optimiser_mean_cost: f64,
    pub optimiser_infeasible_steps: u64,
    pub optimiser_fixed_rule_mean_cost: f64,
}

/// Units and labels for `summary.md`, in the same order as the fields.
pub const LABELS: &[(&str, &str, &str)] = &[
    ("speed_mps", "m/s", "walking speed"),
    ("cadence_spm", "steps/min", "cadence"),
    ("stride_length_m", "m", "stride length"),
    ("step_width_m", "m", "step width"),
    ("cycle_s", "s", "gait cycle"),
    ("stance_pct", "%", "stance"),
    ("double_support_pct", "%", "double support"),
    ("pelvis_vertical_range_cm", "cm", "pelvis vertical range"),
    ("pelvis_lateral_range_cm", "cm", "pelvis lateral range"),
    ("pelvis_tilt_range_deg", "deg", "pelvic tilt range"),
    ("pelvis_obliquity_range_deg", "deg", "pelvic obliquity range"),
    ("pelvis_rotation_range_deg", "deg", "pelvic rotation range"),
    ("hip_flex_max_deg", "deg", "peak hip flexion"),
    ("hip_ext_max_deg", "deg", "peak hip extension"),
    ("knee_flex_max_stance_deg", "deg", "peak knee flexion in stance (at toe-off, where pre-swing ends)"),
    ("knee_flex_max_swing_deg", "deg", "peak knee flexion in swing"),
    ("ankle_dorsi_max_deg", "deg", "peak ankle dorsiflexion"),
    ("ankle_plantar_max_deg", "deg", "peak ankle plantarflexion"),
    ("shoulder_flex_range_deg", "deg", "shoulder flexion range"),
    ("elbow_flex_range_deg", "deg", "elbow flexion range"),
    ("min_toe_clearance_cm", "cm", "minimum toe clearance (mid-swing)"),
    ("max_heel_clearance_cm", "cm", "maximum heel clearance (swing)"),
    ("foot_skate_mm", "mm", "foot skate (largest stance slide)"),
    ("terrain_penetration_mm", "mm", "terrain penetration (deepest)"),
    ("reach_failures", "", "IK reach failures"),
    ("non_finite_values", "", "non-finite values"),
    ("optimiser_steps", "", "optimiser steps (planned in the measured cycles; optimisation.csv has every step)"),
    ("optimiser_mean_cost", "", "optimiser mean cost (chosen)"),
    ("optimiser_infeasible_steps", "", "steps without a feasible candidate"),
    ("optimiser_fixed_rule_mean_cost", "", "fixed rule's mean cost, same steps"),
];

/// Why a run cannot be summarised.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct TooShort(pub String);

impl std::fmt::Display for TooShort {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for TooShort {}

fn mean(values: impl IntoIterator<Item = f64>) -> f64 {
    let (sum, n) = values.into_iter().fold((0.0, 0usize), |(s, n), v| (s + v, n + 1));
    if n == 0 { 0.0 } else { sum / n as f64 }
}

fn span(values: impl Iterator<Item = f64>) -> f64 {
    let (lo, hi) = values.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| (lo.min(v), hi.max(v)));
    if lo.is_finite() { hi - lo } else { 0.0 }
}

/// Range of a value over a cycle after removing the straight line from its first to its
/// last frame: on stairs and slopes the pelvis's bob, not the climb.
fn detrended_span(cycle: &[Frame], value: impl Fn(&Frame) -> f64) -> f64 {
    let (first, last) = (&cycle[0], &cycle[cycle.len() - 1]);
    let (t0, t1) = (first.time_s, last.time_s.max(first.time_s + 1e-9));
    let (v0, v1) = (value(first), value(last));
    span(cycle.iter().map(|f| value(f) - (v0 + (v1 - v0) * (f.time_s - t0) / (t1 - t0))))
}

/// Where the steady-state figures are measured: frames `first` to `last`, right heel strike
/// to right heel strike.
#[derive(Clone, Debug, PartialEq)]
pub struct SteadyWindow {
    /// The first measured cycle's heel strike (frame).
    pub first: usize,
    /// The last measured cycle's closing heel strike (frame).
    pub last: usize,
    /// Every right heel strike from `first` to `last`: the whole cycles lie between neighbours.
    pub strikes: Vec<usize>,
    /// The plateau measured, for a walk that was not steady throughout (a pace schedule
    /// changed its speed or stopped it); `None`: every cycle after start-up.
    pub plateau: Option<SteadyPlateau>,
    /// The cycles on the walk's stairs or slope, where it has whole ones there
    /// ([`analysis::steady::on_terrain_feature`]): the level walking before and after is left
    /// out; `None` on level or rough ground.
    pub terrain: Option<TerrainPart>,
    /// Where a walk on stairs or a slope would have been measured when no whole cycle lies
    /// there (a flight of one or two treads, a short walk): every cycle is, and the outputs say
    /// so.
    pub terrain_missed: Option<&'static str>,
}

impl SteadyWindow {
    /// The window is a part of the walk (a plateau, or the cycles on the stairs or slope), not
    /// every cycle after start-up.
    #[must_use]
    pub fn is_part(&self) -> bool {
        self.plateau.is_some() || self.terrain.is_some()
    }

    /// The part measured, as the outputs name it; `None` for every cycle after start-up on level
    /// ground (on stairs or a slope with no whole cycle there, a sentence saying so).
    #[must_use]
    pub fn describe(&self) -> Option<String> {
        match (self.plateau, self.terrain) {
            (Some(p), None) => Some(p.describe()),
            (None, Some(t)) => Some(t.describe()),
            (Some(p), Some(t)) => Some(format!("{}, of {}", t.describe(), p.describe())),
            (None, None) => self
                .terrain_missed
                .map(|on| format!("every cycle after start-up: none lies whole {on}, so level cycles are averaged in")),
        }
    }
}

/// The cycles of a walk on its stairs or slope.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TerrainPart {
    /// Its first measured heel strike (s).
    pub from_s: f64,
    /// Its last measured heel strike (s).
    pub to_s: f64,
    /// Whole gait cycles measured.
    pub cycles: usize,
    /// Where: "on the stairs", "on the slope".
    pub on: &'static str,
    /// Cycles walked on the level before or after were left out.
    pub left_out: bool,
}

impl TerrainPart {
    /// As the outputs name it: "4.08–8.17 s, 3 cycles on the stairs (level walking left
    /// out)".
    #[must_use]
    pub fn describe(&self) -> String {
        let plural = if self.cycles == 1 { "" } else { "s" };
        let left_out = if self.left_out { " (level walking left out)" } else { "" };
        format!("{:.2}–{:.2} s, {} cycle{plural} {}{left_out}", self.from_s, self.to_s, self.cycles, self.on)
    }
}

/// The plateau a walk's steady-state figures were measured on ([`analysis::steady`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SteadyPlateau {
    /// The speed asked for on it (m/s).
    pub asked_mps: f64,
    /// Its first measured heel strike (s).
    pub from_s: f64,
    /// Its last measured heel strike (s).
    pub to_s: f64,
    /// Whole gait cycles measured.
    pub cycles: usize,
}

impl SteadyPlateau {
    /// As the outputs name it: "6.42–8.37 s, the 1.60 m/s plateau, 2 cycles".
    #[must_use]
    pub fn describe(&self) -> String {
        let plural = if self.cycles == 1 { "" } else { "s" };
        format!(
            "{:.2}–{:.2} s, the {:.2} m/s plateau, {} cycle{plural}",
            self.from_s, self.to_s, self.asked_mps, self.cycles
        )
    }
}

/// The steady window of a run: a walk steady throughout is measured from its second to its
/// last right heel strike (the first cycle is start-up, and the first whole one is left out
/// too, as the figures always have); a walk whose pace changed or that stopped, over the
/// whole cycles of its plateau with the most of them
/// ([`analysis::steady::measured_plateau`]): speed changes, stopping and standing are never
/// averaged in.
pub fn steady_window(run: &Run) -> Result<SteadyWindow, TooShort> {
    let parts = analysis::steady::parts(run);
    let throughout = analysis::steady::steady_throughout(&parts);
    let plateau = analysis::steady::measured_plateau(&parts).ok_or_else(|| too_short(run, &parts))?;
    let strikes = if throughout { &plateau.strikes[1..] } else { &plateau.strikes[..] };
    if strikes.len() < 2 {
        return Err(too_short(run, &parts));
    }
    let described = SteadyPlateau {
        asked_mps: plateau.asked_mps,
        from_s: run.frames[strikes[0]].time_s,
        to_s: run.frames[strikes[strikes.len() - 1]].time_s,
        cycles: strikes.len() - 1,
    };
    let feature = analysis::steady::on_terrain_feature(run, strikes);
    let (part, terrain) = match feature {
        Some((a, b, on)) => {
            let part = &strikes[a..=b];
            let t = |k: usize| run.frames[part[k]].time_s;
            let left_out = part.len() < strikes.len();
            let cycles = part.len() - 1;
            (part, Some(TerrainPart { from_s: t(0), to_s: t(part.len() - 1), cycles, on, left_out }))
        }
        None => (strikes, None),
    };
    let terrain_missed = if terrain.is_none() { analysis::steady::terrain_feature(run) } else { None };
    let (first, last) = (part[0], part[part.len() - 1]);
    let plateau = (!throughout).then_some(described);
    Ok(SteadyWindow { first, last, strikes: part.to_vec(), plateau, terrain, terrain_missed })
}

fn too_short(run: &Run, parts: &[analysis::steady::Part]) -> TooShort {
    if analysis::steady::steady_throughout(parts) {
        let strikes = crate::analysis::events::heel_strikes(&run.frames, 0).len();
        return TooShort(format!(
            "the walk needs at least 3 right heel strikes to measure a steady cycle; this run has {strikes} (simulate more cycles)"
        ));
    }
    let longest = parts
        .iter()
        .filter(|p| p.kind == analysis::steady::PartKind::Plateau)
        .map(|p| p.span_s(&run.frames))
        .max_by(|a, b| (a.1 - a.0).total_cmp(&(b.1 - b.0)));
    TooShort(format!(
        "no steady plateau of the walk's pace holds a whole gait cycle (the longest: {}); lengthen a plateau of \
         `[[walk.schedule]]` or simulate more cycles",
        longest.map_or_else(|| "none".into(), |(a, b)| format!("{a:.2}–{b:.2} s"))
    ))
}

/// Measures `run` over its steady window ([`steady_window`]).
pub fn summarise(run: &Run) -> Result<Summary, TooShort> {
    Ok(summarise_window(run, &steady_window(run)?))
}

/// Measures `run` over `window`.
#[must_use]
pub fn summarise_window(run: &Run, window: &SteadyWindow) -> Summary {
    let frames = &run.frames;
    let (first, last, strikes) = (window.first, window.last, &window.strikes);
    let steady = &frames[first..last];
    let cycles: Vec<&[Frame]> = strikes.windows(2).map(|w| &frames[w[0]..w[1]]).collect();
    let t0 = frames[first].time_s;
    let t1 = frames[last].time_s;
    let cycle_s = mean(strikes.windows(2).map(|w| frames[w[1]].time_s - frames[w[0]].time_s));
    let per_cycle = |f: &dyn Fn(&Frame) -> f64| mean(cycles.iter().map(|c| span(c.iter().map(f))));
    let both =
        |f: &dyn Fn(&LegFrame) -> f64| -> Vec<f64> { steady.iter().flat_map(|fr| fr.legs.iter().map(f)).collect() };
    let hip = both(&|l| l.hip_flex_deg);
    let ankle = both(&|l| l.ankle_dorsi_deg);
    let knee_in = |stance: bool| {
        steady
            .iter()
            .flat_map(|fr| fr.legs.iter())
            .filter(|l| l.leg_phase.is_stance() == stance)
            .map(|l| l.knee_flex_deg)
            .fold(0.0, f64::max)
    };
    let (min_toe, max_heel) = swing_clearances(steady);
    let (stride, width) =
        if window.is_part() { strike_spacing(frames, window) } else { footfall_spacing(run, frames[last].pelvis.x) };
    let checks = analysis::checks(frames);
    // Steps decided inside the steady window: each plan is made at a toe-off, in order (a
    // walk whose pace changed has no one cycle duration to turn a plan's phase into time).
    let toe_offs = crate::analysis::events::toe_offs(frames);
    let steps: Vec<_> =
        run.step_plans.iter().zip(toe_offs).filter(|&(_, j)| j > first && j <= last).map(|(p, _)| p).collect();
    let chosen: Vec<f64> = steps.iter().filter_map(|p| p.optimisation.chosen.cost).collect();
    let fixed: Vec<f64> = steps.iter().filter_map(|p| p.optimisation.fixed_rule.cost).collect();
    Summary {
        speed_mps: (frames[last].pelvis.x - frames[first].pelvis.x) / (t1 - t0),
        cadence_spm: 120.0 / cycle_s,
        stride_length_m: stride,
        step_width_m: width,
        cycle_s,
        stance_pct: 100.0
            * steady.iter().flat_map(|fr| fr.legs.iter()).filter(|l| l.leg_phase.is_stance()).count() as f64
            / (2 * steady.len()) as f64,
        double_support_pct: 100.0 * steady.iter().filter(|fr| fr.support == Support::Double).count() as f64
            / steady.len() as f64,
        pelvis_vertical_range_cm: 100.0 * mean(cycles.iter().map(|c| detrended_span(c, |f| f.pelvis.y))),
        pelvis_lateral_range_cm: 100.0 * per_cycle(&|f| f.pelvis.z),
        pelvis_tilt_range_deg: per_cycle(&|f| f.pelvis_tilt_deg),
        pelvis_obliquity_range_deg: per_cycle(&|f| f.pelvis_obliquity_deg),
        pelvis_rotation_range_deg: per_cycle(&|f| f.pelvis_rotation_deg),
        hip_flex_max_deg: hip.iter().copied().fold(f64::NEG_INFINITY, f64::max),
        hip_ext_max_deg: -hip.iter().copied().fold(f64::INFINITY, f64::min),
        knee_flex_max_stance_deg: knee_in(true),
        knee_flex_max_swing_deg: knee_in(false),
        ankle_dorsi_max_deg: ankle.iter().copied().fold(f64::NEG_INFINITY, f64::max),
        ankle_plantar_max_deg: -ankle.iter().copied().fold(f64::INFINITY, f64::min),
        shoulder_flex_range_deg: 0.5
            * (per_cycle(&|f| f.legs[0].shoulder_flex_deg) + per_cycle(&|f| f.legs[1].shoulder_flex_deg)),
        elbow_flex_range_deg: 0.5
            * (per_cycle(&|f| f.legs[0].elbow_flex_deg) + per_cycle(&|f| f.legs[1].elbow_flex_deg)),
        min_toe_clearance_cm: if min_toe.is_finite() { min_toe } else { 0.0 },
        max_heel_clearance_cm: if max_heel.is_finite() { max_heel } else { 0.0 },
        foot_skate_mm: checks.foot_skate_mm,
        terrain_penetration_mm: checks.terrain_penetration_mm,
        reach_failures: checks.reach_failures,
        non_finite_values: checks.non_finite_values,
        optimiser_steps: steps.len() as u64,
        optimiser_mean_cost: mean(chosen),
        optimiser_infeasible_steps: steps.iter().filter(|p| p.optimisation.fallback).count() as u64,
        optimiser_fixed_rule_mean_cost: mean(fixed),
    }
}

/// The swing foot's lowest toe clearance in mid-swing and highest heel clearance over the
/// whole swing (cm) in `steady`, infinite when no leg swings there. Mid-swing only for the
/// toe: leaving and meeting the ground, it is at zero by design.
fn swing_clearances(steady: &[Frame]) -> (f64, f64) {
    let swing = |l: &&LegFrame| l.leg_phase == LegPhase::Swing;
    let min_toe = steady
        .iter()
        .flat_map(|fr| fr.legs.iter())
        .filter(swing)
        .filter(|l| (0.7..=0.9).contains(&l.phase))
        .map(|l| (l.toe.y - l.ground_under_toe) * 100.0)
        .fold(f64::INFINITY, f64::min);
    let max_heel = steady
        .iter()
        .flat_map(|fr| fr.legs.iter())
        .filter(swing)
        .map(|l| (l.heel.y - l.ground_under_heel) * 100.0)
        .fold(f64::NEG_INFINITY, f64::max);
    (min_toe, max_heel)
}

/// Stride length and step width (m) on a plateau, from the heels at its heel strikes: the
/// right heel's travel from strike to strike, and the sideways distance between the heels
/// of consecutive strikes of opposite feet. (The footfalls a planned walk lists carry no
/// time, and a plateau between pace changes is too short to leave any out as start-up.)
fn strike_spacing(frames: &[Frame], window: &SteadyWindow) -> (f64, f64) {
    let stride = mean(window.strikes.windows(2).map(|w| frames[w[1]].legs[0].heel.x - frames[w[0]].legs[0].heel.x));
    let struck: Vec<(usize, f64)> = crate::analysis::events::steps(frames)
        .into_iter()
        .filter(|s| (window.first..=window.last).contains(s))
        .map(|s| {
            let side = usize::from(!crate::analysis::events::is_heel_strike(&frames[s - 1], &frames[s], 0));
            (side, frames[s].legs[side].heel.z)
        })
        .collect();
    let width = mean(struck.windows(2).filter(|w| w[0].0 != w[1].0).map(|w| (w[1].1 - w[0].1).abs()));
    (stride, width)
}

/// Stride length and step width (m) from the footfalls landed in the steady window: past
/// start-up's first two steps, and not the one still being swung to when the pelvis is at
/// `end_x`.
fn footfall_spacing(run: &Run, end_x: f64) -> (f64, f64) {
    let landed: Vec<_> = run.footfalls.iter().filter(|f| f.step >= 2 && f.heel.x <= end_x).collect();
    let right: Vec<f64> = landed.iter().filter(|f| f.side == Side::Right).map(|f| f.heel.x).collect();
    let stride = mean(right.windows(2).map(|w| w[1] - w[0]));
    let width = mean(landed.windows(2).filter(|w| w[0].side != w[1].side).map(|w| (w[1].heel.z - w[0].heel.z).abs()));
    (stride, width)
}
