//! The walk's parameters, typed and in the config's units (spec §10).
//!
//! Fields that are `Option` are *derived* when absent: the high-level knobs (`walk.speed_mps`,
//! `walk.sway`, body height) fill them in [`WalkParams::resolve`]. Setting one in the config
//! overrides the derivation for that field only. The config module maps keys, ranges and
//! docs onto these fields; the model never sees a key string.

use crate::model::body::{BodyDims, Sex};
use crate::model::ik::IkSettings;
pub use crate::model::ik::params::IkParams;
use crate::model::schedule::PaceEntry;
use crate::model::speed_laws::{
    WALK_RATIO_PER_175, double_support_key_share, heel_pad_mm, heel_rise_phase, midstance_drop_cm, midstance_offset_cm,
    obliquity_range_deg, stance_rise, swing_lead, vertical_range_cm,
};
use crate::model::terrain::{LEAST_CLEARANCE_M, TerrainKind};
use std::collections::BTreeMap;

/// Default extra heel rise past the curve (deg) that a candidate may ask of a stance leg
/// beyond what the fixed rule's position asks (what the fixed rule itself asks is in
/// benches/README.md, "Optimiser allowances"); `optimiser.heel_rise_slack_deg`.
pub(crate) const HEEL_RISE_SLACK_DEG: f64 = 0.5;

/// Default hip extension (deg) that a candidate may ask of a stance leg beyond what the fixed
/// rule's position asks; `optimiser.hip_extension_slack_deg`. Why 5°: with no slack the
/// optimiser's whole gain on a flat walk would be a longer push-off, so it keeps the fixed
/// rule; 5° lets it choose while keeping hip extension in the normal range (the measured
/// trade-off is in benches/README.md, "optimiser allowances").
pub(crate) const HIP_EXTENSION_SLACK_DEG: f64 = 5.0;

/// `[body]`.
#[derive(Clone, Debug, PartialEq)]
#[allow(missing_docs)]
pub struct BodyParams {
    pub(crate) height_m: f64,
    pub(crate) sex: Sex,
    pub(crate) thigh_m: Option<f64>,
    pub(crate) shank_m: Option<f64>,
    pub(crate) ankle_height_m: Option<f64>,
    pub(crate) foot_length_m: Option<f64>,
    pub(crate) upper_arm_m: Option<f64>,
    pub(crate) forearm_m: Option<f64>,
    pub(crate) hand_m: Option<f64>,
    pub(crate) hip_width_m: Option<f64>,
    pub(crate) shoulder_width_m: Option<f64>,
    pub(crate) trunk_m: Option<f64>,
}

/// `[walk]`.
#[derive(Clone, Debug, PartialEq)]
#[allow(missing_docs)]
pub struct WalkGroup {
    pub speed_mps: f64,
    pub sway: f64,
    pub stride_m: Option<f64>,
    pub cadence_spm: Option<f64>,
    pub step_width_m: Option<f64>,
}

/// `[pelvis]`.
#[derive(Clone, Debug, PartialEq)]
#[allow(missing_docs)]
pub struct PelvisParams {
    pub(crate) rotation_range_deg: Option<f64>,
    pub(crate) obliquity_range_deg: Option<f64>,
    pub tilt_range_deg: f64,
    pub(crate) vertical_range_cm: Option<f64>,
    pub(crate) lateral_range_cm: Option<f64>,
    pub(crate) midstance_drop_cm: Option<f64>,
    pub(crate) midstance_offset_cm: Option<f64>,
    pub(crate) stance_rise: Option<f64>,
    pub(crate) trunk_lean_deg: f64,
    pub(crate) rest_tilt_deg: f64,
}

/// `[legs]`.
#[derive(Clone, Debug, PartialEq)]
#[allow(missing_docs)]
pub struct LegParams {
    pub(crate) foot_flat: f64,
    pub heel_rise: Option<f64>,
    pub(crate) toe_off: Option<f64>,
    pub(crate) turnout_deg: f64,
    pub knee_lift_cm: f64,
    pub(crate) clearance_cm: f64,
    pub(crate) heel_pad_mm: Option<f64>,
}

