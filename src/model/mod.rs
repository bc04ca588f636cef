//! The walk model: everything that moves the body, with no terminal, file or CLI code.
//!
//! - [`curve`]: piecewise Bézier curves y(x) and the operations the walk performs on them;
//! - [`curve_edit`]: moving a control point by hand with the joins kept smooth;
//! - [`gait_curves`]: the model's named curves and their default designs;
//! - [`terrain`]: the ground profile;
//! - [`body`]: skeleton, segment lengths, poses;
//! - [`ik`]: the analytic two-bone solver;
//! - [`params`]: typed parameters and how the high-level knobs derive the rest;
//! - [`schedule`]: the pace schedule (speed changes and the stop) a walk plays;
//! - [`speed_laws`]: how the walking speed sets the step and the mid-stance pelvis;
//! - [`walk`]: phases, footfalls, swing planning, pelvis, upper body, frames;
//! - [`optimise`]: the pelvis-position search at double support;
//! - [`variants`]: enum variant tables for the name tables strum derives.

pub mod body;
pub mod curve;
pub mod curve_edit;
pub mod gait_curves;
pub mod ik;
pub mod optimise;
pub mod params;
pub mod schedule;
pub mod search;
pub mod speed_laws;
pub mod terrain;
pub mod variants;
pub mod walk;
