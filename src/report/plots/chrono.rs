//! The stick-figure plot's layout as a chronophotograph: the instants of one steady cycle
//! that are drawn, each figure's segments in a view, and the slot each figure is moved into
//! so that no two overlap, with the ground under it.

use super::data::Data;
use crate::analysis::events as gait_events;
use crate::model::body::{Bone, Pose, Side};
use crate::model::terrain::Terrain;
use crate::model::walk::frame::LegFrame;
use glam::DVec3;

/// Figures per view: eight keep a figure over 300 px tall while the widest (double
/// support, about a metre from back heel to front toe) still fits eight across.
pub(super) const FIGURES: usize = 8;
/// Head radius (m): a circle sized in metres keeps the figure's proportions at any scale.
pub(super) const HEAD_M: f64 = 0.1;
/// Space between two neighbouring figures' boxes (m).
const GAP_M: f64 = 0.2;
/// Each slot's ground stops this far (m) short of the slot's edge, so that neighbouring
/// grounds read as separate pieces rather than one walk's terrain.
const GROUND_INSET_M: f64 = 0.04;

/// The plane a figure is drawn in.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum View {
    /// Forward x to the right, height y up: the walker seen from its right.
    Side,
    /// Lateral -z to the right, height y up: the walker seen from in front, as the lab's
    /// frontal view shows it (the right side on the page's left).
    Front,
}

impl View {
    /// A point's page coordinates (m) in this view.
    pub(super) fn project(self, p: DVec3) -> (f64, f64) {
        match self {
            View::Side => (p.x, p.y),
            View::Front => (-p.z, p.y),
        }
    }
}

/// One drawn instant of the cycle.
pub(super) struct Instant {
    /// Frame index.
    pub(super) frame: usize,
    /// Percent of the cycle, from the frame's own time.
    pub(super) pct: f64,
    /// The gait events nearest this instant, in cycle order.
    pub(super) events: Vec<&'static str>,
}

/// Which colour a segment takes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Part {
    Trunk,
    Leg(Side),
    Arm(Side),
}

/// A segment on the page (m), with its part.
pub(super) type Segment = ((f64, f64), (f64, f64), Part);

/// One figure of a row, moved into its slot.
pub(super) struct Figure {
    /// The body's segments, far side first so the near side is drawn over it.
    pub(super) segments: Vec<Segment>,
    /// The head circle's centre (radius [`HEAD_M`]).
    pub(super) head: (f64, f64),
    /// The ground profile under the figure, across its slot.
    pub(super) ground: Vec<(f64, f64)>,
    /// The slot's centre on the page (m).
    pub(super) centre: f64,
}

impl Figure {
    /// Every point that bounds the figure: segment ends and the head circle's extremes.
    fn points(&self) -> impl Iterator<Item = (f64, f64)> + '_ {
        let (hx, hy) = self.head;
        self.segments
            .iter()
            .flat_map(|(a, b, _)| [*a, *b])
            .chain([(hx - HEAD_M, hy - HEAD_M), (hx + HEAD_M, hy + HEAD_M)])
    }

    /// Left, bottom, right, top (m).
    fn bounds(&self) -> (f64, f64, f64, f64) {
        self.points().fold((f64::INFINITY, f64::INFINITY, f64::NEG_INFINITY, f64::NEG_INFINITY), |b, (x, y)| {
            (b.0.min(x), b.1.min(y), b.2.max(x), b.3.max(y))
        })
    }

    /// Moves the figure `dx` metres along the page.
    fn shift(&mut self, dx: f64) {
        for (a, b, _) in &mut self.segments {
            a.0 += dx;
            b.0 += dx;
        }
        self.head.0 += dx;
        for p in &mut self.ground {
            p.0 += dx;
        }
        self.centre += dx;
    }

    /// The lowest ground in the figure's slot (m): where its labels hang from.
    pub(super) fn lowest_ground(&self) -> f64 {
        self.ground.iter().map(|p| p.1).fold(f64::INFINITY, f64::min)
    }
}

/// One view's figures in their slots, from page x = 0.
pub(super) struct Row {
    pub(super) figures: Vec<Figure>,
    /// The slots' total width (m).
    pub(super) width: f64,
    /// Lowest ground and highest head top over the row (m).
    pub(super) low: f64,
    pub(super) high: f64,
}

impl Row {
    /// Moves every figure `dx` metres along the page (to centre the row in its panel).
    pub(super) fn shift(&mut self, dx: f64) {
        for f in &mut self.figures {
            f.shift(dx);
        }
    }
}

