//! The steady parts of a walk: which stretches of a recording steady-state figures (cadence,
//! stride, stance, joint ranges, the mean joint curves) may be measured on, and which are
//! transitions, listed but never averaged in.
//!
//! Every frame gets a label, from the walker's state at that frame, the pace events and the
//! gait events ([`super::events`]):
//! - **not walking**: any state but walking — stopping (the step under way when the stop is
//!   asked, then the braking step, then the closing step and the settle, told apart by the
//!   pace events), standing, or any other the walker reports (a standing start's);
//! - **speed change**: from the frame a new speed is asked to the end of the cadence blend
//!   after it was reached (the `SpeedReached` event falls at the heel strike that takes the
//!   ramp's last step, and the cadence then blends over [`CADENCE_BLEND_CYCLES`], two more
//!   steps), so the ramp's steps are never steady;
//! - **start-up**: the first gait cycle, from the start pose to the first right heel strike
//!   (the cycle [`super::CycleSummary`] numbers 0);
//! - **plateau**: the rest — walking at an asked speed already reached.
//!
//! Consecutive frames with the same label and asked speed make a [`Part`]. A walk without a
//! schedule is start-up and then one plateau to its end ([`steady_throughout`]); its
//! steady-state figures stay the whole-walk figures they always were, which leave out the
//! plateau's first whole cycle too (`crate::report::metrics::steady_window`).

use super::{Run, events};
use crate::model::walk::frame::Frame;
use crate::model::walk::pace::{CADENCE_BLEND_CYCLES, PaceEventKind, WalkState};

/// What a stretch of the walk was doing.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PartKind {
    /// Before the walk's first right heel strike; after a start from standing, from the
    /// pelvis joining the walk's path to the heel strike after the second step's.
    StartUp,
    /// Walking steadily at the asked speed.
    Plateau,
    /// A speed change: the ramp's steps and the cadence blend after them.
    SpeedChange,
    /// The braking step of a stop: from its toe-off (the pelvis starts to settle) to the
    /// closing step's.
    Braking,
    /// The closing step of a stop and the settle, to standing.
    Closing,
    /// Not walking (stopping before the braking step, standing, ...), as the walker said.
    NotWalking(WalkState),
}

impl PartKind {
    /// How tables name it.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            PartKind::StartUp => "start-up",
            PartKind::Plateau => "plateau",
            PartKind::SpeedChange => "speed change",
            PartKind::Braking => "braking step",
            PartKind::Closing => "closing step and settle",
            PartKind::NotWalking(state) => state.name(),
        }
    }
}

/// A stretch of consecutive frames with one label.
#[derive(Clone, Debug, PartialEq)]
pub struct Part {
    /// What the walk was doing.
    pub kind: PartKind,
    /// The speed asked for (m/s): the config's, then each new ask's (a speed change's is
    /// the speed it goes to); 0 from a stop on.
    pub asked_mps: f64,
    /// First frame.
    pub first: usize,
    /// One past the last frame.
    pub end: usize,
    /// Frames of the right heel strikes inside: whole gait cycles lie between neighbours.
    pub strikes: Vec<usize>,
    /// Frames of the heel strikes of either leg inside: whole steps lie between neighbours.
    pub steps: Vec<usize>,
}

impl Part {
    /// Whole right gait cycles inside.
    #[must_use]
    pub fn cycles(&self) -> usize {
        self.strikes.len().saturating_sub(1)
    }

    /// Whole steps inside.
    #[must_use]
    pub fn whole_steps(&self) -> usize {
        self.steps.len().saturating_sub(1)
    }

    /// First and last frame's time (s).
    #[must_use]
    pub fn span_s(&self, frames: &[Frame]) -> (f64, f64) {
        (frames[self.first].time_s, frames[self.end - 1].time_s)
    }
}

/// A plateau's figures over its whole steps (heel strike of either leg to heel strike).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct StepFigures {
    /// Pelvis travel over time (m/s).
    pub speed_mps: f64,
    /// Steps a minute.
    pub cadence_spm: f64,
    /// Two steps' pelvis travel (m).
    pub stride_m: f64,
    /// Frames of either leg in stance over frames of both legs (%).
    pub stance_pct: f64,
    /// First and last step's heel strike (s).
    pub span_s: (f64, f64),
}

