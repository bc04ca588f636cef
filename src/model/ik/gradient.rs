//! Seed 002's gradient descent, on the leg. The cost is the squared ankle position error plus
//! the weighted squared swivel arc of the knee (both in mm), over the four joint angles in
//! degrees. Each descent estimates the gradient by forward differences, steps `δ·∇F`, keeps
//! the step only if the cost fell and otherwise halves `δ`, from `δ0` down to `ε`. On the
//! first frame it descends from random starting poses and keeps the best; on every frame it
//! then tries random perturbations of every angle, each descended and kept only if it ends
//! lower. The generator is seeded, so a run repeats exactly.

use crate::model::ik::chain::{LegAngles, LegChain};
use crate::model::ik::iterate::Iterated;
use crate::model::ik::settings::IkSettings;
use crate::model::terrain::SplitMix64;
use glam::DVec3;

/// Forward-difference step (deg).
const H_DEG: f64 = 1e-4;

struct Problem<'a> {
    chain: &'a LegChain,
    target: DVec3,
    side: f64,
    weight_swivel: f64,
    tolerance_mm: f64,
}

impl Problem<'_> {
    /// The cost (mm²) and whether the pose is within the tolerance, for angles in degrees.
    fn cost(&self, deg: [f64; 4]) -> (f64, bool) {
        let angles = LegAngles::from_array(deg.map(f64::to_radians));
        let (distance, arc) = self.chain.residual(self.chain.forward(angles, self.side), self.target);
        let (d_mm, arc_mm) = (distance * 1e3, arc * 1e3);
        (
            d_mm * d_mm + self.weight_swivel * arc_mm * arc_mm,
            d_mm <= self.tolerance_mm && arc_mm.abs() <= self.tolerance_mm,
        )
    }

    fn clamp(&self, deg: [f64; 4]) -> [f64; 4] {
        let clamped = self.chain.limits.clamp(LegAngles::from_array(deg.map(f64::to_radians)));
        clamped.to_array().map(f64::to_degrees)
    }

    fn gradient(&self, deg: [f64; 4], f0: f64) -> [f64; 4] {
        let mut g = [0.0; 4];
        for (j, gj) in g.iter_mut().enumerate() {
            let mut nudged = deg;
            nudged[j] += H_DEG;
            *gj = (self.cost(nudged).0 - f0) / H_DEG;
        }
        g
    }

    /// One descent from `deg`; returns the end, its cost, and the steps taken.
    fn descend(&self, mut deg: [f64; 4], s: &IkSettings) -> ([f64; 4], f64, u32) {
        let g_settings = &s.gradient;
        let mut delta = g_settings.delta0;
        let (mut f0, mut done) = self.cost(deg);
        let mut g = self.gradient(deg, f0);
        let mut steps = 0;
        while !done && delta >= g_settings.epsilon && steps < g_settings.max_steps {
            steps += 1;
            let mut candidate = deg;
            for (x, gj) in candidate.iter_mut().zip(g) {
                *x -= delta * gj;
            }
            let candidate = self.clamp(candidate);
            let (f, within) = self.cost(candidate);
            if f < f0 {
                deg = candidate;
                f0 = f;
                done = within;
                g = self.gradient(deg, f0);
            } else {
                delta /= 2.0;
            }
        }
        (deg, f0, steps)
    }
}

/// Solves for the ankle at `target` (leg frame) from `start`; `first` runs the random restarts.
#[must_use]
pub fn solve(
    chain: &LegChain,
    target: DVec3,
    side: f64,
    start: LegAngles,
    s: &IkSettings,
    first: bool,
    rng: &mut SplitMix64,
) -> Iterated {
    let problem =
        Problem { chain, target, side, weight_swivel: s.gradient.weight_swivel, tolerance_mm: s.tolerance * 1e3 };
    let (mut best, mut best_cost, mut steps) = problem.descend(start.to_array().map(f64::to_degrees), s);
    if first {
        let ranges = sampling_ranges(chain);
        for _ in 0..s.gradient.restarts {
            let mut deg = [0.0; 4];
            for (x, (lo, hi)) in deg.iter_mut().zip(ranges) {
                *x = lo + (hi - lo) * 0.5 * (rng.next_signed_unit() + 1.0);
            }
            let (end, cost, n) = problem.descend(deg, s);
            steps += n;
            if cost < best_cost {
                (best, best_cost) = (end, cost);
            }
        }
    }
    let range_deg = s.gradient.perturbation.to_degrees();
    for _ in 0..s.gradient.perturbations {
        let mut deg = best;
        for x in &mut deg {
            *x += range_deg * rng.next_signed_unit();
        }
        let (end, cost, n) = problem.descend(problem.clamp(deg), s);
        steps += n;
        if cost < best_cost {
            (best, best_cost) = (end, cost);
        }
    }
    Iterated { angles: LegAngles::from_array(best.map(f64::to_radians)), iterations: steps, pose: None }
}

/// Where random starting poses are drawn from (deg): the joint ranges, or plausible leg poses
/// when limits are off.
fn sampling_ranges(chain: &LegChain) -> [(f64, f64); 4] {
    if chain.limits.enabled {
        chain.limits.ranges().map(|(lo, hi)| (lo.to_degrees(), hi.to_degrees()))
    } else {
        [(-60.0, 120.0), (-45.0, 45.0), (-60.0, 60.0), (0.0, 150.0)]
    }
}
