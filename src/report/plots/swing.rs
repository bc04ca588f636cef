//! Plots of the swing's curves over their own span: each design curve, and each step's
//! curve as the planner adapted it to the terrain.

use super::common::{
    DESIGN, FONT, LEFT, LEGEND_FONT_PX, PALETTE, RIGHT, Res, draw_legend, err, legend_corner, percent_chart, titled,
    y_range,
};
use super::data::Data;
use crate::model::body::HEEL_FRACTION;
use crate::model::curve::Curve;
use crate::model::gait_curves::CurveName;
use crate::model::walk::HEEL_RISE_DESIGN_STRIDE_M;
use crate::model::walk::frame::LegFrame;
use crate::model::walk::leg::LegPhase;
use plotters::coord::Shift;
use plotters::prelude::*;

/// A curve sampled over its span.
type Sampled = Vec<(f64, f64)>;

/// Each step's adapted curves of one walk: legend name, colour, curves.
type Steps<'a> = (String, RGBColor, &'a [Sampled]);

/// A chart of curves over 0–100 % of their own span: the design curve over each walk's
/// steps (one walk's in red; compared walks' in their palette colours, named).
fn curve_chart<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    title: &str,
    x_desc: &str,
    y_desc: &str,
    design: &[(f64, f64)],
    walks: &[Steps<'_>],
) -> Res {
    let mut all: Vec<&[(f64, f64)]> = vec![design];
    all.extend(walks.iter().flat_map(|(_, _, steps)| steps.iter().map(Vec::as_slice)));
    let y = y_range(&all);
    let mut chart = percent_chart(area, title, y.clone())?;
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
    let mut labels: Vec<&str> = Vec::new();
    for (name, color, steps) in walks {
        let color = *color;
        for (k, s) in steps.iter().enumerate() {
            let series = chart.draw_series(LineSeries::new(s.clone(), color.mix(0.45).stroke_width(2))).map_err(err)?;
            if k == 0 {
                series
                    .label(name.as_str())
                    .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 24, y)], color.stroke_width(2)));
                labels.push(name);
            }
        }
    }
    chart
        .draw_series(LineSeries::new(design.to_vec(), DESIGN.stroke_width(3)))
        .map_err(err)?
        .label("design")
        .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 24, y)], DESIGN.stroke_width(3)));
    labels.push("design");
    let corner = legend_corner(chart.plotting_area().dim_in_pixel(), 0.0..100.0, y, &labels, &all);
    draw_legend(&mut chart, LEGEND_FONT_PX, Some(corner))?;
    Ok(())
}

/// Each walk's steps as one legend entry: a lone walk's in red as "adapted, each step", with
/// `--compare` each walk's in its palette colour under its name.
fn steps_of<'a>(walks: &[(String, &'a [Sampled])]) -> Vec<Steps<'a>> {
    if let [(_, steps)] = walks {
        return vec![("adapted, each step".to_string(), RIGHT, steps)];
    }
    walks
        .iter()
        .enumerate()
        .map(|(k, (name, steps))| (format!("{name}, each step"), PALETTE[k % PALETTE.len()], *steps))
        .collect()
}

/// A curve at each percent of its span, times `scale`.
fn sample(curve: &Curve, scale: f64) -> Vec<(f64, f64)> {
    (0..=100).map(|p| (p as f64, curve.eval(p as f64 / 100.0) * scale)).collect()
}