/// The part's figures over its whole steps; `None` with fewer than one.
#[must_use]
pub fn step_figures(frames: &[Frame], part: &Part) -> Option<StepFigures> {
    let (&a, &b) = (part.steps.first()?, part.steps.last()?);
    if part.whole_steps() == 0 || frames[b].time_s <= frames[a].time_s {
        return None;
    }
    let (fa, fb) = (&frames[a], &frames[b]);
    let (travel, time, steps) = (fb.pelvis.x - fa.pelvis.x, fb.time_s - fa.time_s, part.whole_steps() as f64);
    let legs = frames[a..b].iter().flat_map(|f| f.legs.iter());
    let stance = legs.clone().filter(|l| l.leg_phase.is_stance()).count() as f64 / legs.count() as f64;
    Some(StepFigures {
        speed_mps: travel / time,
        cadence_spm: 60.0 * steps / time,
        stride_m: 2.0 * travel / steps,
        stance_pct: 100.0 * stance,
        span_s: (fa.time_s, fb.time_s),
    })
}

/// The parts of `run`, in time order.
#[must_use]
pub fn parts(run: &Run) -> Vec<Part> {
    let right = events::heel_strikes(&run.frames, 0);
    let steps = events::steps(&run.frames);
    let mut parts: Vec<Part> = Vec::new();
    for (i, (kind, asked_mps)) in frame_labels(run, &right, &steps).into_iter().enumerate() {
        match parts.last_mut() {
            Some(p) if p.kind == kind && p.asked_mps.to_bits() == asked_mps.to_bits() => p.end = i + 1,
            _ => parts.push(Part { kind, asked_mps, first: i, end: i + 1, strikes: Vec::new(), steps: Vec::new() }),
        }
    }
    let inside = |p: &Part, list: &[usize]| list.iter().copied().filter(|s| (p.first..p.end).contains(s)).collect();
    for p in &mut parts {
        p.strikes = inside(p, &right);
        p.steps = inside(p, &steps);
    }
    parts
}

/// The plateau steady-state figures are measured on: the one with the most whole gait
/// cycles (the later on a tie: the pace the walk settled to), `None` when no plateau holds
/// one. The longest, not the last: the more cycles a mean is taken over, the less one
/// step's planning shows in it, and a schedule's last plateau is often the short one
/// before a stop.
#[must_use]
pub fn measured_plateau(parts: &[Part]) -> Option<&Part> {
    parts.iter().filter(|p| p.kind == PartKind::Plateau && p.cycles() > 0).max_by_key(|p| p.cycles())
}

/// Whether the walk was steady throughout: start-up, then one plateau to the end.
#[must_use]
pub fn steady_throughout(parts: &[Part]) -> bool {
    parts.iter().filter(|p| p.kind != PartKind::StartUp).count() <= 1
        && parts.iter().all(|p| matches!(p.kind, PartKind::StartUp | PartKind::Plateau))
}

/// The speed asked of a walk as its pace events go by: the config's (none while a walk that
/// begins standing waits for its start), each new ask's, none from a stop on, and the last
/// asked again from a start. One rule for the steady parts and the speed plot.
pub(crate) struct AskedSpeed {
    /// Asked now (m/s).
    pub(crate) now: f64,
    /// What a start sets off at: the last speed asked of the walk.
    walk: f64,
}

impl AskedSpeed {
    /// Before the first event of `run`.
    pub(crate) fn new(run: &Run) -> Self {
        let walk = run.start_speed_mps;
        AskedSpeed { now: if run.states.first() == Some(&WalkState::Standing) { 0.0 } else { walk }, walk }
    }

    /// Takes an event; `Some` new asked speed when it asks one.
    pub(crate) fn take(&mut self, kind: PaceEventKind) -> Option<f64> {
        self.now = match kind {
            PaceEventKind::SpeedAsked(v) => {
                self.walk = v;
                v
            }
            PaceEventKind::StopAsked => 0.0,
            PaceEventKind::StartAsked => self.walk,
            _ => return None,
        };
        Some(self.now)
    }
}

