//! Changes during the walk: new parameters applied without a jump, each part at the moment
//! it can change unseen — the cycle curves bend from where they are playing and settle at a
//! cycle's end, the trajectory curves wait for the next pelvis key, and everything planned per
//! step takes the new values from the next toe-off.

use crate::model::curve::{Curve, LiveCurve};
use crate::model::gait_curves::CurveName;
use crate::model::params::WalkParams;
use crate::model::walk::gait::{cycle_targets, trajectory_curves};
use crate::model::walk::leg::{LegPhase, PhaseBounds};
use crate::model::walk::upper::ArmHang;
use crate::model::walk::{ModelError, Walker, check};

impl Walker {
    /// A cycle curve being played, in real units (for plots): pelvis obliquity, rotation,
    /// tilt (rad) and lateral (m); shoulder and elbow of the right arm (rad). While a change
    /// blends over a cycle (`LiveCurve::blend_to`) this is the curve it goes to; the walk
    /// plays [`Walker::live_value`].
    #[must_use]
    pub fn live_curve(&self, name: CurveName) -> Option<&Curve> {
        self.live(name).map(LiveCurve::playing)
    }

    /// The value a cycle curve of [`Walker::live_curve`] plays at cycle phase `x` (0 to 1),
    /// a blend under way included: the lab's chart drew the target at once while the walk
    /// still blended for a whole cycle.
    #[must_use]
    pub fn live_value(&self, name: CurveName, x: f64) -> Option<f64> {
        self.live(name).map(|c| c.eval(x))
    }

    fn live(&self, name: CurveName) -> Option<&LiveCurve> {
        let live = &self.gait.live;
        Some(match name {
            CurveName::PelvisObliquity => &live.obliquity,
            CurveName::PelvisRotation => &live.rotation,
            CurveName::PelvisTilt => &live.tilt,
            CurveName::PelvisLateral => &live.lateral,
            CurveName::Shoulder => &live.shoulder[0],
            CurveName::Elbow => &live.elbow[0],
            _ => return None,
        })
    }

    /// Applies new parameters during the walk without a jump: cycle curves change from the
    /// segment after the one playing, trajectory curves at the next pelvis key, everything
    /// planned per step (footfalls, swing, pelvis keys) from the next toe-off. Body and
    /// terrain cannot change under a walking body: returns false, and the caller restarts.
    pub fn set_params(&mut self, params: &WalkParams) -> Result<bool, ModelError> {
        self.set_params_at(params, self.phase)
    }

    /// [`Walker::set_params`] as at master phase `phase` (the walk's, or a phase boundary
    /// inside the update under way: the pace changes speed at heel strike).
    pub(super) fn set_params_at(&mut self, params: &WalkParams, phase: f64) -> Result<bool, ModelError> {
        if params.body != self.params.body || params.terrain != self.params.terrain {
            return Ok(false);
        }
        // What a new walker is built from, by the same checks (stairs or not, the phases in order).
        let (r, design) = check(params)?;
        let p_right = phase.rem_euclid(1.0);
        let p_left = (phase - 0.5).rem_euclid(1.0);
        self.gait.live.change_to(cycle_targets(&design, &r), p_right, p_left);
        let traj = trajectory_curves(&design);
        if traj.forward_ds_ms != self.gait.traj.forward_ds_ms
            || traj.forward_ms_ds != self.gait.traj.forward_ms_ds
            || traj.vertical_ms_ds != self.gait.traj.vertical_ms_ds
            || traj.vertical_ds_ms != self.gait.traj.vertical_ds_ms
        {
            self.pending_traj = Some(traj);
        }
        let mut r = r;
        let wanted = PhaseBounds { foot_flat: r.foot_flat, heel_rise: r.heel_rise, toe_off: r.toe_off };
        let bounded = self.bounded_phases(wanted, phase);
        self.held_phases = (bounded != wanted).then_some(wanted);
        (r.foot_flat, r.heel_rise, r.toe_off) = (bounded.foot_flat, bounded.heel_rise, bounded.toe_off);
        self.arm_hang = ArmHang::new(&r.dims, r.arm_spread, r.elbow_min_flex);
        if r.ik != self.gait.r.ik {
            for solver in &mut self.leg_solvers {
                solver.set_settings(r.ik);
            }
        }
        let hip_heights_changed = r.obliquity_range != self.gait.r.obliquity_range
            || r.tilt_range != self.gait.r.tilt_range
            || design.get(CurveName::PelvisObliquity) != self.gait.design.get(CurveName::PelvisObliquity)
            || design.get(CurveName::PelvisTilt) != self.gait.design.get(CurveName::PelvisTilt);
        self.gait.design = design;
        self.gait.r = r;
        self.params = params.clone();
        if hip_heights_changed {
            self.guard_swing_landing_again(phase);
        }
        self.guard_standing_leg_again(phase);
        Ok(true)
    }

