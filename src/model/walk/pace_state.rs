//! The pace's state (see `pace.rs` and `initiation.rs`, which play it): what the walker is
//! doing, the events reports show, and the schedule, ramp, cadence blend, start and stop a
//! walker carries. Its own file so the walker's struct can hold it without importing the
//! `impl Walker` files back.

use crate::model::body::Side;
use crate::model::schedule::PaceEntry;
use crate::model::walk::leg::Footfall;

/// What the walker is doing, as the lab's status line and the reports say it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum WalkState {
    /// Setting off from standing: the first steps, until the pelvis has joined the walk's path.
    Starting,
    /// Steady or changing pace.
    Walking,
    /// A stop is asked or under way.
    Stopping,
    /// At rest, both feet down.
    Standing,
}

impl WalkState {
    /// Lower-case name, as shown and written.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            WalkState::Starting => "starting",
            WalkState::Walking => "walking",
            WalkState::Stopping => "stopping",
            WalkState::Standing => "standing",
        }
    }
}

/// Something the pace did, for reports: when, and what.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PaceEvent {
    /// Seconds since the start (at the frame in which it happened).
    pub time_s: f64,
    /// What happened.
    pub kind: PaceEventKind,
}

/// The kinds of [`PaceEvent`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum PaceEventKind {
    /// A new speed was asked (m/s).
    SpeedAsked(f64),
    /// The asked speed is now the walk's: the last step of its ramp began (m/s).
    SpeedReached(f64),
    /// A stop was asked.
    StopAsked,
    /// The braking step was planned: the body starts to settle.
    Braking,
    /// The closing step was planned: the trailing foot comes beside the leading one.
    Closing,
    /// The body is at rest.
    Standing,
    /// A start from standing was asked.
    StartAsked,
    /// The first step of a start was planned: the initiating foot leaves the ground.
    FirstStep,
    /// The start is over: the pelvis moves on the walk's own path.
    Walking,
}

impl PaceEventKind {
    /// Short name, as written in tables.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            PaceEventKind::SpeedAsked(_) => "speed_asked",
            PaceEventKind::SpeedReached(_) => "speed_reached",
            PaceEventKind::StopAsked => "stop_asked",
            PaceEventKind::Braking => "braking",
            PaceEventKind::Closing => "closing",
            PaceEventKind::Standing => "standing",
            PaceEventKind::StartAsked => "start_asked",
            PaceEventKind::FirstStep => "first_step",
            PaceEventKind::Walking => "walking",
        }
    }
}

/// Where a stop is.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum StopStage {
    None,
    Asked,
    /// The braking step onto `final_step` is planned.
    Braking {
        final_step: i64,
    },
    /// The closing step beside `final_step` is planned.
    Closing {
        final_step: i64,
    },
    Standing {
        final_step: i64,
    },
}

/// Where a start from standing is.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum StartStage {
    None,
    /// Started: the first step, onto `first` (planned when the start was asked, so the
    /// pelvis's launch could aim at its double support), is still to be planned.
    FirstStep {
        first: Footfall,
        initiator: Side,
    },
    /// The first step is planned; the pelvis is still on its launch (the plan's).
    Launching,
}

/// The kind of step the planner is to plan next.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum StepKind {
    /// The first step from standing: [`super::initiation::FIRST_STEP`] of a steady step.
    Starting,
    Steady,
    Braking,
    Closing,
}

/// The walker's pace: schedule, speed ramp, cadence blend, stop.
#[derive(Clone, Debug)]
pub(crate) struct Pace {
    pub(crate) entries: Vec<PaceEntry>,
    pub(crate) next: usize,
    /// A speed change under way: from, to, steps taken of [`RAMP_STEPS`].
    pub(crate) ramp: Option<(f64, f64, u32)>,
    /// Whether a toe-off has planned its step since the ramp was asked: only then does a heel
    /// strike take a step of it. The step landing is planned at its toe-off with the ramp's
    /// coming pace (its mid-stance offset, drop and pace); a speed asked during the swing and
    /// taken at its heel strike landed a step planned for the old speed (the lab's 1.0 -> 0.8
    /// m/s edit a frame before a heel strike: the pelvis's velocity change per frame 1.81x a
    /// steady walk's).
    pub(crate) ramp_planned: bool,
    /// The cadence blend under way: the phase it began at, the cycle duration (s) and its
    /// slope (s per cycle) it began with; over [`super::pace::CADENCE_BLEND_CYCLES`] the
    /// duration goes to the walk's on a cubic Hermite.
    pub(crate) rate_from: Option<(f64, f64, f64)>,
    pub(crate) stop: StopStage,
    pub(crate) start: StartStage,
    /// A pace change's heel strike (master phase) whose landed leg is to be guarded again
    /// once the cycle curves it will stand under are playing.
    pub(crate) reguard_landing: Option<f64>,
    pub(crate) start_x: f64,
    pub(crate) events: Vec<PaceEvent>,
}

impl Pace {
    /// The pace of a walk with `entries`, its pelvis starting at `start_x`, standing (both
    /// feet held, numbered −1 and 0) or walking.
    pub(crate) fn new(entries: &[PaceEntry], start_x: f64, standing: bool) -> Self {
        Pace {
            entries: entries.to_vec(),
            next: 0,
            ramp: None,
            ramp_planned: false,
            rate_from: None,
            stop: if standing { StopStage::Standing { final_step: -1 } } else { StopStage::None },
            start: StartStage::None,
            reguard_landing: None,
            start_x,
            events: Vec::new(),
        }
    }
}