/// The right leg's steady cycle the plot draws (the middle one: on stairs or a slope, on
/// the climb rather than before it), sampled at [`FIGURES`] evenly spaced instants from its
/// heel strike, with the cycle's own events put on the instant nearest each. `None` when
/// the walk has no whole steady cycle with poses.
pub(super) fn instants(d: &Data<'_>) -> Option<Vec<Instant>> {
    let frames = &d.run.frames;
    let mid = d.strikes[0].len().saturating_sub(2) / 2;
    let start = (*d.strikes[0].get(mid)?).max(1);
    let end = d.strikes[0].get(mid + 1).copied().unwrap_or(frames.len() - 1).min(frames.len() - 1);
    if end <= start || d.run.poses.len() <= end {
        return None;
    }
    let (t0, t1) = (frames[start].time_s, frames[end].time_s);
    let pct = |i: usize| 100.0 * (frames[i].time_s - t0) / (t1 - t0);
    let mut out: Vec<Instant> = (0..FIGURES)
        .map(|k| {
            let want = 100.0 * k as f64 / FIGURES as f64;
            let frame = (start..end).min_by(|&a, &b| (pct(a) - want).abs().total_cmp(&(pct(b) - want).abs()))?;
            Some(Instant { frame, pct: pct(frame), events: Vec::new() })
        })
        .collect::<Option<_>>()?;
    out.dedup_by_key(|i| i.frame);
    let find = |side: usize, toe_off: bool| {
        (start + 1..end).find(|&i| {
            let (a, b) = (&frames[i - 1], &frames[i]);
            if toe_off { gait_events::is_toe_off(a, b, side) } else { gait_events::is_heel_strike(a, b, side) }
        })
    };
    let mut events = vec![("RHS", start)];
    for (name, side, toe_off) in [("LTO", 1, true), ("LHS", 1, false), ("RTO", 0, true)] {
        events.extend(find(side, toe_off).map(|i| (name, i)));
    }
    events.sort_by_key(|e| e.1);
    for (name, i) in events {
        let at = pct(i);
        let nearest = out.iter_mut().min_by(|a, b| (a.pct - at).abs().total_cmp(&(b.pct - at).abs()))?;
        nearest.events.push(name);
    }
    Some(out)
}

/// The figures of `instants` in `view`, each moved into its own slot: slots as wide as the
/// widest figure plus a gap, each figure centred in its slot by its bounding box, so that no
/// two figures' boxes overlap whatever the pose.
pub(super) fn row(d: &Data<'_>, instants: &[Instant], view: View) -> Row {
    let frames = &d.run.frames;
    let mut figures: Vec<Figure> = instants
        .iter()
        .map(|i| {
            let (segments, head) = figure(&d.run.poses[i.frame], &frames[i.frame].legs, view);
            Figure { segments, head, ground: Vec::new(), centre: 0.0 }
        })
        .collect();
    let widest = figures.iter().map(|f| f.bounds()).map(|b| b.2 - b.0).fold(0.0, f64::max);
    let slot = widest + GAP_M;
    for (k, (f, i)) in figures.iter_mut().zip(instants).enumerate() {
        let (left, _, right, _) = f.bounds();
        let centre = (k as f64 + 0.5) * slot;
        // The figure's own page x of the slot's edges: the ground is taken there, then
        // moved with the figure.
        let own = 0.5 * (left + right);
        let (x0, x1) = (own - 0.5 * slot + GROUND_INSET_M, own + 0.5 * slot - GROUND_INSET_M);
        f.ground = match view {
            View::Side => side_ground(&d.run.terrain, x0, x1),
            View::Front => front_ground(&d.run.terrain, &frames[i.frame].legs, x0, x1),
        };
        f.centre = own;
        f.shift(centre - own);
    }
    let low = figures.iter().map(Figure::lowest_ground).fold(f64::INFINITY, f64::min);
    let high = figures.iter().map(|f| f.bounds().3).fold(f64::NEG_INFINITY, f64::max);
    Row { width: slot * figures.len() as f64, figures, low, high }
}

/// The terrain's profile from `x0` to `x1`: the ends and every corner, a riser's two
/// heights both, which is exact for the piecewise-linear terrains. Both heights are taken a
/// nanometre either side of the corner: at the corner itself, rounding can put a stair's
/// riser (`start + i·run`) a hair short of the next step, which drew the tread beyond it as
/// a ramp.
pub(super) fn side_ground(terrain: &Terrain, x0: f64, x1: f64) -> Vec<(f64, f64)> {
    let mut profile = vec![(x0, terrain.height(x0))];
    for c in terrain.corners_between(x0, x1) {
        profile.push((c, terrain.height(c - 1e-9)));
        profile.push((c, terrain.height(c + 1e-9)));
    }
    profile.push((x1, terrain.height(x1)));
    profile
}

