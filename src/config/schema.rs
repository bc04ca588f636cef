//! Every config key: its unit, valid range, doc line, and where it lives in [`WalkParams`].
//!
//! This table is the single source for validation, `gaitlab init`, `--set`, and (later) the
//! TUI's parameter editor. Defaults come from `WalkParams::default()`, never from here.

use crate::model::body::Sex;
use crate::model::gait_curves::CurveName;
use crate::model::ik::{IkSolverKind, JacobianVariant};
use crate::model::params::{CostForm, SearchMethod, TerrainChoice, WalkParams};

/// A parameter's value.
#[derive(Clone, Debug, PartialEq)]
pub enum Value {
    /// A number in the key's unit.
    Real(f64),
    /// A derived value that is not set (the knobs fill it in).
    Auto,
    /// A whole number.
    Int(i64),
    /// One of a list of words.
    Word(&'static str),
    /// A switch.
    Bool(bool),
}

/// What values a key takes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Kind {
    /// A number in `[min, max]`; `auto` keys may be left out to be derived.
    Real {
        /// Smallest valid value.
        min: f64,
        /// Largest valid value.
        max: f64,
        /// Whether leaving it out derives it from the knobs.
        auto: bool,
    },
    /// A whole number in `[min, max]`.
    Int {
        /// Smallest valid value.
        min: i64,
        /// Largest valid value.
        max: i64,
    },
    /// One of these words.
    Choice(&'static [&'static str]),
    /// true or false.
    Bool,
}

/// One config key.
#[derive(Clone, Copy)]
pub struct ParamSpec {
    /// Dotted key, `group.name`.
    pub key: &'static str,
    /// Unit as shown to users (`m`, `deg`, `%`, `` for plain numbers).
    pub unit: &'static str,
    /// One line of documentation.
    pub doc: &'static str,
    /// Valid values.
    pub kind: Kind,
    /// Reads the value.
    pub get: fn(&WalkParams) -> Value,
    /// Writes a value already checked against `kind`.
    pub set: fn(&mut WalkParams, &Value),
}

impl std::fmt::Debug for ParamSpec {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("ParamSpec").field("key", &self.key).field("kind", &self.kind).finish()
    }
}

impl ParamSpec {
    /// The group (`walk` of `walk.speed_mps`).
    #[must_use]
    pub fn group(&self) -> &'static str {
        self.key.split_once('.').map_or(self.key, |(g, _)| g)
    }

    /// The name within the group.
    #[must_use]
    pub fn name(&self) -> &'static str {
        self.key.split_once('.').map_or(self.key, |(_, n)| n)
    }

    /// The valid values, as said in docs and the lab's editor.
    #[must_use]
    pub(crate) fn valid_range(&self) -> String {
        let auto =
            if matches!(self.kind, Kind::Real { auto: true, .. }) { ", or leave it out to derive it" } else { "" };
        format!("{}{auto}", self.value_kind())
    }

    /// What a value of this key must be, as a problem with one says it after "KEY needs":
    /// "a number from 0.4 to 2 m/s". An auto key's alternative is the word a value can
    /// give (`auto`), since the file, `--set` and the lab's editor all take it.
    #[must_use]
    pub(crate) fn needs(&self) -> String {
        let auto = if matches!(self.kind, Kind::Real { auto: true, .. }) { " or \"auto\"" } else { "" };
        format!("{}{auto}", self.value_kind())
    }

    fn value_kind(&self) -> String {
        match self.kind {
            Kind::Real { min, max, .. } => {
                let unit = if self.unit.is_empty() { String::new() } else { format!(" {}", self.unit) };
                format!("a number from {min} to {max}{unit}")
            }
            Kind::Int { min, max } => format!("a whole number from {min} to {max}"),
            Kind::Choice(words) => {
                format!("one of {}", words.iter().map(|w| format!("\"{w}\"")).collect::<Vec<_>>().join(", "))
            }
            Kind::Bool => "true or false".to_string(),
        }
    }
}

