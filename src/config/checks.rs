//! Rules a single key's type and range cannot say: a curve override's shape, and checks
//! across keys on the resolved parameters (cadence, stride, phase order, a foot on a tread).

use crate::config::{echo, schema};
use crate::model::curve::{Curve, CurveError};
use crate::model::gait_curves::CurveName;
use crate::model::params::{TerrainChoice, WalkParams};

/// Checks control points of the named model curve: valid Bézier chain over x ∈ [0, 1], ends
/// and control points within the curve's [`schema::CurveLimits`], and for cycle curves, ends
/// that meet.
pub fn check_curve(name: &str, pairs: &[(f64, f64)]) -> Result<(), String> {
    let n = echo::number;
    let curve = Curve::from_pairs(name, pairs).map_err(|e| match e {
        // The model's own wording, with its numbers kept short.
        CurveError::NonMonotoneX { index, x_prev, x, .. } => format!(
            "curve `{name}`: control point {index} has x = {} after x = {}; x must increase along the curve",
            n(x),
            n(x_prev)
        ),
        other => other.to_string(),
    })?;
    if curve.x_start() != 0.0 || curve.x_end() != 1.0 {
        return Err(format!(
            "curve `{name}` must run from x = 0 to x = 1 (it runs from {} to {})",
            n(curve.x_start()),
            n(curve.x_end())
        ));
    }
    let kind = CurveName::from_key(name).expect("checked by caller");
    let limits = schema::curve_limits(kind);
    let ends = [("start", limits.start, curve.eval(0.0)), ("end", limits.end, curve.eval(1.0))];
    for (which, wanted, y) in ends {
        if let Some(wanted) = wanted
            && (y - wanted).abs() > 1e-9
        {
            return Err(format!(
                "curve `{name}` must {which} at y = {} ({}); it {which}s at {}",
                n(wanted),
                limits.meaning,
                n(y)
            ));
        }
    }
    if let Some((i, (_, y))) = pairs.iter().enumerate().find(|(_, (_, y))| !(limits.lo..=limits.hi).contains(y)) {
        return Err(format!(
            "curve `{name}`: control point {i} has y = {}; valid: {} to {} ({})",
            n(*y),
            n(limits.lo),
            n(limits.hi),
            limits.meaning
        ));
    }
    if kind.is_forward_progress() {
        // Sampled finely enough that a dip between two control points shows: a Bézier
        // segment turns at most twice, and 400 samples over [0, 1] see a back-step of a
        // curve's width of 0.0025.
        let samples: Vec<(f64, f64)> = (0..=400).map(|i| f64::from(i) / 400.0).map(|x| (x, curve.eval(x))).collect();
        if let Some(w) = samples.windows(2).find(|w| w[1].1 < w[0].1 - 1e-9) {
            let (top_x, top) = samples
                .iter()
                .take_while(|s| s.0 <= w[0].0)
                .fold((0.0, f64::NEG_INFINITY), |a, s| if s.1 > a.1 { *s } else { a });
            let (low_x, low) = samples.iter().skip_while(|s| s.0 < w[1].0).take_while(|s| s.1 <= top).fold(
                (w[1].0, w[1].1),
                |a, s| {
                    if s.1 < a.1 { *s } else { a }
                },
            );
            return Err(format!(
                "curve `{name}` must never go back ({}): it falls from {} at x = {} to {} at x = {}",
                limits.meaning,
                n((top * 1000.0).round() / 1000.0),
                n((top_x * 1000.0).round() / 1000.0),
                n((low * 1000.0).round() / 1000.0),
                n((low_x * 1000.0).round() / 1000.0)
            ));
        }
    }
    if kind.is_cyclic() && (curve.eval(0.0) - curve.eval(1.0)).abs() > 1e-9 {
        return Err(format!(
            "curve `{name}` repeats every gait cycle, so its ends must meet: y(0) = {} but y(1) = {}",
            n(curve.eval(0.0)),
            n(curve.eval(1.0))
        ));
    }
    Ok(())
}

/// Checks across keys; each problem names the keys to blame, the first that was set being
/// reported.
#[must_use]
pub fn cross_check(p: &WalkParams) -> Vec<(Vec<&'static str>, String)> {
    let mut out = Vec::new();
    let r = p.resolve();
    let speed_keys = |k: &'static str| vec![k, "walk.speed_mps"];
    let cadence = 120.0 / r.cycle_s;
    if !(50.0..=160.0).contains(&cadence) {
        out.push((
            speed_keys("walk.cadence_spm"),
            format!(
                "cadence resolves to {cadence:.1} steps/min (speed {} m/s, stride {:.2} m); valid: 50 to 160",
                p.walk.speed_mps, r.stride_m
            ),
        ));
    }
    if !(0.5..=2.0).contains(&r.stride_m) {
        out.push((
            speed_keys("walk.stride_m"),
            format!(
                "stride resolves to {:.2} m (speed {} m/s, cadence {cadence:.1}); valid: 0.5 to 2.0 m",
                r.stride_m, p.walk.speed_mps
            ),
        ));
    }
    if r.toe_off - 0.5 < 0.02 {
        out.push((
            speed_keys("legs.toe_off"),
            format!("toe-off at {:.3} of the cycle leaves almost no double support: that is a run, which gaitlab does not model; valid: toe_off from 0.52", r.toe_off),
        ));
    }
    // A heel rise the user did not set follows speed: say so, or the message blames a key the
    // config never names.
    let heel_rise = match p.legs.heel_rise {
        Some(_) => echo::number(r.heel_rise),
        None => format!("{}, derived from walk.speed_mps; set legs.heel_rise to choose it", echo::number(r.heel_rise)),
    };
    if r.heel_rise - r.foot_flat < 0.05 {
        out.push((
            vec!["legs.heel_rise", "legs.foot_flat", "walk.speed_mps"],
            format!("heel_rise ({heel_rise}) must come at least 0.05 of a cycle after foot_flat ({})", r.foot_flat),
        ));
    }
    if r.toe_off - r.heel_rise < 0.05 {
        out.push((
            vec!["legs.toe_off", "legs.heel_rise"],
            format!("toe_off ({:.3}) must come at least 0.05 of a cycle after heel_rise ({heel_rise})", r.toe_off),
        ));
    }
    if 1.0 - r.toe_off < 0.25 {
        out.push((
            vec!["legs.toe_off"],
            format!("toe_off ({:.3}) leaves a swing shorter than a quarter cycle; valid: up to 0.75", r.toe_off),
        ));
    }
    if p.terrain.kind == TerrainChoice::Stairs {
        let foot = r.dims.foot_length * r.turnout.cos() + 2.0 * r.clearance + 0.01;
        if p.terrain.run_m < foot {
            out.push((
                vec!["terrain.run_m", "terrain.kind"],
                format!("a tread of {} m cannot hold a {:.3} m foot with the clearance on both sides; valid: at least {foot:.3} m", p.terrain.run_m, r.dims.foot_length),
            ));
        }
    }
    if out.is_empty()
        && let Err(e) = crate::model::walk::check(p)
    {
        out.push((vec!["walk.speed_mps"], e.0));
    }
    out
}
