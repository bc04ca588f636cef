//! The report's plots, each as a 1600x1000 PNG and an SVG, drawn with plotters and a font
//! embedded in the binary (DejaVu Sans, `assets/fonts`), so no system font is needed.
//!
//! Curves over the gait cycle are the mean of the steady cycles with their min–max band;
//! the right leg's cycle runs from its heel strike, the left leg's from its own. Vertical
//! lines mark the gait events (mean over the cycles): right toe-off (RTO), left heel strike
//! (LHS), left toe-off (LTO).

use crate::analysis::Run;
use crate::analysis::events as gait_events;
use crate::analysis::ik::{IkSample, IkTarget, SolverRun};
use crate::model::body::{Bone, Side};
use crate::model::gait_curves::CurveName;
use crate::model::walk::frame::Frame;
use plotters::coord::Shift;
use plotters::prelude::*;
use std::path::Path;
use std::sync::Once;

/// Pixel size of every PNG (and the SVG's nominal size).
pub const SIZE: (u32, u32) = (1600, 1000);

/// Plot names, each written as `plots/<name>.png` and `plots/<name>.svg`.
pub const PLOTS: &[&str] = &["pelvis", "swing_foot", "ankle", "joints", "stick_figure", "optimisation", "ik"];

const FONT: &str = "sans-serif";
static REGISTER_FONT: Once = Once::new();

fn register_font() {
    REGISTER_FONT.call_once(|| {
        let bytes: &'static [u8] = include_bytes!("../../assets/fonts/DejaVuSans.ttf");
        // The font is compiled in and known to parse; failure would be a build problem.
        let _ = plotters::style::register_font(FONT, FontStyle::Normal, bytes);
    });
}

type Res = Result<(), String>;

fn err<E: std::fmt::Debug>(e: E) -> String {
    format!("plot: {e:?}")
}

/// A quantity over the gait cycle: mean, min and max at each percent.
struct Cycle {
    mean: Vec<(f64, f64)>,
    band: Vec<(f64, f64)>,
}

/// Everything the plots need, prepared once.
struct Data<'a> {
    run: &'a Run,
    /// Heel strikes per side (frame indices), steady ones only (start-up cycle dropped).
    strikes: [Vec<usize>; 2],
    /// Mean % of the right cycle: right toe-off, left heel strike, left toe-off.
    events: Vec<(&'static str, f64)>,
}

fn strikes_of(frames: &[Frame], side: usize) -> Vec<usize> {
    gait_events::heel_strikes(frames, side).into_iter().skip(1).collect()
}

impl<'a> Data<'a> {
    fn new(run: &'a Run) -> Data<'a> {
        let frames = &run.frames;
        let strikes = [strikes_of(frames, 0), strikes_of(frames, 1)];
        let right = &strikes[0];
        let mut events = Vec::new();
        let pct_of = |pred: &dyn Fn(&Frame, &Frame) -> bool| {
            let mut v = Vec::new();
            for w in right.windows(2) {
                if let Some(i) = (w[0] + 1..w[1]).find(|&i| pred(&frames[i - 1], &frames[i])) {
                    v.push(
                        100.0 * (frames[i].time_s - frames[w[0]].time_s) / (frames[w[1]].time_s - frames[w[0]].time_s),
                    );
                }
            }
            if v.is_empty() { f64::NAN } else { v.iter().sum::<f64>() / v.len() as f64 }
        };
        events.push(("RTO", pct_of(&|a: &Frame, b: &Frame| gait_events::is_toe_off(a, b, 0))));
        events.push(("LHS", pct_of(&|a: &Frame, b: &Frame| gait_events::is_heel_strike(a, b, 1))));
        events.push(("LTO", pct_of(&|a: &Frame, b: &Frame| gait_events::is_toe_off(a, b, 1))));
        events.retain(|e| e.1.is_finite());
        Data { run, strikes, events }
    }

    /// `value` per frame, normalised to each of `side`'s steady cycles.
    fn cycle(&self, side: usize, value: &dyn Fn(usize) -> f64) -> Cycle {
        let frames = &self.run.frames;
        let mut samples: Vec<Vec<f64>> = vec![Vec::new(); 101];
        for w in self.strikes[side].windows(2) {
            let (t0, t1) = (frames[w[0]].time_s, frames[w[1]].time_s);
            let mut i = w[0];
            for (p, bucket) in samples.iter_mut().enumerate() {
                let t = t0 + (t1 - t0) * p as f64 / 100.0;
                while i + 1 < w[1] && frames[i + 1].time_s <= t {
                    i += 1;
                }
                let (ta, tb) = (frames[i].time_s, frames[i + 1].time_s);
                let s = if tb > ta { ((t - ta) / (tb - ta)).clamp(0.0, 1.0) } else { 0.0 };
                bucket.push(value(i) * (1.0 - s) + value(i + 1) * s);
            }
        }
        let mean = samples
            .iter()
            .enumerate()
            .map(|(p, v)| (p as f64, v.iter().sum::<f64>() / v.len().max(1) as f64))
            .collect();
        let lo: Vec<(f64, f64)> = samples
            .iter()
            .enumerate()
            .map(|(p, v)| (p as f64, v.iter().copied().fold(f64::INFINITY, f64::min)))
            .collect();
        let hi: Vec<(f64, f64)> = samples
            .iter()
            .enumerate()
            .map(|(p, v)| (p as f64, v.iter().copied().fold(f64::NEG_INFINITY, f64::max)))
            .collect();
        let band = lo.into_iter().chain(hi.into_iter().rev()).collect();
        Cycle { mean, band }
    }
}

fn y_range(series: &[&[(f64, f64)]]) -> std::ops::Range<f64> {
    let (lo, hi) = series
        .iter()
        .flat_map(|s| s.iter().map(|p| p.1))
        .filter(|y| y.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), y| (a.min(y), b.max(y)));
    if !lo.is_finite() {
        return 0.0..1.0;
    }
    let pad = ((hi - lo) * 0.1).max(1e-3);
    (lo - pad)..(hi + pad)
}

