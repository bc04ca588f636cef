//! Property tests of the curve operations (spec §4): joins stay G1 after every operation,
//! y(x) agrees with dense sampling of the Bézier segments, and raising at x raises y(x) by
//! the asked amount while leaving segments two or more away untouched.

use gaitlab::model::curve::{Curve, G1_TOLERANCE};
use proptest::prelude::*;

/// A random smooth curve: keys with increasing x, random y and slopes.
fn curve_strategy() -> impl Strategy<Value = Curve> {
    (2usize..7)
        .prop_flat_map(|n| {
            (
                prop::collection::vec(0.05f64..1.0, n),
                prop::collection::vec(-2.0f64..2.0, n + 1),
                prop::collection::vec(-3.0f64..3.0, n + 1),
            )
        })
        .prop_map(|(gaps, ys, slopes)| {
            let total: f64 = gaps.iter().sum();
            let mut x = 0.0;
            let mut keys = vec![(0.0, ys[0], slopes[0])];
            for (i, g) in gaps.iter().enumerate() {
                x += g / total;
                keys.push((if i + 1 == gaps.len() { 1.0 } else { x }, ys[i + 1], slopes[i + 1]));
            }
            Curve::hermite("random", &keys).expect("increasing keys make a valid curve")
        })
}

/// y at x found by dense sampling of the parameter t and bisection on the samples: an
/// evaluation path independent of the curve's own Newton solve.
fn y_by_sampling(c: &Curve, x: f64) -> f64 {
    let j = c.segment_at(x);
    let (mut lo, mut hi) = (0.0f64, 1.0f64);
    // 2000 samples to bracket, then bisection on the bracket.
    let n = 2000;
    for i in 0..n {
        let (a, b) = (i as f64 / n as f64, (i + 1) as f64 / n as f64);
        if c.point_at(j, a).x <= x && x <= c.point_at(j, b).x {
            lo = a;
            hi = b;
            break;
        }
    }
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if c.point_at(j, mid).x < x {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    c.point_at(j, 0.5 * (lo + hi)).y
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    #[test]
    fn evaluation_matches_dense_sampling(c in curve_strategy(), x in 0.0f64..1.0) {
        let a = c.eval(x);
        let b = y_by_sampling(&c, x);
        prop_assert!((a - b).abs() < 1e-9, "eval {a} vs sampled {b} at x={x}");
    }

    #[test]
    fn every_operation_keeps_joins_g1(c in curve_strategy(), h in -1.0f64..1.0, x in 0.02f64..0.98,
                                      delta in -0.5f64..0.5, sx in 0.2f64..3.0, sy in -3.0f64..3.0) {
        prop_assert!(c.joins_are_g1(G1_TOLERANCE));
        let mut s = c.clone();
        s.scale(sx, sy);
        prop_assert!(s.joins_are_g1(G1_TOLERANCE), "scale");
        let mut e = c.clone();
        e.shift_end(h);
        prop_assert!(e.joins_are_g1(G1_TOLERANCE), "shift_end");
        let mut r = c.clone();
        r.raise_at(x, delta);
        prop_assert!(r.joins_are_g1(G1_TOLERANCE), "raise_at");
        let mut l = c.clone();
        l.shift_last_two(h);
        prop_assert!(l.joins_are_g1(G1_TOLERANCE), "shift_last_two");
        let mut live = c.clone();
        live.live_change(&c.scaled(1.0, sy), x);
        prop_assert!(live.joins_are_g1(G1_TOLERANCE), "live_change");
    }

    #[test]
    fn raising_lifts_y_by_delta_and_spares_far_segments(c in curve_strategy(), f in 0.05f64..0.95, delta in -0.3f64..0.3) {
        prop_assume!(c.segment_count() >= 3);
        // A middle segment, so both its ends are free.
        let j = 1 + ((c.segment_count() - 2) as f64 * f) as usize % (c.segment_count() - 2);
        let p = c.points();
        let x = p[3 * j].x + (p[3 * j + 3].x - p[3 * j].x) * (0.1 + 0.8 * f);
        let mut r = c.clone();
        let achieved = r.raise_at(x, delta);
        prop_assert!((achieved - delta).abs() < 1e-9);
        prop_assert!((r.eval(x) - c.eval(x) - delta).abs() < 1e-7, "rise {} wanted {delta}", r.eval(x) - c.eval(x));
        // Only the segment's ends and the handles beside them move (indices 3j-1..=3j+4): the
        // neighbouring segments change only in the handle next to the shared point, and
        // segments two away not at all.
        for (i, (a, b)) in c.points().iter().zip(r.points()).enumerate() {
            if i + 1 < 3 * j || i > 3 * j + 4 {
                prop_assert_eq!(a, b, "control point {} moved", i);
            }
        }
        // The start and end of the curve never move.
        prop_assert_eq!(c.eval(0.0), r.eval(0.0));
        prop_assert_eq!(c.eval(1.0), r.eval(1.0));
    }

    #[test]
    fn shift_end_moves_the_end_by_h(c in curve_strategy(), h in -1.0f64..1.0) {
        let mut e = c.clone();
        e.shift_end(h);
        prop_assert!((e.eval(0.0) - c.eval(0.0)).abs() < 1e-12);
        prop_assert!((e.eval(1.0) - c.eval(1.0) - h).abs() < 1e-12);
    }
}