/// `[arms]`.
#[derive(Clone, Debug, PartialEq)]
#[allow(missing_docs)]
pub struct ArmParams {
    pub(crate) shoulder_range_deg: Option<f64>,
    pub(crate) elbow_range_deg: Option<f64>,
    pub(crate) elbow_min_flex_deg: f64,
    pub(crate) spread_deg: f64,
    pub(crate) counter_rotation_pct: f64,
}

/// How the pelvis position at double support is searched for (spec §8).
#[derive(
    Clone, Copy, Debug, PartialEq, Eq, strum::IntoStaticStr, strum::EnumString, strum::VariantArray, strum::EnumCount,
)]
#[strum(serialize_all = "snake_case")]
pub enum SearchMethod {
    /// The thesis's two levels: evenly spaced candidates, then a finer set around the best.
    Thesis,
    /// The thesis's first level, then the second level's budget spent by golden sections
    /// in the bracket around its best (the thesis's grid where that bracket's ends are both
    /// infeasible): never more evaluations than the thesis, never a higher cost.
    Golden,
    /// As `Golden`, with parabolic steps through the bracket where all three costs are known.
    Brent,
    /// The thesis's two levels, then Brent's method on the position to the tolerance, on
    /// the height, and on the position again: the deepest and slowest search
    /// (Chung & Hahn search both).
    Joint,
}

crate::model::variants::named_variants!(SearchMethod);

/// How joint accelerations are summed into the cost.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CostForm {
    /// Σ W·θ̈²·Δt: smooth, the standard form.
    Squared,
    /// Σ W·|θ̈|·Δt: the thesis's literal integral of the second derivative.
    Absolute,
}

/// `[optimiser]`: the pelvis-acceleration optimisation (spec §8).
#[derive(Clone, Debug, PartialEq)]
#[allow(missing_docs)]
pub struct OptimiserParams {
    pub enabled: bool,
    pub method: SearchMethod,
    pub candidates: u32,
    pub(crate) refine: u32,
    pub cost: CostForm,
    pub samples: u32,
    pub(crate) range_pct: f64,
    pub tolerance_mm: f64,
    pub weight_hip: f64,
    pub weight_knee: f64,
    pub weight_ankle: f64,
    pub(crate) heel_rise_slack_deg: f64,
    pub(crate) hip_extension_slack_deg: f64,
}

/// The kind of ground in `[terrain]`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[allow(missing_docs)]
pub enum TerrainChoice {
    Flat,
    Stairs,
    Slope,
    Random,
}

/// `[terrain]`: every kind's settings, so switching kinds keeps the others' values.
#[derive(Clone, Debug, PartialEq)]
#[allow(missing_docs)]
pub struct TerrainParams {
    pub kind: TerrainChoice,
    pub(crate) start_x_m: f64,
    pub rise_m: f64,
    pub run_m: f64,
    pub count: u32,
    pub up: bool,
    pub grade_pct: f64,
    pub seed: u64,
    pub(crate) roughness: f64,
    pub(crate) amplitude_m: f64,
    pub(crate) segment_m: f64,
    pub(crate) length_m: f64,
}

impl TerrainParams {
    /// The model's terrain description for the chosen kind.
    #[must_use]
    pub fn kind(&self) -> TerrainKind {
        match self.kind {
            TerrainChoice::Flat => TerrainKind::Flat,
            TerrainChoice::Stairs => TerrainKind::Stairs {
                rise_m: self.rise_m,
                run_m: self.run_m,
                count: self.count,
                up: self.up,
                start_x_m: self.start_x_m,
            },
            TerrainChoice::Slope => TerrainKind::Slope { grade_pct: self.grade_pct, start_x_m: self.start_x_m },
            TerrainChoice::Random => TerrainKind::Random {
                seed: self.seed,
                roughness: self.roughness,
                amplitude_m: self.amplitude_m,
                segment_m: self.segment_m,
                length_m: self.length_m,
                start_x_m: self.start_x_m,
            },
        }
    }
}