const RIGHT: RGBColor = RGBColor(200, 40, 40);
const LEFT: RGBColor = RGBColor(30, 80, 200);
const DESIGN: RGBColor = RGBColor(20, 20, 20);

/// One chart over % of the gait cycle: each (name, colour, cycle) as mean line and band.
fn cycle_chart<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    title: &str,
    y_desc: &str,
    lines: &[(&str, RGBColor, &Cycle)],
    events: &[(&'static str, f64)],
) -> Res {
    let all: Vec<&[(f64, f64)]> = lines.iter().flat_map(|(_, _, c)| [c.mean.as_slice(), c.band.as_slice()]).collect();
    let y = y_range(&all);
    let mut chart = ChartBuilder::on(area)
        .caption(title, (FONT, 30))
        .margin(12)
        .x_label_area_size(55)
        .y_label_area_size(80)
        .build_cartesian_2d(0f64..100f64, y.clone())
        .map_err(err)?;
    chart
        .configure_mesh()
        .x_desc("% of gait cycle")
        .x_labels(11)
        .x_label_formatter(&|x| format!("{x:.0}"))
        .y_desc(y_desc)
        .label_style((FONT, 20))
        .axis_desc_style((FONT, 22))
        .draw()
        .map_err(err)?;
    for (name, color, c) in lines {
        chart.draw_series(std::iter::once(Polygon::new(c.band.clone(), color.mix(0.18)))).map_err(err)?;
        chart
            .draw_series(LineSeries::new(c.mean.clone(), color.stroke_width(3)))
            .map_err(err)?
            .label(*name)
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 24, y)], color.stroke_width(3)));
    }
    for (name, pct) in events {
        chart
            .draw_series(std::iter::once(PathElement::new(
                vec![(*pct, y.start), (*pct, y.end)],
                BLACK.mix(0.5).stroke_width(1),
            )))
            .map_err(err)?;
        chart
            .draw_series(std::iter::once(Text::new(
                name.to_string(),
                (*pct + 0.8, y.end - (y.end - y.start) * 0.06),
                (FONT, 18),
            )))
            .map_err(err)?;
    }
    chart
        .configure_series_labels()
        .label_font((FONT, 20))
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .position(SeriesLabelPosition::UpperRight)
        .draw()
        .map_err(err)?;
    Ok(())
}

/// Pelvis panels: title, unit.
const PELVIS_PANELS: [(&str, &str); 6] = [
    ("tilt", "anterior tilt (deg)"),
    ("obliquity", "right hip up (deg)"),
    ("rotation", "right hip forward (deg)"),
    ("vertical", "height above lower foot's ground (cm)"),
    ("lateral", "position, right + (cm)"),
    ("forward velocity", "velocity (m/s)"),
];