/// The ground seen from in front across the slot `x0..x1` (page x): the height a foot
/// stands on (the highest ground under its heel and toe) under each half of the slot, the
/// two halves split between the feet. On the flat one line; on stairs the two steps the
/// feet are on.
pub(super) fn front_ground(terrain: &Terrain, legs: &[LegFrame; 2], x0: f64, x1: f64) -> Vec<(f64, f64)> {
    let mut feet: Vec<(f64, f64)> = legs
        .iter()
        .map(|l| {
            let across = View::Front.project(0.5 * (l.heel + l.toe)).0;
            (across, terrain.max_height_between(l.heel.x.min(l.toe.x), l.heel.x.max(l.toe.x)))
        })
        .collect();
    feet.sort_by(|a, b| a.0.total_cmp(&b.0));
    let split = 0.5 * (feet[0].0 + feet[1].0);
    // On level ground a riser of no height: a repeated point draws a notch in the PNG.
    if (feet[0].1 - feet[1].1).abs() < 1e-9 {
        return vec![(x0, feet[0].1), (x1, feet[1].1)];
    }
    vec![(x0, feet[0].1), (split, feet[0].1), (split, feet[1].1), (x1, feet[1].1)]
}

/// The stick figure of one frame in `view`, and its head circle's centre: per side the hip,
/// the leg from the frame's joints (as the joint table has them) and the arm from the pose,
/// and the trunk from the pelvis to the head. Seen from the side the far (left) limbs come
/// first and the near ones last, so that the body is drawn over what it hides.
pub(super) fn figure(pose: &Pose, legs: &[LegFrame; 2], view: View) -> (Vec<Segment>, (f64, f64)) {
    let mut segments = Vec::new();
    let mut seg = |a: DVec3, b: DVec3, part: Part| segments.push((view.project(a), view.project(b), part));
    let limbs = |side: Side, seg: &mut dyn FnMut(DVec3, DVec3, Part)| {
        let l = &legs[side.index()];
        let toe = pose.pos(Bone::toe(side));
        seg(pose.pos(Bone::Pelvis), l.hip, Part::Trunk);
        for (a, b) in [(l.hip, l.knee), (l.knee, l.ankle), (l.ankle, l.heel), (l.heel, toe), (toe, l.toe)] {
            seg(a, b, Part::Leg(side));
        }
        let (shoulder, elbow, hand) =
            (pose.pos(Bone::upper_arm(side)), pose.pos(Bone::forearm(side)), pose.pos(Bone::hand(side)));
        seg(pose.pos(Bone::Neck), shoulder, Part::Trunk);
        seg(shoulder, elbow, Part::Arm(side));
        seg(elbow, hand, Part::Arm(side));
    };
    let (far, near) = if view == View::Side { (Side::Left, Side::Right) } else { (Side::Right, Side::Left) };
    limbs(far, &mut seg);
    let trunk =
        [(Bone::Pelvis, Bone::Spine), (Bone::Spine, Bone::Chest), (Bone::Chest, Bone::Neck), (Bone::Neck, Bone::Head)];
    for (a, b) in trunk {
        seg(pose.pos(a), pose.pos(b), Part::Trunk);
    }
    limbs(near, &mut seg);
    let head = view.project(pose.pos(Bone::Head));
    (segments, (head.0, head.1 + HEAD_M))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::terrain::TerrainKind;

    #[test]
    fn the_ground_of_stairs_is_level_treads_and_upright_risers() {
        // The stairs_up config's flight: at its second riser (x = 2.34), `start + i·run`
        // rounds a hair short of the step, which once drew the tread beyond as a ramp.
        for up in [true, false] {
            let kind = TerrainKind::Stairs { rise_m: 0.15, run_m: 0.34, count: 8, up, start_x_m: 2.0 };
            let ground = side_ground(&Terrain::new(kind), 1.5, 5.5);
            assert_eq!(ground.len(), 2 + 2 * 8);
            for w in ground.windows(2) {
                let (a, b) = (w[0], w[1]);
                let riser = a.0 == b.0 && ((a.1 - b.1).abs() - 0.15).abs() < 1e-9;
                assert!(riser || (a.1 - b.1).abs() < 1e-12, "neither tread nor riser: {a:?} to {b:?}");
            }
        }
    }
}
