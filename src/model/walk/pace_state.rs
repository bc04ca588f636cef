//! The pace's state (see `pace.rs`, which plays it): what the walker is doing, the events
//! reports show, and the schedule, ramp, cadence blend and stop a walker carries. Its own
//! file so the walker's struct can hold it without importing the `impl Walker` file back.

use crate::model::schedule::PaceEntry;

/// What the walker is doing, as the lab's status line and the reports say it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum WalkState {
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

/// The kind of step the planner is to plan next.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum StepKind {
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
    /// The cadence blend under way: the phase it began at, the cycle duration (s) and its
    /// slope (s per cycle) it began with; over [`super::pace::CADENCE_BLEND_CYCLES`] the
    /// duration goes to the walk's on a cubic Hermite.
    pub(crate) rate_from: Option<(f64, f64, f64)>,
    pub(crate) stop: StopStage,
    pub(crate) start_x: f64,
    pub(crate) events: Vec<PaceEvent>,
}

impl Pace {
    /// The pace of a walk with `entries`, its pelvis starting at `start_x`.
    pub(crate) fn new(entries: &[PaceEntry], start_x: f64) -> Self {
        Pace {
            entries: entries.to_vec(),
            next: 0,
            ramp: None,
            rate_from: None,
            stop: StopStage::None,
            start_x,
            events: Vec::new(),
        }
    }
}