/// The six pelvis quantities of one walk over its right cycle, in [`PELVIS_PANELS`] order.
fn pelvis_cycles(d: &Data<'_>) -> Vec<Cycle> {
    let f = &d.run.frames;
    let dt = 1.0 / d.run.fps;
    let velocity = |i: usize| {
        let (a, b) = (i.saturating_sub(1), (i + 1).min(f.len() - 1));
        (f[b].pelvis.x - f[a].pelvis.x) / ((b - a).max(1) as f64 * dt)
    };
    let base_y = |i: usize| f[i].pelvis.y - f[i].legs.iter().map(|l| l.ground_under_heel).fold(f64::INFINITY, f64::min);
    vec![
        d.cycle(0, &|i| f[i].pelvis_tilt_deg),
        d.cycle(0, &|i| f[i].pelvis_obliquity_deg),
        d.cycle(0, &|i| f[i].pelvis_rotation_deg),
        d.cycle(0, &|i| base_y(i) * 100.0),
        d.cycle(0, &|i| f[i].pelvis.z * 100.0),
        d.cycle(0, &velocity),
    ]
}

/// Colours of compared walks, the report's own first.
const PALETTE: [RGBColor; 5] = [
    RGBColor(200, 40, 40),
    RGBColor(30, 80, 200),
    RGBColor(30, 150, 60),
    RGBColor(230, 130, 0),
    RGBColor(130, 40, 170),
];

fn pelvis<DB: DrawingBackend>(root: DrawingArea<DB, Shift>, walks: &[(String, Data<'_>)]) -> Res {
    root.fill(&WHITE).map_err(err)?;
    let root = root
        .titled("Pelvis over the right gait cycle (mean and min-max band of the steady cycles)", (FONT, 34))
        .map_err(err)?;
    let areas = root.split_evenly((2, 3));
    let cycles: Vec<Vec<Cycle>> = walks.iter().map(|(_, d)| pelvis_cycles(d)).collect();
    for (p, (area, (title, unit))) in areas.iter().zip(PELVIS_PANELS).enumerate() {
        let lines: Vec<(&str, RGBColor, &Cycle)> = walks
            .iter()
            .enumerate()
            .map(|(k, (name, _))| (name.as_str(), PALETTE[k % PALETTE.len()], &cycles[k][p]))
            .collect();
        cycle_chart(area, title, unit, &lines, &walks[0].1.events)?;
    }
    root.present().map_err(err)
}

fn joints<DB: DrawingBackend>(root: DrawingArea<DB, Shift>, walks: &[(String, Data<'_>)]) -> Res {
    root.fill(&WHITE).map_err(err)?;
    let title = if walks.len() == 1 {
        "Joint angles, each leg over its own gait cycle (mean and min-max band)"
    } else {
        "Joint angles of the right leg, each walk over its own gait cycle (mean and min-max band)"
    };
    let root = root.titled(title, (FONT, 34)).map_err(err)?;
    let areas = root.split_evenly((1, 3));
    type Pick = fn(&crate::model::walk::frame::LegFrame) -> f64;
    let joints: [(&str, &str, Pick); 3] = [
        ("hip", "flexion + (deg)", |l| l.hip_flex_deg),
        ("knee", "flexion + (deg)", |l| l.knee_flex_deg),
        ("ankle", "dorsiflexion + (deg)", |l| l.ankle_dorsi_deg),
    ];
    for (area, (name, unit, pick)) in areas.iter().zip(joints) {
        let mut cycles = Vec::new();
        for (k, (walk, d)) in walks.iter().enumerate() {
            let f = &d.run.frames;
            if walks.len() == 1 {
                cycles.push(("right".to_string(), RIGHT, d.cycle(0, &|i| pick(&f[i].legs[0]))));
                cycles.push(("left".to_string(), LEFT, d.cycle(1, &|i| pick(&f[i].legs[1]))));
            } else {
                cycles.push((walk.clone(), PALETTE[k % PALETTE.len()], d.cycle(0, &|i| pick(&f[i].legs[0]))));
            }
        }
        let lines: Vec<(&str, RGBColor, &Cycle)> = cycles.iter().map(|(n, c, cy)| (n.as_str(), *c, cy)).collect();
        cycle_chart(area, name, unit, &lines, &walks[0].1.events)?;
    }
    root.present().map_err(err)
}

/// A chart of curves over 0–100 % of their own span.
fn curve_chart<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    title: &str,
    x_desc: &str,
    y_desc: &str,
    design: &[(f64, f64)],
    steps: &[Vec<(f64, f64)>],
) -> Res {
    let mut all: Vec<&[(f64, f64)]> = vec![design];
    all.extend(steps.iter().map(Vec::as_slice));
    let y = y_range(&all);
    let mut chart = ChartBuilder::on(area)
        .caption(title, (FONT, 30))
        .margin(12)
        .x_label_area_size(55)
        .y_label_area_size(80)
        .build_cartesian_2d(0f64..100f64, y)
        .map_err(err)?;
    chart
        .configure_mesh()
        .x_desc(x_desc)
        .x_labels(11)
        .x_label_formatter(&|x| format!("{x:.0}"))
        .y_desc(y_desc)
        .label_style((FONT, 20))
        .axis_desc_style((FONT, 22))
        .draw()
        .map_err(err)?;
    for (k, s) in steps.iter().enumerate() {
        let series = chart.draw_series(LineSeries::new(s.clone(), RIGHT.mix(0.45).stroke_width(2))).map_err(err)?;
        if k == 0 {
            series
                .label("adapted, each step")
                .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 24, y)], RIGHT.stroke_width(2)));
        }
    }
    chart
        .draw_series(LineSeries::new(design.to_vec(), DESIGN.stroke_width(3)))
        .map_err(err)?
        .label("design")
        .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 24, y)], DESIGN.stroke_width(3)));
    chart
        .configure_series_labels()
        .label_font((FONT, 20))
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .draw()
        .map_err(err)?;
    Ok(())
}

