//! The side view: the body as a stick figure at intervals over one steady gait cycle, on the
//! terrain, with the heel and toe paths of both feet.

use super::common::{DESIGN, FONT, LEFT, RIGHT, Res, SIZE, err};
use super::data::Data;
use crate::model::body::{Bone, Pose, Side};
use crate::model::terrain::Terrain;
use crate::model::walk::frame::{Frame, LegFrame};
use glam::DVec3;
use plotters::coord::Shift;
use plotters::coord::types::RangedCoordf64;
use plotters::prelude::*;

/// A chart in metres on both axes.
type MetreChart<'a, DB> = ChartContext<'a, DB, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

/// The side view over the middle steady cycle (on stairs or a slope, on the climb rather
/// than before it).
pub(super) fn stick_figure<DB: DrawingBackend>(root: DrawingArea<DB, Shift>, d: &Data<'_>) -> Res {
    root.fill(&WHITE).map_err(err)?;
    let frames = &d.run.frames;
    let mid = d.strikes[0].len().saturating_sub(2) / 2;
    let Some(&start) = d.strikes[0].get(mid) else { return root.present().map_err(err) };
    let end = d.strikes[0].get(mid + 1).copied().unwrap_or(frames.len() - 1).min(frames.len() - 1);
    // The recorded full-body poses of the window (the frames hold the legs only).
    let step = ((end - start) / 16).max(1);
    let poses: Vec<(usize, &Pose)> = (start.max(1)..=end)
        .filter(|i| (i - start) % step == 0)
        .filter_map(|i| d.run.poses.get(i).map(|p| (i, p)))
        .collect();
    let (x0, x1, y0, y1) = view(&frames[start..=end]);
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
    draw_terrain(&mut chart, &d.run.terrain, x0, x1)?;
    draw_foot_paths(&mut chart, &frames[start..=end])?;
    for (i, pose) in &poses {
        chart.draw_series(figure(pose, &frames[*i].legs)).map_err(err)?;
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

/// The view's x and y ranges (m) around the cycle's `frames`: the pelvis's travel with room
/// for the legs ahead and behind, from just under the lowest ground to above the head, at
/// equal metres per pixel on both axes so the figure is not distorted.
fn view(frames: &[Frame]) -> (f64, f64, f64, f64) {
    let x0 = frames[0].pelvis.x - 0.6;
    let x1 = frames[frames.len() - 1].pelvis.x + 0.6;
    let ground = frames.iter().flat_map(|f| f.legs.iter().map(|l| l.ground_under_heel)).fold(f64::INFINITY, f64::min);
    let top = frames.iter().map(|f| f.pelvis.y).fold(f64::NEG_INFINITY, f64::max) + 1.0;
    // The plotting area in pixels: the image less the margins, the y labels, the x labels
    // and the caption (measured from the SVG: 1500 x 875).
    let (w, h) = (f64::from(SIZE.0 - 2 * 15 - 70), f64::from(SIZE.1 - 2 * 15 - 55 - 40));
    let y0 = ground - 0.1;
    let y1 = (y0 + (x1 - x0) * h / w).max(top);
    // A tall walk (stairs, the head) widens the view rather than stretching the metres of
    // one axis: the figure keeps its proportions.
    let width = (y1 - y0) * w / h;
    let middle = 0.5 * (x0 + x1);
    (middle - 0.5 * width, middle + 0.5 * width, y0, y1)
}

/// The terrain's profile from `x0` to `x1`, sampled finely enough to show stair nosings.
fn draw_terrain<DB: DrawingBackend>(chart: &mut MetreChart<'_, DB>, terrain: &Terrain, x0: f64, x1: f64) -> Res {
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
    Ok(())
}

/// Each foot's heel path (strong) and toe path (faint) through `frames`.
fn draw_foot_paths<DB: DrawingBackend>(chart: &mut MetreChart<'_, DB>, frames: &[Frame]) -> Res {
    for (side, color, name) in [(0usize, RIGHT, "right heel / toe path"), (1, LEFT, "left heel / toe path")] {
        for (k, pick) in [|l: &LegFrame| l.heel, |l: &LegFrame| l.toe].iter().enumerate() {
            let s = chart
                .draw_series(LineSeries::new(
                    frames.iter().map(|f| {
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
    Ok(())
}

/// The stick figure of one frame: the trunk from the pelvis to the head, then per side the
/// leg from the frame's joints (as the joint table has them) and the arm from the pose.
fn figure(pose: &Pose, legs: &[LegFrame; 2]) -> Vec<PathElement<(f64, f64)>> {
    let seg = |a: DVec3, b: DVec3, c: RGBAColor| PathElement::new(vec![(a.x, a.y), (b.x, b.y)], c.stroke_width(2));
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
    elements
}
