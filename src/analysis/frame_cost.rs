//! What a frame of the walk costs, part by part (thesis table 6.1), measured on this build.
//!
//! The same walk is run `repeats` times by two walkers in step, frame by frame: one plainly,
//! timing only its whole frame (the frame update and the frame's numbers), the other with the
//! walker's lap timer charging each part ([`FramePart`]). Walking them in step lets both see
//! the same machine, however its load drifts. A part's figure is its median over the timed runs and
//! the whole frame's the median over the plain runs, both per frame; the parts summing to
//! the plain whole shows that they cover the frame and that the timer itself costs little.
//! Each step's planning and pelvis choice happen at one frame in a step and are spread over
//! all frames here, as table 6.1 gives shares of the time spent.
//!
//! This is a measurement, not a test: the figures depend on the machine and its load.

use crate::model::params::WalkParams;
use crate::model::walk::timing::{FramePart, FrameTimer};
use crate::model::walk::{ModelError, Walker};
use std::hint::black_box;
use std::time::Instant;

/// The measured costs.
#[derive(Clone, Debug, PartialEq)]
pub struct FrameCosts {
    /// Each part's median time per frame (µs), in [`FramePart::ALL`] order.
    pub parts_us: Vec<(FramePart, f64)>,
    /// The whole frame's median time (µs), walked without the timer.
    pub whole_us: f64,
    /// Frames of each run.
    pub frames: u64,
    /// Steps (toe-offs) of each run.
    pub steps: usize,
    /// Frame rate walked (frames/s).
    pub fps: f64,
    /// Paired runs.
    pub repeats: usize,
}

impl FrameCosts {
    /// The parts' sum (µs per frame).
    #[must_use]
    pub fn parts_sum_us(&self) -> f64 {
        self.parts_us.iter().map(|(_, us)| us).sum()
    }

    /// Frames in a step, on average, of the walk measured.
    #[must_use]
    pub fn frames_per_step(&self) -> f64 {
        self.frames as f64 / self.steps.max(1) as f64
    }
}

/// Parts of one frame (s), in [`FramePart::ALL`] order.
type Parts = [f64; FramePart::ALL.len()];

/// One run of two walkers in step, frame by frame, so that both see the machine as it is at
/// that moment: each frame's whole time (s) on the plain walker, its parts on the timed
/// one, and the steps walked.
fn paired_run(params: &WalkParams, frames: u64, fps: f64) -> Result<(Vec<f64>, Vec<Parts>, usize), ModelError> {
    let mut plain = Walker::new(params)?;
    let mut timed = Walker::new(params)?;
    timed.set_frame_timer(Some(FrameTimer::new(Instant::now)));
    let mut wholes = Vec::with_capacity(frames as usize);
    let mut parts = Vec::with_capacity(frames as usize);
    let mut before = [0.0; FramePart::ALL.len()];
    for i in 1..=frames {
        let started = Instant::now();
        plain.advance(1.0 / fps);
        black_box(plain.frame(i));
        wholes.push(started.elapsed().as_secs_f64());
        timed.restart_timer();
        timed.advance(1.0 / fps);
        black_box(timed.frame(i));
        timed.lap(FramePart::Frame);
        let now = timed.frame_timer().map_or(before, FrameTimer::totals_s);
        parts.push(std::array::from_fn(|k| now[k] - before[k]));
        before = now;
    }
    Ok((wholes, parts, plain.step_plans().len()))
}

/// The median of `values` (0 for none).
fn median(values: &mut [f64]) -> f64 {
    values.sort_by(f64::total_cmp);
    match values.len() {
        0 => 0.0,
        n if n % 2 == 1 => values[n / 2],
        n => 0.5 * (values[n / 2 - 1] + values[n / 2]),
    }
}

/// Measures `params`' walk over `cycles` gait cycles at `fps`, in `repeats` paired runs.
///
/// A busy machine takes the processor away for milliseconds at a time, landing on a few
/// frames of a run; so each frame is taken at its median over the runs: the plain walker's
/// frame time, and the parts of the timed walker's run whose frame total is that frame's
/// median. The figures are those sums over the frames, per frame.
pub fn measure(params: &WalkParams, cycles: f64, fps: f64, repeats: usize) -> Result<FrameCosts, ModelError> {
    let cycle_s = Walker::new(params)?.resolved().cycle_s;
    let frames = ((cycles * cycle_s * fps).round() as u64).max(1);
    let repeats = repeats.max(1);
    // A first run warms caches and the clock up, not counted.
    paired_run(params, frames.min(200), fps)?;
    let mut runs = Vec::with_capacity(repeats);
    for _ in 0..repeats {
        runs.push(paired_run(params, frames, fps)?);
    }
    let steps = runs[0].2;
    let (mut whole, mut parts) = (0.0, [0.0; FramePart::ALL.len()]);
    for f in 0..frames as usize {
        whole += median(&mut runs.iter().map(|r| r.0[f]).collect::<Vec<f64>>());
        let mut by_total: Vec<&Parts> = runs.iter().map(|r| &r.1[f]).collect();
        by_total.sort_by(|a, b| a.iter().sum::<f64>().total_cmp(&b.iter().sum::<f64>()));
        let middle = by_total[by_total.len() / 2];
        for (sum, t) in parts.iter_mut().zip(middle) {
            *sum += t;
        }
    }
    let per_frame_us = 1e6 / frames as f64;
    Ok(FrameCosts {
        parts_us: FramePart::ALL.iter().zip(parts).map(|(&p, t)| (p, t * per_frame_us)).collect(),
        whole_us: whole * per_frame_us,
        frames,
        steps,
        fps,
        repeats,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn medians_of_odd_and_even_counts() {
        assert_eq!(median(&mut [3.0, 1.0, 2.0]), 2.0);
        assert_eq!(median(&mut [4.0, 1.0, 3.0, 2.0]), 2.5);
        assert_eq!(median(&mut []), 0.0);
    }

    #[test]
    fn every_part_of_the_default_walk_is_charged() {
        let params = crate::config::presets::params("default").unwrap().unwrap();
        let costs = measure(&params, 3.0, 60.0, 1).unwrap();
        for (part, us) in &costs.parts_us {
            assert!(*us > 0.0, "{part:?} was never charged");
        }
        assert!(costs.steps >= 5, "{}", costs.steps);
    }
}