fn sample(curve: &crate::model::curve::Curve, scale: f64) -> Vec<(f64, f64)> {
    (0..=100).map(|p| (p as f64, curve.eval(p as f64 / 100.0) * scale)).collect()
}

fn swing_foot<DB: DrawingBackend>(root: DrawingArea<DB, Shift>, d: &Data<'_>) -> Res {
    root.fill(&WHITE).map_err(err)?;
    let root = root
        .titled("Swing foot: design curves and each step's terrain-adapted heel height", (FONT, 34))
        .map_err(err)?;
    let areas = root.split_evenly((1, 3));
    let design = d.run.gait.design_curves();
    let steps: Vec<Vec<(f64, f64)>> = d.run.step_plans.iter().map(|p| sample(&p.swing_heel_height, 100.0)).collect();
    curve_chart(
        &areas[0],
        "forward progress",
        "% of swing",
        "heel progress to footfall (0-1)",
        &sample(design.get(CurveName::SwingForward), 1.0),
        &[],
    )?;
    curve_chart(
        &areas[1],
        "lateral",
        "% of swing",
        "weight toward hip line (0-1)",
        &sample(design.get(CurveName::SwingLateral), 1.0),
        &[],
    )?;
    curve_chart(
        &areas[2],
        "heel height",
        "% of swing",
        "above toe-off ground (cm)",
        &sample(design.get(CurveName::SwingHeelHeight), 100.0),
        &steps,
    )?;
    root.present().map_err(err)
}

fn ankle<DB: DrawingBackend>(root: DrawingArea<DB, Shift>, d: &Data<'_>) -> Res {
    root.fill(&WHITE).map_err(err)?;
    let root = root.titled("Foot pitch through the swing, and heel rise", (FONT, 34)).map_err(err)?;
    let areas = root.split_evenly((1, 2));
    let design = d.run.gait.design_curves();
    let steps: Vec<Vec<(f64, f64)>> = d.run.step_plans.iter().map(|p| sample(&p.swing_ankle_deg, 1.0)).collect();
    curve_chart(
        &areas[0],
        "ankle curve (foot pitch)",
        "% of swing",
        "toe up + (deg)",
        &sample(design.get(CurveName::SwingAnkle), 1.0),
        &steps,
    )?;
    curve_chart(
        &areas[1],
        "heel rise",
        "% of heel-rise phase",
        "foot-ground angle (deg)",
        &sample(design.get(CurveName::HeelRise), 1.0),
        &[],
    )?;
    root.present().map_err(err)
}

