//! Plots over the gait cycle, mean and min–max band of the steady cycles: the pelvis and the
//! joint angles, with compared walks overlaid.

use super::common::{FONT, LEFT, LEGEND_FONT_PX, PALETTE, RIGHT, Res, err, legend_height_px, y_range};
use super::data::{Cycle, Data};
use crate::model::walk::frame::LegFrame;
use plotters::coord::Shift;
use plotters::prelude::*;

/// One chart over % of the gait cycle: each (name, colour, cycle) as mean line and band.
fn cycle_chart<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    title: &str,
    y_desc: &str,
    lines: &[(&str, RGBColor, &Cycle)],
    events: &[(&'static str, f64)],
) -> Res {
    let all: Vec<&[(f64, f64)]> = lines.iter().flat_map(|(_, _, c)| [c.mean.as_slice(), c.band.as_slice()]).collect();
    let y = y_range(&all);
    // Room above the data for the event names and, above them, the legend, so neither covers
    // a curve nor each other; a lone line needs no legend (the figure's title and summary.md
    // name the walk). The plot's height is the area's less the caption, margins and x labels.
    let legend = lines.len() > 1;
    let plot_px = (f64::from(area.dim_in_pixel().1) - 30.0 - 2.0 * 12.0 - 55.0).max(100.0);
    let legend_px = if legend { legend_height_px(lines.len()) + 8.0 } else { 0.0 };
    let headroom_px = (legend_px + 30.0).min(0.6 * plot_px);
    let span = y.end - y.start;
    let y = y.start..y.start + span * plot_px / (plot_px - headroom_px);
    let label_y = y.end - (y.end - y.start) * (legend_px + 4.0) / plot_px;
    let mut chart = ChartBuilder::on(area)
        .caption(title, (FONT, 30))
        .margin(12)
        // The last x label ("100") is centred on the axis's end: room for its right half.
        .margin_right(28)
        .x_label_area_size(55)
        .y_label_area_size(80)
        .build_cartesian_2d(0f64..100f64, y.clone())
        .map_err(err)?;
    chart
        .configure_mesh()
        .x_desc("% of gait cycle")
        .x_labels(11)
        .x_label_formatter(&|x| format!("{x:.0}"))
        .y_desc(y_desc)
        .label_style((FONT, 20))
        .axis_desc_style((FONT, 22))
        .draw()
        .map_err(err)?;
    for (name, color, c) in lines {
        chart.draw_series(std::iter::once(Polygon::new(c.band.clone(), color.mix(0.18)))).map_err(err)?;
        chart
            .draw_series(LineSeries::new(c.mean.clone(), color.stroke_width(3)))
            .map_err(err)?
            .label(*name)
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 24, y)], color.stroke_width(3)));
    }
    for (name, pct) in events {
        chart
            .draw_series(std::iter::once(PathElement::new(
                vec![(*pct, y.start), (*pct, y.end)],
                BLACK.mix(0.5).stroke_width(1),
            )))
            .map_err(err)?;
        chart
            .draw_series(std::iter::once(Text::new(name.to_string(), (*pct + 0.8, label_y), (FONT, 18))))
            .map_err(err)?;
    }
    if legend {
        chart
            .configure_series_labels()
            .label_font((FONT, LEGEND_FONT_PX))
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK)
            .position(SeriesLabelPosition::UpperRight)
            .draw()
            .map_err(err)?;
    }
    Ok(())
}

/// Pelvis panels: title, unit.
const PELVIS_PANELS: [(&str, &str); 6] = [
    ("tilt", "anterior tilt (deg)"),
    ("obliquity", "right hip up (deg)"),
    ("rotation", "right hip forward (deg)"),
    ("vertical", "height above lower foot's ground (cm)"),
    ("lateral", "position, right + (cm)"),
    ("forward velocity", "velocity (m/s)"),
];

/// The six pelvis quantities of one walk over its right cycle, in [`PELVIS_PANELS`] order.
fn pelvis_cycles(d: &Data<'_>) -> Vec<Cycle> {
    let f = &d.run.frames;
    let dt = 1.0 / d.run.fps;
    let velocity = |i: usize| {
        let (a, b) = (i.saturating_sub(1), (i + 1).min(f.len() - 1));
        (f[b].pelvis.x - f[a].pelvis.x) / ((b - a).max(1) as f64 * dt)
    };
    let base_y = |i: usize| f[i].pelvis.y - f[i].legs.iter().map(|l| l.ground_under_heel).fold(f64::INFINITY, f64::min);
    vec![
        d.cycle(0, &|i| f[i].pelvis_tilt_deg),
        d.cycle(0, &|i| f[i].pelvis_obliquity_deg),
        d.cycle(0, &|i| f[i].pelvis_rotation_deg),
        d.cycle(0, &|i| base_y(i) * 100.0),
        d.cycle(0, &|i| f[i].pelvis.z * 100.0),
        d.cycle(0, &velocity),
    ]
}

