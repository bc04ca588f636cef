//! gaitlab: a procedural human walk after Mohelník 2016 (Bézier-driven pelvis and feet,
//! analytic two-bone leg IK, terrain adaptation), with a headless CLI on top.
//!
//! The crate is layered: [`model`] is the walk and knows nothing of files or terminals;
//! [`config`] reads and validates TOML into model parameters; [`output`] writes the joint
//! table; [`analysis`] measures walks; [`report`] writes report folders; [`snapshot`] checks walks against stored figures; [`tui`] is the terminal lab and [`cli`] the command
//! line, both on top of the rest.
//!
//! The model's spec is `docs/gait-model.md` in the repository: "spec §N" in these docs is its
//! section N. Bracketed numbers like [6.3.2] and "fig 6.12" are sections and figures of the
//! thesis the spec follows (P. Mohelník, *Procedural animation of human walk*, Brno 2016).

#![warn(missing_docs)]

pub use error::{Error, Result};

pub mod analysis;
pub mod cli;
pub mod config;
pub mod error;
pub mod fit;
pub mod model;
pub mod normative;
pub mod output;
pub mod report;
pub mod snapshot;
pub mod tui;
