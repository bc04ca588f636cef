//! When the lab's walk takes its next frame, and the frame rate the status line shows.
//!
//! Frames fall due on a fixed grid at the `--fps` cap. Timed from the moment each frame was
//! taken instead, every frame came a wake-up's lateness after the last (about a millisecond),
//! and the lab at `--fps 60` ran at 57. The walk still advances by the time that really
//! passed, so its speed does not depend on the grid.

use std::time::{Duration, Instant};

/// The lab's frame schedule and its measured rate.
#[derive(Debug)]
pub(super) struct FrameClock {
    interval: Duration,
    /// When the next frame is due.
    next_due: Instant,
    /// When the walk last advanced (or was paused).
    last_tick: Instant,
    /// Frames drawn that showed a newer walk since `counted_from`.
    frames: u32,
    counted_from: Instant,
    /// The walk advanced and the next draw shows it.
    walked: bool,
    /// Paused: the first frame due after it starts the schedule and the count afresh.
    paused: bool,
}

impl FrameClock {
    /// A clock for `fps` frames a second, started at `now`.
    pub(super) fn new(fps: f64, now: Instant) -> Self {
        FrameClock {
            interval: Duration::from_secs_f64(1.0 / fps),
            next_due: now,
            last_tick: now,
            frames: 0,
            counted_from: now,
            walked: false,
            paused: false,
        }
    }

    /// How long until the next frame is due at `now` (zero when it is).
    pub(super) fn until_due(&self, now: Instant) -> Duration {
        self.next_due.saturating_duration_since(now)
    }

    /// The seconds to advance the walk by when a frame is due at `now`: the time since the
    /// last frame, at most 0.25 s (a stall, a suspended lab or a slow link, is not replayed at
    /// once). The next frame falls due one interval on, or one interval from now when the lab
    /// has fallen a whole frame behind.
    pub(super) fn due(&mut self, now: Instant) -> Option<f64> {
        if std::mem::take(&mut self.paused) {
            // Walking again: from now, not from the paused loop's last wake-up (up to a second
            // before), which had the walk jump 0.25 s and the rate read 3-21 fps for a second.
            (self.next_due, self.last_tick, self.counted_from, self.frames) = (now + self.interval, now, now, 0);
            return None;
        }
        if now < self.next_due {
            return None;
        }
        let elapsed = now.duration_since(self.last_tick).as_secs_f64().min(0.25);
        self.last_tick = now;
        self.next_due = if now.duration_since(self.next_due) < self.interval {
            self.next_due + self.interval
        } else {
            now + self.interval
        };
        self.walked = true;
        Some(elapsed)
    }

    /// The walk is paused at `now`: nothing falls due, and the rate is counted anew from the
    /// moment it walks again (counting the pause had the status line read 0 fps for a second
    /// after a 3 s pause).
    pub(super) fn pause(&mut self, now: Instant) {
        (self.next_due, self.last_tick, self.counted_from, self.frames) = (now, now, now, 0);
        self.paused = true;
    }

    /// A frame was drawn. Redraws for keys, the mouse or a resize show no newer walk and are
    /// not counted: counted, the status line read 48 fps while keys were typed into a lab
    /// capped at 30.
    pub(super) fn drawn(&mut self) {
        if std::mem::take(&mut self.walked) {
            self.frames += 1;
        }
    }

    /// The walk's frames drawn per second over the last second or more, once one has passed
    /// at `now`; then counted anew.
    pub(super) fn rate(&mut self, now: Instant) -> Option<f64> {
        let counted = now.duration_since(self.counted_from);
        if counted < Duration::from_secs(1) {
            return None;
        }
        let fps = f64::from(self.frames) / counted.as_secs_f64();
        (self.frames, self.counted_from) = (0, now);
        Some(fps)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn frames_keep_to_the_cap_though_each_wake_up_comes_late() {
        let start = Instant::now();
        let mut clock = FrameClock::new(60.0, start);
        let late = Duration::from_micros(900);
        let mut now = start;
        let (mut frames, mut walked) = (0, 0.0);
        while now < start + Duration::from_secs(1) {
            // The loop sleeps until the frame is due and wakes 0.9 ms late.
            now += clock.until_due(now) + late;
            if let Some(dt) = clock.due(now) {
                frames += 1;
                walked += dt;
                clock.drawn();
            }
        }
        assert!((59..=61).contains(&frames), "{frames} frames in a second at --fps 60");
        // The walk advances by the time that passed, not by the grid.
        let passed = now.duration_since(start).as_secs_f64();
        assert!((walked - passed).abs() < 1e-9, "{walked} s walked in {passed} s");
        let fps = clock.rate(now).expect("a second has passed");
        assert!((58.0..=61.0).contains(&fps), "{fps}");
    }

    #[test]
    fn the_rate_counts_walk_frames_not_redraws_and_starts_anew_after_a_pause() {
        let start = Instant::now();
        let mut clock = FrameClock::new(30.0, start);
        let step = Duration::from_secs_f64(1.0 / 30.0);
        let mut now = start;
        for _ in 0..30 {
            assert!(clock.due(now).is_some());
            clock.drawn();
            // Keys typed between frames redraw the same walk.
            clock.drawn();
            now += step;
        }
        assert_eq!(clock.rate(start + Duration::from_millis(999)), None);
        // 30 steps of a rounded 1/30 s fall a nanosecond short of the second.
        now += Duration::from_millis(1);
        let fps = clock.rate(now).expect("a second has passed");
        assert!((fps - 30.0).abs() < 0.05, "{fps}");
        // Paused: the loop wakes once a second and last saw the pause 0.9 s before the walk
        // resumed; the first reading after is of the walking, and the walk does not jump.
        clock.pause(now + Duration::from_millis(2400));
        now += Duration::from_millis(3300);
        assert_eq!(clock.due(now), None, "the first frame falls an interval after resuming");
        now += step;
        let dt = clock.due(now).expect("due an interval on");
        assert!((dt - step.as_secs_f64()).abs() < 1e-9, "the walk advances {dt} s, not the pause");
        clock.drawn();
        now += step;
        for _ in 0..29 {
            assert!(clock.due(now).is_some());
            clock.drawn();
            now += step;
        }
        let fps = clock.rate(now).expect("a second of walking");
        assert!((fps - 30.0).abs() < 1.05, "{fps} after a pause");
        // A long stall advances the walk by 0.25 s at most and restarts the grid.
        now += Duration::from_secs(2);
        assert_eq!(clock.due(now), Some(0.25));
        assert_eq!(clock.until_due(now), step);
    }
}
