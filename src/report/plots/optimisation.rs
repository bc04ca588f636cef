//! The pelvis-acceleration optimisation: one step's cost landscape, and every step's chosen
//! position and cost against the fixed rule's.

use super::common::{DESIGN, FONT, LEFT, RIGHT, Res, SIZE, draw_legend, err, titled, y_range};
use super::data::Data;
use crate::model::optimise::{Candidate, StepProblem};
use crate::model::walk::{Gait, StepPlan};
use plotters::coord::Shift;
use plotters::prelude::*;

/// The landscape of the middle step (left half), the chosen position per step (top right)
/// and the cost per step (bottom right).
pub(super) fn optimisation<DB: DrawingBackend>(root: DrawingArea<DB, Shift>, d: &Data<'_>) -> Res {
    root.fill(&WHITE).map_err(err)?;
    let root = titled(&root, "Pelvis-acceleration optimisation", 34)?;
    let (left, right) = root.split_horizontally(SIZE.0 / 2);
    let plans = &d.run.step_plans;
    // A representative step: the middle one; its landscape by re-walking to it.
    let target = plans.len() / 2;
    let recorded = d.run.step_problems.get(target).and_then(Option::as_ref);
    if let (Some((problem, gait)), Some(plan)) = (recorded, plans.get(target)) {
        landscape(&left, problem, gait, plan)?;
    }
    let (top, bottom) = right.split_vertically(SIZE.1 / 2 - 30);
    let steps: Vec<f64> = plans.iter().map(|p| p.step as f64).collect();
    let smax = steps.iter().copied().fold(1.0, f64::max);
    chosen_per_step(&top, plans, smax)?;
    cost_per_step(&bottom, plans, smax)?;
    root.present().map_err(err)
}

/// The cost of candidate double-support positions across the step's search range, the
/// unreachable ones marked at the bottom, and the position chosen.
fn landscape<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    problem: &StepProblem,
    gait: &Gait,
    plan: &StepPlan,
) -> Res {
    let (lo, hi) = problem.range;
    let (x_from, x_to, land) = zoom_to_feasible(problem, gait);
    let feasible: Vec<(f64, f64)> = land.iter().filter_map(|c| c.cost.map(|k| ((c.x - lo) * 100.0, k))).collect();
    // The landscape is at the planned height; a search that also moves the height (joint)
    // can choose a point below all of it, or outside the zoomed band: the axes take it in,
    // so it is not drawn clipped onto the row of unreachable marks.
    let chosen = plan.optimisation.chosen;
    let chosen_point: Vec<(f64, f64)> = chosen.cost.map(|c| ((chosen.x - lo) * 100.0, c)).into_iter().collect();
    let (x_from, x_to) = match chosen.cost {
        Some(_) => (x_from.min(chosen.x), x_to.max(chosen.x)),
        None => (x_from, x_to),
    };
    let x_axis = (x_from - lo) * 100.0..((x_to - lo) * 100.0).max((x_from - lo) * 100.0 + 1e-6);
    // Beside the costs the legend covered three of brisk's samples.
    let y = legend_headroom(y_range(&[feasible.as_slice(), chosen_point.as_slice()]));
    let zoomed = if (x_from, x_to) == (lo, hi) { String::new() } else { " (feasible band)".to_string() };
    let mut chart = ChartBuilder::on(area)
        .caption(format!("cost landscape, step {}{zoomed}", plan.step), (FONT, 30))
        .margin(12)
        .x_label_area_size(55)
        .y_label_area_size(90)
        .build_cartesian_2d(x_axis, y.clone())
        .map_err(err)?;
    let y_label = cost_label(y.end - y.start);
    chart
        .configure_mesh()
        .x_desc("pelvis x at double support, from range start (cm)")
        .y_desc("cost (rad^2/s^3)")
        .y_label_formatter(&y_label)
        .label_style((FONT, 20))
        .axis_desc_style((FONT, 22))
        .draw()
        .map_err(err)?;
    chart
        .draw_series(feasible.iter().map(|p| Circle::new(*p, 4, RIGHT.filled())))
        .map_err(err)?
        .label("landscape, feasible")
        .legend(|(x, y)| Circle::new((x + 10, y), 4, RIGHT.filled()));
    let unreachable: Vec<(f64, f64)> =
        land.iter().filter(|c| c.cost.is_none()).map(|c| ((c.x - lo) * 100.0, y.start)).collect();
    chart
        .draw_series(unreachable.iter().map(|p| Cross::new(*p, 5, BLACK.stroke_width(2))))
        .map_err(err)?
        .label("landscape, unreachable")
        .legend(|(x, y)| Cross::new((x + 10, y), 5, BLACK.stroke_width(2)));
    if let Some(&point) = chosen_point.first() {
        let lowered_cm = (problem.ds.y - chosen.y) * 100.0;
        let label =
            if lowered_cm.abs() < 0.05 { "chosen".to_string() } else { format!("chosen, {lowered_cm:.1} cm lower") };
        chart
            .draw_series(std::iter::once(TriangleMarker::new(point, 12, LEFT.filled())))
            .map_err(err)?
            .label(label)
            .legend(|(x, y)| TriangleMarker::new((x + 10, y), 8, LEFT.filled()));
    }
    draw_legend(&mut chart, 20, Some(SeriesLabelPosition::UpperRight))?;
    Ok(())
}

