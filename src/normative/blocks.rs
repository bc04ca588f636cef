//! Norms tabulated in speed blocks: which blocks a walk's speed falls between, and how to say
//! so. Shared by the joint-curve references, the spatiotemporal norms and the pelvis norms.

/// Of `speeds` (rising), the two blocks around `speed_mps` and how far between them it is
/// (0 at the first): the end block twice beyond either end or for NaN.
pub(super) fn bracket(speeds: &[f64], speed_mps: f64) -> (usize, usize, f64) {
    let last = speeds.len() - 1;
    if speed_mps.is_nan() || speed_mps <= speeds[0] {
        return (0, 0, 0.0);
    }
    if speed_mps >= speeds[last] {
        return (last, last, 0.0);
    }
    let i = speeds.windows(2).position(|w| speed_mps < w[1]).unwrap_or(0);
    (i, i + 1, (speed_mps - speeds[i]) / (speeds[i + 1] - speeds[i]))
}

/// Which blocks (`from`, `to` m/s) a norm at `speed_mps` came from, in words: "the 1.232 m/s
/// block", "interpolated between the 1.232 and 1.417 m/s blocks", or "the 1.417 m/s block,
/// the fastest (the walk is faster; not extrapolated)".
pub(super) fn blocks_used(speed_mps: f64, (from, to): (f64, f64)) -> String {
    if from < to {
        format!("interpolated between the {from:.3} and {to:.3} m/s blocks")
    } else if speed_mps > to + 1e-9 {
        format!("the {to:.3} m/s block, the fastest (the walk is faster; not extrapolated)")
    } else if speed_mps < from - 1e-9 {
        format!("the {from:.3} m/s block, the slowest (the walk is slower; not extrapolated)")
    } else {
        format!("the {from:.3} m/s block")
    }
}
