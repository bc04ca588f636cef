//! The swing simulation (spec §6.3.2): once a step is planned, its swing is walked at 50
//! samples and its heel-height and ankle curves raised where the leg cannot reach or the foot
//! would come within the clearance of the ground; and the ground the swing starts from (a
//! riser ahead of the toe, the piece of ground it leaves), which the swing target keeps the
//! foot clear of between samples and frames alike.
//!
//! An `impl Walker` block beside the planner, which calls it once a step.

use crate::model::body::Side;
use crate::model::walk::gait::{SwingCurvesAt, swing_target_at};
use crate::model::walk::leg::{Footfall, LegPose, LegTarget, RiserAhead, SwingPlan, ToeFloor};
use crate::model::walk::pose::solve_leg;
use crate::model::walk::{SWING_SAMPLES, Walker};
use glam::DVec3;

impl Walker {
    /// The stair riser the foot leaving `toe_off_pose` for `to` has just ahead of its toe
    /// (within [`RISER_NEAR_M`] and [`RISER_NEAR_STEP_SHARE`] of its heel's way), where its
    /// ground (`ground_from`) steps up by more than 1 cm.
    pub(super) fn riser_ahead(&self, toe_off_pose: &LegPose, ground_from: f64, to: &Footfall) -> Option<RiserAhead> {
        let toe_x = toe_off_pose.toe_tip.x.max(toe_off_pose.ball.x);
        let t = &self.terrain;
        let near = RISER_NEAR_M + RISER_NEAR_STEP_SHARE * (to.heel.x - toe_off_pose.heel.x).max(0.0);
        let riser_x = t
            .corners_between(toe_x, toe_x + near)
            .into_iter()
            .find(|&x| t.riser_height_at(x) > 0.01 && t.corner_top(x) > ground_from + 0.01)?;
        let nosing_y = t.corner_top(riser_x);
        // Held back by half the clearance where there is room, or where the toe left the
        // tread; at least 5 mm, as exactly on the riser's x the ground reads as the tread
        // above it (at a clearance of 0 the simulation raised a held heel 1.5 m, the leg
        // upside down for 18 frames; a reviewer's find).
        let gap = (0.5 * self.gait.r.clearance).max(RISER_HOLD_GAP_MIN_M);
        Some(RiserAhead { hold_x: (riser_x - gap).max(toe_x), nosing_y })
    }

    /// The ground under the toe of `toe_off_pose` and where that piece of it ends ahead
    /// (within a metre).
    pub(super) fn toe_floor(&self, toe_off_pose: &LegPose) -> ToeFloor {
        let t = &self.terrain;
        let x = toe_off_pose.toe_tip.x;
        let until_x = t.corners_between(x + 1e-6, x + 1.0).first().copied().unwrap_or(x + 1.0);
        let y = t.height(x);
        // The piece of ground is a line (the terrains are piecewise linear between corners).
        ToeFloor { x, y, slope: (t.height(until_x - 1e-6) - y) / (until_x - 1e-6 - x).max(1e-6), until_x }
    }

