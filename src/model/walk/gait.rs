//! The walk's rules at one moment, without its clock: the resolved parameters, the design
//! curves and the live cycle curves, and what they give — the pelvis under a plan, a leg's IK
//! target in each phase, a stance leg projected forward.
//!
//! Why its own type: the optimiser costs candidate pelvis positions by running exactly this
//! code forward (spec §8), and must borrow it without the [`Walker`](super::Walker) that
//! calls the optimiser. The walker owns one and delegates to it.

use crate::model::body::{BodyDims, Side};
use crate::model::curve::{Curve, LiveCurve};
use crate::model::gait_curves::{CurveName, CurveSet};
use crate::model::ik::softened_distance;
use crate::model::params::Resolved;
use crate::model::terrain::Terrain;
use crate::model::walk::ankle_pitch::foot_pitch_for_ankle;
use crate::model::walk::leg::{Footfall, LegPhase, LegState, LegTarget, SwingPlan, foot_rotation, led_fraction};
use crate::model::walk::pelvis::{PelvisPlan, PelvisPose, TrajectoryCurves};
use crate::model::walk::reach_angles::{REACH_RESCUE_GAP, heel_rise_to_reach, heel_rocker_to_reach};
use glam::DVec3;

/// Stride the heel-rise curve is designed for (m) [fig 6.5].
pub const HEEL_RISE_DESIGN_STRIDE_M: f64 = 1.8;
/// Least foot–ground angle at heel strike (rad): the heel, not the toe, lands first.
pub const MIN_STRIKE_ANGLE: f64 = 0.035;

/// Share of the stance leg's reach limit from which the heel-rise phase eases the leg toward
/// the limit instead of clamping at it (for equal bones: knee 11.5° down to the 3.2° limit).
pub(crate) const REACH_EASE: f64 = 0.995;

/// Share of the heel-rise phase over which [`REACH_EASE`]'s softening comes in. Midstance
/// leaves the knee at the reach limit (3.2°) and the softening holds it near 7°; brought in
/// over 0.1 of the phase (before session 21) the knee flexed those 4° within two frames, a
/// notch at 30-33 % of the cycle in every joint plot: its largest acceleration there 2.2 /
/// 5.6 / 7.0 / 7.7°/frame² at 0.8 / 1.3 / 1.6 / 1.75 m/s, the steady walk's largest
/// anywhere 7.9 at 1.6. Over 0.3: 1.1 / 3.2 / 4.3 / 4.5, the joint curves' RMS against the
/// norms within 0.1° but the 1.6 m/s hip (+0.14). A knee eased nearer the limit (0.998,
/// people's knee goes on straightening to 3° at 40-44 %) took stairs_up's push-off from 7.8
/// to 5.2° and the fast walks' hip 0.3° further from the norms (docs/gait-model.md §12).
const HEEL_RISE_EASE_IN: f64 = 0.3;

/// The cycle curves played live, in real units (rad or m).
#[derive(Clone, Debug)]
pub(crate) struct LiveCurves {
    pub(crate) obliquity: LiveCurve,
    pub(crate) rotation: LiveCurve,
    pub(crate) tilt: LiveCurve,
    pub(crate) lateral: LiveCurve,
    pub(crate) shoulder: [LiveCurve; 2],
    pub(crate) elbow: [LiveCurve; 2],
    /// The master cycle the pelvis curves are playing (the integer part of its phase): a
    /// later phase evaluates what will play then.
    pub(crate) pelvis_cycle: i64,
}

impl LiveCurves {
    /// Plays `targets` (in [`cycle_targets`] order) from the start, unchanged.
    pub(crate) fn new(targets: [Curve; 6]) -> Self {
        let [obliquity, rotation, tilt, lateral, shoulder, elbow] = targets;
        LiveCurves {
            obliquity: LiveCurve::new(obliquity),
            rotation: LiveCurve::new(rotation),
            tilt: LiveCurve::new(tilt),
            lateral: LiveCurve::new(lateral),
            shoulder: [LiveCurve::new(shoulder.clone()), LiveCurve::new(shoulder)],
            elbow: [LiveCurve::new(elbow.clone()), LiveCurve::new(elbow)],
            pelvis_cycle: 0,
        }
    }

