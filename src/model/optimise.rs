//! The pelvis-acceleration optimisation (spec §8): once per step the walk chooses where the
//! pelvis will be at the next mid double support.
//!
//! The numerical search knows nothing of the walk ([`crate::model::search`]); the step problem
//! that builds its cost from the walk's own phase and IK code lives with the walk
//! ([`crate::model::walk::step_problem`]). This module names both where callers look for them.

pub use crate::model::search::Candidate;
pub use crate::model::walk::step_problem::{StepProblem, StepRecord, acceleration_cost};