macro_rules! real {
    ($($grp:ident).+ => $field:ident, $unit:expr, $min:expr, $max:expr, $doc:expr) => {
        ParamSpec {
            key: concat!(stringify!($($grp).+), ".", stringify!($field)),
            unit: $unit,
            doc: $doc,
            kind: Kind::Real { min: $min, max: $max, auto: false },
            get: |p| Value::Real(p.$($grp).+.$field),
            set: |p, v| {
                if let Value::Real(x) = v {
                    p.$($grp).+.$field = *x;
                }
            },
        }
    };
}

macro_rules! auto {
    ($grp:ident => $field:ident, $unit:expr, $min:expr, $max:expr, $doc:expr) => {
        ParamSpec {
            key: concat!(stringify!($grp), ".", stringify!($field)),
            unit: $unit,
            doc: $doc,
            kind: Kind::Real { min: $min, max: $max, auto: true },
            get: |p| p.$grp.$field.map_or(Value::Auto, Value::Real),
            set: |p, v| {
                p.$grp.$field = match v {
                    Value::Real(x) => Some(*x),
                    _ => None,
                }
            },
        }
    };
}

macro_rules! int {
    ($grp:ident => $field:ident, $ty:ty, $min:expr, $max:expr, $doc:expr) => {
        ParamSpec {
            key: concat!(stringify!($grp), ".", stringify!($field)),
            unit: "",
            doc: $doc,
            kind: Kind::Int { min: $min, max: $max },
            get: |p| Value::Int(p.$grp.$field as i64),
            set: |p, v| {
                if let Value::Int(n) = v {
                    // In range: checked against `kind` before any set.
                    p.$grp.$field = <$ty>::try_from(*n).unwrap_or_default();
                }
            },
        }
    };
}

macro_rules! switch {
    ($grp:ident => $field:ident, $doc:expr) => {
        ParamSpec {
            key: concat!(stringify!($grp), ".", stringify!($field)),
            unit: "",
            doc: $doc,
            kind: Kind::Bool,
            get: |p| Value::Bool(p.$grp.$field),
            set: |p, v| {
                if let Value::Bool(b) = v {
                    p.$grp.$field = *b;
                }
            },
        }
    };
}

/// A key whose value is one of an enum's names (the enum has `name` and `from_name`).
macro_rules! choice {
    ($grp:ident => $field:ident, $ty:ident, $words:expr, $doc:expr) => {
        ParamSpec {
            key: concat!(stringify!($grp), ".", stringify!($field)),
            unit: "",
            doc: $doc,
            kind: Kind::Choice($words),
            get: |p| Value::Word(p.$grp.$field.name()),
            set: |p, v| {
                if let Value::Word(w) = v {
                    // In the list: checked against `kind` before any set.
                    if let Some(x) = $ty::from_name(w) {
                        p.$grp.$field = x;
                    }
                }
            },
        }
    };
}

const SOLVERS: &[&str] = &["analytic", "ccd", "fabrik", "jacobian_dls", "gradient"];
const JACOBIAN_VARIANTS: &[&str] = &["dls", "transpose", "pseudo_inverse"];
const SEXES: &[&str] = &["female", "male"];
const METHODS: &[&str] = &["thesis", "golden", "brent", "joint"];
const COST_FORMS: &[&str] = &["squared", "absolute"];
const TERRAINS: &[&str] = &["flat", "stairs", "slope", "random"];
const DIRECTIONS: &[&str] = &["up", "down"];