/// Each frame's label and asked speed. A pace event is stamped with the time of the frame
/// the walker advanced from: it shows from the next frame on.
fn frame_labels(run: &Run, right: &[usize], steps: &[usize]) -> Vec<(PartKind, f64)> {
    let frames = &run.frames;
    let start_up_end = right.first().copied().unwrap_or(frames.len());
    let mut events = run.pace_events.iter().peekable();
    let mut asked = AskedSpeed::new(run);
    // A start from standing's start-up runs to this frame (exclusive).
    let mut started_until = 0;
    // A speed change runs to this frame (exclusive); `usize::MAX` until its speed is reached.
    let mut change_until = 0;
    let mut stop_stage = None;
    let mut labels = Vec::with_capacity(frames.len());
    let blend_steps = ((2.0 * CADENCE_BLEND_CYCLES).ceil() as usize).max(1);
    for (i, f) in frames.iter().enumerate() {
        while let Some(e) = events.next_if(|e| e.time_s < f.time_s - 1e-9) {
            asked.take(e.kind);
            match e.kind {
                PaceEventKind::SpeedAsked(_) => change_until = usize::MAX,
                // The reaching heel strike is frame `i`; steady from the heel strike that
                // ends the cadence blend it started.
                PaceEventKind::SpeedReached(_) => {
                    change_until =
                        steps.iter().copied().filter(|&s| s > i).nth(blend_steps - 1).unwrap_or(frames.len());
                }
                PaceEventKind::Braking => stop_stage = Some(PartKind::Braking),
                PaceEventKind::Closing => stop_stage = Some(PartKind::Closing),
                PaceEventKind::StartAsked => stop_stage = None,
                // The pelvis is on the walk's path from frame `i`; the second step lands at the
                // next heel strike, and the walk is steady from the one after.
                PaceEventKind::Walking => {
                    started_until = steps.iter().copied().filter(|&s| s > i).nth(1).unwrap_or(frames.len());
                }
                // Standing (and any event a later walk adds): the walker's state says it.
                _ => {}
            }
        }
        let kind = match (run.states.get(i), stop_stage) {
            (Some(WalkState::Stopping), Some(stage)) => stage,
            (Some(&state), _) if state != WalkState::Walking => PartKind::NotWalking(state),
            _ if i < change_until => PartKind::SpeedChange,
            _ if i < start_up_end || i < started_until => PartKind::StartUp,
            _ => PartKind::Plateau,
        };
        labels.push((kind, asked.now));
    }
    labels
}

/// Where a walk on stairs or a slope is measured: "on the stairs", "on the slope"; `None` on
/// level or rough ground (and on a slope of grade 0).
#[must_use]
pub fn terrain_feature(run: &Run) -> Option<&'static str> {
    use crate::model::terrain::TerrainKind;
    match *run.terrain.kind() {
        TerrainKind::Stairs { .. } => Some("on the stairs"),
        TerrainKind::Slope { grade_pct, .. } if grade_pct != 0.0 => Some("on the slope"),
        _ => None,
    }
}

/// Of the right heel strikes `strikes` (in order), the longest run of whole cycles walked on
/// the walk's stairs or slope, as (first, last) indices into `strikes` and the feature's name:
/// cycles whose heel strikes, both feet's, all land on the flight's treads (or on the slope),
/// none on the level before or after it. `None` on level or rough ground, or where no whole
/// cycle is on the feature. A stairs walk's level approach and landing averaged in had its mean
/// cycle mix three kinds of step (configs/stairs_up.toml: 3 cycles on the stairs, 2 onto and off
/// them, 4 level). Told by where the feet land, not by how far a cycle climbs, so that treads
/// longer than a step or a flight too short for a cycle are read for what they are.
#[must_use]
pub fn on_terrain_feature(run: &Run, strikes: &[usize]) -> Option<(usize, usize, &'static str)> {
    use crate::model::terrain::TerrainKind;
    let name = terrain_feature(run)?;
    // Where the feature lies along x: the flight's treads, or the slope onward.
    let (from_x, to_x) = match *run.terrain.kind() {
        TerrainKind::Stairs { run_m, count, start_x_m, .. } => (start_x_m, start_x_m + f64::from(count) * run_m),
        TerrainKind::Slope { start_x_m, .. } => (start_x_m, f64::INFINITY),
        _ => return None,
    };
    let left = events::heel_strikes(&run.frames, 1);
    let lands_on = |frame: usize, side: usize| (from_x..to_x).contains(&run.frames[frame].legs[side].heel.x);
    let on = |k: usize| {
        let (from, to) = (strikes[k], strikes[k + 1]);
        lands_on(from, 0) && lands_on(to, 0) && left.iter().filter(|&&s| s > from && s < to).all(|&s| lands_on(s, 1))
    };
    // The longest run of cycles on it; one step past the last cycle closes an open run.
    let cycles = strikes.len().saturating_sub(1);
    let (mut best, mut start) = (None::<(usize, usize)>, None);
    for k in 0..=cycles {
        match (k < cycles && on(k), start) {
            (true, None) => start = Some(k),
            (false, Some(a)) => {
                start = None;
                if best.is_none_or(|(b0, b1)| k - a > b1 - b0) {
                    best = Some((a, k));
                }
            }
            _ => {}
        }
    }
    best.map(|(a, b)| (a, b, name))
}
