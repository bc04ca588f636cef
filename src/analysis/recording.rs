//! A walk recorded once, by the one frame loop every headless command shares: the report
//! (tables, BVH, every plot, metrics), `gaitlab ik` and the lab's export read what they need
//! from a [`Recording`] instead of walking the config again.
//!
//! What costs memory per frame or per step (full-body poses, IK questions, the optimiser's
//! step problems) is kept only when asked for in [`Keep`].

use crate::model::body::{Pose, Side};
use crate::model::ik::IkQuestion;
use crate::model::optimise::StepProblem;
use crate::model::params::WalkParams;
use crate::model::terrain::Terrain;
use crate::model::walk::frame::Frame;
use crate::model::walk::leg::Footfall;
use crate::model::walk::pace::{PaceEvent, WalkState};
use crate::model::walk::{Gait, ModelError, StepPlan, Walker, ik_question};

/// One IK question the walk asked.
#[derive(Clone, Copy, Debug)]
pub struct IkTarget {
    /// Frame number.
    pub frame: u64,
    /// Time (s).
    pub time_s: f64,
    /// Which leg.
    pub side: Side,
    /// The question.
    pub question: IkQuestion,
}

/// What a recording keeps beside the frames, footfalls and step plans.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Keep {
    /// Every frame's full-body pose (BVH, the stick figure): ~1.4 KB a frame.
    pub poses: bool,
    /// Both legs' IK questions of every frame (`ik.csv`, `gaitlab ik`).
    pub(crate) ik_targets: bool,
    /// Each step's optimisation problem with the walk's rules at that moment, so that a
    /// step's cost landscape can be drawn afterwards: a few KB a step.
    pub(crate) step_problems: bool,
}

impl Keep {
    /// Everything: what a report reads.
    pub const ALL: Keep = Keep { poses: true, ik_targets: true, step_problems: true };
}

/// A finished headless walk.
#[derive(Clone, Debug)]
pub struct Recording {
    /// Every frame, frame 0 being the start pose.
    pub frames: Vec<Frame>,
    /// Footfalls in order.
    pub footfalls: Vec<Footfall>,
    /// Per-step planning decisions.
    pub step_plans: Vec<StepPlan>,
    /// IK reach failures over all frames.
    pub reach_failures: u64,
    /// Cycle duration (s).
    pub cycle_s: f64,
    /// Frames per second.
    pub fps: f64,
    /// The ground walked on.
    pub terrain: Terrain,
    /// The walk's rules at the start (design curves, resolved parameters).
    pub gait: Gait,
    /// Full-body pose of every frame ([`Keep::poses`]; empty otherwise).
    pub poses: Vec<Pose>,
    /// Both legs' IK questions of every frame, right then left ([`Keep::ik_targets`]).
    pub(crate) ik_targets: Vec<IkTarget>,
    /// For each entry of `step_plans`, the problem its pelvis choice solved and the rules it
    /// was costed with ([`Keep::step_problems`]; `None` where none was recorded).
    pub(crate) step_problems: Vec<Option<(StepProblem, Gait)>>,
    /// What the pace schedule did (`[[walk.schedule]]`), in order; empty without one.
    pub pace_events: Vec<PaceEvent>,
    /// What the walker was doing at each frame (walking, stopping, standing, ...): the
    /// steady parts ([`super::steady`]) count only walking frames as steady.
    pub states: Vec<WalkState>,
    /// The speed the walk was asked for at the start (m/s, the config's `walk.speed_mps`):
    /// the first plateau's, before any `SpeedAsked` event.
    pub start_speed_mps: f64,
}

/// Runs `cycles` gait cycles at `fps` frames per second, keeping what `keep` asks for.
pub fn record(params: &WalkParams, cycles: f64, fps: f64, keep: Keep) -> Result<Recording, ModelError> {
    let mut walker = Walker::new(params)?;
    let cycle_s = walker.resolved().cycle_s;
    let count = (cycles * cycle_s * fps).round() as u64;
    let mut rec = Recording {
        frames: Vec::with_capacity(count as usize + 1),
        footfalls: Vec::new(),
        step_plans: Vec::new(),
        reach_failures: 0,
        cycle_s,
        fps,
        terrain: walker.terrain().clone(),
        gait: walker.gait().clone(),
        poses: Vec::new(),
        ik_targets: Vec::new(),
        step_problems: Vec::new(),
        pace_events: Vec::new(),
        states: Vec::with_capacity(count as usize + 1),
        start_speed_mps: params.walk.speed_mps,
    };
    for i in 0..=count {
        if i > 0 {
            walker.advance(1.0 / fps);
        }
        rec.frames.push(walker.frame(i));
        rec.states.push(walker.walk_state());
        if keep.poses {
            rec.poses.push(walker.pose().clone());
        }
        if keep.ik_targets {
            for side in Side::BOTH {
                let pose = &walker.leg(side).pose;
                rec.ik_targets.push(IkTarget {
                    frame: i,
                    time_s: walker.time_s(),
                    side,
                    question: ik_question(pose.hip, pose.target, side),
                });
            }
        }
        if keep.step_problems {
            // A new plan and its problem appear together at a toe-off; a frame never holds
            // two toe-offs of the same walk at any allowed frame rate, but if it did, only
            // the last plan's problem would be known.
            let plans = walker.step_plans().len();
            while rec.step_problems.len() < plans {
                let latest = rec.step_problems.len() + 1 == plans;
                rec.step_problems.push(if latest {
                    walker.last_step_problem().map(|p| (p.clone(), walker.gait().clone()))
                } else {
                    None
                });
            }
        }
    }
    rec.footfalls = walker.footfalls().to_vec();
    rec.step_plans = walker.step_plans().to_vec();
    rec.reach_failures = walker.reach_failures();
    rec.pace_events = walker.pace_events().to_vec();
    Ok(rec)
}