/// Every key, in the order `gaitlab init` prints them.
pub static PARAMS: &[ParamSpec] = &[
    real!(body => height_m, "m", 1.2, 2.2, "Standing height; every segment is a proportion of it (Drillis & Contini)"),
    ParamSpec {
        key: "body.sex",
        unit: "",
        doc: "Sets hip and shoulder widths: female bodies have a wider pelvis and narrower shoulders",
        kind: Kind::Choice(SEXES),
        get: |p| Value::Word(if p.body.sex == Sex::Female { "female" } else { "male" }),
        set: |p, v| {
            if let Value::Word(w) = v {
                p.body.sex = if *w == "female" { Sex::Female } else { Sex::Male };
            }
        },
    },
    auto!(body => thigh_m, "m", 0.2, 0.7, "Hip to knee joint centre; default 0.245 H"),
    auto!(body => shank_m, "m", 0.2, 0.7, "Knee to ankle joint centre; default 0.246 H"),
    auto!(body => ankle_height_m, "m", 0.03, 0.12, "Ankle joint above the sole; default 0.039 H"),
    auto!(body => foot_length_m, "m", 0.15, 0.35, "Heel to toe tip; default 0.152 H"),
    auto!(body => upper_arm_m, "m", 0.15, 0.5, "Shoulder to elbow; default 0.186 H"),
    auto!(body => forearm_m, "m", 0.12, 0.45, "Elbow to wrist; default 0.146 H"),
    auto!(body => hand_m, "m", 0.08, 0.3, "Wrist to finger tip; default 0.108 H"),
    auto!(body => hip_width_m, "m", 0.1, 0.35, "Between the hip joint centres; default 0.098 H (male), 0.108 H (female)"),
    auto!(body => shoulder_width_m, "m", 0.2, 0.6, "Between the shoulder joints; default 0.220 H (male), 0.200 H (female)"),
    auto!(body => trunk_m, "m", 0.3, 0.8, "Hip-joint level to shoulder level; default 0.288 H"),
    real!(walk => speed_mps, "m/s", 0.4, 2.0, "Walking speed: drives stride, cadence, step width, double support, pelvis and arm amplitudes"),
    real!(walk => sway, "", 0.0, 3.0, "Sway knob: scales pelvic obliquity (played up to 20 deg peak to peak), lateral pelvis sway and with them the trunk's side bend"),
    auto!(walk => stride_m, "m", 0.5, 2.0, "Heel strike to heel strike of one foot; derived from speed and a constant walk ratio"),
    auto!(walk => cadence_spm, "steps/min", 50.0, 160.0, "Steps per minute; the cycle lasts 120/cadence s"),
    auto!(walk => step_width_m, "m", 0.0, 0.35, "Lateral distance between the two feet's heel lines"),
    auto!(pelvis => rotation_range_deg, "deg", 0.0, 20.0, "Peak-to-peak pelvic rotation (transverse plane) of the curve; the default shape, people's, peaks at 0.96 of it"),
    auto!(pelvis => obliquity_range_deg, "deg", 0.0, 20.0, "Peak-to-peak pelvic obliquity (frontal plane), before the sway knob"),
    real!(pelvis => tilt_range_deg, "deg", 0.0, 12.0, "Peak-to-peak pelvic tilt (sagittal plane), two waves a cycle"),
    auto!(pelvis => vertical_range_cm, "cm", 0.0, 8.0, "How far below its mid-stance height the pelvis is asked to pass at double support on level ground; the reach guard lowers it further where a leg needs it (0: as high as the legs reach)"),
    auto!(pelvis => lateral_range_cm, "cm", 0.0, 15.0, "Peak-to-peak side-to-side pelvis sway, before the sway knob"),
    auto!(pelvis => midstance_drop_cm, "cm", 0.0, 10.0, "How far below standing hip height the pelvis passes at mid-stance (its highest point)"),
    auto!(pelvis => midstance_offset_cm, "cm", -10.0, 30.0, "Pelvis ahead of the stance heel at mid-stance"),
    auto!(pelvis => stance_rise, "", 0.0, 1.0, "How far the pelvis rises from its keyed height toward the stance leg standing with people's mid-stance knee (7 deg easing to 4) through single support, as a slow walker vaults over the leg: 0 none, 1 all the way; on level ground only"),
    real!(pelvis => trunk_lean_deg, "deg", -10.0, 30.0, "Forward lean of the trunk"),
    real!(pelvis => rest_tilt_deg, "deg", 0.0, 20.0, "Anterior tilt of the pelvis's anatomical frame (the plane of the iliac spines) when standing: the joint table's hip flexion and pelvic tilt are measured against it, as gait labs measure them (Fukuchi 2018's adults: 10 on average); the figure is unchanged"),
    real!(legs => foot_flat, "cycle", 0.03, 0.3, "Cycle phase at which the heel rocker ends and the foot is flat (measured adults: within 3 deg of flat by 0.08; the thesis's 0.12 is where the loading response ends)"),
    auto!(legs => heel_rise, "cycle", 0.15, 0.5, "Cycle phase at which the heel rises (end of midstance)"),
    auto!(legs => toe_off, "cycle", 0.51, 0.75, "Cycle phase of toe-off; stance lasts this share of the cycle, double support twice (toe_off - 0.5)"),
    real!(legs => turnout_deg, "deg", -10.0, 30.0, "Foot turnout about the vertical; also turns the knee's reference direction"),
    real!(legs => knee_lift_cm, "cm", 0.0, 30.0, "Extra heel height in mid-swing"),
    real!(legs => clearance_cm, "cm", 0.0, 10.0, "Clearance the swing planner keeps between the foot and the ground or stair nosings; at least 0.2 cm is kept"),
    auto!(legs => heel_pad_mm, "mm", 0.0, 10.0, "How far the stance ankle sinks into the heel pad in the loading response on flat ground, let go by 30 % of the cycle (25 % from 1.6 m/s): 6 from 1.0 m/s, none at 0.8 m/s and slower; 0 for a rigid foot, as BVH and glTF skeletons have (their soles otherwise dip this much under the ground)"),
    auto!(arms => shoulder_range_deg, "deg", 0.0, 90.0, "Peak-to-peak shoulder flexion of the arm swing"),
    auto!(arms => elbow_range_deg, "deg", 0.0, 90.0, "Peak-to-peak elbow flexion of the arm swing"),
    real!(arms => elbow_min_flex_deg, "deg", 0.0, 90.0, "Least elbow flexion (the arm's greatest extension)"),
    real!(arms => spread_deg, "deg", 0.0, 45.0, "Arm abduction away from the trunk"),
    real!(arms => counter_rotation_pct, "%", 0.0, 150.0, "Thorax counter-rotation against the pelvic rotation"),
    real!(ik => reach_margin, "", 0.95, 1.0, "Share of full leg reach the planner keeps the stance leg within (the knee never locks)"),
    choice!(ik => solver, IkSolverKind, SOLVERS, "Leg IK: analytic (exact, the reference), ccd, fabrik, jacobian_dls or gradient (seed 002); the planner always predicts with analytic"),
    real!(ik => tolerance_mm, "mm", 0.001, 10.0, "Iterative solvers stop when the ankle is this close to its target and the knee this close to the reference plane"),
    int!(ik => max_iterations, u32, 1, 1_000_000, "Most iterations of ccd, fabrik and jacobian_dls per solve"),
    switch!(ik => limits, "Iterative solvers keep the joints within the ranges below (the analytic solver is only measured against them)"),
    real!(ik => hip_flex_max_deg, "deg", 30.0, 150.0, "Hip flexion limit"),
    real!(ik => hip_ext_max_deg, "deg", 0.0, 60.0, "Hip extension limit, from the vertical (the leg frame does not tilt with the pelvis; 40 is the anatomical 30 at 10 deg anterior tilt)"),
    real!(ik => hip_abd_max_deg, "deg", 0.0, 90.0, "Hip abduction limit"),
    real!(ik => hip_add_max_deg, "deg", 0.0, 60.0, "Hip adduction limit"),
    real!(ik => hip_int_rot_max_deg, "deg", 0.0, 90.0, "Hip internal rotation limit"),
    real!(ik => hip_ext_rot_max_deg, "deg", 0.0, 90.0, "Hip external rotation limit"),
    real!(ik => knee_flex_max_deg, "deg", 60.0, 170.0, "Knee flexion limit (the knee never hyperextends past straight)"),
    real!(ik => soften, "", 0.5, 1.0, "Analytic (the walk too): share of full reach past which the knee eases into extension instead of snapping straight, the ankle falling short of its target (1: off)"),
    real!(ik => twist_deg, "deg", -90.0, 90.0, "Analytic (the walk too): extra turn of the knee about the hip-ankle line after the reference vector placed it"),
    real!(ik => ccd_stiffness_hip, "", 0.01, 1.0, "CCD: share of each hip turn applied per iteration"),
    real!(ik => ccd_stiffness_knee, "", 0.01, 1.0, "CCD: share of each knee turn applied per iteration"),
    real!(ik => dls_damping_m, "m", 0.0, 1.0, "Jacobian: damping lambda of damped least squares"),
    choice!(ik => jacobian, JacobianVariant, JACOBIAN_VARIANTS, "Jacobian update: dls (damped least squares), transpose or pseudo_inverse"),
    real!(ik => gradient_delta0, "", 0.001, 100.0, "Gradient: starting step, the multiple of the gradient subtracted (seed 002: 5)"),
    real!(ik => gradient_epsilon, "", 1e-8, 1.0, "Gradient: a descent ends when the halved step falls below this (seed 002: 0.0001)"),
    int!(ik => gradient_restarts, u32, 0, 1000, "Gradient: random starting poses descended on the first frame, the best kept (seed 002: 100)"),
    int!(ik => gradient_perturbations, u32, 0, 1000, "Gradient: random perturbations tried every frame, each kept only if it lowers the cost (seed 002: 100)"),
    real!(ik => gradient_perturbation_deg, "deg", 0.0, 90.0, "Gradient: perturbation range, plus or minus, on every angle (seed 002: 15)"),
    int!(ik => gradient_seed, u64, 0, 9_007_199_254_740_991, "Gradient: seed of the portable generator; the same seed gives the same poses every run"),
    real!(ik => gradient_weight_swivel, "", 0.0, 1000.0, "Gradient: weight of the knee's squared swivel arc against the squared ankle error"),
    int!(ik => gradient_max_steps, u32, 10, 1_000_000, "Gradient: most steps (kept or halved) of one descent"),
    ParamSpec {
        key: "optimiser.enabled",
        unit: "",
        doc: "Choose the pelvis position at each double support by the acceleration cost; false uses the fixed rule (halfway between mid-stances)",
        kind: Kind::Bool,
        get: |p| Value::Bool(p.optimiser.enabled),
        set: |p, v| {
            if let Value::Bool(b) = v {
                p.optimiser.enabled = *b;
            }
        },
    },
    choice!(optimiser => method, SearchMethod, METHODS, "Search: thesis (two levels of candidates); golden / brent (the thesis's first level, then as many points again placed by golden sections / parabolas around its best: no slower, up to 4 % higher on steep uphill steps, lower only where the first level's best is not at the edge of what the legs reach); joint (both levels, then Brent on position, height, position: deepest, ~5x slower)"),
    int!(optimiser => candidates, u32, 3, 50, "Evenly spaced candidates over the range: the first level, with which every method starts"),
    int!(optimiser => refine, u32, 0, 50, "Candidates spread around the first level's best: the second level (0: none); golden and brent spend the same number, joint refines after it"),
    ParamSpec {
        key: "optimiser.cost",
        unit: "",
        doc: "squared: sum of W x squared joint acceleration x dt; absolute: sum of W x |acceleration| x dt",
        kind: Kind::Choice(COST_FORMS),
        get: |p| Value::Word(if p.optimiser.cost == CostForm::Absolute { "absolute" } else { "squared" }),
        set: |p, v| {
            if let Value::Word(w) = v {
                p.optimiser.cost = if *w == "absolute" { CostForm::Absolute } else { CostForm::Squared };
            }
        },
    },
    int!(optimiser => samples, u32, 10, 400, "Samples of the simulated stance, half mid-stance to double support, half double support to the next mid-stance"),
    real!(optimiser => range_pct, "%", 10.0, 95.0, "Width of the searched range, centred between the two mid-stance positions, as a share of their distance"),
    real!(optimiser => tolerance_mm, "mm", 0.01, 10.0, "Golden and brent stop early, joint stops, when the position is known this closely"),
    real!(optimiser => weight_hip, "", 0.0, 100.0, "Weight of the hip's squared angular acceleration in the pelvis choice"),
    real!(optimiser => weight_knee, "", 0.0, 100.0, "Weight of the knee's squared angular acceleration in the pelvis choice"),
    real!(optimiser => weight_ankle, "", 0.0, 100.0, "Weight of the ankle's squared angular acceleration in the pelvis choice"),
    real!(optimiser => heel_rise_slack_deg, "deg", 0.0, 30.0, "A candidate may roll the trailing foot this much further over its toes than the fixed rule does (the cost alone favours a stiff push-off)"),
    real!(optimiser => hip_extension_slack_deg, "deg", 0.0, 30.0, "A candidate may extend the trailing hip this much further than the fixed rule does (the cost alone favours a hyper-extended push-off)"),
    ParamSpec {
        key: "terrain.kind",
        unit: "",
        doc: "Ground profile: flat, stairs, slope or random (midpoint displacement)",
        kind: Kind::Choice(TERRAINS),
        get: |p| {
            Value::Word(match p.terrain.kind {
                TerrainChoice::Flat => "flat",
                TerrainChoice::Stairs => "stairs",
                TerrainChoice::Slope => "slope",
                TerrainChoice::Random => "random",
            })
        },
        set: |p, v| {
            if let Value::Word(w) = v {
                p.terrain.kind = match *w {
                    "stairs" => TerrainChoice::Stairs,
                    "slope" => TerrainChoice::Slope,
                    "random" => TerrainChoice::Random,
                    _ => TerrainChoice::Flat,
                };
            }
        },
    },
    real!(terrain => start_x_m, "m", 0.0, 50.0, "Where stairs, slope or rough ground begin; level before"),
    real!(terrain => rise_m, "m", 0.02, 0.25, "Stairs: height of one step"),
    real!(terrain => run_m, "m", 0.2, 0.8, "Stairs: depth of one tread (must hold a whole foot)"),
    int!(terrain => count, u32, 1, 500, "Stairs: number of steps; level ground after the last"),
    ParamSpec {
        key: "terrain.direction",
        unit: "",
        doc: "Stairs: up or down",
        kind: Kind::Choice(DIRECTIONS),
        get: |p| Value::Word(if p.terrain.up { "up" } else { "down" }),
        set: |p, v| {
            if let Value::Word(w) = v {
                p.terrain.up = *w == "up";
            }
        },
    },
    real!(terrain => grade_pct, "%", -25.0, 25.0, "Slope: rise over run x 100, negative downhill"),
    int!(terrain => seed, u64, 0, 9_007_199_254_740_991, "Random: seed of the portable generator; the same seed gives the same ground everywhere"),
    real!(terrain => roughness, "", 0.0, 1.0, "Random: roughness exponent H; large is smooth, small is rough"),
    real!(terrain => amplitude_m, "m", 0.0, 0.3, "Random: range of the first displacement"),
    real!(terrain => segment_m, "m", 0.1, 2.0, "Random: width of one terrain segment"),
    real!(terrain => length_m, "m", 10.0, 5000.0, "Random: length of ground generated; level after it"),
    real!(sim => fps, "frames/s", 10.0, 1000.0, "Frame rate of simulate and report when --fps is not given"),
    int!(sim => cycles, u32, 1, 100_000, "Gait cycles simulated when --cycles is not given"),
];