    /// Starts changing every curve toward `targets` (in [`cycle_targets`] order): the tilt and
    /// the arms from where they are now (the pelvis and the right arm at `p_right` of their
    /// cycle, the left arm at `p_left`, half a cycle behind), each bending from its own present;
    /// the obliquity from the next wrap; the rotation and the side sway over the whole cycle
    /// after the next wrap.
    pub(crate) fn change_to(&mut self, targets: [Curve; 6], p_right: f64, p_left: f64) {
        let [obliquity, rotation, tilt, lateral, shoulder, elbow] = targets;
        // The obliquity raises and lowers the hips, whose reach the pelvis keys already
        // planned were guarded with: it changes from the next wrap, where the planner looks
        // ahead with the curve that will play. Mid-cycle, a faster and wider walk asked in the
        // last frames of a swing lifted the landing hip out of reach at heel strike (the
        // norms' obliquity has the landing side up), the pelvis keys of the strike playing.
        self.obliquity.change_at_wrap(obliquity);
        // The rotation and the side sway move a standing hip too: blended over the next whole
        // cycle, not switched segment by segment (see `LiveCurve::blend_to`).
        self.rotation.blend_to(rotation);
        self.tilt.change_to(tilt, p_right);
        self.lateral.blend_to(lateral);
        self.shoulder[0].change_to(shoulder.clone(), p_right);
        self.shoulder[1].change_to(shoulder, p_left);
        self.elbow[0].change_to(elbow.clone(), p_right);
        self.elbow[1].change_to(elbow, p_left);
    }

    /// Ends the cycle of the curves that `side`'s cycle times: its arm's, and with the right
    /// leg's (the master phase) the pelvis's. A change under way finishes only here, at a
    /// cycle's end, where the played curve meets its target without a jump.
    pub(crate) fn wrap(&mut self, side: Side) {
        let i = side.index();
        self.shoulder[i].wrap();
        self.elbow[i].wrap();
        if side == Side::Right {
            for c in [&mut self.obliquity, &mut self.rotation, &mut self.tilt, &mut self.lateral] {
                c.wrap();
            }
            self.pelvis_cycle += 1;
        }
    }
}

/// Real-unit cycle curves for a parameter set.
pub(crate) fn cycle_targets(design: &CurveSet, r: &Resolved) -> [Curve; 6] {
    let half = |name: CurveName, range: f64| design.get(name).scaled(1.0, 0.5 * range);
    let mut elbow = half(CurveName::Elbow, r.elbow_range);
    elbow.offset_y(r.elbow_min_flex + 0.5 * r.elbow_range);
    [
        half(CurveName::PelvisObliquity, r.played_obliquity_range()),
        half(CurveName::PelvisRotation, r.rotation_range),
        half(CurveName::PelvisTilt, r.tilt_range),
        half(CurveName::PelvisLateral, r.lateral_range),
        half(CurveName::Shoulder, r.shoulder_range),
        elbow,
    ]
}

/// The pelvis's forward and vertical design curves.
#[must_use]
pub(crate) fn trajectory_curves(design: &CurveSet) -> TrajectoryCurves {
    TrajectoryCurves {
        forward_ds_ms: design.get(CurveName::PelvisForwardDsMs).clone(),
        forward_ms_ds: design.get(CurveName::PelvisForwardMsDs).clone(),
        vertical_ms_ds: design.get(CurveName::PelvisVertical).clone(),
        vertical_ds_ms: design.get(CurveName::PelvisVerticalDsMs).clone(),
    }
}

/// The walk's rules at one moment (see the module docs).
#[derive(Clone, Debug)]
pub struct Gait {
    pub(crate) r: Resolved,
    pub(crate) design: CurveSet,
    pub(crate) traj: TrajectoryCurves,
    pub(crate) live: LiveCurves,
}

impl Gait {
    /// The resolved parameters in force.
    #[must_use]
    pub fn resolved(&self) -> &Resolved {
        &self.r
    }

    /// The design curves in force (normalised, as drawn in the thesis's figures).
    #[must_use]
    pub fn design_curves(&self) -> &CurveSet {
        &self.design
    }

    /// Forward position and height of the pelvis at `phase` under a given plan (the optimiser
    /// tries candidate plans; the rest of the pose does not depend on the plan).
    #[must_use]
    pub fn pelvis_position_with_plan(&self, plan: &PelvisPlan, phase: f64) -> (f64, f64) {
        plan.position(phase, &self.traj)
    }

