//! Moving one control point of a design curve by hand (the lab's curve editor), with the
//! shape rules the rest of the curve relies on kept by moving its neighbours along.
//!
//! What moves with a dragged point:
//!
//! - **A join** (a segment's end, every third point) takes its two handles with it, by the
//!   same offset: the tangent at the join keeps its direction, so the join stays G1, and the
//!   segments either side keep their shapes relative to it.
//! - **A handle** turns the tangent at its join; the handle on the other side of the join
//!   keeps its distance in x from the join and takes the new slope, so the join stays G1
//!   (collinear handles) and the neighbouring segment keeps its timing. A handle straight
//!   above or below its join (a vertical tangent) would give the other side no slope: it is
//!   refused.
//! - **An end** of the curve moves only in y: curves run from x = 0 to x = 1. On a cycle
//!   curve both ends move together, with both end handles, so the ends still meet with the
//!   same slope (the cycle's join is G1 like any other); a cycle curve's first handle and last
//!   handle are the two sides of that join.
//!
//! Whether the result is a valid curve (x increasing, limits, fixed ends) is not decided
//! here: the caller checks it with the config's own rules (`config::checks::check_curve`),
//! so a dragged curve is refused for the same reasons, in the same words, as a file's.

use glam::DVec2;

/// Control points of a curve with point `index` moved to `to`, neighbours moved as the
/// module docs say. `Err`: why the move cannot keep the joins smooth.
pub fn drag_control_point(
    points: &[(f64, f64)],
    index: usize,
    to: (f64, f64),
    cyclic: bool,
) -> Result<Vec<(f64, f64)>, String> {
    let n = points.len();
    if n < 4 || index >= n {
        return Err(format!("no control point {index} (the curve has {n})"));
    }
    let mut p: Vec<DVec2> = points.iter().map(|&(x, y)| DVec2::new(x, y)).collect();
    let last = n - 1;
    let to = DVec2::new(to.0, to.1);
    if index == 0 || index == last {
        move_end(&mut p, index, to.y, cyclic);
    } else if index.is_multiple_of(3) {
        let delta = to - p[index];
        for i in [index - 1, index, index + 1] {
            p[i] += delta;
        }
    } else {
        move_handle(&mut p, index, to, cyclic)?;
    }
    Ok(p.iter().map(|q| (q.x, q.y)).collect())
}

/// An end point moves in y only, with its handle; a cycle curve's other end and handle too.
fn move_end(p: &mut [DVec2], index: usize, y: f64, cyclic: bool) {
    let last = p.len() - 1;
    let dy = y - p[index].y;
    let mut moved = vec![index, if index == 0 { 1 } else { last - 1 }];
    if cyclic {
        moved = vec![0, 1, last - 1, last];
    }
    for i in moved {
        p[i].y += dy;
    }
}

/// A handle moves freely; the handle across its join takes the same slope at its own x.
fn move_handle(p: &mut [DVec2], index: usize, to: DVec2, cyclic: bool) -> Result<(), String> {
    let last = p.len() - 1;
    // The join this handle belongs to, and the handle (and its join) on the other side.
    let (join, other, other_join) = if index % 3 == 1 {
        (index - 1, index.checked_sub(2), index - 1)
    } else {
        (index + 1, Some(index + 2).filter(|&o| o <= last), index + 1)
    };
    let (other, other_join) = match other {
        Some(o) => (Some(o), other_join),
        // A cycle curve's first and last handles are the two sides of the cycle's join.
        None if cyclic && index == 1 => (Some(last - 1), last),
        None if cyclic && index == last - 1 => (Some(1), 0),
        None => (None, other_join),
    };
    p[index] = to;
    let Some(other) = other else { return Ok(()) };
    let dx = to.x - p[join].x;
    if dx.abs() < 1e-12 {
        return Err(format!(
            "control point {index} straight above its join would make the slope vertical at x = {}; move it sideways",
            p[join].x
        ));
    }
    let slope = (to.y - p[join].y) / dx;
    p[other].y = p[other_join].y + slope * (p[other].x - p[other_join].x);
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::curve::{Curve, G1_TOLERANCE};
    use crate::model::gait_curves::CurveName;

    fn pairs(c: CurveName) -> Vec<(f64, f64)> {
        c.default_curve().points().iter().map(|p| (p.x, p.y)).collect()
    }

    fn smooth(points: &[(f64, f64)]) -> bool {
        Curve::from_pairs("t", points).unwrap().joins_are_g1(G1_TOLERANCE)
    }

    #[test]
    fn a_join_takes_its_handles_along_and_stays_smooth() {
        let before = pairs(CurveName::SwingHeelHeight);
        let after = drag_control_point(&before, 6, (0.5, 0.16), false).unwrap();
        let d = (0.5 - before[6].0, 0.16 - before[6].1);
        for i in 5..=7 {
            assert!((after[i].0 - before[i].0 - d.0).abs() < 1e-12 && (after[i].1 - before[i].1 - d.1).abs() < 1e-12);
        }
        assert_eq!(&after[..5], &before[..5]);
        assert_eq!(&after[8..], &before[8..]);
        assert!(smooth(&after));
    }

    #[test]
    fn a_handle_turns_the_other_side_at_its_own_x() {
        let before = pairs(CurveName::SwingHeelHeight);
        let after = drag_control_point(&before, 4, (0.25, 0.25), false).unwrap();
        assert_eq!(after[4], (0.25, 0.25));
        assert_eq!(after[2].0, before[2].0);
        assert_ne!(after[2].1, before[2].1);
        assert!(smooth(&after));
        assert!(drag_control_point(&before, 4, (before[3].0, 0.3), false).is_err());
    }

    #[test]
    fn cycle_ends_move_together_and_keep_their_slope() {
        let before = pairs(CurveName::PelvisRotation);
        let last = before.len() - 1;
        let after = drag_control_point(&before, last, (0.9, 0.8), true).unwrap();
        assert_eq!(after[0], (0.0, 0.8));
        assert_eq!(after[last], (1.0, 0.8));
        // Both ends' handles move with them, by what the ends moved.
        let moved = 0.8 - before[last].1;
        assert!(moved.abs() > 0.05, "{moved}");
        assert!(
            (after[1].1 - before[1].1 - moved).abs() < 1e-12
                && (after[last - 1].1 - before[last - 1].1 - moved).abs() < 1e-12
        );
        let turned = drag_control_point(&before, 1, (before[1].0, 1.3), true).unwrap();
        let c = Curve::from_pairs("t", &turned).unwrap();
        assert!((c.slope(0.0) - c.slope(1.0)).abs() < 1e-6, "{} {}", c.slope(0.0), c.slope(1.0));
        assert!(smooth(&turned));
    }
}
