//! A scheduled walk's pace in the report (`[[walk.schedule]]`): `plots/speed.{png,svg}`, the
//! pelvis's forward speed over time with the schedule's events marked, and a *Pace* section
//! in `summary.md` listing the events, each plateau's figures and the transitions
//! ([`crate::analysis::steady`]). Written only for a walk whose schedule did something.

use super::metrics::SteadyPlateau;
use super::plots::{Figure, Line, Panel, write_figure};
use crate::analysis::Run;
use crate::analysis::steady::{self, AskedSpeed, Part, PartKind};
use crate::model::walk::frame::Frame;
use crate::model::walk::pace::PaceEventKind;
use std::fmt::Write as _;
use std::path::Path;

/// The plot's file stem under `plots/`.
pub(crate) const SPEED_PLOT: &str = "speed";

/// The pelvis's forward speed (m/s) over each step, heel strike to heel strike (either
/// leg), at the step's middle, then over what follows the last strike: a step's own rise and
/// fall of speed is not the pace.
fn step_mean_speed(run: &Run) -> Vec<(f64, f64)> {
    let frames = &run.frames;
    let mut strikes: Vec<usize> = vec![0];
    strikes.extend(
        (1..frames.len())
            .filter(|&i| (0..2).any(|side| frames[i].legs[side].phase < frames[i - 1].legs[side].phase - 0.5)),
    );
    strikes.push(frames.len() - 1);
    strikes.dedup();
    strikes
        .windows(2)
        .filter(|w| frames[w[1]].time_s > frames[w[0]].time_s)
        .map(|w| {
            let (a, b) = (&frames[w[0]], &frames[w[1]]);
            (0.5 * (a.time_s + b.time_s), (b.pelvis.x - a.pelvis.x) / (b.time_s - a.time_s))
        })
        .collect()
}

/// The asked speed over time, as a step line (see [`AskedSpeed`]).
fn asked_speed(run: &Run) -> Vec<(f64, f64)> {
    let end = run.frames.last().map_or(0.0, |f| f.time_s);
    let mut asked = AskedSpeed::new(run);
    let mut points = vec![(0.0, asked.now)];
    for e in &run.pace_events {
        let before = asked.now;
        if let Some(to) = asked.take(e.kind) {
            points.push((e.time_s, before));
            points.push((e.time_s, to));
        }
    }
    points.push((end, asked.now));
    points
}

fn label(kind: PaceEventKind) -> String {
    match kind {
        PaceEventKind::SpeedAsked(v) => format!("{v:.2} m/s asked"),
        PaceEventKind::SpeedReached(v) => format!("{v:.2} m/s reached"),
        other => other.name().replace('_', " "),
    }
}

/// Writes `plots/speed.png` and `.svg` when the walk has pace events; false when it has none.
pub(crate) fn write_speed_plot(
    dir: &Path,
    name: &str,
    run: &Run,
    steady: Option<&SteadyPlateau>,
) -> Result<bool, String> {
    if run.pace_events.is_empty() {
        return Ok(false);
    }
    let end = run.frames.last().map_or(1.0, |f| f.time_s).max(1e-3);
    let panel = Panel {
        title: "pelvis forward speed, mean over each step (heel strike to heel strike)".into(),
        x_desc: "time (s)".into(),
        y_desc: "speed (m/s)".into(),
        x: 0.0..end,
        lines: vec![
            Line { name: "asked (schedule)".into(), rgb: (120, 120, 120), width: 2, points: asked_speed(run) },
            Line { name: "walked".into(), rgb: (200, 30, 30), width: 3, points: step_mean_speed(run) },
        ],
        band: None,
        // The figures of summary.md come from this stretch only: shown where it lies.
        span: steady.map(|p| (p.from_s, p.to_s, "summary figures measured here".to_string())),
        marks: run.pace_events.iter().map(|e| (e.time_s, label(e.kind))).collect(),
    };
    let figure =
        Figure { title: format!("{name}: pace over time, the schedule's events marked"), rows: 1, panels: vec![panel] };
    write_figure(dir, SPEED_PLOT, &figure)?;
    Ok(true)
}

