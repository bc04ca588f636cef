//! Piecewise cubic Bézier curves y(x), the shape language of the whole walk (spec §4).
//!
//! A curve is a chain of cubic segments sharing end points: `3n + 1` control points for `n`
//! segments. Control-point x must not decrease inside a segment and must increase from one
//! segment's start to its end, which makes x(t) monotone so that y is a function of x.
//! Evaluating y at x solves x(t) = x numerically on every call (safeguarded Newton), so a
//! curve that is edited live is never read through a stale lookup table.

use glam::DVec2;
use std::fmt;

/// How close to collinear (as a sine of the kink angle) a join must stay to count as smooth.
pub const G1_TOLERANCE: f64 = 1e-9;

/// A piecewise cubic Bézier curve y(x).
///
/// ```
/// use gaitlab::model::curve::Curve;
/// use glam::DVec2;
/// let ramp = Curve::new("ramp", vec![
///     DVec2::new(0.0, 0.0), DVec2::new(1.0 / 3.0, 1.0 / 3.0),
///     DVec2::new(2.0 / 3.0, 2.0 / 3.0), DVec2::new(1.0, 1.0),
/// ]).unwrap();
/// assert!((ramp.eval(0.25) - 0.25).abs() < 1e-12);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Curve {
    name: String,
    points: Vec<DVec2>,
}

/// Why a set of control points is not a valid curve.
#[allow(missing_docs)]
#[derive(Clone, Debug, PartialEq)]
pub enum CurveError {
    /// The point count is not `3n + 1` with `n ≥ 1`.
    PointCount { curve: String, count: usize },
    /// A control point is NaN or infinite.
    NonFinite { curve: String, index: usize },
    /// x decreases inside a segment or does not advance across one.
    NonMonotoneX { curve: String, index: usize, x_prev: f64, x: f64 },
}

impl fmt::Display for CurveError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            CurveError::PointCount { curve, count } => write!(
                f,
                "curve `{curve}` has {count} control points; a chain of n cubic segments needs 3n+1 (4, 7, 10, …)"
            ),
            CurveError::NonFinite { curve, index } => {
                write!(f, "curve `{curve}`: control point {index} is not a finite number")
            }
            CurveError::NonMonotoneX { curve, index, x_prev, x } => write!(
                f,
                "curve `{curve}`: control point {index} has x = {x} after x = {x_prev}; x must increase along the curve"
            ),
        }
    }
}

impl std::error::Error for CurveError {}

#[inline]
fn bezier(p0: f64, p1: f64, p2: f64, p3: f64, t: f64) -> f64 {
    let u = 1.0 - t;
    u * u * u * p0 + 3.0 * u * u * t * p1 + 3.0 * u * t * t * p2 + t * t * t * p3
}

#[inline]
fn bezier_d(p0: f64, p1: f64, p2: f64, p3: f64, t: f64) -> f64 {
    let u = 1.0 - t;
    3.0 * u * u * (p1 - p0) + 6.0 * u * t * (p2 - p1) + 3.0 * t * t * (p3 - p2)
}

/// Bernstein weights of a cubic at t.
#[inline]
fn bernstein(t: f64) -> [f64; 4] {
    let u = 1.0 - t;
    [u * u * u, 3.0 * u * u * t, 3.0 * u * t * t, t * t * t]
}

impl Curve {
    /// Builds a curve, checking the point count and that x is monotone.
    pub fn new(name: impl Into<String>, points: Vec<DVec2>) -> Result<Self, CurveError> {
        let curve = Curve { name: name.into(), points };
        curve.validate()?;
        Ok(curve)
    }

    /// Builds a curve from `(x, y)` pairs.
    pub(crate) fn from_pairs(name: impl Into<String>, pairs: &[(f64, f64)]) -> Result<Self, CurveError> {
        Self::new(name, pairs.iter().map(|&(x, y)| DVec2::new(x, y)).collect())
    }

