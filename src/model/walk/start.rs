//! The walk's first instant: the double support right after a right heel strike, in the
//! steady-state pose of the walk, so the first steps are not a start-up of their own.

use crate::model::body::Side;
use crate::model::gait_curves::{CurveName, CurveSet};
use crate::model::params::Resolved;
use crate::model::terrain::Terrain;
use crate::model::walk::ankle_pitch::foot_pitch_for_ankle;
use crate::model::walk::gait::{HEEL_RISE_DESIGN_STRIDE_M, MIN_STRIKE_ANGLE, place_footfall};
use crate::model::walk::heel_pad::HeelPad;
use crate::model::walk::leg::{LegPhase, LegPose, LegState, LegTarget, foot_rotation};
use glam::{DQuat, DVec3};

/// The two legs at the start, right then left: the right heel just struck at x = 0, the
/// left foot half a stride behind, already in heel rise on its toe joint. Their poses are
/// placeholders until the walker first solves them.
pub(crate) fn standing_start(terrain: &Terrain, r: &Resolved, design: &CurveSet) -> [LegState; 2] {
    let dims = &r.dims;
    let right = place_footfall(terrain, r, 0, Side::Right, 0.0);
    let step = 0.5 * r.stride_m;
    let left = place_footfall(terrain, r, -1, Side::Left, -step);
    // The right heel lands at the angle a steady step's swing would have brought it in at:
    // the design ankle curve's end on a leg reaching the heel from where a steady walk's
    // pelvis is at heel strike (mid double support's height, the mid-stance offset behind
    // the step's middle).
    let heel_rise_scale = r.stride_m / HEEL_RISE_DESIGN_STRIDE_M;
    let hip = DVec3::new(
        right.heel.x - (step / 2.0 - r.midstance_offset).max(0.0),
        right.heel.y + dims.standing_hip_height() - r.midstance_drop - r.vertical_range,
        0.0,
    );
    let design_strike = design.get(CurveName::SwingAnkle).eval(1.0).to_radians();
    let strike_angle =
        (foot_pitch_for_ankle(hip, right.heel, right.yaw, design_strike, r) - right.ground_angle).max(MIN_STRIKE_ANGLE);
    let placeholder = LegPose {
        hip: DVec3::ZERO,
        knee: DVec3::ZERO,
        ankle: DVec3::ZERO,
        swivel: DVec3::X,
        foot: DQuat::IDENTITY,
        toe: DQuat::IDENTITY,
        heel: DVec3::ZERO,
        ball: DVec3::ZERO,
        toe_tip: DVec3::ZERO,
        reached: true,
        target: LegTarget { ankle: DVec3::ZERO, pitch: 0.0, toe_bend: 0.0, yaw: 0.0, extra_heel_rise: 0.0, pad: 0.0 },
    };
    let left_ball = left.heel + foot_rotation(left.yaw, left.ground_angle) * (dims.ball_local() - dims.heel_local());
    [
        LegState {
            side: Side::Right,
            phase: LegPhase::LoadingResponse,
            cycle_start: 0.0,
            footfall: right,
            anchor: right.heel,
            strike_angle,
            heel_rise_scale,
            heel_rise_curve: design.get(CurveName::HeelRise).clone(),
            toe_off: r.toe_off,
            heel_rise: r.heel_rise,
            stance_rise: 0.0,
            stance_reach: r.reach_margin * dims.leg_reach(),
            pad: HeelPad::default(),
            swing: None,
            phase_serial: 0,
            pose: placeholder,
        },
        LegState {
            side: Side::Left,
            phase: LegPhase::HeelRise,
            cycle_start: -0.5,
            footfall: left,
            anchor: left_ball,
            strike_angle,
            heel_rise_scale,
            heel_rise_curve: design.get(CurveName::HeelRise).clone(),
            toe_off: r.toe_off,
            heel_rise: r.heel_rise,
            stance_rise: 0.0,
            stance_reach: r.reach_margin * dims.leg_reach(),
            pad: HeelPad::default(),
            swing: None,
            phase_serial: 0,
            pose: placeholder,
        },
    ]
}