    /// The pelvis at `phase` under a given plan.
    #[must_use]
    pub fn pelvis_with_plan(&self, plan: &PelvisPlan, phase: f64) -> PelvisPose {
        let (x, y) = plan.position(phase, &self.traj);
        let p = phase.rem_euclid(1.0);
        // Setting off and at the walk's end the sway and the rotations fade from and to
        // standing (zero).
        let keep = plan.walking_weight(phase);
        let live = &self.live;
        // Obliquity and tilt raise and lower the hips: a phase in a later cycle takes the
        // curves that will play then, so that a step's reach is guarded with the hip heights
        // the leg will meet (a live `walk.sway` edit changes the next cycle's obliquity). The
        // sideways sway and the rotation, which a speed change moves too, keep this cycle's:
        // looking ahead with them too moved the optimiser's choices on a scheduled walk and
        // raised its pelvis's velocity jump at a speed change from 1.47x to 1.73x the steady
        // walk's, and reach did not need them (the live-change sweep in tests/gait_normal.rs).
        let ahead = (phase.floor() as i64) > live.pelvis_cycle;
        let hip_height_curve = |curve: &LiveCurve| if ahead { curve.eval_next_cycle(p) } else { curve.eval(p) };
        let z = live.lateral.eval(p) * keep;
        let z = plan.weight_shift(phase).map_or(z, |shift| z + shift);
        PelvisPose::new(
            DVec3::new(x, y, z),
            live.rotation.eval(p) * keep,
            hip_height_curve(&live.obliquity) * keep,
            hip_height_curve(&live.tilt) * keep,
            0.5 * self.r.dims.hip_width,
        )
    }

    /// The IK target of a leg in state `leg` (real, or projected by the optimiser) at master
    /// phase `phase`: the one place where the four phases turn into ankle targets.
    #[must_use]
    pub fn target_of(&self, leg: &LegState, phase: f64, hip: DVec3) -> LegTarget {
        let pad = super::heel_pad::compression_of(leg, phase - leg.cycle_start);
        if pad == 0.0 {
            return self.rigid_target_of(leg, phase, hip);
        }
        // The rigid foot's target for a hip `pad` higher is the padded foot's, `pad` higher:
        // every reach rule of the rigid foot then holds for the padded one as written.
        let mut target = self.rigid_target_of(leg, phase, hip + DVec3::new(0.0, pad, 0.0));
        target.ankle.y -= pad;
        target.pad = pad;
        target
    }

