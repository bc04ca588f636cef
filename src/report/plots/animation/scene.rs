//! Each animation frame as shapes in pixels, shared by the GIF's rasteriser and the SVG:
//! the side view on the left with a camera that travels with the walker, the frontal view
//! (from ahead, the right side on the page's left) on the right, both at one scale.
//!
//! The camera moves at the stretch's mean velocity (from the pelvis at its first frame to
//! the pelvis at its last), so the figure sways about the middle of its panel as a walker's
//! pelvis does, the ground scrolls beneath it, and at the loop's seam the camera is exactly
//! one stretch further on with the figure in the same place in its cycle. Marks on the
//! ground every ~0.5 m show the scrolling on level ground; their spacing divides the
//! stretch's travel, so they do not jump at the seam either.

use super::super::chrono::{self, Part, Segment, View};
use super::clip::Clip;
use crate::analysis::Run;
use crate::model::body::Side;

/// Image width (px): a 16:9 slide's small video size, 640x360.
pub const WIDTH: u32 = 640;
/// Image height (px).
pub const HEIGHT: u32 = 360;
/// The caption band across the top (px), and its text's size (px).
pub(super) const BAND_PX: f64 = 24.0;
pub(super) const CAPTION_PX: u32 = 16;
/// Width of the side view's panel (px); the frontal view takes the rest.
pub(super) const SIDE_W: f64 = 424.0;
/// Room kept between the figure and a panel's edges (px).
const MARGIN_PX: f64 = 8.0;
/// Ground shown under the lowest foot (m).
const EARTH_M: f64 = 0.25;
/// Spacing aimed at between the ground marks (m), and how deep a mark goes (m).
const MARK_M: f64 = 0.5;
const MARK_DEPTH_M: f64 = 0.07;
/// Stroke widths (px): legs and trunk thick enough to read on a projected slide, arms a
/// little thinner, the head's outline, the ground line and its marks.
pub(super) const LEG_PX: f64 = 5.0;
pub(super) const ARM_PX: f64 = 3.5;
pub(super) const HEAD_PX: f64 = 3.0;
pub(super) const GROUND_PX: f64 = 2.5;
pub(super) const MARK_PX: f64 = 2.0;

/// The colours the animation is drawn in: one palette for every frame.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Ink {
    Paper,
    Trunk,
    Right,
    Left,
    RightArm,
    LeftArm,
    Ground,
    Earth,
    Mark,
    Text,
    Rule,
}

impl Ink {
    /// Every ink, in palette order.
    pub(super) const ALL: [Ink; 11] = [
        Ink::Paper,
        Ink::Trunk,
        Ink::Right,
        Ink::Left,
        Ink::RightArm,
        Ink::LeftArm,
        Ink::Ground,
        Ink::Earth,
        Ink::Mark,
        Ink::Text,
        Ink::Rule,
    ];

    /// The ink's colour: the report's stick figure's (trunk black, right limbs red, left
    /// blue, the arms as the report's 60 % mix of those with white, its ground green).
    pub(super) fn rgb(self) -> [u8; 3] {
        match self {
            Ink::Paper => [255, 255, 255],
            Ink::Trunk => [20, 20, 20],
            Ink::Right => [200, 40, 40],
            Ink::Left => [30, 80, 200],
            Ink::RightArm => [222, 126, 126],
            Ink::LeftArm => [120, 150, 222],
            Ink::Ground => [60, 140, 60],
            Ink::Earth => [225, 238, 218],
            Ink::Mark => [140, 185, 130],
            Ink::Text => [40, 40, 40],
            Ink::Rule => [190, 190, 190],
        }
    }
}

/// A line through `points` (px), round-capped and round-joined.
#[derive(Clone, Debug, PartialEq)]
pub(super) struct Stroke {
    pub(super) points: Vec<(f64, f64)>,
    pub(super) width: f64,
    pub(super) ink: Ink,
}

/// One view of one frame.
#[derive(Clone, Debug, PartialEq)]
pub(super) struct Panel {
    /// The panel's left and right edges (px); it runs from the band to the bottom.
    pub(super) x0: f64,
    pub(super) x1: f64,
    /// The ground line across the panel (px, left to right; a riser is two points at one x),
    /// earth under it.
    pub(super) ground: Vec<(f64, f64)>,
    /// Marks on the ground, then the body (far limbs first, the trunk, the near limbs).
    pub(super) strokes: Vec<Stroke>,
    /// The head's outline: centre and radius (px).
    pub(super) head: ((f64, f64), f64),
}

