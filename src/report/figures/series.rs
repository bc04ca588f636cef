//! Each thesis figure's data, from the walks `gaitlab figures` records: the figure to draw,
//! its numbers as CSV, and the sentence `figures.md` gives it.

use crate::analysis::Recording;
use crate::analysis::events::heel_strikes;
use crate::model::body::Side;
use crate::model::gait_curves::CurveName;
use crate::model::params::WalkParams;
use crate::model::terrain::{Terrain, TerrainKind};
use crate::model::walk::leg::LegPhase;
use crate::normative::References;
use crate::report::plots::data::Data;
use crate::report::plots::{Band, Figure, Line, Panel};
use std::fmt::Write as _;

/// A figure made: what to draw, its numbers, and its sentence for the index.
pub(super) struct Made {
    pub(super) figure: Figure,
    pub(super) csv: String,
    pub(super) note: String,
}

const RED: (u8, u8, u8) = (200, 40, 40);
const BLUE: (u8, u8, u8) = (30, 80, 200);
const GREEN: (u8, u8, u8) = (30, 150, 60);
const BLACK: (u8, u8, u8) = (20, 20, 20);

fn line(name: &str, rgb: (u8, u8, u8), width: u32, points: Vec<(f64, f64)>) -> Line {
    Line { name: name.to_string(), rgb, width, points }
}

fn panel(title: &str, x_desc: &str, y_desc: &str, x: std::ops::Range<f64>, lines: Vec<Line>) -> Panel {
    Panel {
        title: title.into(),
        x_desc: x_desc.into(),
        y_desc: y_desc.into(),
        x,
        lines,
        band: None,
        span: None,
        marks: Vec::new(),
    }
}

/// Root mean square of the height change from one terrain segment to the next (cm): the
/// roughness a foot meets, larger for a rougher profile.
#[must_use]
pub(super) fn rms_step_cm(heights_cm: &[f64]) -> f64 {
    let steps: Vec<f64> = heights_cm.windows(2).map(|w| w[1] - w[0]).collect();
    (steps.iter().map(|d| d * d).sum::<f64>() / steps.len().max(1) as f64).sqrt()
}

/// Fig 6.2: the config's random terrain at H 0.3 and H 0.1 (same seed, amplitude, segment).
pub(super) fn terrain(params: &WalkParams) -> Made {
    let t = &params.terrain;
    let shown_m = t.length_m.min(100.0);
    let n = (shown_m / t.segment_m).round() as usize;
    let xs: Vec<f64> = (0..=n).map(|i| i as f64 * t.segment_m).collect();
    let profile = |h: f64| {
        let ground = Terrain::new(TerrainKind::Random {
            seed: t.seed,
            roughness: h,
            amplitude_m: t.amplitude_m,
            segment_m: t.segment_m,
            length_m: t.length_m,
            start_x_m: 0.0,
        });
        xs.iter().map(|&x| ground.height(x) * 100.0).collect::<Vec<f64>>()
    };
    let (smooth, rough) = (profile(0.3), profile(0.1));
    let (rms_smooth, rms_rough) = (rms_step_cm(&smooth), rms_step_cm(&rough));
    let mut csv = String::from("x_m,height_h03_cm,height_h01_cm\n");
    for (i, x) in xs.iter().enumerate() {
        let _ = writeln!(csv, "{x:.3},{:.4},{:.4}", smooth[i], rough[i]);
    }
    let pts = |h: &[f64]| xs.iter().copied().zip(h.iter().copied()).collect::<Vec<_>>();
    let x_desc = "distance along the walk (m)";
    let title = |h: &str, rms: f64| format!("H = {h} (RMS change between segments {rms:.2} cm)");
    let figure = Figure {
        title: "Thesis fig. 6.2: random terrain by midpoint displacement, H = 0.3 (top) and H = 0.1 (bottom)".into(),
        rows: 2,
        panels: vec![
            panel(
                &title("0.3", rms_smooth),
                x_desc,
                "height (cm)",
                0.0..shown_m,
                vec![line("H = 0.3", GREEN, 2, pts(&smooth))],
            ),
            panel(
                &title("0.1", rms_rough),
                x_desc,
                "height (cm)",
                0.0..shown_m,
                vec![line("H = 0.1", RED, 2, pts(&rough))],
            ),
        ],
    };
    let note = format!(
        "Thesis fig. 6.2: the ground of `[terrain]` (seed {}, amplitude {} m, segments of {} m) generated at roughness H = 0.3 and H = 0.1; the RMS height change between neighbouring segments is {rms_smooth:.2} cm and {rms_rough:.2} cm: the smaller H, the rougher.",
        t.seed, t.amplitude_m, t.segment_m
    );
    Made { figure, csv, note }
}