    fn rigid_target_of(&self, leg: &LegState, phase: f64, hip: DVec3) -> LegTarget {
        let r = &self.r;
        let dims = &r.dims;
        let q = phase - leg.cycle_start;
        let ff = &leg.footfall;
        match leg.phase {
            LegPhase::LoadingResponse => {
                let s = (q / r.foot_flat).clamp(0.0, 1.0);
                let pitch = ff.ground_angle + leg.strike_angle * (1.0 - s);
                let pitch = heel_rocker_to_reach(leg.anchor, ff.yaw, pitch, dims.heel_local(), hip, dims.leg_reach());
                let ankle = leg.anchor - foot_rotation(ff.yaw, pitch) * dims.heel_local();
                LegTarget { ankle, pitch, toe_bend: 0.0, yaw: ff.yaw, extra_heel_rise: 0.0, pad: 0.0 }
            }
            LegPhase::Midstance => {
                // Past full reach (measured only after big pace changes: the guard keeps a
                // planned step's hip within the margin) the heel leaves the ground just
                // enough, the ball planted.
                let limit = dims.leg_reach() - REACH_RESCUE_GAP;
                let ball = || leg.anchor + foot_rotation(ff.yaw, ff.ground_angle) * dims.ball_local();
                let angle = if hip.distance(leg.anchor) > limit {
                    heel_rise_to_reach(ball(), ff, dims.ball_local(), hip, limit, 0.0).unwrap_or(0.0)
                } else {
                    0.0
                };
                let ankle = if angle == 0.0 {
                    leg.anchor
                } else {
                    ball() - foot_rotation(ff.yaw, ff.ground_angle - angle) * dims.ball_local()
                };
                LegTarget {
                    ankle,
                    pitch: ff.ground_angle - angle,
                    toe_bend: angle,
                    yaw: ff.yaw,
                    extra_heel_rise: angle,
                    pad: 0.0,
                }
            }
            LegPhase::HeelRise => {
                let s = ((q - leg.heel_rise) / (leg.toe_off - leg.heel_rise)).clamp(0.0, 1.0);
                let curve_angle = (leg.heel_rise_curve.eval(s) * leg.heel_rise_scale).to_radians().max(0.0);
                let ankle_at =
                    |angle: f64| leg.anchor - foot_rotation(ff.yaw, ff.ground_angle - angle) * dims.ball_local();
                let limit = r.reach_margin * dims.leg_reach();
                let mut angle = curve_angle;
                // The hip moving past what the curve's heel rise lets the leg reach makes the
                // foot roll further over the toes. Not by clamping the leg at its limit — that
                // pins the knee with a corner in every joint's angle, which the optimiser's
                // squared accelerations then see as a spike wherever it falls between two
                // samples — but eased in: from REACH_EASE of the limit on, the hip-ankle
                // distance follows the softening curve that approaches the limit with slope 1
                // at its start, ramped in over the first [`HEEL_RISE_EASE_IN`] of the phase so
                // that nothing jumps when heel rise begins.
                let d0 = hip.distance(ankle_at(angle));
                let ramp = (s / HEEL_RISE_EASE_IN).clamp(0.0, 1.0);
                let ramp = ramp * ramp * (3.0 - 2.0 * ramp);
                let eased = d0 - ramp * (d0 - softened_distance(d0, limit, REACH_EASE));
                let wanted = eased.min(limit);
                if d0 > wanted + 1e-12
                    && let Some(reaching) = heel_rise_to_reach(leg.anchor, ff, dims.ball_local(), hip, wanted, angle)
                {
                    angle = reaching;
                }
                LegTarget {
                    ankle: ankle_at(angle),
                    pitch: ff.ground_angle - angle,
                    toe_bend: angle,
                    yaw: ff.yaw,
                    extra_heel_rise: angle - curve_angle,
                    pad: 0.0,
                }
            }
            LegPhase::Swing => {
                let plan = leg.swing.as_ref().expect("a swinging leg has a plan");
                let s = ((q - leg.toe_off) / (1.0 - leg.toe_off)).clamp(0.0, 1.0);
                swing_target(plan, s, leg.side, r, hip)
            }
        }
    }

    /// Moves a copy of a stance leg's state forward to master phase `phase` through its stance
    /// phase changes: what the leg will be doing then, by the same code the walk runs. Stops
    /// before toe-off (a swing needs planning, not projection). The pelvis does not enter: each
    /// stance phase starts from the flat foot's contact point.
    pub fn project_stance(&self, leg: &mut LegState, phase: f64) {
        loop {
            let end = match leg.phase {
                LegPhase::LoadingResponse => self.r.foot_flat,
                LegPhase::Midstance => leg.heel_rise,
                LegPhase::HeelRise | LegPhase::Swing => return,
            };
            let boundary = leg.cycle_start + end;
            if phase < boundary {
                return;
            }
            enter_stance_phase(leg, &self.r, &self.design);
        }
    }
}

impl AsRef<Gait> for Gait {
    fn as_ref(&self) -> &Gait {
        self
    }
}

/// The footfall of step `step` on `side`, meant for `nominal_x` on unbroken ground and
/// settled on the terrain (on stairs, onto one tread), with the ground's height and slope
/// there. The start of the walk and every step's planning place their feet here, so the two
/// can never disagree on where a foot stands.
#[must_use]
pub fn place_footfall(terrain: &Terrain, r: &Resolved, step: i64, side: Side, nominal_x: f64) -> Footfall {
    let yaw = -side.sign() * r.turnout;
    let foot_x = r.dims.foot_length * yaw.cos();
    let x = terrain.settle_footfall(nominal_x, foot_x, r.clearance);
    // The slope along the foot, not along x: a foot turned out by the yaw runs 1 / cos(yaw)
    // as far for the same rise, and pitched at the slope along x its toe tip went 0.2 mm
    // under slope_down's 10 % grade through every stance (0.12 mm on rough). And to where
    // the pitched foot's toe tip is, cos(pitch) as far forward as a flat one's: across the
    // slope's first corner the chord to the flat foot's tip left it 0.013 mm under.
    let along_foot = |toe_x: f64| (terrain.angle_between(x, x + toe_x).tan() * yaw.cos()).atan();
    let ground_angle = along_foot(foot_x * along_foot(foot_x).cos());
    Footfall {
        step,
        side,
        heel: DVec3::new(x, terrain.height(x), side.sign() * 0.5 * r.step_width_m),
        ground_angle,
        yaw,
        nominal_x,
    }
}

