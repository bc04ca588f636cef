//! Plots over the gait cycle, mean and min–max band of the steady cycles: the pelvis and the
//! joint angles, with compared walks overlaid and measured adults' mean ± 1 SD behind them.

use super::common::{
    EVENTS_CAPTION, FONT, LEFT, LEGEND_FONT_PX, PALETTE, RIGHT, Res, captioned, draw_legend, err, legend_height_px,
    percent_chart, titled, y_range,
};
use super::data::{Cycle, Data};
use crate::model::walk::frame::LegFrame;
use crate::normative::{PelvisAtSpeed, PelvisNorms, Reference, References};
use plotters::coord::Shift;
use plotters::prelude::*;

/// One chart over % of the gait cycle: each (name, colour, cycle) as mean line and band,
/// in order, so the first is drawn behind the rest. An empty name leaves its line out of the
/// legend (a lone walk is the report's own); a name of several lines takes a legend row each.
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
    // a curve nor each other. The plot's height is the area's less the caption, margins and
    // x labels.
    let rows = lines.iter().filter(|l| !l.0.is_empty()).map(|l| l.0.lines().count()).sum::<usize>();
    let plot_px = (f64::from(area.dim_in_pixel().1) - 30.0 - 2.0 * 12.0 - 55.0).max(100.0);
    let legend_px = if rows > 0 { legend_height_px(rows) + 8.0 } else { 0.0 };
    let headroom_px = (legend_px + 30.0).min(0.6 * plot_px);
    let span = y.end - y.start;
    let y = y.start..y.start + span * plot_px / (plot_px - headroom_px);
    let label_y = y.end - (y.end - y.start) * (legend_px + 4.0) / plot_px;
    let mut chart = percent_chart(area, title, y.clone())?;
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
    for (i, (name, color, c)) in lines.iter().enumerate() {
        // The last line drawn is thin over a thick one before it: a level walk's left leg lay
        // exactly over its right, and the red line the legend promised was nowhere to be seen.
        let width = match lines.len() - 1 - i {
            0 if lines.len() > 1 => 2,
            1 => 5,
            _ => 3,
        };
        chart.draw_series(std::iter::once(Polygon::new(c.band.clone(), color.mix(0.18)))).map_err(err)?;
        let line = chart.draw_series(LineSeries::new(c.mean.clone(), color.stroke_width(width))).map_err(err)?;
        let mut rows = name.lines();
        if let Some(first) = rows.next() {
            let color = *color;
            line.label(first)
                .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 24, y)], color.stroke_width(width)));
        }
        // A name too wide for a panel's legend goes on in rows without a swatch, so that it
        // still reads as one entry.
        for row in rows {
            chart
                .draw_series(std::iter::empty::<PathElement<(f64, f64)>>())
                .map_err(err)?
                .label(row)
                .legend(|(x, y)| EmptyElement::at((x, y)));
        }
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
    if rows > 0 {
        draw_legend(&mut chart, LEGEND_FONT_PX, Some(SeriesLabelPosition::UpperRight))?;
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

/// The pelvis's six quantities over the right gait cycle, one panel each; the three angles
/// over measured adults' mean +- 1 SD (the report's own walk's mean for the tilt).
pub(super) fn pelvis<DB: DrawingBackend>(root: DrawingArea<DB, Shift>, walks: &[(String, Data<'_>)]) -> Res {
    root.fill(&WHITE).map_err(err)?;
    let root = titled(&root, "Pelvis over the right gait cycle (mean and min-max band; grey: measured adults)", 34)?;
    let root = captioned(&root, EVENTS_CAPTION, 20)?;
    let areas = root.split_evenly((2, 3));
    let cycles: Vec<Vec<Cycle>> = walks.iter().map(|(_, d)| pelvis_cycles(d)).collect();
    let reference = speed_matched(&walks[0].1);
    let level = walks[0].1.on_level_ground();
    // Signs, checked before drawing: the walk's obliquity is + with the right hip up and its
    // rotation + with the right hip forward (`PelvisPose::new`, its test
    // `obliquity_lifts_the_right_hip`); the reference's are the right side's pelvis angles
    // on the right leg's cycle, + ipsilateral up / forward (normative_adult_walking.md,
    // from the shapes: +5.5° at 16 %, +4.3° at 4 %). The default walk agrees where the
    // events say it must (obliquity +3.5° at 16 %, rotation +4.0° at right heel strike;
    // `gaitlab compare` r +0.72 and +0.63, where a flipped sign would be negative), so the
    // bands are drawn as they stand. The reference's tilt carries a ~10° offset from its
    // marker model and the walk's tilt is a swing about its posture: a shape band, moved
    // onto the report's own walk's mean.
    // People's pelvis is measured as a range, not a curve: drawn as a band that tall about the
    // walk's mean height, so the walk's shortfall shows at a glance.
    let people = PelvisNorms::built_in().at(walks[0].1.speed_mps());
    let norms = [
        normative_cycle(&reference, "pelvis_tilt_ant", Some(mean_of(&cycles[0][0]))),
        normative_cycle(&reference, "pelvis_obliq_up", None),
        normative_cycle(&reference, "pelvis_rot_fwd", None),
        Some(range_band(mean_of(&cycles[0][3]), people.vertical_range_cm.0)),
    ];
    let range_name = format!(
        "adults' range, {:.1} cm at {}\ncentred on the walk's mean (WBDS){}",
        people.vertical_range_cm.0,
        measured_at(&people),
        ground_line(level)
    );
    for (p, (area, (title, unit))) in areas.iter().zip(PELVIS_PANELS).enumerate() {
        let mut lines: Vec<(&str, RGBColor, &Cycle)> = walks
            .iter()
            .enumerate()
            .map(|(k, (name, _))| {
                // A lone walk is the report's own (the summary names it): the legend names
                // only the band, and no box of walk names sits over a lone curve.
                let name = if walks.len() == 1 { "" } else { name.as_str() };
                (name, PALETTE[k % PALETTE.len()], &cycles[k][p])
            })
            .collect();
        let band_name = if p == 3 { range_name.clone() } else { norm_name(&reference, p == 0, level) };
        if let Some(norm) = norms.get(p).and_then(Option::as_ref) {
            lines.insert(0, (band_name.as_str(), NORM, norm));
        }
        cycle_chart(area, title, unit, &lines, &walks[0].1.events)?;
    }
    root.present().map_err(err)
}

/// The normative band's colour: grey, behind the walks.
const NORM: RGBColor = RGBColor(120, 120, 120);

/// The normative band's legend entry: whose, at what speed; for the pelvic tilt, that the band
/// is the reference's shape, not its level; for a walk off level ground, that the adults walked
/// on level ground (a stairs walk's knee against a level band read as a 40° error).
fn norm_name(reference: &Reference, tilt: bool, level: bool) -> String {
    let shape = if tilt { "\nshape about the walk's mean" } else { "" };
    format!("adults at {:.2} m/s, Fukuchi 2018 (±1 SD){shape}{}", reference.speed_mps, ground_line(level))
}

/// A band's legend line for a walk off level ground (`level` false): the adults walked on the
/// level. Its own line: a longer first line pushed the legend's text over its swatches.
fn ground_line(level: bool) -> &'static str {
    if level { "" } else { "\nwalking on level ground" }
}

/// The built-in references at the speed `walk` walked its drawn cycles at, as the summary's
/// comparison reads them.
fn speed_matched(walk: &Data<'_>) -> Reference {
    References::built_in().at(walk.speed_mps())
}

/// The mean of a cycle's mean curve over its points.
fn mean_of(c: &Cycle) -> f64 {
    c.mean.iter().map(|p| p.1).sum::<f64>() / c.mean.len().max(1) as f64
}

/// A band `range` tall centred on `level` over the whole cycle, with its middle as the line.
fn range_band(level: f64, range: f64) -> Cycle {
    let (lo, hi) = (level - 0.5 * range, level + 0.5 * range);
    Cycle { mean: vec![(0.0, level), (100.0, level)], band: vec![(0.0, lo), (100.0, lo), (100.0, hi), (0.0, hi)] }
}

/// `reference`'s curve `stem`: its mean and a mean +- 1 SD band over 0-100 % of the cycle;
/// with `about` its mean over the cycle moved there (a shape band).
fn normative_cycle(reference: &Reference, stem: &str, about: Option<f64>) -> Option<Cycle> {
    let (_, mean, sd) = reference.curves.iter().find(|(s, _, _)| s == stem)?;
    let shift = about.map_or(0.0, |level| level - mean.iter().sum::<f64>() / mean.len() as f64);
    let pct = |i: usize| i as f64;
    let lo = mean.iter().zip(sd).enumerate().map(|(i, (m, s))| (pct(i), m + shift - s));
    let hi: Vec<(f64, f64)> = mean.iter().zip(sd).enumerate().map(|(i, (m, s))| (pct(i), m + shift + s)).collect();
    Some(Cycle {
        mean: mean.iter().enumerate().map(|(i, m)| (pct(i), m + shift)).collect(),
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
    let root = titled(&root, title, 34)?;
    let root = captioned(&root, EVENTS_CAPTION, 20)?;
    let areas = root.split_evenly((1, 3));
    type Pick = fn(&LegFrame) -> f64;
    let joints: [(&str, &str, &str, Pick); 3] = [
        ("hip", "hip_flex", "flexion + (deg)", |l| l.hip_flex_deg),
        ("knee", "knee_flex", "flexion + (deg)", |l| l.knee_flex_deg),
        ("ankle", "ankle_dorsi", "dorsiflexion + (deg)", |l| l.ankle_dorsi_deg),
    ];
    let reference = speed_matched(&walks[0].1);
    let band_name = norm_name(&reference, false, walks[0].1.on_level_ground());
    for (area, (name, stem, unit, pick)) in areas.iter().zip(joints) {
        let mut cycles = Vec::new();
        for (k, (walk, d)) in walks.iter().enumerate() {
            let f = &d.run.frames;
            if walks.len() == 1 {
                let (right, left) = (d.cycle(0, &|i| pick(&f[i].legs[0])), d.cycle(1, &|i| pick(&f[i].legs[1])));
                // A steady level walk's legs mirror each other: the left curve is drawn but lies
                // under the right, so the legend says so rather than leave it looking missing.
                let apart = right.mean.iter().zip(&left.mean).map(|(a, b)| (a.1 - b.1).abs()).fold(0.0, f64::max);
                let left_name =
                    if apart < 0.5 { format!("left (under right, within {apart:.1} deg)") } else { "left".to_string() };
                cycles.push(("right".to_string(), RIGHT, right));
                cycles.push((left_name, LEFT, left));
            } else {
                cycles.push((walk.clone(), PALETTE[k % PALETTE.len()], d.cycle(0, &|i| pick(&f[i].legs[0]))));
            }
        }
        // Measured adult walking behind the walk's curves: mean and +-1 SD.
        if let Some(norm) = normative_cycle(&reference, stem, None) {
            cycles.insert(0, (band_name.clone(), NORM, norm));
        }
        let lines: Vec<(&str, RGBColor, &Cycle)> = cycles.iter().map(|(n, c, cy)| (n.as_str(), *c, cy)).collect();
        cycle_chart(area, name, unit, &lines, &walks[0].1.events)?;
    }
    root.present().map_err(err)
}

/// The speed people's pelvis range was read at: the walk's, or the nearest block's where the
/// walk is faster or slower than every block (the table is not extrapolated: a 1.75 m/s walk
/// is shown the 1.57 m/s block's range, and the legend says so on a line of its own, the
/// legend's width kept).
fn measured_at(people: &PelvisAtSpeed) -> String {
    match people.beyond_measured() {
        Some(end) => format!("{:.2} m/s\n(the {end} measured)", people.from_block_mps),
        None => format!("{:.2} m/s", people.speed_mps),
    }
}
