//! The analytic two-bone solve: law of cosines for the middle joint's distance along the
//! root→target axis, the swivel toward a reference vector (see the module docs of
//! [`crate::model::ik`]), with the softening and twist mature solvers add.

use glam::DVec3;

/// What mature two-bone solvers (ozz-animation's `IKTwoBoneJob`, Godot's `TwoBoneIK3D`) add to
/// the bare law-of-cosines solve.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TwoBoneOptions {
    /// Share of full reach (0..1] beyond which the chain eases into full extension instead of
    /// snapping straight: past `soften × reach` the end falls ever further behind the target,
    /// approaching full reach only asymptotically. 1 turns softening off.
    pub soften: f64,
    /// Extra turn of the middle joint about the root→end axis, after the reference vector has
    /// placed it (rad, right-handed about the axis).
    pub twist: f64,
}

impl Default for TwoBoneOptions {
    fn default() -> Self {
        TwoBoneOptions { soften: 1.0, twist: 0.0 }
    }
}

/// The distance the chain actually reaches for a target at `distance`, after softening.
///
/// ozz's curve: with `da = soften·reach` and `ds = reach − da`, a target beyond `da` is pulled in
/// to `da + ds·(1 − (4 / (α + 4))⁴)` with `α = (distance − da) / ds`: slope 1 where softening
/// starts, concave, never reaching `reach`. (ozz writes 3 for the 4s; that curve starts with
/// slope 4/3 and so puts the ankle past a target just beyond the softening point.)
#[must_use]
pub(crate) fn softened_distance(distance: f64, reach: f64, soften: f64) -> f64 {
    let da = reach * soften.clamp(0.0, 1.0);
    let ds = reach - da;
    if distance <= da || ds <= 0.0 {
        return distance;
    }
    let alpha = (distance - da) / ds;
    let ratio = (4.0 / (alpha + 4.0)).powi(4);
    da + ds * (1.0 - ratio)
}

/// The solved chain.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TwoBoneSolution {
    /// Middle joint (knee, elbow), world position (m).
    pub middle: DVec3,
    /// End joint (ankle, wrist) as placed: the target, or the nearest point the chain reaches.
    pub end: DVec3,
    /// Unit direction from the root→end axis toward the middle joint: the swivel direction.
    pub swivel: DVec3,
    /// Whether the target was reached without clamping.
    pub reached: bool,
}

/// Unit component of `k` orthogonal to the unit axis `a`; falls back to any unit vector
/// orthogonal to `a` when `k` is (nearly) parallel to it.
#[must_use]
pub(crate) fn orthogonal_part(a: DVec3, k: DVec3) -> DVec3 {
    let u = k - a * a.dot(k);
    let len = u.length();
    if len > 1e-9 { u / len } else { a.any_orthonormal_vector() }
}

/// Solves the chain root → middle → end for `target`, with the middle joint toward `reference`.
///
/// A target beyond full reach, or closer than `|l1 − l2|`, is clamped onto the reachable
/// shell along the root→target line and the solution is flagged `reached = false`; the result
/// is always finite for finite input.
///
/// ```
/// use gaitlab::model::ik::solve_two_bone;
/// use glam::DVec3;
/// let s = solve_two_bone(DVec3::ZERO, DVec3::new(0.0, -0.8, 0.0), 0.43, 0.43, DVec3::X);
/// assert!(s.reached);
/// assert!((s.middle.distance(DVec3::ZERO) - 0.43).abs() < 1e-12);
/// assert!(s.middle.x > 0.0); // the knee points forward, toward the reference
/// ```
#[must_use]
pub fn solve_two_bone(root: DVec3, target: DVec3, l1: f64, l2: f64, reference: DVec3) -> TwoBoneSolution {
    solve_two_bone_with(root, target, l1, l2, reference, TwoBoneOptions::default())
}