/// The sentence `summary.md` opens its figures with for a walk that was not steady
/// throughout: which part they were measured on.
pub(crate) fn headline(md: &mut String, plateau: &SteadyPlateau) {
    let _ = writeln!(
        md,
        "Steady part: {}. The walk's pace changed, so the figures below (and *Against measured gait*) are \
         measured on that plateau's whole gait cycles only, the plateau with the most of them; speed changes, \
         stopping and standing are never averaged in (every part is listed in *Pace* at the end). The health \
         checks (foot skate, penetration, reach failures, non-finite values) cover every frame.\n",
        plateau.describe()
    );
}

/// The *Pace* section of `summary.md`: each event with its time, a row per plateau with its
/// figures over its whole steps, the transitions, and which part the figures above were
/// measured on.
pub(crate) fn section(md: &mut String, run: &Run) {
    if run.pace_events.is_empty() {
        return;
    }
    md.push_str(
        "\n## Pace\n\nThe walk followed a pace schedule (`[[walk.schedule]]`):\n\n| time (s) | event |\n|---:|---|\n",
    );
    for e in &run.pace_events {
        let _ = writeln!(md, "| {:.2} | {} |", e.time_s, label(e.kind));
    }
    let parts = steady::parts(run);
    plateau_table(md, run, &parts);
    transition_table(md, &run.frames, &parts);
    let _ = writeln!(md, "\n[speed](plots/{SPEED_PLOT}.png) ([svg](plots/{SPEED_PLOT}.svg)) shows the pace over time.");
}

/// A row per plateau: asked and walked speed, cadence, stride and stance over its whole
/// steps, the time from its first to its last step's heel strike, the steps and the whole
/// right gait cycles in it, and which one the figures above were measured on.
fn plateau_table(md: &mut String, run: &Run, parts: &[Part]) {
    md.push_str(
        "\nA plateau is steady from the end of the cadence blend after its speed was reached (two steps on) \
         to the next speed or stop asked. Each is measured here over its whole steps (heel strike to heel strike, either foot), so that one shorter \
         than a gait cycle still shows its pace; the figures at the top over the whole right gait cycles of \
         the one marked *measured* (the plateau with the most of them).\n\n\
         | plateau | asked (m/s) | walked (m/s) | cadence (steps/min) | stride (m) | stance (%) | time (s) | steps | cycles |\n\
         |---|---:|---:|---:|---:|---:|---|---:|---:|\n",
    );
    let measured = steady::measured_plateau(parts).map(|m| m.first);
    let plateaus = parts.iter().filter(|p| p.kind == PartKind::Plateau);
    for (n, p) in plateaus.enumerate() {
        let name = format!("{}{}", n + 1, if measured == Some(p.first) { ", measured" } else { "" });
        let figures = match steady::step_figures(&run.frames, p) {
            Some(f) => format!(
                "{:.3} | {:.1} | {:.3} | {:.1} | {:.2}–{:.2}",
                f.speed_mps, f.cadence_spm, f.stride_m, f.stance_pct, f.span_s.0, f.span_s.1
            ),
            None => {
                let (a, b) = p.span_s(&run.frames);
                format!("— | — | — | — | {a:.2}–{b:.2}")
            }
        };
        let _ = writeln!(md, "| {name} | {:.2} | {figures} | {} | {} |", p.asked_mps, p.whole_steps(), p.cycles());
    }
}

/// The transitions: start-up, speed changes, stopping, standing (any part but a plateau),
/// with their times.
fn transition_table(md: &mut String, frames: &[Frame], parts: &[Part]) {
    md.push_str("\nTransitions, not averaged into any figure:\n\n| part | time (s) | asked (m/s) |\n|---|---|---:|\n");
    for p in parts.iter().filter(|p| p.kind != PartKind::Plateau) {
        let (a, b) = p.span_s(frames);
        let _ = writeln!(md, "| {} | {a:.2}–{b:.2} | {:.2} |", p.kind.name(), p.asked_mps);
    }
}