fn stick_figure<DB: DrawingBackend>(root: DrawingArea<DB, Shift>, d: &Data<'_>) -> Res {
    root.fill(&WHITE).map_err(err)?;
    let frames = &d.run.frames;
    // The middle steady cycle: on stairs or a slope, on the climb rather than before it.
    let mid = d.strikes[0].len().saturating_sub(2) / 2;
    let Some(&start) = d.strikes[0].get(mid) else { return root.present().map_err(err) };
    let end = d.strikes[0].get(mid + 1).copied().unwrap_or(frames.len() - 1).min(frames.len() - 1);
    // The recorded full-body poses of the window (the frames hold the legs only).
    let step = ((end - start) / 16).max(1);
    let poses: Vec<(usize, &crate::model::body::Pose)> = (start.max(1)..=end)
        .filter(|i| (i - start) % step == 0)
        .filter_map(|i| d.run.poses.get(i).map(|p| (i, p)))
        .collect();
    let x0 = frames[start].pelvis.x - 0.6;
    let x1 = frames[end].pelvis.x + 0.6;
    let ground = frames[start..=end]
        .iter()
        .flat_map(|f| f.legs.iter().map(|l| l.ground_under_heel))
        .fold(f64::INFINITY, f64::min);
    let top = frames[start..=end].iter().map(|f| f.pelvis.y).fold(f64::NEG_INFINITY, f64::max) + 1.0;
    // Equal metres per pixel on both axes.
    let (w, h) = (f64::from(SIZE.0 - 120), f64::from(SIZE.1 - 160));
    let height = (x1 - x0) * h / w;
    let y0 = ground - 0.1;
    let y1 = (y0 + height).max(top);
    let mut chart = ChartBuilder::on(&root)
        .caption("Side view over one gait cycle, with heel and toe paths", (FONT, 34))
        .margin(15)
        .x_label_area_size(55)
        .y_label_area_size(70)
        .build_cartesian_2d(x0..x1, y0..y1)
        .map_err(err)?;
    chart
        .configure_mesh()
        .x_desc("forward x (m)")
        .y_desc("height y (m)")
        .label_style((FONT, 20))
        .axis_desc_style((FONT, 22))
        .draw()
        .map_err(err)?;
    let terrain = &d.run.terrain;
    chart
        .draw_series(std::iter::once(PathElement::new(
            (0..=400)
                .map(|k| {
                    let x = x0 + (x1 - x0) * f64::from(k) / 400.0;
                    (x, terrain.height(x))
                })
                .collect::<Vec<_>>(),
            RGBColor(60, 140, 60).stroke_width(3),
        )))
        .map_err(err)?
        .label("terrain")
        .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 24, y)], RGBColor(60, 140, 60).stroke_width(3)));
    for (side, color, name) in [(0usize, RIGHT, "right heel / toe path"), (1, LEFT, "left heel / toe path")] {
        for (k, pick) in
            [|l: &crate::model::walk::frame::LegFrame| l.heel, |l: &crate::model::walk::frame::LegFrame| l.toe]
                .iter()
                .enumerate()
        {
            let s = chart
                .draw_series(LineSeries::new(
                    frames[start..=end].iter().map(|f| {
                        let p = pick(&f.legs[side]);
                        (p.x, p.y)
                    }),
                    color.mix(if k == 0 { 0.9 } else { 0.5 }).stroke_width(2),
                ))
                .map_err(err)?;
            if k == 0 {
                s.label(name).legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 24, y)], color.stroke_width(2)));
            }
        }
    }
    for (i, pose) in &poses {
        let legs = &frames[*i].legs;
        let seg = |a: glam::DVec3, b: glam::DVec3, c: RGBAColor| {
            PathElement::new(vec![(a.x, a.y), (b.x, b.y)], c.stroke_width(2))
        };
        let mut elements = vec![
            seg(pose.pos(Bone::Pelvis), pose.pos(Bone::Spine), DESIGN.mix(1.0)),
            seg(pose.pos(Bone::Spine), pose.pos(Bone::Chest), DESIGN.mix(1.0)),
            seg(pose.pos(Bone::Chest), pose.pos(Bone::Neck), DESIGN.mix(1.0)),
            seg(pose.pos(Bone::Neck), pose.pos(Bone::Head), DESIGN.mix(1.0)),
        ];
        for side in Side::BOTH {
            let c = if side == Side::Right { RIGHT } else { LEFT };
            let l = &legs[side.index()];
            elements.push(seg(l.hip, l.knee, c.mix(1.0)));
            elements.push(seg(l.knee, l.ankle, c.mix(1.0)));
            elements.push(seg(l.ankle, l.heel, c.mix(1.0)));
            elements.push(seg(l.heel, pose.pos(Bone::toe(side)), c.mix(1.0)));
            elements.push(seg(pose.pos(Bone::toe(side)), l.toe, c.mix(1.0)));
            elements.push(seg(pose.pos(Bone::Neck), pose.pos(Bone::upper_arm(side)), DESIGN.mix(0.6)));
            elements.push(seg(pose.pos(Bone::upper_arm(side)), pose.pos(Bone::forearm(side)), c.mix(0.6)));
            elements.push(seg(pose.pos(Bone::forearm(side)), pose.pos(Bone::hand(side)), c.mix(0.6)));
        }
        chart.draw_series(elements).map_err(err)?;
        let head = pose.pos(Bone::Head);
        chart
            .draw_series(std::iter::once(Circle::new((head.x, head.y + 0.1), 8, DESIGN.stroke_width(2))))
            .map_err(err)?;
    }
    chart
        .configure_series_labels()
        .label_font((FONT, 20))
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .position(SeriesLabelPosition::UpperLeft)
        .draw()
        .map_err(err)?;
    root.present().map_err(err)
}