/// The swing foot's forward, lateral and heel-height curves; with `--compare` every walk's
/// steps overlaid on the heel height.
pub(super) fn swing_foot<DB: DrawingBackend>(root: DrawingArea<DB, Shift>, walks: &[(String, Data<'_>)]) -> Res {
    root.fill(&WHITE).map_err(err)?;
    let title = if walks.len() == 1 {
        "Swing foot: design curves and each step's terrain-adapted heel height"
    } else {
        "Swing foot: design curves and each walk's terrain-adapted heel height, step by step"
    };
    let root = titled(&root, title, 34)?;
    let areas = root.split_evenly((1, 3));
    let design = walks[0].1.run.gait.design_curves();
    let heights: Vec<(String, Vec<Sampled>)> = walks
        .iter()
        .map(|(name, d)| (name.clone(), d.run.step_plans.iter().map(|p| sample(&p.swing_heel_height, 100.0)).collect()))
        .collect();
    let named: Vec<(String, &[Sampled])> = heights.iter().map(|(n, s)| (n.clone(), s.as_slice())).collect();
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
        &steps_of(&named),
    )?;
    root.present().map_err(err)
}

/// `value` of each leg frame through every whole `phase` either leg walked, each span over
/// 0-100 %: a span under way at the first frame is not whole, and one still under way at
/// the last is never closed.
fn walked_spans(d: &Data<'_>, phase: LegPhase, value: impl Fn(&LegFrame) -> f64) -> Vec<Sampled> {
    let mut spans: Vec<Sampled> = Vec::new();
    for side in 0..2 {
        // (phase serial, values, whole)
        let mut current: Option<(u64, Vec<f64>, bool)> = None;
        for (i, f) in d.run.frames.iter().enumerate() {
            let leg = &f.legs[side];
            let inside = leg.leg_phase == phase;
            if let Some((serial, values, _)) = &mut current
                && inside
                && *serial == leg.phase_serial
            {
                values.push(value(leg));
                continue;
            }
            if let Some((_, values, true)) = current.take() {
                spans.push(over_span(&values));
            }
            if inside {
                current = Some((leg.phase_serial, vec![value(leg)], i > 0));
            }
        }
    }
    spans.retain(|s| s.len() > 2);
    spans
}

/// The ankle angle each swing walked. Beside the planned curve it shows what the foot
/// actually did: over the first 15 % of the swing the foot eases from its toe-off pitch into
/// the curve, so at brisk the planned curve dipped to −23° where the ankle itself reached −17
/// to −19.5° (a reader took the planned curve for the push-off).
fn walked_swing_ankles(d: &Data<'_>) -> Vec<Sampled> {
    walked_spans(d, LegPhase::Swing, |leg| leg.ankle_dorsi_deg)
}

/// Each heel rise's foot-ground angle as walked (deg, heel up +), from the heel's place below
/// and behind the ankle: the chart drew the design alone, and the stance leg's reach lifting
/// the heel above it (`Gait::target_of`) was nowhere to be seen.
fn walked_heel_rises(d: &Data<'_>) -> Vec<Sampled> {
    let dims = &d.run.gait.resolved().dims;
    // The heel's direction from the ankle with the foot flat, in the foot's plane.
    let flat = (-dims.ankle_height).atan2(-HEEL_FRACTION * dims.foot_length);
    walked_spans(d, LegPhase::HeelRise, |leg| {
        let v = leg.heel - leg.ankle;
        let along = -(v.x * v.x + v.z * v.z).sqrt();
        // Into (-180, 180]: past 60 deg the heel's direction crosses the atan2 cut.
        let turned = flat - v.y.atan2(along);
        (turned - std::f64::consts::TAU * (turned / std::f64::consts::TAU).round()).to_degrees()
    })
}

/// Samples at 0..100 % of their span.
fn over_span(angles: &[f64]) -> Sampled {
    let last = angles.len().saturating_sub(1).max(1) as f64;
    angles.iter().enumerate().map(|(i, &a)| (100.0 * i as f64 / last, a)).collect()
}

/// The ankle through the swing (against the shank), each step's as planned and as walked,
/// and the heel-rise curve.
pub(super) fn ankle<DB: DrawingBackend>(root: DrawingArea<DB, Shift>, d: &Data<'_>) -> Res {
    root.fill(&WHITE).map_err(err)?;
    let root = titled(&root, "Ankle through the swing, and heel rise", 34)?;
    let areas = root.split_evenly((1, 2));
    let design = d.run.gait.design_curves();
    let steps: Vec<Vec<(f64, f64)>> = d.run.step_plans.iter().map(|p| sample(&p.swing_ankle_deg, 1.0)).collect();
    let walked = walked_swing_ankles(d);
    let mut series = steps_of(&[(String::new(), &steps)]);
    series[0].0 = "planned, each step".into();
    series.push(("walked, each swing".into(), LEFT, &walked));
    curve_chart(
        &areas[0],
        "ankle (foot against the shank): planned and walked",
        "% of swing",
        "dorsiflexion + (deg)",
        &sample(design.get(CurveName::SwingAnkle), 1.0),
        &series,
    )?;
    // The design is drawn for a 1.8 m stride; the walk scales it by its own stride.
    let stride_scale = d.run.gait.resolved().stride_m / HEEL_RISE_DESIGN_STRIDE_M;
    let rises = walked_heel_rises(d);
    curve_chart(
        &areas[1],
        "heel rise: design at this stride, and walked",
        "% of heel-rise phase",
        "foot-ground angle (deg)",
        &sample(design.get(CurveName::HeelRise), stride_scale),
        &[("walked, each heel rise".into(), LEFT, &rises)],
    )?;
    root.present().map_err(err)
}