/// One swing of a leg, at each percent of its time: heel forward of where it left (m),
/// heel above the ground it left (cm); and the ground's change from take-off to landing (m).
struct Swing {
    forward_m: Vec<f64>,
    heel_cm: Vec<f64>,
    rise_m: f64,
    start_s: f64,
}

/// Every swing of `run` after its first cycle (start-up), both legs, in time order.
fn swings(run: &Recording) -> Vec<Swing> {
    let f = &run.frames;
    let mut out = Vec::new();
    for side in 0..2 {
        let mut i = 1;
        while i < f.len() {
            if f[i].legs[side].leg_phase != LegPhase::Swing {
                i += 1;
                continue;
            }
            let start = i;
            while i < f.len() && f[i].legs[side].leg_phase == LegPhase::Swing {
                i += 1;
            }
            if i >= f.len() || f[start].time_s < run.cycle_s || i - start < 2 {
                continue;
            }
            let end = i - 1;
            let g0 = f[start].legs[side].ground_under_heel;
            let (t0, t1) = (f[start].time_s, f[end].time_s);
            let heel = |p: usize| {
                let t = t0 + (t1 - t0) * p as f64 / 100.0;
                let k = (start..end).find(|&k| f[k + 1].time_s >= t).unwrap_or(end - 1);
                let s = ((t - f[k].time_s) / (f[k + 1].time_s - f[k].time_s)).clamp(0.0, 1.0);
                f[k].legs[side].heel.lerp(f[k + 1].legs[side].heel, s)
            };
            let h0 = f[start].legs[side].heel;
            out.push(Swing {
                forward_m: (0..=100).map(|p| heel(p).x - h0.x).collect(),
                heel_cm: (0..=100).map(|p| (heel(p).y - g0) * 100.0).collect(),
                rise_m: f[i].legs[side].ground_under_heel - g0,
                start_s: t0,
            });
        }
    }
    out.sort_by(|a, b| a.start_s.total_cmp(&b.start_s));
    out
}

/// Fig 6.6: the swing foot on the flat, over a step up and over a step down.
pub(super) fn swing_foot(flat: &Recording, up: &Recording, down: &Recording, rise_m: f64) -> Result<Made, String> {
    let none = |what: &str| format!("the {what} walk has no steady swing to draw");
    let flat_swings = swings(flat);
    let level = flat_swings.get(flat_swings.len() / 2).ok_or_else(|| none("flat"))?;
    let highest = |run: &Recording, sign: f64| {
        swings(run).into_iter().max_by(|a, b| (sign * a.rise_m).total_cmp(&(sign * b.rise_m)))
    };
    let step_up = highest(up, 1.0).ok_or_else(|| none("step-up"))?;
    let step_down = highest(down, -1.0).ok_or_else(|| none("step-down"))?;
    let pct = |v: &[f64]| v.iter().enumerate().map(|(p, y)| (p as f64, *y)).collect::<Vec<_>>();
    let design = flat.gait.design_curves().get(CurveName::SwingForward);
    let reach = level.forward_m[100];
    let designed: Vec<(f64, f64)> = (0..=100).map(|p| (p as f64, design.eval(p as f64 / 100.0) * reach)).collect();
    let names = [
        "flat",
        &format!("step up {:.0} cm", step_up.rise_m * 100.0),
        &format!("step down {:.0} cm", -step_down.rise_m * 100.0),
    ];
    let walks = [level, &step_up, &step_down];
    let colours = [BLACK, RED, BLUE];
    let mut forward: Vec<Line> =
        walks.iter().zip(names).zip(colours).map(|((s, n), c)| line(n, c, 3, pct(&s.forward_m))).collect();
    forward.push(line("design curve x flat step", GREEN, 2, designed));
    let heel: Vec<Line> =
        walks.iter().zip(names).zip(colours).map(|((s, n), c)| line(n, c, 3, pct(&s.heel_cm))).collect();
    let x = "% of swing (toe-off to heel strike)";
    let figure = Figure {
        title: "Thesis fig. 6.6: the swing foot on the flat, over a step up and a step down (terrain-adapted curves)"
            .into(),
        rows: 1,
        panels: vec![
            panel("heel forward progress", x, "heel forward of toe-off (m)", 0.0..100.0, forward),
            panel("heel height", x, "heel above toe-off ground (cm)", 0.0..100.0, heel),
        ],
    };
    let mut csv =
        String::from("swing_pct,flat_forward_m,up_forward_m,down_forward_m,flat_heel_cm,up_heel_cm,down_heel_cm\n");
    for p in 0..=100 {
        let _ = writeln!(
            csv,
            "{p},{:.5},{:.5},{:.5},{:.3},{:.3},{:.3}",
            level.forward_m[p],
            step_up.forward_m[p],
            step_down.forward_m[p],
            level.heel_cm[p],
            step_up.heel_cm[p],
            step_down.heel_cm[p]
        );
    }
    let note = format!(
        "Thesis fig. 6.6: the heel through one swing of the walk on level ground, over a single {:.0} cm step up and down (`terrain.rise_m`), as the planner adapted its curves; the forward curve beside the design curve scaled to the flat step.",
        rise_m * 100.0
    );
    Ok(Made { figure, csv, note })
}