    /// Builds a curve through keys `(x, y, dy/dx)`: one cubic segment per gap, handles a
    /// third of the gap along each key's tangent. Joins are G1 by construction (both handles
    /// of a key lie on its tangent line), and x is monotone when the keys' x increase.
    pub fn hermite(name: impl Into<String>, keys: &[(f64, f64, f64)]) -> Result<Self, CurveError> {
        let mut points = Vec::with_capacity(3 * keys.len().saturating_sub(1) + 1);
        for (i, w) in keys.windows(2).enumerate() {
            let ((x0, y0, s0), (x1, y1, s1)) = (w[0], w[1]);
            let h = (x1 - x0) / 3.0;
            if i == 0 {
                points.push(DVec2::new(x0, y0));
            }
            points.push(DVec2::new(x0 + h, y0 + s0 * h));
            points.push(DVec2::new(x1 - h, y1 - s1 * h));
            points.push(DVec2::new(x1, y1));
        }
        Self::new(name, points)
    }

    /// Checks point count, finiteness and monotone x.
    pub(crate) fn validate(&self) -> Result<(), CurveError> {
        let n = self.points.len();
        if n < 4 || !(n - 1).is_multiple_of(3) {
            return Err(CurveError::PointCount { curve: self.name.clone(), count: n });
        }
        for (index, p) in self.points.iter().enumerate() {
            if !p.is_finite() {
                return Err(CurveError::NonFinite { curve: self.name.clone(), index });
            }
        }
        for index in 1..n {
            let (x_prev, x) = (self.points[index - 1].x, self.points[index].x);
            // Handles may sit on a neighbour's x (a vertical tangent is still monotone), but a
            // segment must advance from its start to its end.
            let segment_end = index % 3 == 0;
            let x_start = self.points[(index - 1) / 3 * 3].x;
            if x < x_prev || (segment_end && x <= x_start) {
                return Err(CurveError::NonMonotoneX { curve: self.name.clone(), index, x_prev, x });
            }
        }
        Ok(())
    }

    /// The curve's name, used in error messages and plots.
    #[must_use]
    pub fn name(&self) -> &str {
        &self.name
    }

    /// The control points (`3n + 1` of them).
    #[must_use]
    pub fn points(&self) -> &[DVec2] {
        &self.points
    }

    /// Number of cubic segments.
    #[must_use]
    pub fn segment_count(&self) -> usize {
        (self.points.len() - 1) / 3
    }

    /// x of the first control point.
    #[must_use]
    pub(crate) fn x_start(&self) -> f64 {
        self.points[0].x
    }

    /// x of the last control point.
    #[must_use]
    pub(crate) fn x_end(&self) -> f64 {
        self.points[self.points.len() - 1].x
    }

    /// The segment that holds x (x clamped to the curve's extent).
    #[must_use]
    pub fn segment_at(&self, x: f64) -> usize {
        let n = self.segment_count();
        // Few segments (≤ 6 in every model curve): a linear scan beats a binary search.
        (0..n - 1).find(|&j| x < self.points[3 * j + 3].x).unwrap_or(n - 1)
    }

    /// Solves x(t) = x inside segment `j` for t ∈ [0, 1]: Newton steps, falling back to
    /// bisection whenever a step leaves the bracket, to 1e-14 in x.
    #[must_use]
    pub(crate) fn solve_t(&self, j: usize, x: f64) -> f64 {
        let p = &self.points[3 * j..3 * j + 4];
        let (x0, x1, x2, x3) = (p[0].x, p[1].x, p[2].x, p[3].x);
        if x <= x0 {
            return 0.0;
        }
        if x >= x3 {
            return 1.0;
        }
        let (mut lo, mut hi) = (0.0_f64, 1.0_f64);
        let mut t = (x - x0) / (x3 - x0);
        // Handles at the thirds make x(t) linear: the first guess is the answer.
        let third = (x3 - x0) / 3.0;
        if ((x1 - x0) - third).abs() <= 1e-15 * (1.0 + x3.abs())
            && ((x3 - x2) - third).abs() <= 1e-15 * (1.0 + x3.abs())
        {
            return t;
        }
        for _ in 0..60 {
            let fx = bezier(x0, x1, x2, x3, t) - x;
            if fx == 0.0 {
                break;
            }
            if fx > 0.0 {
                hi = t;
            } else {
                lo = t;
            }
            let d = bezier_d(x0, x1, x2, x3, t);
            let newton = t - fx / d;
            let next = if d > 0.0 && newton > lo && newton < hi { newton } else { 0.5 * (lo + hi) };
            // 1e-13 in t is far below the 1e-9 the curves are checked to.
            let done = (next - t).abs() < 1e-13 || hi - lo < 1e-13;
            t = next;
            if done {
                break;
            }
        }
        t
    }