/// The spec of `key`.
#[must_use]
pub fn spec(key: &str) -> Option<&'static ParamSpec> {
    PARAMS.iter().find(|p| p.key == key)
}

/// What a curve override's control points may hold.
///
/// Every control point's y lies within `lo..=hi`, so the curve does too (a Bézier curve stays
/// inside its control points): the walk cannot be handed a pelvis a kilometre up or a foot
/// turned 800°. Where the walk joins a curve to what comes before and after it, the ends are
/// fixed: a progress curve runs from 0 to 1, a swing weight starts and ends at 0, the heel
/// rise starts flat; another end would make the body jump there.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CurveLimits {
    /// Least control-point y.
    pub lo: f64,
    /// Greatest control-point y.
    pub hi: f64,
    /// y at x = 0, if fixed.
    pub start: Option<f64>,
    /// y at x = 1, if fixed.
    pub end: Option<f64>,
    /// What y is, as messages say it.
    pub(crate) meaning: &'static str,
}

/// The limits of curve `c`'s control points (see [`CurveLimits`]).
#[must_use]
pub fn curve_limits(c: CurveName) -> CurveLimits {
    use CurveName::*;
    let limits = |lo, hi, start, end, meaning| CurveLimits { lo, hi, start, end, meaning };
    match c {
        // Unit shapes: the matching range parameter is their peak-to-peak size.
        PelvisObliquity | PelvisRotation | PelvisTilt | PelvisLateral | Shoulder | Elbow => {
            limits(-1.0, 1.0, None, None, "a unit shape, -1 to 1")
        }
        PelvisVertical | PelvisVerticalDsMs | PelvisForwardDsMs | PelvisForwardMsDs => {
            limits(0.0, 1.0, Some(0.0), Some(1.0), "progress from one pelvis key to the next, 0 to 1")
        }
        HeelRise => limits(0.0, 90.0, Some(0.0), None, "the foot-ground angle, 0 to 90 deg"),
        SwingForward => limits(0.0, 1.0, Some(0.0), Some(1.0), "progress from toe-off to the footfall, 0 to 1"),
        SwingLateral => {
            limits(0.0, 1.0, Some(0.0), Some(0.0), "a weight from the step-width line to the hip line, 0 to 1")
        }
        SwingAnkle => limits(-30.0, 30.0, None, None, "the foot pitch for 15 deg at toe-off, -30 to 30 deg"),
        SwingHeelHeight => limits(0.0, 0.5, None, None, "the heel height for 0.2 m at toe-off, 0 to 0.5 m"),
    }
}