    /// The 50-sample swing simulation [6.3.2]: at each sample, the pelvis pose, the heel from
    /// the plan, IK; raise the heel-height curve where the ankle is beyond reach, then where
    /// heel, toe tip or sole would come within the clearance of the ground. Up to eight passes.
    /// The first 8 % of the swing are left alone, as the toe is on the ground at toe-off by
    /// design: there the swing target holds it behind a riser and on the ground it leaves.
    ///
    /// A pass changes only the heel-height and ankle curves, and a raise moves one only near
    /// the sample that asked: the pelvis is the same in every pass, and a sample whose heel
    /// height and ankle came out bit for bit as before has the same target and pose as before
    /// (on the default walk about four passes ran, each solving all fifty samples again).
    pub(super) fn simulate_swing(&self, side: Side, toe_off_phase: f64, plan: &mut SwingPlan) {
        let r = &self.gait.r;
        let dims = &r.dims;
        let limit = r.reach_margin * dims.leg_reach();
        let span = 1.0 - r.toe_off;
        let sample_s = |i: usize| (i as f64 + 0.5) / SWING_SAMPLES as f64;
        let hips: [DVec3; SWING_SAMPLES] =
            std::array::from_fn(|i| self.pelvis_at(toe_off_phase + sample_s(i) * span).hip(side.sign()));
        // Only those two are raised: the other curves' values at each sample hold.
        let curves: [SwingCurvesAt; SWING_SAMPLES] = std::array::from_fn(|i| SwingCurvesAt::of(plan, sample_s(i)));
        let mut solved: [Option<SolvedSample>; SWING_SAMPLES] = [None; SWING_SAMPLES];
        // Until a pass raises the ankle curve, the values read at the start are its values.
        let mut ankle_raised = false;
        for _pass in 0..8 {
            let mut raised = false;
            let toe_from_x = plan.heel_from.x + dims.foot_length;
            let mut prev_toe = DVec3::new(toe_from_x, self.terrain.height(toe_from_x), plan.heel_from.z);
            let mut prev_heel = plan.heel_from;
            for i in 0..SWING_SAMPLES {
                let s = sample_s(i);
                let hip = hips[i];
                let heel_height = plan.heel_height.eval(s);
                let ankle_deg = if ankle_raised { plan.ankle_deg.eval(s) } else { curves[i].ankle_deg };
                let same = |m: &SolvedSample| (m.heel_height, m.ankle_deg) == (heel_height, ankle_deg);
                let sample = match solved[i] {
                    Some(sample) if same(&sample) => sample,
                    _ => {
                        let at = SwingCurvesAt { heel_height, ankle_deg, ..curves[i] };
                        let target = swing_target_at(plan, &at, side, r, hip);
                        SolvedSample { heel_height, ankle_deg, target, pose: None }
                    }
                };
                solved[i] = Some(sample);
                let target = sample.target;
                // Out of reach: lift the heel until the ankle is back inside the sphere.
                let d = hip - target.ankle;
                let horizontal = (d.x * d.x + d.z * d.z).sqrt();
                if horizontal < limit {
                    let lowest_ok = hip.y - (limit * limit - horizontal * horizontal).sqrt();
                    if target.ankle.y < lowest_ok - 1e-6 && s < 0.97 {
                        plan.heel_height.raise_at(s, lowest_ok - target.ankle.y + 1e-4);
                        plan.raises += 1;
                        raised = true;
                        continue;
                    }
                }
                // Too close to the ground.
                let pose = sample.pose.unwrap_or_else(|| solve_leg(r, hip, target));
                solved[i] = Some(SolvedSample { pose: Some(pose), ..sample });
                let (heel_deficit, toe_deficit, path_lack) =
                    self.sample_clearance(plan, s, curves[i].progress, &pose, (prev_toe, prev_heel));
                (prev_toe, prev_heel) = (pose.toe_tip, pose.heel);
                // `sample_clearance` reads a path only where the simulation raises.
                if let Some((back, lack)) = path_lack {
                    plan.heel_height.raise_at(s - back / SWING_SAMPLES as f64, lack + 1e-4);
                    plan.raises += 1;
                    raised = true;
                    continue;
                }
                // A toe too close to the ground is lifted by the ankle first.
                if toe_deficit.0 > heel_deficit.max(1e-5) && raises_at(s) && lift_toe(plan, s, ankle_deg, toe_deficit) {
                    (raised, ankle_raised) = (true, true);
                    continue;
                }
                let deficit = heel_deficit.max(toe_deficit.0);
                if deficit > 1e-5 && raises_at(s) {
                    plan.heel_height.raise_at(s, deficit + 1e-4);
                    plan.raises += 1;
                    raised = true;
                }
            }
            if !raised {
                break;
            }
        }
    }