    /// y at x; x outside the curve's extent is clamped to its ends.
    #[must_use]
    pub fn eval(&self, x: f64) -> f64 {
        let j = self.segment_at(x);
        let t = self.solve_t(j, x);
        let p = &self.points[3 * j..3 * j + 4];
        bezier(p[0].y, p[1].y, p[2].y, p[3].y, t)
    }

    /// dy/dx at x (one-sided at the ends; 0 where the tangent is vertical in x).
    #[must_use]
    pub fn slope(&self, x: f64) -> f64 {
        let j = self.segment_at(x);
        let t = self.solve_t(j, x);
        let p = &self.points[3 * j..3 * j + 4];
        let dx = bezier_d(p[0].x, p[1].x, p[2].x, p[3].x, t);
        let dy = bezier_d(p[0].y, p[1].y, p[2].y, p[3].y, t);
        if dx.abs() < 1e-300 { 0.0 } else { dy / dx }
    }

    /// The point of segment `j` at parameter `t`.
    #[must_use]
    pub fn point_at(&self, j: usize, t: f64) -> DVec2 {
        let p = &self.points[3 * j..3 * j + 4];
        DVec2::new(bezier(p[0].x, p[1].x, p[2].x, p[3].x, t), bezier(p[0].y, p[1].y, p[2].y, p[3].y, t))
    }

    /// Largest and smallest y over the curve, by dense sampling (for plots and ranges).
    #[must_use]
    pub fn y_range(&self, samples: usize) -> (f64, f64) {
        let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
        for j in 0..self.segment_count() {
            for i in 0..=samples {
                let y = self.point_at(j, i as f64 / samples as f64).y;
                lo = lo.min(y);
                hi = hi.max(y);
            }
        }
        (lo, hi)
    }

    /// Scales amplitude (y) and extent (x) about the origin. A negative or zero `x_factor`
    /// would break monotone x; it is the caller's job to pass a positive one.
    pub fn scale(&mut self, x_factor: f64, y_factor: f64) {
        for p in &mut self.points {
            p.x *= x_factor;
            p.y *= y_factor;
        }
    }

    /// A scaled copy (see [`Curve::scale`]).
    #[must_use]
    pub fn scaled(&self, x_factor: f64, y_factor: f64) -> Curve {
        let mut c = self.clone();
        c.scale(x_factor, y_factor);
        c
    }

    /// Shifts the curve's end by `h` while keeping its start and shape: adds `s·h` to each
    /// control point's y, where s ∈ [0, 1] is the point's x normalised over the curve. The
    /// added term is linear in x, so collinear handles stay collinear [6.3.2].
    pub fn shift_end(&mut self, h: f64) {
        let (x0, x1) = (self.x_start(), self.x_end());
        for p in &mut self.points {
            p.y += (p.x - x0) / (x1 - x0) * h;
        }
    }

    /// Shifts the curve's start by `h` while keeping its end and shape: the mirror of
    /// [`Curve::shift_end`], adding `(1 − s)·h` (linear in x, so joins stay smooth).
    pub fn shift_start(&mut self, h: f64) {
        let (x0, x1) = (self.x_start(), self.x_end());
        for p in &mut self.points {
            p.y += (x1 - p.x) / (x1 - x0) * h;
        }
    }