/// The config groups, in order.
pub(crate) const GROUPS: &[&str] =
    &["body", "walk", "pelvis", "legs", "arms", "ik", "optimiser", "terrain", "sim", "curves"];

/// Levenshtein distance, for "did you mean".
#[must_use]
pub(crate) fn edit_distance(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut row: Vec<usize> = (0..=b.len()).collect();
    for (i, ca) in a.chars().enumerate() {
        let mut prev = row[0];
        row[0] = i + 1;
        for (j, cb) in b.iter().enumerate() {
            let cur = row[j + 1];
            row[j + 1] = (prev + usize::from(ca != *cb)).min(row[j] + 1).min(cur + 1);
            prev = cur;
        }
    }
    row[b.len()]
}

/// The closest of `candidates` to `word`, if close enough to be a likely typo.
///
/// The distance is at least the difference in length, so a word far longer or shorter than a
/// candidate is passed over without measuring (a megabyte-long key costs one count).
#[must_use]
pub(crate) fn did_you_mean<'a>(word: &str, candidates: impl IntoIterator<Item = &'a str>) -> Option<&'a str> {
    let len = word.chars().count();
    candidates
        .into_iter()
        .filter_map(|c| {
            let most = (c.len() / 3).max(2);
            if len.abs_diff(c.chars().count()) > most {
                return None;
            }
            Some((edit_distance(word, c), c)).filter(|(d, _)| *d <= most)
        })
        .min_by_key(|(d, _)| *d)
        .map(|(_, c)| c)
}