/// [`solve_two_bone`] with softening and twist.
///
/// A softened target counts as reached only when the chain ends on it, so `reached` is false
/// wherever softening pulled the end in by more than a nanometre.
///
/// ```
/// use gaitlab::model::ik::{solve_two_bone_with, TwoBoneOptions};
/// use glam::DVec3;
/// let opts = TwoBoneOptions { soften: 0.9, twist: 0.0 };
/// // A target at exactly full reach: the softened leg stops short and keeps its knee bent.
/// let s = solve_two_bone_with(DVec3::ZERO, DVec3::new(0.0, -0.86, 0.0), 0.43, 0.43, DVec3::X, opts);
/// assert!(!s.reached);
/// assert!(s.end.length() < 0.86 && s.middle.x > 0.0);
/// ```
#[must_use]
pub fn solve_two_bone_with(
    root: DVec3,
    target: DVec3,
    l1: f64,
    l2: f64,
    reference: DVec3,
    options: TwoBoneOptions,
) -> TwoBoneSolution {
    let offset = target - root;
    let d_raw = offset.length();
    let a = if d_raw > 1e-12 { offset / d_raw } else { DVec3::NEG_Y };
    let d_max = l1 + l2;
    let d_min = (l1 - l2).abs();
    let d_soft = if options.soften < 1.0 { softened_distance(d_raw, d_max, options.soften) } else { d_raw };
    let softened = d_raw - d_soft > 1e-9;
    let d_raw = d_soft;
    let (d, reached) = if d_raw > d_max {
        (d_max, d_raw - d_max < 1e-9)
    } else if d_raw < d_min {
        (d_min, d_min - d_raw < 1e-9)
    } else {
        (d_raw, true)
    };
    // Distance of the middle joint along the axis, and its radius about it.
    let along = if d > 1e-12 { (l1 * l1 - l2 * l2 + d * d) / (2.0 * d) } else { 0.0 };
    let radius = (l1 * l1 - along * along).max(0.0).sqrt();
    let mut swivel = orthogonal_part(a, reference);
    if options.twist != 0.0 {
        swivel = rotate_about(swivel, a, options.twist);
    }
    let middle = root + a * along + swivel * radius;
    let end = root + a * d;
    TwoBoneSolution { middle, end, swivel, reached: reached && !softened }
}

/// The thesis's swivel angle [6.3.2, eq. on fig 6.12]: the angle θ by which to rotate the
/// root-bone direction `v` about the unit axis `a` so that it points as far along `k` as it
/// can. θ = atan2(2B, C − A) or θ + π, keeping the one where
/// (A − C)/2·cos θ − B·sin θ < 0 (the maximum), with
/// A = (a·v)(a·k) − ((a×v)×a)·k, B = (a×v)·k, C = v·k.
#[must_use]
#[cfg(test)]
pub(crate) fn thesis_swivel_angle(a: DVec3, v: DVec3, k: DVec3) -> f64 {
    let av = a.dot(v);
    let ak = a.dot(k);
    let axv = a.cross(v);
    let big_a = av * ak - axv.cross(a).dot(k);
    let big_b = axv.dot(k);
    let big_c = v.dot(k);
    let theta = (2.0 * big_b).atan2(big_c - big_a);
    let second = |t: f64| (big_a - big_c) / 2.0 * t.cos() - big_b * t.sin();
    if second(theta) < 0.0 { theta } else { theta + std::f64::consts::PI }
}

/// Rodrigues rotation of `v` about the unit axis `a` by `theta`.
#[must_use]
pub(crate) fn rotate_about(v: DVec3, a: DVec3, theta: f64) -> DVec3 {
    let (s, c) = theta.sin_cos();
    v * c + a.cross(v) * s + a * a.dot(v) * (1.0 - c)
}