/// Moves a stance leg into its next stance phase: midstance holds the ankle of the foot laid
/// flat about its heel; heel rise holds the toe joint of the flat foot and freezes the
/// heel-rise curve and its stride scale (the design at the walk's speed then).
pub fn enter_stance_phase(leg: &mut LegState, r: &Resolved, design: &CurveSet) {
    match leg.phase {
        // The flat foot's ankle and ball, not the target's: a leg rolled to reach at the
        // boundary (`heel_rocker_to_reach`, the mid-stance heel rescue) keeps its contact point.
        LegPhase::LoadingResponse => {
            let flat = foot_rotation(leg.footfall.yaw, leg.footfall.ground_angle);
            leg.anchor -= flat * r.dims.heel_local();
            leg.phase = LegPhase::Midstance;
        }
        LegPhase::Midstance => {
            leg.anchor += foot_rotation(leg.footfall.yaw, leg.footfall.ground_angle) * r.dims.ball_local();
            leg.heel_rise_scale = r.stride_m / HEEL_RISE_DESIGN_STRIDE_M;
            leg.heel_rise_curve.clone_from(design.get(CurveName::HeelRise));
            leg.toe_off = r.toe_off;
            leg.phase = LegPhase::HeelRise;
        }
        LegPhase::HeelRise | LegPhase::Swing => {}
    }
}

/// The swing curves' values at one swing fraction: all a swing target takes from its plan's
/// curves. The swing simulation asks each of its instants again after each raise of the heel
/// curve and the reach guard under each lowered pelvis, so they are worked out once there.
#[derive(Clone, Copy, Debug)]
pub struct SwingCurvesAt {
    /// Swing fraction, 0 at toe-off, 1 at heel strike.
    pub s: f64,
    /// Forward progress from the toe-off heel to the footfall (0 to 1).
    pub progress: f64,
    /// Weight toward the hip line (0 to 1).
    pub lateral: f64,
    /// Heel height above the toe-off ground (m).
    pub heel_height: f64,
    /// The ankle against the shank (deg, dorsiflexion +).
    pub ankle_deg: f64,
}

impl SwingCurvesAt {
    /// `plan`'s curves at swing fraction `s`.
    #[must_use]
    pub fn of(plan: &SwingPlan, s: f64) -> Self {
        SwingCurvesAt {
            s,
            progress: plan.progress(s),
            lateral: plan.lateral.eval(s),
            heel_height: plan.heel_height.eval(s),
            ankle_deg: plan.ankle_deg.eval(s),
        }
    }
}

/// Over what share of the swing the foot's toe-off pitch rate dies away (an exponential's time
/// constant) while the swing takes the foot over from the stance ([`swing_target`]). Held at
/// its toe-off pitch, a foot that had pitched 7-8° a frame into toe-off stopped at once and
/// the shank swinging back under it dorsiflexed the ankle for a frame: a notch at toe-off in
/// every joint plot (1.3 m/s: -3.7 / -11.2 / -8.8 / -11.2 / -13.3° on the frames from 0.606 to
/// 0.672 of the cycle) and the walk's largest joint acceleration (12.2°/frame² at 1.3 m/s).
/// Carried on at the full rate (a straight line) the foot overshot: push-off 23° on the default
/// walk, people's 14.5. Dying away over 0.02 of the swing (under half a frame at 1.3 m/s; at
/// most 3.4° more): push-off 13.3 -> 14.1° (brisk 19.2 -> 19.5, people's range 12-20), the ankle's
/// largest acceleration 12.2 -> 9.1°/frame² (docs/gait-model.md §12, session 22).
const PITCH_CARRY_SWING_SHARE: f64 = 0.02;