fn optimisation<DB: DrawingBackend>(root: DrawingArea<DB, Shift>, d: &Data<'_>) -> Res {
    root.fill(&WHITE).map_err(err)?;
    let root = root.titled("Pelvis-acceleration optimisation", (FONT, 34)).map_err(err)?;
    let (left, right) = root.split_horizontally(SIZE.0 / 2);
    let plans = &d.run.step_plans;
    // A representative step: the middle one; its landscape by re-walking to it.
    let target = plans.len() / 2;
    let recorded = d.run.step_problems.get(target).and_then(Option::as_ref);
    if let (Some((problem, gait)), Some(plan)) = (recorded, plans.get(target)) {
        let mut land = problem.landscape(gait, 81);
        let (lo, hi) = problem.range;
        // The feasible band is often a few centimetres of a range tens of centimetres wide:
        // then the plot shows the band (with one unreachable sample each side), sampled at 41
        // points, so the valley the search works in is visible.
        let (mut x_from, mut x_to) = (lo, hi);
        let feasible_x: Vec<f64> = land.iter().filter(|c| c.cost.is_some()).map(|c| c.x).collect();
        if let (Some(&first), Some(&last)) = (feasible_x.first(), feasible_x.last()) {
            let step = (hi - lo) / 80.0;
            if last - first < 0.25 * (hi - lo) {
                x_from = (first - 1.5 * step).max(lo);
                x_to = (last + 1.5 * step).min(hi);
                land = (0..=40)
                    .map(|i| {
                        let x = x_from + (x_to - x_from) * f64::from(i) / 40.0;
                        crate::model::optimise::Candidate {
                            x,
                            y: problem.ds.y,
                            cost: problem.cost(gait, x, problem.ds.y),
                        }
                    })
                    .collect();
            }
        }
        let feasible: Vec<(f64, f64)> = land.iter().filter_map(|c| c.cost.map(|k| ((c.x - lo) * 100.0, k))).collect();
        let x_axis = (x_from - lo) * 100.0..((x_to - lo) * 100.0).max((x_from - lo) * 100.0 + 1e-6);
        let y = y_range(&[feasible.as_slice()]);
        let zoomed = if (x_from, x_to) == (lo, hi) { String::new() } else { " (feasible band)".to_string() };
        let mut chart = ChartBuilder::on(&left)
            .caption(format!("cost landscape, step {}{zoomed}", plan.step), (FONT, 30))
            .margin(12)
            .x_label_area_size(55)
            .y_label_area_size(90)
            .build_cartesian_2d(x_axis, y.clone())
            .map_err(err)?;
        chart
            .configure_mesh()
            .x_desc("pelvis x at double support, from range start (cm)")
            .y_desc("cost (rad^2/s^3)")
            .label_style((FONT, 20))
            .axis_desc_style((FONT, 22))
            .draw()
            .map_err(err)?;
        chart
            .draw_series(feasible.iter().map(|p| Circle::new(*p, 4, RIGHT.filled())))
            .map_err(err)?
            .label("feasible candidate")
            .legend(|(x, y)| Circle::new((x + 10, y), 4, RIGHT.filled()));
        let unreachable: Vec<(f64, f64)> =
            land.iter().filter(|c| c.cost.is_none()).map(|c| ((c.x - lo) * 100.0, y.start)).collect();
        chart
            .draw_series(unreachable.iter().map(|p| Cross::new(*p, 5, BLACK.stroke_width(2))))
            .map_err(err)?
            .label("unreachable")
            .legend(|(x, y)| Cross::new((x + 10, y), 5, BLACK.stroke_width(2)));
        if let Some(cost) = plan.optimisation.chosen.cost {
            chart
                .draw_series(std::iter::once(TriangleMarker::new(
                    ((plan.optimisation.chosen.x - lo) * 100.0, cost),
                    12,
                    LEFT.filled(),
                )))
                .map_err(err)?
                .label("chosen")
                .legend(|(x, y)| TriangleMarker::new((x + 10, y), 8, LEFT.filled()));
        }
        chart
            .configure_series_labels()
            .label_font((FONT, 20))
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK)
            .draw()
            .map_err(err)?;
    }
    let (top, bottom) = right.split_vertically(SIZE.1 / 2 - 30);
    let steps: Vec<f64> = plans.iter().map(|p| p.step as f64).collect();
    let smax = steps.iter().copied().fold(1.0, f64::max);
    let ratio: Vec<(f64, f64)> = plans.iter().map(|p| (p.step as f64, p.optimisation.chosen_ratio())).collect();
    let mut chart = ChartBuilder::on(&top)
        .caption("chosen position per step", (FONT, 28))
        .margin(12)
        .x_label_area_size(50)
        .y_label_area_size(80)
        .build_cartesian_2d(0f64..smax + 1.0, 0f64..1f64)
        .map_err(err)?;
    chart
        .configure_mesh()
        .x_desc("step")
        .y_desc("between mid-stances (0-1)")
        .label_style((FONT, 18))
        .axis_desc_style((FONT, 20))
        .draw()
        .map_err(err)?;
    chart.draw_series(ratio.iter().map(|p| Circle::new(*p, 5, LEFT.filled()))).map_err(err)?;
    let chosen: Vec<(f64, f64)> =
        plans.iter().filter_map(|p| p.optimisation.chosen.cost.map(|c| (p.step as f64, c))).collect();
    let fixed: Vec<(f64, f64)> =
        plans.iter().filter_map(|p| p.optimisation.fixed_rule.cost.map(|c| (p.step as f64, c))).collect();
    let y = y_range(&[chosen.as_slice(), fixed.as_slice()]);
    let mut chart = ChartBuilder::on(&bottom)
        .caption("cost per step", (FONT, 28))
        .margin(12)
        .x_label_area_size(50)
        .y_label_area_size(80)
        .build_cartesian_2d(0f64..smax + 1.0, y)
        .map_err(err)?;
    chart
        .configure_mesh()
        .x_desc("step")
        .y_desc("cost (rad^2/s^3)")
        .label_style((FONT, 18))
        .axis_desc_style((FONT, 20))
        .draw()
        .map_err(err)?;
    chart
        .draw_series(LineSeries::new(fixed, DESIGN.stroke_width(2)))
        .map_err(err)?
        .label("fixed rule")
        .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 24, y)], DESIGN.stroke_width(2)));
    chart
        .draw_series(LineSeries::new(chosen, RIGHT.stroke_width(3)))
        .map_err(err)?
        .label("optimised")
        .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 24, y)], RIGHT.stroke_width(3)));
    chart
        .configure_series_labels()
        .label_font((FONT, 18))
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .draw()
        .map_err(err)?;
    root.present().map_err(err)
}

