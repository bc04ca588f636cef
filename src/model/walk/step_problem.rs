//! The step problem of the pelvis-acceleration optimisation (spec §8, thesis eq. 6.6, after
//! Chung & Hahn 1999); the numerical search it runs is [`crate::model::search`].
//!
//! Once per step, at the toe-off that ends a double support, the walk chooses where the pelvis
//! will be at the *next* mid double support. A candidate position is scored by simulating the
//! stance that it shapes — from the current stance leg's mid-stance to the double support,
//! then the landing leg from the double support to its own mid-stance — with the walk's own
//! phase and IK code ([`Gait::project_stance`], [`Gait::target_of`], [`solve_leg`]), and
//! summing the weighted squared angular accelerations of hip, knee and ankle. A candidate at
//! which a stance leg cannot reach is infeasible.
//!
//! "Cannot reach" includes rolling over the toes further than the heel-rise curve says. The
//! walk lets a trailing leg roll on past its curve when the hip runs ahead of it
//! ([`Gait::target_of`]), so no candidate is ever strictly out of reach in heel rise; but
//! a leg doing that holds its knee straight at the reach limit, which has no knee
//! acceleration at all, and the cost alone would drive the pelvis forward into a stiff,
//! hyper-extended push-off, far past the fixed rule's hip extension and heel rise (figures in
//! benches/README.md, "Optimiser allowances"). A candidate needing more than
//! `HEEL_RISE_SLACK_DEG` of extra heel rise beyond what the fixed rule's position needs
//! (`heel_rise_allowance`) is therefore infeasible.
//!
//! Downhill the same push can come without extra heel rise: once the pelvis kept its speed
//! through its keys, the slope_down walk's optimum moved the pelvis far forward and extended
//! the trailing hip well past normal gait's 10–20° (see benches/README.md). A candidate asking
//! more than `HIP_EXTENSION_SLACK_DEG` of hip extension beyond the fixed rule's is
//! infeasible too (`hip_extension_allowance`).

use crate::model::body::Side;
use crate::model::params::{CostForm, OptimiserParams, SearchMethod};
use crate::model::search::{self, Candidate, SearchSpace};
use crate::model::walk::gait::Gait;
use crate::model::walk::leg::LegState;
use crate::model::walk::pelvis::{KeyKind, PelvisKey, PelvisPlan, PelvisPose};
use crate::model::walk::pose::{sagittal_leg_angles, solve_leg};

/// What was decided for one step, kept for the lab's optimiser panel, `gaitlab optimise` and
/// the report.
#[derive(Clone, Debug, PartialEq)]
pub struct StepRecord {
    /// Step number of the footfall the decision prepares.
    pub step: i64,
    /// The leg taking the step.
    pub side: Side,
    /// Master phase of the decision (the toe-off).
    pub phase: f64,
    /// How it was searched; `None` when the optimiser is off (fixed rule).
    pub method: Option<SearchMethod>,
    /// Every evaluation, in the order made.
    pub candidates: Vec<Candidate>,
    /// The chosen position.
    pub chosen: Candidate,
    /// Forward pelvis positions at the mid-stances before and after the double support (m):
    /// the window the choice sits in.
    pub(crate) window_x: (f64, f64),
    /// The fixed rule's position and cost, for comparison.
    pub fixed_rule: Candidate,
    /// Cost evaluations the search made.
    pub evaluations: u32,
    /// How many of them were feasible.
    pub feasible: u32,
    /// No candidate was feasible and the previous choice was kept.
    pub fallback: bool,
    /// Wall time of the search (µs); the only number in a record that varies between runs.
    pub elapsed_us: f64,
}

impl StepRecord {
    /// Where the chosen position sits between the two mid-stances: 0 at the stance leg's,
    /// 1 at the landing leg's. The fixed rule is 0.5; a steady walk repeats the same ratio.
    #[must_use]
    pub fn chosen_ratio(&self) -> f64 {
        let (a, b) = self.window_x;
        if (b - a).abs() < 1e-12 { 0.5 } else { (self.chosen.x - a) / (b - a) }
    }
}

/// The weighted acceleration cost of joint-angle samples (rad) spaced `dt` seconds apart:
/// Σ_j W_j Σ_i θ̈_j,i² Δt (or |θ̈|·Δt), θ̈ by central differences at the interior samples.
///
/// ```
/// use gaitlab::model::optimise::acceleration_cost;
/// use gaitlab::model::params::CostForm;
/// let uniform: Vec<[f64; 3]> = (0..10).map(|i| [0.5 * i as f64, 0.0, -0.25 * i as f64]).collect();
/// assert_eq!(acceleration_cost(&uniform, 0.01, [1.0, 1.0, 1.0], CostForm::Squared), 0.0);
/// ```
#[must_use]
pub fn acceleration_cost(angles: &[[f64; 3]], dt: f64, weights: [f64; 3], form: CostForm) -> f64 {
    let mut cost = 0.0;
    for w in angles.windows(3) {
        for j in 0..3 {
            let acc = (w[2][j] - 2.0 * w[1][j] + w[0][j]) / (dt * dt);
            cost += weights[j]
                * match form {
                    CostForm::Squared => acc * acc * dt,
                    CostForm::Absolute => acc.abs() * dt,
                };
        }
    }
    cost
}