/// The swing leg's target at swing fraction `s` [6.3.2]: heel forward on the forward curve
/// scaled by the distance from the toe-off heel to the footfall, sideways from the step-width
/// line toward the hip line and back, up on the heel-height curve; the foot set by the ankle
/// curve against the shank the leg will have (from `hip`); toes back to neutral over the first
/// fifth of the swing.
#[must_use]
pub fn swing_target(plan: &SwingPlan, s: f64, side: Side, r: &Resolved, hip: DVec3) -> LegTarget {
    swing_target_at(plan, &SwingCurvesAt::of(plan, s), side, r, hip)
}

/// [`swing_target`] with the curves' values at its instant already worked out.
#[must_use]
// Run in the planner's swing simulation and reach guard, hundreds of times a step; with the
// planner in its own file (another codegen unit) it is only inlined there when marked.
#[inline]
pub fn swing_target_at(plan: &SwingPlan, at: &SwingCurvesAt, side: Side, r: &Resolved, hip: DVec3) -> LegTarget {
    let s = at.s;
    let from = plan.heel_from;
    let to = plan.to.heel;
    let progress = at.progress;
    let x = plan.planned_heel_x(progress);
    let line_z = from.z + (to.z - from.z) * progress;
    let hip_line_z = side.sign() * 0.5 * r.dims.hip_width;
    let z = line_z + (hip_line_z - line_z) * at.lateral;
    let y = plan.ground_from + at.heel_height;
    let mut heel = DVec3::new(x, y, z);
    let mut pitch = swing_pitch(plan, at, r, hip, heel);
    // Below a stair's nosing the foot is held behind its riser (the heel moved back). The
    // front of the foot is within a foot's length of the heel: where that cannot bind, nothing is worked out (the
    // floor below is on every level swing, and this runs for every sample and frame).
    let reach = r.dims.foot_length;
    if let Some(riser) = plan.riser.filter(|h| heel.x + reach > h.front_limit_x(heel.y - reach, s)) {
        let over = |heel: DVec3, p: DVec3| heel.x + p.x - riser.front_limit_x(heel.y + p.y, s);
        push_foot_front(plan, at, r, hip, (&mut heel, &mut pitch), DVec3::NEG_X, over);
    }
    // Over the ground it leaves the front of the foot is lifted (the heel raised) where it
    // would dip into it.
    let floor = plan.toe_floor;
    if heel.y - reach < floor.highest_between(heel.x - reach, heel.x + reach, s) {
        let under = |heel: DVec3, p: DVec3| floor.lowest_y(heel.x + p.x, s) - heel.y - p.y;
        push_foot_front(plan, at, r, hip, (&mut heel, &mut pitch), DVec3::Y, under);
    }
    let ankle = heel - foot_rotation(plan.to.yaw, pitch) * r.dims.heel_local();
    LegTarget {
        ankle,
        pitch,
        toe_bend: swing_toe_bend(plan, s, pitch),
        yaw: plan.to.yaw,
        extra_heel_rise: 0.0,
        pad: 0.0,
    }
}

/// Moves a swing foot's heel along `direction` by the most that the front of the foot (ball,
/// toe tip, from the heel) is past where it may be (`excess` of the heel and that point), its pitch
/// following the heel's new place; twice, as the shank, and with it the pitch, follow the heel.
fn push_foot_front(
    plan: &SwingPlan,
    at: &SwingCurvesAt,
    r: &Resolved,
    hip: DVec3,
    (heel, pitch): (&mut DVec3, &mut f64),
    direction: DVec3,
    excess: impl Fn(DVec3, DVec3) -> f64,
) {
    for _ in 0..2 {
        let most =
            foot_front(plan, at.s, *pitch, &r.dims).map(|p| excess(*heel, p)).into_iter().fold(0.0_f64, f64::max);
        if most <= 0.0 {
            break;
        }
        *heel += direction * most;
        *pitch = swing_pitch(plan, at, r, hip, *heel);
    }
}