/// The same solve as [`solve_two_bone`] done the thesis's way: place the middle joint in an
/// arbitrary plane through the axis, then swivel it by [`thesis_swivel_angle`]. Kept as the
/// reference the closed form is tested against.
#[must_use]
#[cfg(test)]
pub(crate) fn solve_two_bone_thesis(root: DVec3, target: DVec3, l1: f64, l2: f64, reference: DVec3) -> TwoBoneSolution {
    let closed = solve_two_bone(root, target, l1, l2, reference);
    let d = closed.end.distance(root);
    let a = (closed.end - root) / d.max(1e-12);
    let along = (l1 * l1 - l2 * l2 + d * d) / (2.0 * d.max(1e-12));
    let radius = (l1 * l1 - along * along).max(0.0).sqrt();
    let arbitrary = a.any_orthonormal_vector();
    let v = ((a * along + arbitrary * radius) / l1).normalize();
    let theta = thesis_swivel_angle(a, v, reference);
    let v_rot = rotate_about(v, a, theta);
    let middle = root + v_rot * l1;
    TwoBoneSolution { middle, end: closed.end, swivel: orthogonal_part(a, middle - root), reached: closed.reached }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reaches_and_keeps_bone_lengths() {
        let root = DVec3::new(0.1, 0.9, 0.09);
        let target = DVec3::new(0.35, 0.12, 0.05);
        let s = solve_two_bone(root, target, 0.43, 0.44, DVec3::X);
        assert!(s.reached);
        assert!((s.middle.distance(root) - 0.43).abs() < 1e-12);
        assert!((s.middle.distance(target) - 0.44).abs() < 1e-12);
        assert!(s.end.distance(target) < 1e-12);
    }

    #[test]
    fn unreachable_targets_clamp_without_nan() {
        let root = DVec3::ZERO;
        for target in
            [DVec3::new(0.0, -2.0, 0.0), DVec3::ZERO, DVec3::new(1e-14, 0.0, 0.0), DVec3::new(0.0, -0.001, 0.0)]
        {
            let s = solve_two_bone(root, target, 0.43, 0.40, DVec3::X);
            assert!(!s.reached, "{target}");
            assert!(s.middle.is_finite() && s.end.is_finite());
            assert!((s.middle.distance(root) - 0.43).abs() < 1e-9);
            assert!((s.middle.distance(s.end) - 0.40).abs() < 1e-9);
        }
    }

    #[test]
    fn softening_eases_into_full_reach_and_is_continuous() {
        let reach = 0.86;
        let mut previous = 0.0;
        for i in 0..=400 {
            let d = 0.5 + f64::from(i) * 0.002;
            let s = softened_distance(d, reach, 0.9);
            assert!(s <= d + 1e-15 && s < reach, "{d} -> {s}");
            assert!(s >= previous, "monotone");
            if d <= 0.9 * reach {
                assert_eq!(s, d);
            }
            previous = s;
        }
        // Slope 1 where softening starts: no kink in the knee's motion.
        let da = 0.9 * reach;
        let slope = (softened_distance(da + 1e-6, reach, 0.9) - softened_distance(da, reach, 0.9)) / 1e-6;
        assert!((slope - 1.0).abs() < 1e-4, "{slope}");
        assert_eq!(softened_distance(2.0, reach, 1.0), 2.0);
    }

    #[test]
    fn twist_turns_the_knee_about_the_axis_and_keeps_the_end() {
        let root = DVec3::new(0.0, 0.9, 0.0);
        let target = DVec3::new(0.1, 0.15, 0.05);
        let plain = solve_two_bone(root, target, 0.43, 0.44, DVec3::X);
        let turned =
            solve_two_bone_with(root, target, 0.43, 0.44, DVec3::X, TwoBoneOptions { soften: 1.0, twist: 0.3 });
        assert!(turned.reached);
        assert!(turned.end.distance(plain.end) < 1e-12);
        assert!((plain.swivel.angle_between(turned.swivel) - 0.3).abs() < 1e-9);
    }

    #[test]
    fn thesis_angle_and_projection_form_agree() {
        let mut seed = 1u64;
        let mut rnd = || {
            seed = seed.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            (seed >> 11) as f64 / (1u64 << 53) as f64 - 0.5
        };
        for _ in 0..500 {
            let root = DVec3::new(rnd(), 1.0 + rnd(), rnd());
            let target = root + DVec3::new(rnd() * 0.6, -0.5 + rnd() * 0.4, rnd() * 0.3);
            let k = DVec3::new(1.0, 0.0, rnd() * 0.4).normalize();
            let a = solve_two_bone(root, target, 0.43, 0.42, k);
            let b = solve_two_bone_thesis(root, target, 0.43, 0.42, k);
            assert!(a.middle.distance(b.middle) < 1e-9, "{} vs {}", a.middle, b.middle);
        }
    }
}