/// One step's choice: the plan it changes, the legs it simulates and the range it searches.
#[derive(Clone, Debug)]
pub struct StepProblem {
    /// The pelvis plan with the double-support key and the landing leg's mid-stance key last.
    pub plan: PelvisPlan,
    /// The leg that stays on the ground through the coming swing, as it is now.
    pub stance: LegState,
    /// The swinging leg as it will be at its heel strike.
    pub landing: LegState,
    /// The stance leg's mid-stance key (start of the simulated window).
    pub(crate) ms_before: PelvisKey,
    /// The double-support key being chosen (its x and y are the candidate's).
    pub ds: PelvisKey,
    /// The landing leg's mid-stance key (end of the window).
    pub(crate) ms_after: PelvisKey,
    /// Forward positions searched.
    pub range: (f64, f64),
    /// Heights the joint search may use.
    pub(crate) height_range: (f64, f64),
    /// The settings.
    pub settings: OptimiserParams,
    /// The most extra heel rise (rad) a candidate may ask of a stance leg: the fixed rule's
    /// own plus `optimiser.heel_rise_slack_deg` (set by [`StepProblem::with_allowance`]).
    pub(crate) heel_rise_allowance: f64,
    /// The most hip extension (rad, positive) a candidate may ask of a stance leg: the fixed
    /// rule's own plus `optimiser.hip_extension_slack_deg` (set with the heel-rise one).
    pub(crate) hip_extension_allowance: f64,
    /// The fixed rule's cost, found while setting the allowance (`None` if it cannot reach).
    pub(crate) fixed_rule_cost: Option<f64>,
    /// The pelvis pose at each sample of the window, but for its forward position and height,
    /// which are all that a candidate changes (filled by [`StepProblem::with_allowance`];
    /// empty means "compute every pose").
    pub(crate) orientations: Vec<PelvisPose>,
}

impl StepProblem {
    /// The fixed rule's position: halfway between the two mid-stance positions.
    #[must_use]
    pub fn fixed_rule_x(&self) -> f64 {
        0.5 * (self.ms_before.x + self.ms_after.x)
    }

    /// The cost of putting the pelvis at (`x`, `y`) at mid double support; `None` if a stance
    /// leg cannot reach its ground contact somewhere in the simulated window or at the heel
    /// strike.
    #[must_use]
    pub fn cost(&self, walk: &impl AsRef<Gait>, x: f64, y: f64) -> Option<f64> {
        self.simulate(walk.as_ref(), x, y).0
    }

    /// Sets `heel_rise_allowance` from the fixed rule's position.
    #[must_use]
    pub fn with_allowance(mut self, walk: &impl AsRef<Gait>) -> StepProblem {
        let gait = walk.as_ref();
        self.heel_rise_allowance = f64::INFINITY;
        self.hip_extension_allowance = f64::INFINITY;
        // The cache pays for itself from the second evaluation on; with the optimiser off the
        // fixed rule's is the only one.
        if self.settings.enabled {
            let plan = self.plan.clone();
            self.orientations = self.sample_phases().map(|phase| gait.pelvis_with_plan(&plan, phase)).collect();
        }
        let (cost, fixed_rule_extra, fixed_rule_extension) = self.simulate(gait, self.fixed_rule_x(), self.ds.y);
        self.heel_rise_allowance = fixed_rule_extra.max(0.0) + self.settings.heel_rise_slack_deg.to_radians();
        self.hip_extension_allowance = fixed_rule_extension + self.settings.hip_extension_slack_deg.to_radians();
        self.fixed_rule_cost = cost;
        self
    }

    /// The master phases of the samples: `samples / 2` from the stance leg's mid-stance to
    /// the double support, as many from there to the landing leg's mid-stance.
    fn sample_phases(&self) -> impl Iterator<Item = f64> + use<> {
        let per_half = self.per_half();
        let halves = [(self.ms_before.phase, self.ds.phase), (self.ds.phase, self.ms_after.phase)];
        halves.into_iter().flat_map(move |(from, to)| {
            let step = (to - from) / (per_half - 1) as f64;
            (0..per_half).map(move |i| from + step * i as f64)
        })
    }

    fn per_half(&self) -> usize {
        (self.settings.samples as usize / 2).max(3)
    }