    /// After any live change: the leg standing before its heel rise was guarded with the
    /// keys, pace and hip shape it was planned under. A change of pace moves its hip on to the
    /// heel rise at another speed: with the mid-stance key at the leg's reach, a change from
    /// 1.3 to 1.45 m/s asked as a leg passed 0.31 of its cycle left it out of reach for a
    /// frame (tests/gait_normal.rs, the change at frame 154: joint speed 1.52x and jerk 1.82x
    /// the steady walk's without this). Only keys not yet playing move.
    fn guard_standing_leg_again(&mut self, phase: f64) {
        let standing = self.legs.iter().find(|l| matches!(l.phase, LegPhase::LoadingResponse | LegPhase::Midstance));
        if let Some((side, strike)) = standing.map(|l| (l.side, l.cycle_start)) {
            self.guard_stance_reach(side, strike, None, phase);
        }
    }

    /// `wanted` as far as the legs let it be at master phase `phase`: a boundary must not
    /// jump behind a leg inside the phase it ends, and a swinging leg keeps the toe-off its
    /// swing is timed from.
    fn bounded_phases(&self, wanted: PhaseBounds, phase: f64) -> PhaseBounds {
        // The heel rise is each leg's own, frozen when its step was planned.
        let PhaseBounds { mut foot_flat, heel_rise, mut toe_off } = wanted;
        for leg in &self.legs {
            let q = phase - leg.cycle_start;
            match leg.phase {
                LegPhase::LoadingResponse => foot_flat = foot_flat.max(q),
                LegPhase::Midstance => {}
                LegPhase::HeelRise => toe_off = toe_off.max(q),
                LegPhase::Swing => toe_off = self.gait.r.toe_off,
            }
        }
        PhaseBounds { foot_flat, heel_rise, toe_off }
    }

    /// At a heel strike (master phase `at`), when no leg swings: the phase boundaries that a
    /// change held back for a leg inside its phase ([`Self::bounded_phases`]) take the
    /// parameters' own values, under the same rule. Held for good, a live change of speed made
    /// while a leg swung kept the old toe-off for the rest of the walk: after 1.3 -> 1.45 m/s
    /// double support stayed at 26.0 % of the cycle against a fresh 1.45 m/s walk's 24.5 %.
    pub(super) fn restore_phase_bounds(&mut self, at: f64) {
        let Some(wanted) = self.held_phases else { return };
        let bounded = self.bounded_phases(wanted, at);
        self.held_phases = (bounded != wanted).then_some(wanted);
        let r = &mut self.gait.r;
        (r.foot_flat, r.heel_rise, r.toe_off) = (bounded.foot_flat, bounded.heel_rise, bounded.toe_off);
    }

    /// Swaps in edited trajectory curves when the pelvis passes a key, so the segment being
    /// played never changes shape under it.
    pub(super) fn cross_key_boundaries(&mut self, to: f64) {
        if self.pending_traj.is_some() && self.plan.keys().any(|k| k.phase > self.phase && k.phase <= to) {
            self.gait.traj = self.pending_traj.take().expect("checked");
        }
    }
}