/// The pelvis's six quantities over the right gait cycle, one panel each.
pub(super) fn pelvis<DB: DrawingBackend>(root: DrawingArea<DB, Shift>, walks: &[(String, Data<'_>)]) -> Res {
    root.fill(&WHITE).map_err(err)?;
    let root = root
        .titled("Pelvis over the right gait cycle (mean and min-max band of the steady cycles)", (FONT, 34))
        .map_err(err)?;
    let areas = root.split_evenly((2, 3));
    let cycles: Vec<Vec<Cycle>> = walks.iter().map(|(_, d)| pelvis_cycles(d)).collect();
    for (p, (area, (title, unit))) in areas.iter().zip(PELVIS_PANELS).enumerate() {
        let lines: Vec<(&str, RGBColor, &Cycle)> = walks
            .iter()
            .enumerate()
            .map(|(k, (name, _))| (name.as_str(), PALETTE[k % PALETTE.len()], &cycles[k][p]))
            .collect();
        cycle_chart(area, title, unit, &lines, &walks[0].1.events)?;
    }
    root.present().map_err(err)
}

/// The normative band's colour: grey, behind the walks.
const NORM: RGBColor = RGBColor(120, 120, 120);

/// `reference`'s curve for `joint` ("hip", "knee", "ankle"): its mean and a mean +- 1 SD
/// band over 0-100 % of the cycle.
fn normative_cycle(reference: &crate::normative::Reference, joint: &str) -> Option<Cycle> {
    let stem = match joint {
        "hip" => "hip_flex",
        "knee" => "knee_flex",
        "ankle" => "ankle_dorsi",
        _ => return None,
    };
    let (_, mean, sd) = reference.curves.iter().find(|(s, _, _)| s == stem)?;
    let pct = |i: usize| i as f64;
    let lo = mean.iter().zip(sd).enumerate().map(|(i, (m, s))| (pct(i), m - s));
    let hi: Vec<(f64, f64)> = mean.iter().zip(sd).enumerate().map(|(i, (m, s))| (pct(i), m + s)).collect();
    Some(Cycle {
        mean: mean.iter().enumerate().map(|(i, m)| (pct(i), *m)).collect(),
        band: lo.chain(hi.into_iter().rev()).collect(),
    })
}

/// Hip, knee and ankle angles: each leg over its own cycle, or with compared walks the
/// right leg of each, over the built-in measured adults' mean +- 1 SD.
pub(super) fn joints<DB: DrawingBackend>(root: DrawingArea<DB, Shift>, walks: &[(String, Data<'_>)]) -> Res {
    root.fill(&WHITE).map_err(err)?;
    let title = if walks.len() == 1 {
        "Joint angles, each leg over its own gait cycle (mean and min-max band; grey: measured adults)"
    } else {
        "Joint angles of the right leg, each walk over its own cycle (min-max band; grey: measured adults)"
    };
    let root = root.titled(title, (FONT, 34)).map_err(err)?;
    let areas = root.split_evenly((1, 3));
    type Pick = fn(&LegFrame) -> f64;
    let joints: [(&str, &str, Pick); 3] = [
        ("hip", "flexion + (deg)", |l| l.hip_flex_deg),
        ("knee", "flexion + (deg)", |l| l.knee_flex_deg),
        ("ankle", "dorsiflexion + (deg)", |l| l.ankle_dorsi_deg),
    ];
    // The built-in file is part of the binary and checked by a test, so it always parses.
    let reference = crate::normative::Reference::parse(crate::normative::BUILT_IN, "built-in").ok();
    for (area, (name, unit, pick)) in areas.iter().zip(joints) {
        let mut cycles = Vec::new();
        for (k, (walk, d)) in walks.iter().enumerate() {
            let f = &d.run.frames;
            if walks.len() == 1 {
                cycles.push(("right".to_string(), RIGHT, d.cycle(0, &|i| pick(&f[i].legs[0]))));
                cycles.push(("left".to_string(), LEFT, d.cycle(1, &|i| pick(&f[i].legs[1]))));
            } else {
                cycles.push((walk.clone(), PALETTE[k % PALETTE.len()], d.cycle(0, &|i| pick(&f[i].legs[0]))));
            }
        }
        // Measured adult walking behind the walk's curves: mean and +-1 SD.
        if let Some(norm) = reference.as_ref().and_then(|r| normative_cycle(r, name)) {
            cycles.insert(0, ("adults, Fukuchi 2018 (+-1 SD)".to_string(), NORM, norm));
        }
        let lines: Vec<(&str, RGBColor, &Cycle)> = cycles.iter().map(|(n, c, cy)| (n.as_str(), *c, cy)).collect();
        cycle_chart(area, name, unit, &lines, &walks[0].1.events)?;
    }
    root.present().map_err(err)
}