/// `[sim]`.
#[derive(Clone, Debug, PartialEq)]
#[allow(missing_docs)]
pub struct SimParams {
    pub fps: f64,
    pub cycles: u32,
}

/// Every parameter of a walk.
#[derive(Clone, Debug, PartialEq)]
#[allow(missing_docs)]
pub struct WalkParams {
    pub body: BodyParams,
    pub walk: WalkGroup,
    pub pelvis: PelvisParams,
    pub legs: LegParams,
    pub arms: ArmParams,
    pub ik: IkParams,
    pub optimiser: OptimiserParams,
    pub terrain: TerrainParams,
    pub sim: SimParams,
    /// Control-point overrides by curve name (`[curves.<name>] points = [[x, y], …]`).
    pub curves: BTreeMap<String, Vec<(f64, f64)>>,
    /// Pace changes and the stop, in file order (`[[walk.schedule]]`); empty: one steady
    /// speed for ever.
    pub schedule: Vec<PaceEntry>,
}

impl Default for WalkParams {
    fn default() -> Self {
        WalkParams {
            body: BodyParams {
                height_m: 1.75,
                sex: Sex::Male,
                thigh_m: None,
                shank_m: None,
                ankle_height_m: None,
                foot_length_m: None,
                upper_arm_m: None,
                forearm_m: None,
                hand_m: None,
                hip_width_m: None,
                shoulder_width_m: None,
                trunk_m: None,
            },
            walk: WalkGroup { speed_mps: 1.3, sway: 1.0, stride_m: None, cadence_spm: None, step_width_m: None },
            pelvis: PelvisParams {
                rotation_range_deg: None,
                obliquity_range_deg: None,
                tilt_range_deg: 1.8,
                vertical_range_cm: None,
                lateral_range_cm: None,
                midstance_drop_cm: None,
                midstance_offset_cm: None,
                stance_rise: None,
                trunk_lean_deg: 3.0,
                rest_tilt_deg: 10.0,
            },
            legs: LegParams {
                foot_flat: 0.06,
                heel_rise: None,
                toe_off: None,
                turnout_deg: 7.0,
                knee_lift_cm: 0.0,
                clearance_cm: 1.5,
                heel_pad_mm: None,
            },
            arms: ArmParams {
                shoulder_range_deg: None,
                elbow_range_deg: None,
                elbow_min_flex_deg: 12.0,
                spread_deg: 6.0,
                counter_rotation_pct: 60.0,
            },
            ik: IkParams::default(),
            optimiser: OptimiserParams {
                enabled: true,
                method: SearchMethod::Thesis,
                candidates: 5,
                refine: 5,
                cost: CostForm::Squared,
                samples: 50,
                range_pct: 60.0,
                tolerance_mm: 0.5,
                weight_hip: 1.0,
                weight_knee: 1.0,
                weight_ankle: 1.0,
                heel_rise_slack_deg: HEEL_RISE_SLACK_DEG,
                hip_extension_slack_deg: HIP_EXTENSION_SLACK_DEG,
            },
            terrain: TerrainParams {
                kind: TerrainChoice::Flat,
                start_x_m: 2.0,
                rise_m: 0.15,
                run_m: 0.34,
                count: 8,
                up: true,
                grade_pct: 8.0,
                seed: 2016,
                roughness: 0.7,
                amplitude_m: 0.06,
                segment_m: 0.5,
                length_m: 300.0,
            },
            sim: SimParams { fps: 60.0, cycles: 10 },
            curves: BTreeMap::new(),
            schedule: Vec::new(),
        }
    }
}