/// Per frame, the worse of the two legs' values.
fn per_frame(targets: &[IkTarget], run: &SolverRun, value: impl Fn(&IkSample) -> f64) -> Vec<(f64, f64)> {
    let mut out: Vec<(f64, f64)> = Vec::new();
    for (t, x) in targets.iter().zip(&run.samples) {
        let v = value(x);
        match out.last_mut() {
            Some(last) if last.0 == t.time_s => last.1 = last.1.max(v),
            _ => out.push((t.time_s, v)),
        }
    }
    out
}

fn ik<DB: DrawingBackend>(root: DrawingArea<DB, Shift>, targets: &[IkTarget], runs: &[SolverRun]) -> Res {
    root.fill(&WHITE).map_err(err)?;
    let root = root.titled("Leg IK on the walk's targets (worse leg per frame)", (FONT, 34)).map_err(err)?;
    let (top, bottom) = root.split_vertically((SIZE.1 - 50) / 2);
    let t_end = targets.last().map_or(1.0, |t| t.time_s).max(1e-3);
    let errors: Vec<Vec<(f64, f64)>> =
        runs.iter().map(|r| per_frame(targets, r, |x| x.answer.position_error * 1e3)).collect();
    let iterations: Vec<Vec<(f64, f64)>> =
        runs.iter().map(|r| per_frame(targets, r, |x| f64::from(x.answer.iterations.max(1)))).collect();
    // Headroom above the data for the legend.
    let error_max = errors.iter().flatten().map(|p| p.1).fold(0.0, f64::max).max(1e-3) * 1.5;
    let iteration_max = iterations.iter().flatten().map(|p| p.1).fold(1.0, f64::max) * 8.0;
    for (area, caption, y_desc, series, log) in [
        (&top, "ankle position error", "error (mm)", &errors, false),
        (&bottom, "iterations per solve", "iterations (log scale)", &iterations, true),
    ] {
        let mut builder = ChartBuilder::on(area);
        builder.caption(caption, (FONT, 28)).margin(12).x_label_area_size(50).y_label_area_size(90);
        macro_rules! draw {
            ($chart:expr) => {{
                let mut chart = $chart;
                chart
                    .configure_mesh()
                    .x_desc("time (s)")
                    .y_desc(y_desc)
                    .y_label_formatter(&|v| if log { format!("{v:.0}") } else { format!("{v:.3}") })
                    .label_style((FONT, 18))
                    .axis_desc_style((FONT, 20))
                    .draw()
                    .map_err(err)?;
                for (i, (run, points)) in runs.iter().zip(series.iter()).enumerate() {
                    let colour = PALETTE[i % PALETTE.len()];
                    chart
                        .draw_series(LineSeries::new(points.iter().copied(), colour.stroke_width(2)))
                        .map_err(err)?
                        .label(run.solver.name())
                        .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 24, y)], colour.stroke_width(3)));
                }
                chart
                    .configure_series_labels()
                    .label_font((FONT, 18))
                    .background_style(WHITE.mix(0.85))
                    .border_style(BLACK)
                    .position(SeriesLabelPosition::UpperRight)
                    .draw()
                    .map_err(err)?;
            }};
        }
        if log {
            draw!(builder.build_cartesian_2d(0f64..t_end, (1f64..iteration_max).log_scale()).map_err(err)?);
        } else {
            draw!(builder.build_cartesian_2d(0f64..t_end, 0f64..error_max).map_err(err)?);
        }
    }
    root.present().map_err(err)
}