/// Fig 6.8: the ankle over the right gait cycle against measured adults, the swing marked
/// with the planned swing curve of a steady step and the design curve.
pub(super) fn ankle(own: &Recording) -> Result<Made, String> {
    let d = Data::new(own);
    let walk = d.cycle(0, &|i| own.frames[i].legs[0].ankle_dorsi_deg);
    let to = d.events.iter().find(|e| e.0 == "RTO").map_or(62.0, |e| e.1);
    let reference = References::built_in().at(d.speed_mps());
    let (_, mean, sd) = reference.curves.iter().find(|(s, _, _)| s == "ankle_dorsi").ok_or("no ankle norms")?;
    let lower = mean.iter().zip(sd).enumerate().map(|(i, (m, s))| (i as f64, m - s));
    let upper: Vec<(f64, f64)> = mean.iter().zip(sd).enumerate().map(|(i, (m, s))| (i as f64, m + s)).collect();
    let band = Band {
        name: format!(
            "adults{} at {:.2} m/s, Fukuchi 2018 (mean ±1 SD)",
            if d.on_level_ground() { "" } else { " on level ground" },
            reference.speed_mps
        ),
        polygon: lower.chain(upper.into_iter().rev()).collect(),
    };
    let rights: Vec<_> = own.step_plans.iter().filter(|p| p.side == Side::Right).collect();
    let step = rights.get(rights.len() / 2).ok_or("no right step planned")?;
    let on_swing = |c: &crate::model::curve::Curve| {
        (0..=100).map(|p| (to + (100.0 - to) * p as f64 / 100.0, c.eval(p as f64 / 100.0))).collect::<Vec<_>>()
    };
    let planned = on_swing(&step.swing_ankle_deg);
    let design = on_swing(own.gait.design_curves().get(CurveName::SwingAnkle));
    let mut p = panel(
        "ankle dorsiflexion, right leg",
        "% of gait cycle (right heel strike to heel strike)",
        "dorsiflexion + (deg)",
        0.0..100.0,
        vec![
            line("the walk (mean of steady cycles)", RED, 3, walk.mean.clone()),
            line("swing curve as planned (one step)", BLUE, 2, planned.clone()),
            line("swing curve as designed", BLACK, 2, design),
        ],
    );
    p.band = Some(band);
    p.span = Some((to, 100.0, "swing".into()));
    let figure = Figure {
        title: "Thesis fig. 6.8: the ankle through the gait cycle, its swing curve, and measured adults".into(),
        rows: 1,
        panels: vec![p],
    };
    let mut csv = String::from("cycle_pct,walk_ankle_deg,adults_mean_deg,adults_sd_deg\n");
    for (i, (x, y)) in walk.mean.iter().enumerate() {
        let _ = writeln!(
            csv,
            "{x:.0},{y:.4},{:.4},{:.4}",
            mean.get(i).unwrap_or(&f64::NAN),
            sd.get(i).unwrap_or(&f64::NAN)
        );
    }
    let note = format!(
        "Thesis fig. 6.8: the walk's ankle dorsiflexion over the right gait cycle (mean of the steady cycles) over measured adults' mean ±1 SD; the swing (from toe-off at {to:.0} %) shaded, with its Bezier curve as designed and as one step planned it (started at that step's toe-off angle)."
    );
    Ok(Made { figure, csv, note })
}

/// The pelvis's forward progress over the last two right cycles of `run`: time from the
/// first of their heel strikes (s), then progress (m).
fn progress(run: &Recording) -> Result<Vec<(f64, f64)>, String> {
    let strikes = heel_strikes(&run.frames, 0);
    let (a, b) = match strikes.len() {
        n if n >= 3 => (strikes[n - 3], strikes[n - 1]),
        _ => return Err("the walk is too short for two steady cycles".into()),
    };
    let f = &run.frames;
    Ok((a..=b).map(|i| (f[i].time_s - f[a].time_s, f[i].pelvis.x - f[a].pelvis.x)).collect())
}