    /// What the swing sample at `s` (heel `progress` along its way) with its foot in `pose`
    /// lacks of its clearance: the heel's and the toe's ([`Self::clearance_deficits`]), and
    /// where the heel passed a nosing on its way from the last sample (`prev.1`; the toe
    /// came from `prev.0`) with too little over it, or the toe's ([`Self::path_lack`]). Clearance ramps
    /// in over the first 15 % of the swing and out over its end, where the foot leaves and
    /// meets the ground.
    fn sample_clearance(
        &self,
        plan: &SwingPlan,
        s: f64,
        progress: f64,
        pose: &LegPose,
        (prev_toe, prev_heel): (DVec3, DVec3),
    ) -> (f64, (f64, f64), Option<(f64, f64)>) {
        let ramp = |landing: f64| self.gait.r.clearance * (s / 0.15).min((1.0 - s) / landing).min(1.0);
        let needed = (ramp(0.15), ramp(TOE_LANDING_RAMP));
        let mut ground_toe = self.terrain.max_height_between(prev_toe.x, pose.toe_tip.x);
        // A toe held behind a riser (its heel short of the planned one) is as low over it as
        // it is under its nosing.
        if let Some(riser) = plan.riser.filter(|_| pose.heel.x < plan.planned_heel_x(progress) - 1e-5) {
            ground_toe = ground_toe.max(riser.nosing_y);
        }
        let (heel_deficit, toe_deficit) = self.clearance_deficits(pose, ground_toe, needed);
        // Only where the simulation raises for it.
        let path = if raises_at(s) {
            match (self.path_lack(prev_heel, pose.heel, needed.0), self.path_lack(prev_toe, pose.toe_tip, needed.0)) {
                (Some(h), Some(t)) => Some(if t.1 > h.1 { t } else { h }),
                (h, t) => h.or(t),
            }
        } else {
            None
        };
        (heel_deficit, toe_deficit, path)
    }

    /// Where a swing heel or toe tip going from `prev` to `now` passes a nosing with less than
    /// `needed` over it: how far back from `now` along the way (0-1) and how much it lacks
    /// (m). Coming down onto a lower tread the heel cut a nosing's corner between two samples
    /// (both clear): 4 cm under it between two frames on a 10-tread flight at 1.3 m/s; up a
    /// flight of long treads a toe cut one late in the swing (2.7 mm, a reviewer's find).
    fn path_lack(&self, prev: DVec3, now: DVec3, needed: f64) -> Option<(f64, f64)> {
        let lack_at = |corner: f64| {
            let f = (corner - prev.x) / (now.x - prev.x);
            let y = prev.y + (now.y - prev.y) * f;
            (1.0 - f, self.terrain.corner_top(corner) + needed - y)
        };
        self.terrain
            .corners(prev.x, now.x)
            .filter(|&c| c > prev.x && c < now.x)
            .map(lack_at)
            .max_by(|a, b| a.1.total_cmp(&b.1))
            .filter(|&(_, lack)| lack > 1e-5)
    }

    /// How far a swing foot in `pose` is below its clearance (m): the heel's, then the toe's
    /// or sole's (over the ground up to `ground_toe` and any terrain corner under the foot)
    /// with how far ahead of the heel that point is, the lever a dorsiflexion lifts it with.
    /// `needed` is the heel's and a corner's clearance, `toe_needed` the toe's over the ground.
    fn clearance_deficits(
        &self,
        pose: &LegPose,
        ground_toe: f64,
        (needed, toe_needed): (f64, f64),
    ) -> (f64, (f64, f64)) {
        let heel_deficit = self.terrain.height(pose.heel.x) + needed - pose.heel.y;
        let mut toe_deficit = (ground_toe + toe_needed - pose.toe_tip.y, pose.toe_tip.x - pose.heel.x);
        for corner in self.terrain.corners(pose.heel.x, pose.toe_tip.x) {
            let top = self.terrain.corner_top(corner);
            let f = (corner - pose.heel.x) / (pose.toe_tip.x - pose.heel.x).max(1e-9);
            let sole_y = pose.heel.y + (pose.toe_tip.y - pose.heel.y) * f;
            if top + needed - sole_y > toe_deficit.0 {
                toe_deficit = (top + needed - sole_y, corner - pose.heel.x);
            }
        }
        (heel_deficit, toe_deficit)
    }
}

/// Whether the simulation raises the curves for the ground at swing fraction `s`: not in the
/// first 8 % of the swing, where the toe leaves the ground by design (the swing target keeps it
/// clear there), nor in the last 1.5 %, where the heel meets its footfall.
fn raises_at(s: f64) -> bool {
    s > 0.08 && s < 0.985
}