macro_rules! both {
    ($dir:expr, $name:expr, $f:ident $(, $arg:expr)*) => {{
        let png = $dir.join(format!("{}.png", $name));
        let svg = $dir.join(format!("{}.svg", $name));
        $f(BitMapBackend::new(&png, SIZE).into_drawing_area() $(, $arg)*)?;
        $f(SVGBackend::new(&svg, SIZE).into_drawing_area() $(, $arg)*)?;
    }};
}

/// A walk to plot: its name (legend), run and parameters.
pub struct Walk<'a> {
    /// Legend name (the config's file stem).
    pub name: String,
    /// The simulated walk.
    pub run: &'a Run,
}

/// Writes every plot of [`PLOTS`] into `dir` (which must exist). The first walk is the
/// report's; others (from `--compare`) are overlaid on the pelvis and joint-angle plots.
pub fn write_plots(dir: &Path, walks: &[Walk<'_>]) -> Res {
    register_font();
    let all: Vec<(String, Data<'_>)> = walks.iter().map(|w| (w.name.clone(), Data::new(w.run))).collect();
    let d = &all[0].1;
    both!(dir, "pelvis", pelvis, &all);
    both!(dir, "swing_foot", swing_foot, d);
    both!(dir, "ankle", ankle, d);
    both!(dir, "joints", joints, &all);
    both!(dir, "stick_figure", stick_figure, d);
    both!(dir, "optimisation", optimisation, d);
    Ok(())
}

/// Writes `ik.png` and `ik.svg` into `dir`: each solver's error and iterations per frame.
pub fn write_ik_plot(dir: &Path, targets: &[IkTarget], runs: &[SolverRun]) -> Res {
    register_font();
    both!(dir, "ik", ik, targets, runs);
    Ok(())
}