/// The parameters with every derived value filled in, in SI units (m, s, rad) where the
/// model computes with them.
#[derive(Clone, Debug, PartialEq)]
pub struct Resolved {
    /// Segment lengths.
    pub dims: BodyDims,
    /// Cycle duration T = 120 / cadence (s).
    pub cycle_s: f64,
    /// Stride length: heel strike to heel strike of one foot (m).
    pub stride_m: f64,
    /// Lateral distance between the two feet's heel lines (m).
    pub step_width_m: f64,
    /// Cycle phase at which the loading response ends (foot flat).
    pub(crate) foot_flat: f64,
    /// Cycle phase at which the heel rises.
    pub heel_rise: f64,
    /// Cycle phase of toe-off; stance lasts `toe_off` of the cycle.
    pub(crate) toe_off: f64,
    /// The heel pad's largest compression on flat ground (m; `walk::heel_pad`).
    pub(crate) heel_pad: f64,
    /// Where the pelvis's double-support key (its lowest point) falls, as a share of the
    /// double support after heel strike.
    pub(crate) double_support_key: f64,
    /// How far ahead of the swing-forward design curve the swing heel moves: the curve is read
    /// at s + lead·s·(1 − s) of the swing (the speed law `swing_lead`).
    pub(crate) swing_lead: f64,
    /// Peak-to-peak pelvic rotation (rad).
    pub(crate) rotation_range: f64,
    /// Peak-to-peak pelvic obliquity asked (rad): the key times the sway knob. The walk plays
    /// [`Resolved::played_obliquity_range`].
    pub(crate) obliquity_range: f64,
    /// Peak-to-peak pelvic tilt (rad).
    pub(crate) tilt_range: f64,
    /// Peak-to-peak vertical pelvis displacement on level ground (m).
    pub(crate) vertical_range: f64,
    /// Peak-to-peak lateral pelvis displacement (m).
    pub(crate) lateral_range: f64,
    /// Pelvis height at mid-stance below the standing hip height (m).
    pub(crate) midstance_drop: f64,
    /// Pelvis ahead of the stance heel at mid-stance (m).
    pub(crate) midstance_offset: f64,
    /// Share (0 to 1) of the way from the keyed height to the standing stance leg that the
    /// pelvis rises through single support (`walk::stance_rise`).
    pub(crate) stance_rise: f64,
    /// Forward lean of the trunk (rad).
    pub(crate) trunk_lean: f64,
    /// Anterior tilt of the pelvis's anatomical frame against its bone (rad): what clinical
    /// hip flexion and pelvic tilt are measured against.
    pub(crate) rest_tilt: f64,
    /// Foot turnout (rad).
    pub turnout: f64,
    /// Extra heel height in mid-swing (m).
    pub(crate) knee_lift: f64,
    /// Clearance the swing planner keeps over terrain corners (m), at least [`LEAST_CLEARANCE_M`].
    pub clearance: f64,
    /// Peak-to-peak shoulder flexion (rad).
    pub(crate) shoulder_range: f64,
    /// Peak-to-peak elbow flexion (rad).
    pub(crate) elbow_range: f64,
    /// Least elbow flexion (rad).
    pub(crate) elbow_min_flex: f64,
    /// Arm abduction away from the trunk (rad).
    pub(crate) arm_spread: f64,
    /// Thorax counter-rotation as a fraction of pelvic rotation.
    pub(crate) counter_rotation: f64,
    /// Reach fraction kept by the planner.
    pub(crate) reach_margin: f64,
    /// Leg IK solver settings (`[ik]`).
    pub ik: IkSettings,
}

/// The most pelvic obliquity (deg, peak to peak) a walk plays, whatever the sway knob asks:
/// the obliquity key's own limit. With the norms' obliquity (12° at 1.3 m/s) the knob's 3 asked
/// 36-43°, which bent the knee to 84° in swing and the ankle to 32° (the norms' 63 and 10), the
/// legs reaching for hips that far apart in height.
pub(crate) const MOST_OBLIQUITY_DEG: f64 = 20.0;

impl Resolved {
    /// The pelvic obliquity the walk plays (rad, peak to peak): the range asked, at most
    /// [`MOST_OBLIQUITY_DEG`].
    pub(crate) fn played_obliquity_range(&self) -> f64 {
        self.obliquity_range.min(MOST_OBLIQUITY_DEG.to_radians())
    }
}