/// The landscape's x range and candidates: 81 across the whole search range, but where the
/// feasible band is a few centimetres of a range tens of centimetres wide, the band (with
/// one unreachable sample each side) at 41 points, so the valley the search works in is
/// visible.
fn zoom_to_feasible(problem: &StepProblem, gait: &Gait) -> (f64, f64, Vec<Candidate>) {
    let mut land = problem.landscape(gait, 81);
    let (lo, hi) = problem.range;
    let (mut x_from, mut x_to) = (lo, hi);
    let feasible_x: Vec<f64> = land.iter().filter(|c| c.cost.is_some()).map(|c| c.x).collect();
    if let (Some(&first), Some(&last)) = (feasible_x.first(), feasible_x.last()) {
        let step = (hi - lo) / 80.0;
        if last - first < 0.25 * (hi - lo) {
            x_from = (first - 1.5 * step).max(lo);
            x_to = (last + 1.5 * step).min(hi);
            land = (0..=40)
                .map(|i| {
                    let x = x_from + (x_to - x_from) * f64::from(i) / 40.0;
                    Candidate { x, y: problem.ds.y, cost: problem.cost(gait, x, problem.ds.y) }
                })
                .collect();
        }
    }
    (x_from, x_to, land)
}

/// Each step's chosen position as a share of the way between the mid-stances around it.
fn chosen_per_step<DB: DrawingBackend>(area: &DrawingArea<DB, Shift>, plans: &[StepPlan], smax: f64) -> Res {
    let ratio: Vec<(f64, f64)> = plans.iter().map(|p| (p.step as f64, p.optimisation.chosen_ratio())).collect();
    let mut chart = ChartBuilder::on(area)
        .caption("chosen position per step", (FONT, 28))
        .margin(12)
        .x_label_area_size(50)
        .y_label_area_size(80)
        .build_cartesian_2d(0f64..smax + 1.0, 0f64..1f64)
        .map_err(err)?;
    chart
        .configure_mesh()
        .x_desc("step")
        // Steps are whole numbers: "2.0, 4.0" read as if there were half steps.
        .x_label_formatter(&|x| format!("{x:.0}"))
        .y_desc("between mid-stances (0-1)")
        .label_style((FONT, 18))
        .axis_desc_style((FONT, 20))
        .draw()
        .map_err(err)?;
    chart.draw_series(ratio.iter().map(|p| Circle::new(*p, 5, LEFT.filled()))).map_err(err)?;
    Ok(())
}