/// How near the toe at toe-off a riser must be for the swing to hold the toe behind it (m),
/// with [`RISER_NEAR_STEP_SHARE`] of the heel's way to its footfall: further off, the swing
/// simulation, which looks from 8 % of the swing on, keeps the toe clear. A fixed 10 cm left
/// a riser 10-11 cm ahead to the toe at 1.5-2.0 m/s (30 mm into it at 240 frames a second; a
/// reviewer's find).
const RISER_NEAR_M: f64 = 0.10;

/// The least gap a toe is held behind a riser (m).
const RISER_HOLD_GAP_MIN_M: f64 = 0.005;

/// The share of the heel's way to its footfall added to [`RISER_NEAR_M`]: the heel's progress
/// by 8 % of the swing is under 5 % of its way, and the foot's pitch hand-over carries the toe
/// a few centimetres further.
const RISER_NEAR_STEP_SHARE: f64 = 0.15;

/// Raises `plan`'s ankle curve at swing fraction `s` (where the ankle is at `ankle_deg`) by
/// the dorsiflexion that lifts a toe `deficit.0` m short of its clearance, `deficit.1` m ahead
/// of the heel, as the tibialis anterior does in mid-swing, up to [`SWING_DORSI_MAX_DEG`]:
/// lifting the heel instead bends the knee and tips the foot further down. False when the
/// ankle has no room left.
fn lift_toe(plan: &mut SwingPlan, s: f64, ankle_deg: f64, (deficit, lever): (f64, f64)) -> bool {
    let room_deg = SWING_DORSI_MAX_DEG - ankle_deg;
    if room_deg <= 0.05 {
        return false;
    }
    let wanted_deg = (deficit / lever.max(0.05)).min(1.0).asin().to_degrees() + 0.05;
    plan.ankle_deg.raise_at(s, wanted_deg.min(room_deg));
    plan.raises += 1;
    true
}

/// Share of the swing's end over which the toe's clearance above the ground ramps out (the
/// heel's and a stair nosing's ramp out over the last 0.15). The toe needs its full clearance
/// at mid-swing, where the foot passes lowest, not just before the heel lands: held to it
/// until 0.85 of the swing, a short step whose foot ends pitched toward rising ground (the
/// closing step of a stop on slope_up) kept its heel 10-15 cm up and dropped it in the last
/// five frames, the knee extending 9°/frame against the steady walk's 6.6 at the fastest.
const TOE_LANDING_RAMP: f64 = 0.35;

/// Most dorsiflexion (deg) the swing simulation asks of the ankle, where a toe needs lifting,
/// before it lifts the heel instead: the normative swing ankle peaks at 5.4-6.7 deg at 84-85 %
/// of the cycle from 0.8 to 1.6 m/s (data/normative/), and normal adults' at 0-5 deg (issue
/// 12's table). A raise moves a knot of the curve, which carries the samples beside it further.
/// At 7 deg (sessions 15-25) the default walk's ankle peaked at 6.0 deg, the toe's clearance
/// at 83-87 % of the cycle (the foot still pitched down, its heel 4-9 cm up) bought by the ankle
/// alone; at 5 it peaks at 4.7 (0.8 / 1.6 m/s: 7.8 -> 7.2, 7.2 -> 6.1 deg against people's 6.7 /
/// 5.9), the rest bought by the heel. With the cap alone the late-swing hip flexed up to 1.7 deg
/// more (at 90 % of the cycle); with the heel-height design refitted beside it, the hip runs
/// -1.7 to +1.0 deg of before from 74 to 94 % and its RMS against the norms +0.08 deg at 1.3 m/s
/// (docs/gait-model.md §12, session 26).
const SWING_DORSI_MAX_DEG: f64 = 5.0;

/// One sample of the swing simulation as a pass left it: the heel height and ankle it was
/// solved at, its target, and its leg pose once solved (a sample lifted for reach is not).
#[derive(Clone, Copy)]
struct SolvedSample {
    heel_height: f64,
    ankle_deg: f64,
    target: LegTarget,
    pose: Option<LegPose>,
}