/// The swing foot's pitch at `at` with its heel at `heel` ([`swing_target_at`]).
#[inline]
fn swing_pitch(plan: &SwingPlan, at: &SwingCurvesAt, r: &Resolved, hip: DVec3, heel: DVec3) -> f64 {
    // A lagging swing (a riser ahead, [`SwingPlan::lead`] below 0) hands the pitch over on its
    // heel's clock: flattening at once swung the toe 6 cm forward about the heel.
    let (s, hand_over_s) = (at.s, if plan.lead < 0.0 { led_fraction(at.s, plan.lead) } else { at.s });
    let mut pitch = foot_pitch_for_ankle(hip, heel, plan.to.yaw, at.ankle_deg.to_radians(), r);
    // Just after toe-off the foot keeps its pitch, carried on briefly at the rate it left the
    // ground with ([`PITCH_CARRY_SWING_SHARE`]), and hands it to the ankle curve over the
    // first 15 % of the swing. Hung from the shank at once, a leg still stretched from the
    // push-off feeds on itself: the hip runs ahead, the shank leans, the steeper foot drops
    // the ankle further from the hip (on stairs up the knee locked out of reach).
    if hand_over_s < 0.15 {
        let w = hand_over_s / 0.15;
        let carried = plan.pitch_from
            + plan.pitch_rate_from * PITCH_CARRY_SWING_SHARE * (1.0 - (-hand_over_s / PITCH_CARRY_SWING_SHARE).exp());
        pitch = carried + w * w * (3.0 - 2.0 * w) * (pitch - carried);
    }
    // The heel must land first even where the pelvis ends up lower or further back than the
    // planner foresaw (the optimiser and the reach guard move it after the ankle curve is
    // set), or the toe strikes into the tread: over the last fifth of the swing the foot is
    // eased up to the least strike angle where the shank would leave it below.
    let floor = plan.to.ground_angle + MIN_STRIKE_ANGLE;
    if pitch < floor && s > 0.8 {
        let w = ((s - 0.8) / 0.2).clamp(0.0, 1.0);
        pitch += w * w * (3.0 - 2.0 * w) * (floor - pitch);
    }
    pitch
}

/// The swing toes' bend at `s` with the foot at `pitch`: back to neutral over the first fifth
/// of the swing, but never pointing below the horizontal while the foot is still pitched
/// down: a toe tip dipping back into the ground it just left is what a literal linear return
/// would draw.
fn swing_toe_bend(plan: &SwingPlan, s: f64, pitch: f64) -> f64 {
    (plan.toe_bend_from * (1.0 - s / 0.2).max(0.0)).max(-pitch).max(0.0)
}

/// The ball and the toe tip of a swing foot at `pitch` from its heel (m, sagittal x and y):
/// the front of the foot, which meets a riser first.
///
/// In the plane, not by quaternions: the foot's rotation is its yaw's about the vertical
/// after its pitch's about z (`foot_rotation`), and the toes' bend is about the same z, so
/// the ball is `(heel→ball) · (cos pitch · cos yaw, sin pitch)` and the toe segment the same at
/// `pitch + bend` (the swing target runs this for every early sample on stairs; with two
/// quaternions a call the stairs_up step's planning took about 4 µs more, of a 100 µs budget).
fn foot_front(plan: &SwingPlan, s: f64, pitch: f64, dims: &BodyDims) -> [DVec3; 2] {
    let cos_yaw = plan.to.yaw.cos();
    let along = |length: f64, angle: f64| {
        let (sin, cos) = angle.sin_cos();
        DVec3::new(length * cos * cos_yaw, length * sin, 0.0)
    };
    let ball = along((dims.ball_local() - dims.heel_local()).x, pitch);
    [ball, ball + along(dims.toe_length(), pitch + swing_toe_bend(plan, s, pitch))]
}

/// The shank's sagittal angle (rad, from straight down, its lower end forward +) of a
/// two-bone leg from `hip` to `ankle` with the knee forward of the hip–ankle line — the
/// analytic IK's answer, in the walking plane. A neutral foot (ankle 0) is pitched by this.
#[must_use]
pub fn shank_angle(hip: DVec3, ankle: DVec3, thigh: f64, shank: f64) -> f64 {
    let d = ankle - hip;
    let length = d.x.hypot(d.y).clamp((thigh - shank).abs() + 1e-9, thigh + shank - 1e-9);
    let toward_ankle = d.x.atan2(-d.y);
    let at_ankle = ((shank * shank + length * length - thigh * thigh) / (2.0 * shank * length)).clamp(-1.0, 1.0).acos();
    toward_ankle - at_ankle
}