    /// The cost (as [`StepProblem::cost`]), and the most extra heel rise and the most hip
    /// extension a stance leg needed before the simulation ended (rad).
    fn simulate(&self, gait: &Gait, x: f64, y: f64) -> (Option<f64>, f64, f64) {
        let mut most_extra: f64 = 0.0;
        let mut most_extension = f64::NEG_INFINITY;
        let mut plan = self.plan.clone();
        let key = plan.last_of_mut(KeyKind::DoubleSupport).expect("the problem's plan has its key");
        key.x = x;
        key.y = y;
        let r = gait.resolved();
        let limit = r.reach_margin * r.dims.leg_reach() + 1e-9;
        let s = &self.settings;
        let weights = [s.weight_hip, s.weight_knee, s.weight_ankle];
        let per_half = self.per_half();
        let mut angles = Vec::with_capacity(per_half);
        let mut total = 0.0;
        let halves =
            [(&self.stance, self.ms_before.phase, self.ds.phase), (&self.landing, self.ds.phase, self.ms_after.phase)];
        for (half, (leg, from, to)) in halves.into_iter().enumerate() {
            let mut leg = leg.clone();
            angles.clear();
            let step = (to - from) / (per_half - 1) as f64;
            for i in 0..per_half {
                let phase = from + step * i as f64;
                gait.project_stance(&mut leg, phase);
                let pelvis = match self.orientations.get(half * per_half + i) {
                    Some(cached) => {
                        let mut pose = *cached;
                        (pose.position.x, pose.position.y) = gait.pelvis_position_with_plan(&plan, phase);
                        pose
                    }
                    None => gait.pelvis_with_plan(&plan, phase),
                };
                let hip = pelvis.hip(leg.side.sign());
                let target = gait.target_of(&leg, phase, hip);
                most_extra = most_extra.max(target.extra_heel_rise);
                if hip.distance(target.ankle) > limit || target.extra_heel_rise > self.heel_rise_allowance {
                    return (None, most_extra, most_extension);
                }
                let pose = solve_leg(r, hip, target);
                let sagittal = sagittal_leg_angles(pelvis.rotation, &pose);
                most_extension = most_extension.max(-sagittal[0]);
                if -sagittal[0] > self.hip_extension_allowance {
                    return (None, most_extra, most_extension);
                }
                angles.push(sagittal);
            }
            total += acceleration_cost(&angles, step * r.cycle_s, weights, s.cost);
        }
        // The landing leg must reach its footfall at heel strike, before the window starts.
        let strike = self.landing.cycle_start;
        let hip = gait.pelvis_with_plan(&plan, strike).hip(self.landing.side.sign());
        if hip.distance(gait.target_of(&self.landing, strike, hip).ankle) > limit {
            return (None, most_extra, most_extension);
        }
        (Some(total), most_extra, most_extension)
    }

    /// Samples the cost over the whole forward range at the problem's height (for plots).
    #[must_use]
    pub fn landscape(&self, walk: &impl AsRef<Gait>, count: usize) -> Vec<Candidate> {
        let gait = walk.as_ref();
        let (lo, hi) = self.range;
        (0..count.max(2))
            .map(|i| {
                let x = lo + (hi - lo) * i as f64 / (count.max(2) - 1) as f64;
                Candidate { x, y: self.ds.y, cost: self.simulate(gait, x, self.ds.y).0 }
            })
            .collect()
    }

    /// Runs the configured search. Returns every evaluation, the fixed rule's first when
    /// [`StepProblem::with_allowance`] has costed it; the best feasible one is the choice (the
    /// caller falls back when there is none).
    #[must_use]
    pub fn search(&self, walk: &impl AsRef<Gait>) -> Vec<Candidate> {
        let gait = walk.as_ref();
        // The fixed rule's position is the middle of the range, so with an odd first level it
        // is one of its candidates: its cost, found while setting the allowance, is reused.
        let done = if self.heel_rise_allowance.is_finite() {
            vec![Candidate { x: self.fixed_rule_x(), y: self.ds.y, cost: self.fixed_rule_cost }]
        } else {
            Vec::new()
        };
        let space = SearchSpace {
            method: self.settings.method,
            candidates: self.settings.candidates,
            refine: self.settings.refine,
            tolerance_m: self.settings.tolerance_mm / 1000.0,
            range: self.range,
            height_range: self.height_range,
            y: self.ds.y,
        };
        search::run(&space, done, &mut |x, y| self.simulate(gait, x, y).0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn uniform_motion_costs_nothing_and_jerky_motion_costs_more() {
        let dt = 0.02;
        let uniform: Vec<[f64; 3]> =
            (0..25).map(|i| [0.015625 * i as f64, 0.03125 * i as f64, -0.0078125 * i as f64]).collect();
        let jerky: Vec<[f64; 3]> = (0..25)
            .map(|i| {
                [0.015625 * i as f64 + if i % 2 == 0 { 0.001 } else { 0.0 }, 0.03125 * i as f64, -0.0078125 * i as f64]
            })
            .collect();
        let w = [1.0, 1.0, 1.0];
        assert_eq!(acceleration_cost(&uniform, dt, w, CostForm::Squared), 0.0);
        assert!(acceleration_cost(&jerky, dt, w, CostForm::Squared) > 0.0);
        assert!(acceleration_cost(&jerky, dt, w, CostForm::Absolute) > 0.0);
        // Weights scale their joint's term alone: the jerk is all in the hip.
        let c1 = acceleration_cost(&jerky, dt, [1.0, 1.0, 1.0], CostForm::Squared);
        let c3 = acceleration_cost(&jerky, dt, [3.0, 7.0, 9.0], CostForm::Squared);
        assert!((c3 - 3.0 * c1).abs() < 1e-9 * c3);
    }
}
