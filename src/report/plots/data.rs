//! The run prepared once for every plot: its steady heel strikes, the gait events, and any
//! per-frame value resampled over the gait cycle.

use crate::analysis::Run;
use crate::analysis::events as gait_events;
use crate::model::walk::frame::Frame;
use crate::report::metrics;

/// A quantity over the gait cycle: mean, min and max at each percent.
pub(crate) struct Cycle {
    /// Mean at each percent.
    pub(crate) mean: Vec<(f64, f64)>,
    /// Min along the cycle, then max back: a closed polygon.
    pub(crate) band: Vec<(f64, f64)>,
}

/// Everything the plots need, prepared once.
pub(crate) struct Data<'a> {
    /// The walk.
    pub(super) run: &'a Run,
    /// Heel strikes per side (frame indices), steady ones only (start-up cycle dropped).
    pub(super) strikes: [Vec<usize>; 2],
    /// Mean % of the right cycle: right toe-off, left heel strike, left toe-off.
    pub(crate) events: Vec<(&'static str, f64)>,
}

/// Steady heel strikes of `side`: the start-up cycle's first strike dropped; for a walk
/// whose pace changed, or on stairs or a slope, those on the part its figures are measured on
/// ([`metrics::steady_window`]), so that the cycle plots draw what the figures measure.
fn strikes_of(run: &Run, side: usize) -> Vec<usize> {
    let all = gait_events::heel_strikes(&run.frames, side);
    match metrics::steady_window(run) {
        Ok(w) if w.is_part() => all.into_iter().filter(|s| (w.first..=w.last).contains(s)).collect(),
        _ => all.into_iter().skip(1).collect(),
    }
}

impl<'a> Data<'a> {
    /// Prepares `run`.
    pub(crate) fn new(run: &'a Run) -> Data<'a> {
        let frames = &run.frames;
        let strikes = [strikes_of(run, 0), strikes_of(run, 1)];
        let right = &strikes[0];
        let mut events = Vec::new();
        let pct_of = |pred: &dyn Fn(&Frame, &Frame) -> bool| {
            let mut v = Vec::new();
            for w in right.windows(2) {
                if let Some(i) = (w[0] + 1..w[1]).find(|&i| pred(&frames[i - 1], &frames[i])) {
                    v.push(
                        100.0 * (frames[i].time_s - frames[w[0]].time_s) / (frames[w[1]].time_s - frames[w[0]].time_s),
                    );
                }
            }
            if v.is_empty() { f64::NAN } else { v.iter().sum::<f64>() / v.len() as f64 }
        };
        events.push(("RTO", pct_of(&|a: &Frame, b: &Frame| gait_events::is_toe_off(a, b, 0))));
        events.push(("LHS", pct_of(&|a: &Frame, b: &Frame| gait_events::is_heel_strike(a, b, 1))));
        events.push(("LTO", pct_of(&|a: &Frame, b: &Frame| gait_events::is_toe_off(a, b, 1))));
        events.retain(|e| e.1.is_finite());
        Data { run, strikes, events }
    }

    /// The walk's speed over the cycles drawn (m/s), right heel strike to right heel strike as
    /// the summary measures it; the config's speed for a walk with fewer than two strikes.
    /// The walk is on level ground, as the normative adults walked: off it, the bands say so.
    pub(crate) fn on_level_ground(&self) -> bool {
        self.run.terrain.kind().is_level()
    }

    pub(crate) fn speed_mps(&self) -> f64 {
        let f = &self.run.frames;
        match (self.strikes[0].first(), self.strikes[0].last()) {
            (Some(&a), Some(&b)) if b > a => (f[b].pelvis.x - f[a].pelvis.x) / (f[b].time_s - f[a].time_s),
            _ => self.run.start_speed_mps,
        }
    }

    /// `value` per frame, normalised to each of `side`'s steady cycles.
    pub(crate) fn cycle(&self, side: usize, value: &dyn Fn(usize) -> f64) -> Cycle {
        let frames = &self.run.frames;
        let mut samples: Vec<Vec<f64>> = vec![Vec::new(); 101];
        for w in self.strikes[side].windows(2) {
            let (t0, t1) = (frames[w[0]].time_s, frames[w[1]].time_s);
            let mut i = w[0];
            for (p, bucket) in samples.iter_mut().enumerate() {
                let t = t0 + (t1 - t0) * p as f64 / 100.0;
                while i + 1 < w[1] && frames[i + 1].time_s <= t {
                    i += 1;
                }
                let (ta, tb) = (frames[i].time_s, frames[i + 1].time_s);
                let s = if tb > ta { ((t - ta) / (tb - ta)).clamp(0.0, 1.0) } else { 0.0 };
                bucket.push(value(i) * (1.0 - s) + value(i + 1) * s);
            }
        }
        let mean = samples
            .iter()
            .enumerate()
            .map(|(p, v)| (p as f64, v.iter().sum::<f64>() / v.len().max(1) as f64))
            .collect();
        let lo: Vec<(f64, f64)> = samples
            .iter()
            .enumerate()
            .map(|(p, v)| (p as f64, v.iter().copied().fold(f64::INFINITY, f64::min)))
            .collect();
        let hi: Vec<(f64, f64)> = samples
            .iter()
            .enumerate()
            .map(|(p, v)| (p as f64, v.iter().copied().fold(f64::NEG_INFINITY, f64::max)))
            .collect();
        let band = lo.into_iter().chain(hi.into_iter().rev()).collect();
        Cycle { mean, band }
    }
}