    /// Raises the curve locally so that y(x) grows by `delta` [6.3.2, fig 6.11].
    ///
    /// The segment holding x has its two end points raised together with the handles on both
    /// sides of each (moving a join and both its handles by the same amount keeps them
    /// collinear). The curve's own first and last points stay put. In a middle segment the
    /// raise is split between the two sides by where x lies: the further left x is, the more
    /// the left end takes. The split is then scaled so that y(x) rises by exactly `delta`,
    /// except beside a fixed curve end, where the end point's share is capped at 3× the asked
    /// rise so a point next to a pinned end cannot fling its neighbour (the caller re-checks).
    /// Segments two or more away from x are untouched. Returns the rise actually achieved at x.
    pub fn raise_at(&mut self, x: f64, delta: f64) -> f64 {
        let j = self.segment_at(x);
        let n = self.segment_count();
        let p = &self.points[3 * j..3 * j + 4];
        let s = ((x - p[0].x) / (p[3].x - p[0].x)).clamp(0.0, 1.0);
        let t = self.solve_t(j, x);
        let b = bernstein(t);
        let left_free = j > 0;
        let right_free = j + 1 < n;
        let (w_left, w_right) = match (left_free, right_free) {
            (true, true) => (1.0 - s, s),
            (true, false) => (1.0, 0.0),
            (false, true) => (0.0, 1.0),
            (false, false) => return 0.0,
        };
        let gain = w_left * (b[0] + b[1]) + w_right * (b[2] + b[3]);
        let scale = (1.0 / gain.max(1e-12)).min(if left_free && right_free { f64::INFINITY } else { 3.0 });
        let (d_left, d_right) = (delta * w_left * scale, delta * w_right * scale);
        if left_free {
            for i in 3 * j - 1..=3 * j + 1 {
                self.points[i].y += d_left;
            }
        }
        if right_free {
            for i in 3 * j + 2..=3 * j + 4 {
                self.points[i].y += d_right;
            }
        }
        delta * gain * scale
    }

    /// Makes the curve arrive at its end with a slope of at most `max_slope` (dy/dx) by moving
    /// the last handle only: the end point and every join stay where they are. Returns
    /// whether anything changed.
    pub(crate) fn limit_end_slope(&mut self, max_slope: f64) -> bool {
        let n = self.points.len();
        let (handle, end) = (self.points[n - 2], self.points[n - 1]);
        let dx = end.x - handle.x;
        if dx <= 0.0 || (end.y - handle.y) / dx <= max_slope {
            return false;
        }
        self.points[n - 2].y = end.y - max_slope * dx;
        true
    }

    /// Adds `dy` to every control point: moves the whole curve up without changing its shape.
    pub(crate) fn offset_y(&mut self, dy: f64) {
        for p in &mut self.points {
            p.y += dy;
        }
    }

    /// Adds `dy` to the last two control points: turns the curve's end without moving its
    /// start (the swing-ankle correction on uphill footfalls [6.3.2]).
    pub fn shift_last_two(&mut self, dy: f64) {
        let n = self.points.len();
        self.points[n - 2].y += dy;
        self.points[n - 1].y += dy;
    }

    /// Replaces the curve by `target` without a jump at `x_now` [6.4, fig 6.18]: control
    /// points from the third control point of the segment after the one holding `x_now`
    /// onward take the target's values; the segment being played, and the first handle of
    /// the next one (which keeps the join smooth), are left as they were. Returns false,
    /// changing nothing, when `x_now` is in the last or second-to-last segment reach (no
    /// third control point of a next segment exists) or the curves differ in point count.
    pub fn live_change(&mut self, target: &Curve, x_now: f64) -> bool {
        if target.points.len() != self.points.len() {
            return false;
        }
        let first = 3 * (self.segment_at(x_now) + 1) + 2;
        if first >= self.points.len() {
            return false;
        }
        self.points[first..].copy_from_slice(&target.points[first..]);
        true
    }

    /// Overwrites every control point with `target`'s (same count), keeping the name.
    pub(crate) fn copy_points_from(&mut self, target: &Curve) {
        self.points.clone_from(&target.points);
    }

    /// Whether every join is G1 (the handles on both sides of a join are collinear with it,
    /// pointing away from each other, or one of them sits on the join).
    #[must_use]
    pub fn joins_are_g1(&self, tolerance: f64) -> bool {
        (1..self.segment_count()).all(|j| {
            let a = self.points[3 * j] - self.points[3 * j - 1];
            let b = self.points[3 * j + 1] - self.points[3 * j];
            let (la, lb) = (a.length(), b.length());
            if la < 1e-12 || lb < 1e-12 {
                return true;
            }
            let sine = a.perp_dot(b) / (la * lb);
            sine.abs() <= tolerance && a.dot(b) > 0.0
        })
    }
}