impl WalkParams {
    /// Fills in the derived values. How the knobs map (v = speed in m/s, H = height in m):
    ///
    /// - cadence = √(60·v / r) steps/min and stride = 2·r·cadence, with the walk ratio
    ///   r = 0.0055·H/1.75 (the normative walk's own, 0.0054–0.0056 at every treadmill speed of
    ///   `data/normative/spatiotemporal_by_speed.csv`): 1.3 m/s gives 119 steps/min
    ///   and 1.31 m;
    ///   a set stride or cadence takes the other from v = stride·cadence/120;
    /// - step width 0.10 m at 1.3 m/s, 2 cm narrower per 1 m/s faster (≥ 0.05 m);
    /// - toe-off at 0.62 of the cycle at 1.3 m/s, 0.04 earlier per 1 m/s faster (double
    ///   support shrinks with speed);
    /// - pelvis vertical range asked: from 1.3 m/s none, the double support as high as the legs
    ///   reach; slower 1.05-1.3 cm, with the slow walk's late fall into double support
    ///   (`speed_laws::vertical_range_cm`; the thesis's Orendurff-based law asked the pelvis
    ///   below where the legs reach at every speed and bent both knees); lateral range 6.9 cm at
    ///   0.7 m/s falling 3.44 cm per m/s (×sway), after Orendurff et al. 2004;
    ///   rotation 6° + 3.3°/(m/s) above 0.7 m/s; obliquity 8.2° at 0.8 m/s, 7.7°/(m/s)
    ///   more, at most 14.5° (×sway; `speed_laws::obliquity_range_deg`, the norms' own);
    /// - mid-stance drop 0.8 cm at 1.3 m/s, 3.5 cm less per m/s slower (none from 1.07 m/s
    ///   down) and 2 cm less per m/s faster: about as high as the stance leg reaches
    ///   (`speed_laws::midstance_drop_cm`);
    /// - mid-stance offset, the lowest point's share of the double support and the heel-rise
    ///   phase: laws given at knots from 0.4 to 2.0 m/s, fitted to the speed-matched norms (on
    ///   stairs, slower than 1.3 m/s, session 19's: `speed_laws::STAIRS`; the offset with height)
    ///   (`speed_laws::midstance_offset_cm`, `double_support_key_share`, `heel_rise_phase`);
    /// - stance rise all the way to the standing stance leg up to 0.8 m/s, none from 1.3 m/s
    ///   (`speed_laws::stance_rise`); the heel pad none up to 0.8 m/s, 6 mm from 1.0 m/s
    ///   (`speed_laws::heel_pad_mm`);
    /// - arm swing: shoulder range 25° and elbow range 15° at 1.3 m/s, +30°/+20° per m/s.
    #[must_use]
    pub fn resolve(&self) -> Resolved {
        let (v, stairs) = (self.walk.speed_mps, self.terrain.kind == TerrainChoice::Stairs);
        let b = &self.body;
        let mut dims = BodyDims::from_height(b.height_m, b.sex);
        let set = |slot: &mut f64, value: Option<f64>| {
            if let Some(x) = value {
                *slot = x;
            }
        };
        set(&mut dims.thigh, b.thigh_m);
        set(&mut dims.shank, b.shank_m);
        set(&mut dims.ankle_height, b.ankle_height_m);
        set(&mut dims.foot_length, b.foot_length_m);
        set(&mut dims.upper_arm, b.upper_arm_m);
        set(&mut dims.forearm, b.forearm_m);
        set(&mut dims.hand, b.hand_m);
        set(&mut dims.hip_width, b.hip_width_m);
        set(&mut dims.shoulder_width, b.shoulder_width_m);
        set(&mut dims.trunk, b.trunk_m);

        let ratio = WALK_RATIO_PER_175 * b.height_m / 1.75;
        let (stride_m, cadence) = match (self.walk.stride_m, self.walk.cadence_spm) {
            (Some(s), Some(c)) => (s, c),
            (Some(s), None) => (s, 120.0 * v / s),
            (None, Some(c)) => (120.0 * v / c, c),
            (None, None) => {
                let c = (60.0 * v / ratio).sqrt();
                (2.0 * ratio * c, c)
            }
        };
        let sway = self.walk.sway;
        let fast = v - 1.3;
        let above_slow = (v - 0.7).max(0.0);
        let deg = f64::to_radians;
        let p = &self.pelvis;
        let a = &self.arms;
        Resolved {
            cycle_s: 120.0 / cadence,
            stride_m,
            step_width_m: self.walk.step_width_m.unwrap_or((0.10 - 0.02 * fast).max(0.05)),
            foot_flat: self.legs.foot_flat,
            heel_rise: self.legs.heel_rise.unwrap_or(heel_rise_phase(v, stairs)),
            toe_off: self.legs.toe_off.unwrap_or((0.62 - 0.04 * fast).clamp(0.55, 0.70)),
            heel_pad: self.legs.heel_pad_mm.unwrap_or(heel_pad_mm(v)) / 1000.0,
            double_support_key: double_support_key_share(v),
            swing_lead: swing_lead(v),
            rotation_range: deg(p.rotation_range_deg.unwrap_or(6.0 + 3.3 * above_slow)),
            obliquity_range: deg(p.obliquity_range_deg.unwrap_or(obliquity_range_deg(v)) * sway),
            tilt_range: deg(p.tilt_range_deg),
            vertical_range: p.vertical_range_cm.unwrap_or(vertical_range_cm(v, stairs)).max(0.0) / 100.0,
            lateral_range: p.lateral_range_cm.unwrap_or((6.9 - 3.44 * (v - 0.7)).max(1.0)) * sway / 100.0,
            midstance_drop: p.midstance_drop_cm.unwrap_or(midstance_drop_cm(v)) / 100.0,
            midstance_offset: p.midstance_offset_cm.unwrap_or(midstance_offset_cm(v, stairs, b.height_m)) / 100.0,
            stance_rise: p.stance_rise.unwrap_or(stance_rise(v)),
            trunk_lean: deg(p.trunk_lean_deg),
            rest_tilt: deg(p.rest_tilt_deg),
            turnout: deg(self.legs.turnout_deg),
            knee_lift: self.legs.knee_lift_cm / 100.0,
            clearance: (self.legs.clearance_cm / 100.0).max(LEAST_CLEARANCE_M),
            shoulder_range: deg(a.shoulder_range_deg.unwrap_or((25.0 + 30.0 * fast).max(4.0))),
            elbow_range: deg(a.elbow_range_deg.unwrap_or((15.0 + 20.0 * fast).max(2.0))),
            elbow_min_flex: deg(a.elbow_min_flex_deg),
            arm_spread: deg(a.spread_deg),
            counter_rotation: a.counter_rotation_pct / 100.0,
            reach_margin: self.ik.reach_margin,
            ik: self.ik.settings(),
            dims,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn default_speed_gives_normal_adult_figures() {
        let r = WalkParams::default().resolve();
        let cadence = 120.0 / r.cycle_s;
        // The norms at 1.3 m/s: 118.5 +- 6.5 steps/min, stride 1.315 +- 0.126 m.
        assert!((cadence - 119.1).abs() < 0.5, "{cadence}");
        assert!((r.stride_m - 1.310).abs() < 0.01, "{}", r.stride_m);
        assert!((r.stride_m / r.cycle_s - 1.3).abs() < 1e-9);
        assert!((r.toe_off - 0.62).abs() < 1e-12);
    }

    #[test]
    fn set_stride_keeps_speed() {
        let mut p = WalkParams::default();
        p.walk.stride_m = Some(1.6);
        let r = p.resolve();
        assert!((r.stride_m / r.cycle_s - 1.3).abs() < 1e-9);
    }
}