/// Progress less the uniform progress at the window's mean speed (cm).
fn unevenness(p: &[(f64, f64)]) -> Vec<(f64, f64)> {
    let (t1, x1) = *p.last().unwrap_or(&(1.0, 0.0));
    let v = if t1 > 0.0 { x1 / t1 } else { 0.0 };
    p.iter().map(|(t, x)| (*t, (x - v * t) * 100.0)).collect()
}

/// Fig 6.15: the pelvis's forward progress on the flat and downhill.
pub(super) fn pelvis_progress(flat: &Recording, downhill: &Recording, grade_pct: f64) -> Result<Made, String> {
    let (pf, pd) = (progress(flat)?, progress(downhill)?);
    let (uf, ud) = (unevenness(&pf), unevenness(&pd));
    let t_end = pf.last().map_or(1.0, |p| p.0).max(pd.last().map_or(1.0, |p| p.0));
    let slope = format!("downhill {:.0} %", grade_pct);
    let x = "time from a right heel strike (s)";
    let figure = Figure {
        title: "Thesis fig. 6.15: the pelvis's forward progress between double supports, on the flat and downhill"
            .into(),
        rows: 1,
        panels: vec![
            panel(
                "forward progress",
                x,
                "pelvis forward (m)",
                0.0..t_end,
                vec![line("flat", BLACK, 3, pf.clone()), line(&slope, RED, 3, pd.clone())],
            ),
            panel(
                "against uniform progress",
                x,
                "ahead of uniform progress (cm)",
                0.0..t_end,
                vec![line("flat", BLACK, 3, uf.clone()), line(&slope, RED, 3, ud.clone())],
            ),
        ],
    };
    let mut csv = String::from("walk,time_s,pelvis_forward_m,ahead_of_uniform_cm\n");
    for (name, p, u) in [("flat", &pf, &uf), ("downhill", &pd, &ud)] {
        for ((t, x), (_, a)) in p.iter().zip(u) {
            let _ = writeln!(csv, "{name},{t:.5},{x:.5},{a:.4}");
        }
    }
    let note = format!(
        "Thesis fig. 6.15: the pelvis's forward position over two steady gait cycles of the walk on level ground and down a {:.0} % slope (`terrain.grade_pct`), and its lead over uniform progress at each walk's mean speed: fastest at double support, slowest at mid-stance, the keys moved downhill.",
        grade_pct.abs()
    );
    Ok(Made { figure, csv, note })
}

/// Fig 6.17: shoulder and elbow flexion over each arm's cycle.
pub(super) fn arms(own: &Recording) -> Made {
    let d = Data::new(own);
    let f = &own.frames;
    // Both arms over the right leg's cycle, so their swing opposite to each other shows.
    let shoulder = [d.cycle(0, &|i| f[i].legs[0].shoulder_flex_deg), d.cycle(0, &|i| f[i].legs[1].shoulder_flex_deg)];
    let elbow = [d.cycle(0, &|i| f[i].legs[0].elbow_flex_deg), d.cycle(0, &|i| f[i].legs[1].elbow_flex_deg)];
    let x = "% of gait cycle (right heel strike to heel strike)";
    let pair = |c: &[crate::report::plots::data::Cycle; 2]| {
        vec![line("right arm", RED, 3, c[0].mean.clone()), line("left arm", BLUE, 3, c[1].mean.clone())]
    };
    let figure = Figure {
        title: "Thesis fig. 6.17: shoulder and elbow flexion through the gait cycle (from their Bezier curves)".into(),
        rows: 1,
        panels: vec![
            panel("shoulder", x, "flexion + (deg, upper arm forward)", 0.0..100.0, pair(&shoulder)),
            panel("elbow", x, "flexion (deg)", 0.0..100.0, pair(&elbow)),
        ],
    };
    let mut csv = String::from("cycle_pct,shoulder_r_deg,shoulder_l_deg,elbow_r_deg,elbow_l_deg\n");
    for p in 0..shoulder[0].mean.len() {
        let _ = writeln!(
            csv,
            "{p},{:.4},{:.4},{:.4},{:.4}",
            shoulder[0].mean[p].1, shoulder[1].mean[p].1, elbow[0].mean[p].1, elbow[1].mean[p].1
        );
    }
    let note = "Thesis fig. 6.17: the walk's shoulder and elbow flexion, both arms over the right gait cycle (mean of the steady cycles), as the shoulder and elbow Bezier curves drive them: each arm swings opposite to its side's leg, most forward at the other leg's heel strike.".to_string();
    Made { figure, csv, note }
}