/// What the camera does over the stretch, and the one scale of both views.
pub(super) struct Stage<'a> {
    run: &'a Run,
    clip: &'a Clip,
    /// Pixels per metre.
    scale: f64,
    /// The pelvis at the stretch's start, and its travel over the stretch (m).
    from: glam::DVec3,
    travel: glam::DVec3,
    /// Mean lateral page position (-z) of the pelvis over the stretch (m).
    lateral: f64,
    /// How far the highest head top rises above the camera's height (m).
    above: f64,
    /// The ground marks' spacing (m).
    mark_m: f64,
}

/// A figure at a moment: its segments in a view (page metres) and its head's centre.
type Pose2 = (Vec<Segment>, (f64, f64));

impl<'a> Stage<'a> {
    /// The camera for `clip` of `run`, and the largest scale at which every frame's figure
    /// fits its panel with some ground under it.
    pub(super) fn new(run: &'a Run, clip: &'a Clip) -> Stage<'a> {
        let at = |i: usize| run.frames[i].pelvis;
        let (from, travel) = (at(clip.start), at(clip.end) - at(clip.start));
        let lateral = -(clip.start..=clip.end).map(|i| at(i).z).sum::<f64>() / (clip.end - clip.start + 1) as f64;
        let marks = (travel.x.abs() / MARK_M).round();
        let mark_m = if clip.cycles > 0 && marks >= 1.0 { travel.x.abs() / marks } else { MARK_M };
        let mut stage = Stage { run, clip, scale: 1.0, from, travel, lateral, above: 0.0, mark_m };
        let (mut above, mut below, mut side, mut front) = (0.0_f64, 0.0_f64, 0.0_f64, 0.0_f64);
        for k in 0..clip.frames {
            let cam = stage.camera(k);
            for (view, reach) in [(View::Side, &mut side), (View::Front, &mut front)] {
                let (segments, head) = stage.figure(k, view);
                let centre = if view == View::Side { cam.x } else { lateral };
                let points = segments.iter().flat_map(|(a, b, _)| [*a, *b]);
                for (x, y) in points.chain([(head.0, head.1 + chrono::HEAD_M)]) {
                    above = above.max(y - cam.y);
                    below = below.max(cam.y - y);
                    *reach = reach.max((x - centre).abs() + chrono::HEAD_M);
                }
            }
        }
        let tall = f64::from(HEIGHT) - BAND_PX - 2.0 * MARGIN_PX;
        let front_w = f64::from(WIDTH) - SIDE_W;
        stage.scale = (tall / (above + below + EARTH_M))
            .min((0.5 * SIDE_W - MARGIN_PX) / side.max(1e-3))
            .min((0.5 * front_w - MARGIN_PX) / front.max(1e-3));
        stage.above = above;
        stage
    }

    /// The camera's point (m) at animation frame `k`: the pelvis's mean path.
    fn camera(&self, k: usize) -> glam::DVec3 {
        let share = if self.clip.duration_s > 0.0 { self.clip.offset_s(k) / self.clip.duration_s } else { 0.0 };
        self.from + self.travel * share
    }

    /// The recorded frame at or before animation frame `k`'s time and how far (0..1) it is
    /// to the next.
    fn recorded(&self, k: usize) -> (usize, f64) {
        let frames = &self.run.frames;
        let t = frames[self.clip.start].time_s + self.clip.offset_s(k);
        let i = frames.partition_point(|f| f.time_s <= t).saturating_sub(1).min(frames.len().saturating_sub(2));
        let Some(next) = frames.get(i + 1) else { return (i, 0.0) };
        let span = next.time_s - frames[i].time_s;
        (i, if span > 0.0 { ((t - frames[i].time_s) / span).clamp(0.0, 1.0) } else { 0.0 })
    }

    /// The figure at animation frame `k` in `view` (page metres): the two recorded frames
    /// around its time, point by point in proportion, so the animation keeps the walk's
    /// time whatever the recording's frame rate.
    fn figure(&self, k: usize, view: View) -> Pose2 {
        let (i, s) = self.recorded(k);
        let one = |i: usize| chrono::figure(&self.run.poses[i], &self.run.frames[i].legs, view);
        let (a, head_a) = one(i);
        if s == 0.0 {
            return (a, head_a);
        }
        let (b, head_b) = one(i + 1);
        let mix = |p: (f64, f64), q: (f64, f64)| (p.0 + (q.0 - p.0) * s, p.1 + (q.1 - p.1) * s);
        let segments = a.iter().zip(&b).map(|(x, y)| (mix(x.0, y.0), mix(x.1, y.1), x.2)).collect();
        (segments, mix(head_a, head_b))
    }

    /// Frame `k`'s two panels.
    pub(super) fn scene(&self, k: usize) -> [Panel; 2] {
        [self.panel(k, View::Side), self.panel(k, View::Front)]
    }

    /// One view of frame `k`: page metres to pixels, the camera's point at the panel's
    /// centre across and the highest head top just under the band.
    fn panel(&self, k: usize, view: View) -> Panel {
        let cam = self.camera(k);
        let (x0, x1) = if view == View::Side { (0.0, SIDE_W) } else { (SIDE_W, f64::from(WIDTH)) };
        let across = if view == View::Side { cam.x } else { self.lateral };
        let (mid, top) = (0.5 * (x0 + x1), BAND_PX + MARGIN_PX + self.above * self.scale);
        let px = |(x, y): (f64, f64)| (mid + (x - across) * self.scale, top - (y - cam.y) * self.scale);
        // The page metres at the panel's edges, a pixel beyond so the ground meets them.
        let (m0, m1) = (across + (x0 - 1.0 - mid) / self.scale, across + (x1 + 1.0 - mid) / self.scale);
        let terrain = &self.run.terrain;
        let (segments, head) = self.figure(k, view);
        let (ground, mut strokes) = match view {
            View::Side => (chrono::side_ground(terrain, m0, m1), self.marks(m0, m1, &px)),
            View::Front => {
                let (i, s) = self.recorded(k);
                let legs = &self.run.frames[if s < 0.5 { i } else { i + 1 }].legs;
                (chrono::front_ground(terrain, legs, m0, m1), Vec::new())
            }
        };
        strokes.extend(body(&segments).into_iter().map(|mut s| {
            s.points = s.points.into_iter().map(px).collect();
            s
        }));
        Panel {
            x0,
            x1,
            ground: ground.into_iter().map(px).collect(),
            strokes,
            head: (px(head), chrono::HEAD_M * self.scale),
        }
    }

    /// The side view's ground marks between page x `m0` and `m1`, in pixels.
    fn marks(&self, m0: f64, m1: f64, px: &dyn Fn((f64, f64)) -> (f64, f64)) -> Vec<Stroke> {
        let first = ((m0 - self.from.x) / self.mark_m).ceil() as i64;
        let last = ((m1 - self.from.x) / self.mark_m).floor() as i64;
        (first..=last)
            .map(|j| {
                let x = self.from.x + j as f64 * self.mark_m;
                let y = self.run.terrain.height(x);
                Stroke { points: vec![px((x, y)), px((x, y - MARK_DEPTH_M))], width: MARK_PX, ink: Ink::Mark }
            })
            .collect()
    }
}

/// A figure's segments joined into strokes where one continues the last in the same part:
/// a leg from the hip to the toe tip is one stroke, an arm from the shoulder to the hand.
fn body(segments: &[Segment]) -> Vec<Stroke> {
    let mut out: Vec<(Part, Stroke)> = Vec::new();
    for &(a, b, part) in segments {
        match out.last_mut() {
            Some((p, s)) if *p == part && s.points.last() == Some(&a) => s.points.push(b),
            _ => out.push((part, stroke(part, vec![a, b]))),
        }
    }
    out.into_iter().map(|(_, s)| s).collect()
}

/// A new stroke of `part`: its ink and width.
fn stroke(part: Part, points: Vec<(f64, f64)>) -> Stroke {
    let (ink, width) = match part {
        Part::Trunk => (Ink::Trunk, LEG_PX),
        Part::Leg(Side::Right) => (Ink::Right, LEG_PX),
        Part::Leg(Side::Left) => (Ink::Left, LEG_PX),
        Part::Arm(Side::Right) => (Ink::RightArm, ARM_PX),
        Part::Arm(Side::Left) => (Ink::LeftArm, ARM_PX),
    };
    Stroke { points, width, ink }
}
