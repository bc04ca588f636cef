//! Where a frame's time goes (thesis table 6.1): an optional lap timer the walker reports its
//! parts to. Without one (every walk but `gaitlab figures`' measurement) each lap point is a
//! test of an empty `Option`, so the normal walk pays nothing measurable.
//!
//! The timer is a chain of laps: each lap charges the time since the previous one to the part
//! that just ran, so the parts tile the frame exactly and their sum is the instrumented
//! frame. The model keeps no clock of its own: the caller hands the timer its `now`.

use std::time::{Duration, Instant};

/// The parts of a frame, each a row of table 6.1.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum FramePart {
    /// Evaluating the pelvis trajectory and the arm curves at the frame's phase.
    Curves,
    /// The legs' targets: the phase rules and the swing curves giving ankle, heel and foot.
    LegTargets,
    /// Solving each leg's IK toward its target and setting its foot.
    LegIk,
    /// The pelvis choice at each toe-off (the optimiser's search).
    PelvisChoice,
    /// The rest of each toe-off's planning: footfall, pelvis keys, reach guards, the swing
    /// curves adapted and simulated.
    SwingPlanning,
    /// The spine's frontal compensation (Regula Falsi for the trunk bend).
    Spine,
    /// Arms and trunk rotations.
    Arms,
    /// The skeleton's pose by forward kinematics.
    Pose,
    /// The frame's numbers read back from the pose (the joint table's row).
    Frame,
    /// The clock: phase boundaries, pelvis keys passed, live curves.
    Bookkeeping,
}

impl FramePart {
    /// Every part, in table order.
    pub const ALL: [FramePart; 10] = [
        FramePart::Curves,
        FramePart::LegTargets,
        FramePart::LegIk,
        FramePart::PelvisChoice,
        FramePart::SwingPlanning,
        FramePart::Spine,
        FramePart::Arms,
        FramePart::Pose,
        FramePart::Frame,
        FramePart::Bookkeeping,
    ];
}

/// Time charged to each part, and the laps that charged it.
#[derive(Clone, Debug)]
pub struct FrameTimer {
    now: fn() -> Instant,
    last: Instant,
    totals: [Duration; FramePart::ALL.len()],
    laps: [u64; FramePart::ALL.len()],
}

impl FrameTimer {
    /// A timer reading `now`, started at once.
    #[must_use]
    pub fn new(now: fn() -> Instant) -> Self {
        FrameTimer { now, last: now(), totals: [Duration::ZERO; 10], laps: [0; 10] }
    }

    /// Charges the time since the last lap (or the start) to `part`.
    pub fn lap(&mut self, part: FramePart) {
        let t = (self.now)();
        self.totals[part as usize] += t - self.last;
        self.laps[part as usize] += 1;
        self.last = t;
    }

    /// Restarts the chain without charging anyone: time between here and the previous lap
    /// (the caller's own work) is left out.
    pub fn restart(&mut self) {
        self.last = (self.now)();
    }

    /// Time charged to `part` so far.
    #[must_use]
    pub fn total(&self, part: FramePart) -> Duration {
        self.totals[part as usize]
    }

    /// Laps that charged `part`.
    #[must_use]
    pub fn laps(&self, part: FramePart) -> u64 {
        self.laps[part as usize]
    }

    /// Time charged to each part so far, in [`FramePart::ALL`] order (s).
    #[must_use]
    pub fn totals_s(&self) -> [f64; FramePart::ALL.len()] {
        self.totals.map(|d| d.as_secs_f64())
    }
}