/// A curve over one gait cycle, x ∈ [0, 1], whose live edits take effect without a jump and
/// complete when the cycle wraps.
#[derive(Clone, Debug)]
pub(crate) struct LiveCurve {
    playing: Curve,
    target: Curve,
    /// What will play from the next wrap on, while a change is pending: the target with its
    /// start pinned to where `playing` ends. The planner looks into the next cycle (a step's
    /// reach is guarded there), and must see that curve, not this cycle's.
    next: Option<Curve>,
    /// A change asked with [`LiveCurve::blend_to`], waiting for the next wrap.
    blend_pending: Option<Curve>,
    /// While a blended change plays: the curve it blends from, over this whole cycle.
    blend_from: Option<Curve>,
}

impl LiveCurve {
    /// A live curve that plays `curve`.
    #[must_use]
    pub fn new(curve: Curve) -> Self {
        LiveCurve { playing: curve.clone(), target: curve, next: None, blend_pending: None, blend_from: None }
    }

    /// Asks for `target` while the cycle is at `x_now`: the segments still to come switch now
    /// (see [`Curve::live_change`]), the rest when the cycle wraps.
    pub(crate) fn change_to(&mut self, target: Curve, x_now: f64) {
        self.playing.live_change(&target, x_now);
        self.target = target;
        self.next = self.after_wrap();
    }

    /// Asks for `target` from the next wrap on, nothing of it in this cycle.
    pub(crate) fn change_at_wrap(&mut self, target: Curve) {
        self.target = target;
        self.next = self.after_wrap();
    }

    /// What the next wrap will play, when it changes anything.
    fn after_wrap(&self) -> Option<Curve> {
        (self.playing != self.target).then(|| {
            let mut next = self.playing.clone();
            Self::pin_onto(&mut next, &self.target);
            next
        })
    }

    /// `curve` takes `target`'s points with its first point pinned to where `curve` ended,
    /// the first handle moved with it to keep the slope.
    fn pin_onto(curve: &mut Curve, target: &Curve) {
        let end_y = curve.points[curve.points.len() - 1].y;
        let start_dy = end_y - target.points[0].y;
        curve.copy_points_from(target);
        if start_dy != 0.0 {
            curve.points[0].y += start_dy;
            curve.points[1].y += start_dy;
        }
    }

    /// Call when the cycle wraps from x = 1 back to 0. The curve's first point is pinned to
    /// where the old one ended, so the wrap is continuous even when an edit arrived in the
    /// last segments of the previous cycle; the first handle moves with it to keep the slope.
    /// A pinned start differs from the target's, so the change completes at a later wrap.
    pub(crate) fn wrap(&mut self) {
        self.blend_from = None;
        if let Some(target) = self.blend_pending.take() {
            self.blend_from = Some(std::mem::replace(&mut self.playing, target.clone()));
            self.target = target;
            self.next = None;
            return;
        }
        if let Some(next) = self.next.take() {
            self.playing = next;
            self.next = self.after_wrap();
        }
    }

    /// Asks for `target` over the whole next cycle: from the next wrap the curve played goes
    /// from the present one to `target` by a weight easing from 0 to 1 with no step in its
    /// first or second derivative at either end (`smootherstep`). For the curves that move a
    /// standing hip sideways or forward, whose reach the pelvis keys already playing were
    /// guarded for: [`Self::change_to`] switches the segments after the next at once, and a 40 %
    /// wider side sway asked just before a wrap pushed the standing leg past its reach at the
    /// pelvis's highest point (1.22x the steady walks' hip jerk at the norms' rotation); the
    /// rotation's keys are 0.08 of a cycle apart, too close to take a change within one.
    pub(crate) fn blend_to(&mut self, target: Curve) {
        if self.blend_pending.is_none() && self.blend_from.is_none() && target == self.playing {
            return;
        }
        self.blend_pending = Some(target);
    }

    /// y at x of the curve being played.
    #[must_use]
    pub fn eval(&self, x: f64) -> f64 {
        let now = self.playing.eval(x);
        match &self.blend_from {
            Some(from) => {
                let t = x.clamp(0.0, 1.0);
                let w = t * t * t * (t * (6.0 * t - 15.0) + 10.0);
                let before = from.eval(x);
                before + w * (now - before)
            }
            None => now,
        }
    }