/// Each step's cost at the chosen position against the fixed rule's.
fn cost_per_step<DB: DrawingBackend>(area: &DrawingArea<DB, Shift>, plans: &[StepPlan], smax: f64) -> Res {
    let chosen: Vec<(f64, f64)> =
        plans.iter().filter_map(|p| p.optimisation.chosen.cost.map(|c| (p.step as f64, c))).collect();
    let fixed: Vec<(f64, f64)> =
        plans.iter().filter_map(|p| p.optimisation.fixed_rule.cost.map(|c| (p.step as f64, c))).collect();
    // Placed by plotters beside the costs, the legend covered the last steps of a flat series
    // (stroll, default).
    let y = legend_headroom(y_range(&[chosen.as_slice(), fixed.as_slice()]));
    // Where the optimiser keeps the fixed rule the two lines are one; say so, or the fixed
    // rule's line looks missing.
    let caption = match kept_fixed_rule(plans) {
        (0, _) => "cost per step".to_string(),
        (kept, costed) if kept == costed => format!("cost per step (fixed rule kept on all {costed}: lines coincide)"),
        (kept, costed) => format!("cost per step (fixed rule kept on {kept} of {costed})"),
    };
    let mut chart = ChartBuilder::on(area)
        .caption(caption, (FONT, 28))
        .margin(12)
        .x_label_area_size(50)
        .y_label_area_size(80)
        .build_cartesian_2d(0f64..smax + 1.0, y.clone())
        .map_err(err)?;
    let y_label = cost_label(y.end - y.start);
    chart
        .configure_mesh()
        .x_desc("step")
        // Steps are whole numbers: "2.0, 4.0" read as if there were half steps.
        .x_label_formatter(&|x| format!("{x:.0}"))
        .y_desc("cost (rad^2/s^3)")
        .y_label_formatter(&y_label)
        .label_style((FONT, 18))
        .axis_desc_style((FONT, 20))
        .draw()
        .map_err(err)?;
    // A line only joins consecutive steps: a step with no cost (a start's first step and a
    // stop's closing step are not costed) breaks it, instead of a line drawn across the gap
    // as if the steps between had been walked at costs in between. The optimised line is
    // drawn first and wider, the fixed rule's over it: where they coincide both still show.
    for (points, style, name) in
        [(chosen, RIGHT.stroke_width(6), "optimised"), (fixed, DESIGN.stroke_width(2), "fixed rule")]
    {
        for (i, run) in points.chunk_by(|a, b| b.0 - a.0 < 1.5).enumerate() {
            let series = chart.draw_series(LineSeries::new(run.iter().copied(), style)).map_err(err)?;
            if i == 0 {
                series.label(name).legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 24, y)], style));
            }
        }
    }
    draw_legend(&mut chart, 18, Some(SeriesLabelPosition::UpperRight))?;
    Ok(())
}

/// Steps whose chosen double-support position is the fixed rule's, and the steps where both
/// are costed (the optimiser ran and the fixed rule reached).
fn kept_fixed_rule(plans: &[StepPlan]) -> (usize, usize) {
    let costed =
        plans.iter().map(|p| &p.optimisation).filter(|o| o.chosen.cost.is_some() && o.fixed_rule.cost.is_some());
    costed.fold((0, 0), |(kept, n), o| (kept + usize::from((o.chosen.x - o.fixed_rule.x).abs() < 1e-9), n + 1))
}

/// `data`'s y range with a third of its height again above it, where a chart's legend is
/// placed (upper right) clear of the costs.
fn legend_headroom(data: std::ops::Range<f64>) -> std::ops::Range<f64> {
    data.start..data.end + 0.35 * (data.end - data.start)
}

/// Cost tick labels with as many decimals as the axis's `span` needs and no more: a brisk
/// walk's 17 900-18 000 rad²/s³ printed as "17960.0" ran into the axis title.
fn cost_label(span: f64) -> impl Fn(&f64) -> String {
    let decimals = if span >= 10.0 {
        0
    } else if span >= 1.0 {
        1
    } else {
        2
    };
    move |v: &f64| format!("{v:.decimals$}")
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::params::WalkParams;

    #[test]
    fn the_steps_that_keep_the_fixed_rule_are_counted_among_those_costed() {
        let mut params = WalkParams::default();
        let run = crate::analysis::run(&params, 6.0, 60.0).unwrap();
        let plans = &run.step_plans;
        let (kept, costed) = kept_fixed_rule(plans);
        let both =
            plans.iter().filter(|p| p.optimisation.chosen.cost.is_some() && p.optimisation.fixed_rule.cost.is_some());
        assert_eq!(costed, both.clone().count());
        assert!(costed >= 8, "{costed}");
        let same = both.filter(|p| p.optimisation.chosen.x == p.optimisation.fixed_rule.x).count();
        assert_eq!(kept, same);
        // The optimiser off: every costed step is the fixed rule's.
        params.optimiser.enabled = false;
        let off = crate::analysis::run(&params, 6.0, 60.0).unwrap();
        let (kept_off, costed_off) = kept_fixed_rule(&off.step_plans);
        assert!(costed_off >= 8 && kept_off == costed_off, "{kept_off} of {costed_off}");
    }

    #[test]
    fn cost_labels_carry_only_the_decimals_their_axis_needs() {
        assert_eq!(cost_label(400.0)(&17960.0), "17960");
        assert_eq!(cost_label(4.0)(&1986.25), "1986.2");
        assert_eq!(cost_label(0.5)(&1986.257), "1986.26");
    }
}
