//! Which stretch of the recorded walk the animation loops, and when each of its frames is
//! shown.
//!
//! The stretch is a whole number of the right leg's steady gait cycles (heel strike to heel
//! strike, the start-up cycle left out), about [`TARGET_S`] long and taken from the middle
//! of the walk (on stairs or a slope, on the climb rather than before it), so that the last
//! frame runs into the first as the walk runs into its next cycle.

use super::super::data::Data;

/// Frames per second of the animation: 25 is 4/100 s a frame, a whole number of the GIF's
/// delay unit, so every frame is shown for the same time and the loop keeps the walk's pace.
pub const FPS: f64 = 25.0;
/// The loop's length aimed at (s): a few steps, as a slide needs.
pub const TARGET_S: f64 = 4.0;

/// The looped stretch and its frames.
#[derive(Clone, Debug, PartialEq)]
pub struct Clip {
    /// First and last recorded frame of the stretch (the last is the first of the next
    /// loop, not shown).
    pub(super) start: usize,
    pub(super) end: usize,
    /// Whole gait cycles in the stretch; 0 when the walk had no whole steady cycle and the
    /// loop is simply its last seconds.
    pub cycles: usize,
    /// The stretch's length (s).
    pub duration_s: f64,
    /// Animation frames.
    pub frames: usize,
}

impl Clip {
    /// The stretch of `d`'s walk to loop.
    pub(super) fn new(d: &Data<'_>) -> Clip {
        let times: Vec<f64> = d.run.frames.iter().map(|f| f.time_s).collect();
        let strikes = &d.strikes[0];
        let (start, end, cycles) = if strikes.len() >= 2 {
            let whole = strikes.len() - 1;
            let mean_cycle_s = (times[strikes[whole]] - times[strikes[0]]) / whole as f64;
            let cycles = ((TARGET_S / mean_cycle_s).round() as usize).clamp(1, whole);
            let first = (whole - cycles) / 2;
            (strikes[first], strikes[first + cycles], cycles)
        } else {
            // Too short for a whole steady cycle: the last seconds, not seamless.
            let last = times.len() - 1;
            let start = times.partition_point(|&t| t < times[last] - TARGET_S).min(last);
            (start, last, 0)
        };
        let duration_s = times[end] - times[start];
        let frames = ((duration_s * FPS).round() as usize).max(1);
        Clip { start, end, cycles, duration_s, frames }
    }

    /// The stretch in words: "4 gait cycles in 4.35 s".
    #[must_use]
    pub fn describe(&self) -> String {
        match self.cycles {
            0 => format!("{:.2} s", self.duration_s),
            n => format!("{n} gait cycle{} in {:.2} s", if n == 1 { "" } else { "s" }, self.duration_s),
        }
    }

    /// The walk's time (s from the stretch's start) of animation frame `k`.
    pub(super) fn offset_s(&self, k: usize) -> f64 {
        self.duration_s * k as f64 / self.frames as f64
    }

    /// When frame `k` starts, in the GIF's hundredths of a second: rounded from the exact
    /// time rather than summing rounded delays, so the loop's length is right to 1/100 s.
    pub(super) fn start_cs(&self, k: usize) -> u32 {
        (100.0 * self.offset_s(k)).round() as u32
    }

    /// The loop's length in hundredths of a second (at least one).
    pub(super) fn total_cs(&self) -> u32 {
        self.start_cs(self.frames).max(1)
    }

    /// How long frame `k` is shown (1/100 s).
    pub(super) fn delay_cs(&self, k: usize) -> u16 {
        let next = if k + 1 == self.frames { self.total_cs() } else { self.start_cs(k + 1) };
        u16::try_from(next - self.start_cs(k)).unwrap_or(u16::MAX)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn clip(duration_s: f64) -> Clip {
        let frames = ((duration_s * FPS).round() as usize).max(1);
        Clip { start: 0, end: 1, cycles: 1, duration_s, frames }
    }

    #[test]
    fn the_delays_add_up_to_the_stretch_to_a_hundredth_of_a_second() {
        for duration_s in [4.342_857, 4.0, 3.999, 4.019, 1.05, 0.5] {
            let c = clip(duration_s);
            let delays: Vec<u16> = (0..c.frames).map(|k| c.delay_cs(k)).collect();
            let sum: u32 = delays.iter().map(|&d| u32::from(d)).sum();
            assert_eq!(sum, c.total_cs(), "{duration_s} s");
            assert!((f64::from(sum) / 100.0 - duration_s).abs() <= 0.005 + 1e-12, "{duration_s} s: {sum} cs");
            // 25 fps: each frame 4/100 s, a hundredth more or less where the rounding falls.
            assert!(delays.iter().all(|d| (3..=5).contains(d)), "{duration_s} s: {delays:?}");
            if duration_s >= 3.9 {
                assert!(delays.iter().filter(|&&d| d == 4).count() * 10 >= 9 * delays.len(), "{delays:?}");
            }
        }
        // A single frame still has a delay, and the loop a length.
        let still = clip(0.0);
        assert_eq!((still.frames, still.delay_cs(0), still.total_cs()), (1, 1, 1));
    }
}