    /// y at x of the curve that will play in the next cycle (and the ones after it).
    #[must_use]
    pub fn eval_next_cycle(&self, x: f64) -> f64 {
        self.blend_pending.as_ref().or(self.next.as_ref()).unwrap_or(&self.playing).eval(x)
    }

    /// The curve being played.
    #[must_use]
    pub(crate) fn playing(&self) -> &Curve {
        &self.playing
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn wave() -> Curve {
        Curve::from_pairs(
            "wave",
            &[
                (0.0, 0.0),
                (0.1, 0.5),
                (0.2, 1.0),
                (0.3, 1.0),
                (0.4, 1.0),
                (0.5, 0.2),
                (0.6, -0.5),
                (0.7, -1.2),
                (0.9, 0.0),
                (1.0, 0.0),
            ],
        )
        .unwrap()
    }

    #[test]
    fn eval_hits_end_points_and_join_values() {
        let c = wave();
        assert!((c.eval(0.0) - 0.0).abs() < 1e-12);
        assert!((c.eval(0.3) - 1.0).abs() < 1e-12);
        assert!((c.eval(0.6) + 0.5).abs() < 1e-12);
        assert!((c.eval(1.0) - 0.0).abs() < 1e-12);
        assert_eq!(c.eval(-5.0), c.eval(0.0));
        assert_eq!(c.eval(5.0), c.eval(1.0));
    }

    #[test]
    fn non_monotone_x_names_the_curve() {
        let e = Curve::from_pairs("swing_forward", &[(0.0, 0.0), (0.5, 0.0), (0.4, 1.0), (1.0, 1.0)]).unwrap_err();
        assert!(e.to_string().contains("swing_forward"), "{e}");
        assert!(matches!(e, CurveError::NonMonotoneX { index: 2, .. }));
        let e = Curve::from_pairs("c", &[(0.0, 0.0), (1.0, 0.0), (1.0, 1.0)]).unwrap_err();
        assert!(matches!(e, CurveError::PointCount { count: 3, .. }));
    }

    #[test]
    fn shift_end_keeps_start_and_moves_end() {
        let mut c = wave();
        c.shift_end(0.3);
        assert!((c.eval(0.0)).abs() < 1e-12);
        assert!((c.eval(1.0) - 0.3).abs() < 1e-12);
        assert!((c.eval(0.5) - (wave().eval(0.5) + 0.15)).abs() < 1e-9);
    }

    #[test]
    fn shift_last_two_moves_only_the_last_segment() {
        let mut c = wave();
        c.shift_last_two(0.2);
        assert!((c.eval(1.0) - 0.2).abs() < 1e-12);
        assert!((c.eval(0.5) - wave().eval(0.5)).abs() < 1e-12);
    }

    #[test]
    fn live_change_leaves_the_playing_segment_alone() {
        let mut c = wave();
        let target = wave().scaled(1.0, 2.0);
        assert!(c.live_change(&target, 0.05));
        // Segment 0 plays on unchanged; segment 1 blends; segment 2 is the target.
        for x in [0.0, 0.1, 0.2, 0.3] {
            assert!((c.eval(x) - wave().eval(x)).abs() < 1e-12);
        }
        assert!((c.eval(0.8) - target.eval(0.8)).abs() < 1e-12);
        assert!(c.joins_are_g1(G1_TOLERANCE));
        let mut late = wave();
        assert!(!late.live_change(&target, 0.8));
        assert_eq!(late, wave());
    }

    #[test]
    fn live_curve_wraps_without_a_jump() {
        let mut live = LiveCurve::new(wave());
        let target = wave().scaled(1.0, 2.0).clone();
        let mut shifted = target.clone();
        shifted.shift_last_two(0.0);
        live.change_to(shifted, 0.95);
        let end = live.eval(1.0);
        live.wrap();
        assert!((live.eval(0.0) - end).abs() < 1e-12);
        assert!((live.eval(0.8) - target.eval(0.8)).abs() < 1e-12);
    }
}
