//! A walk's pace schedule (`[[walk.schedule]]`): at given times or distances, a new speed
//! or a stop. The config reads it; the walker ([`crate::model::walk`]) plays it step by step.

/// When a schedule entry takes effect.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum PaceTrigger {
    /// Seconds since the walk began.
    TimeS(f64),
    /// Metres the pelvis has travelled forward since the walk began.
    DistanceM(f64),
}

/// What a schedule entry asks for.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum PaceAction {
    /// Walk at this speed (m/s), reached over the next two steps.
    Speed(f64),
    /// Finish the walk: a braking step, then the trailing foot closes beside the leading one
    /// and the body settles to standing.
    Stop,
    /// Set off from standing: the first entry of a walk that begins standing, or one after a
    /// stop.
    Start,
}

/// One `[[walk.schedule]]` entry.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PaceEntry {
    /// When.
    pub trigger: PaceTrigger,
    /// What.
    pub action: PaceAction,
}

impl PaceTrigger {
    /// Whether the trigger has been reached at `time_s` seconds and `distance_m` metres.
    #[must_use]
    pub fn reached(self, time_s: f64, distance_m: f64) -> bool {
        match self {
            PaceTrigger::TimeS(t) => time_s >= t,
            PaceTrigger::DistanceM(d) => distance_m >= d,
        }
    }
}
