//! Curve charts (with control points and a cursor at the current phase) and joint traces.

use crate::model::body::Side;
use crate::model::curve::Curve;
use crate::model::gait_curves::CurveName;
use crate::model::walk::leg::LegPhase;
use crate::tui::app::{App, CurveView};
use crate::tui::keys::Action;
use crate::tui::mouse::ChartHit;
use crate::tui::ui::walk::{LEFT, RIGHT};
use ratatui::prelude::*;
use ratatui::symbols::Marker;
use ratatui::widgets::canvas::{Canvas, Line as CLine};
use ratatui::widgets::{Axis, Chart, Dataset, GraphType, Paragraph};

/// One line of a chart: legend name, colour, points.
pub(crate) type ChartLine = (String, Color, Vec<(f64, f64)>);

/// One chart's data, in display units.
pub struct CurveData {
    /// Title with unit.
    pub(crate) title: &'static str,
    /// What the x axis is.
    pub(crate) x_label: &'static str,
    /// (name, colour, samples) of each line; the first is the curve in force.
    pub lines: Vec<ChartLine>,
    /// Bézier control points of the curve in force.
    pub control: Vec<(f64, f64)>,
    /// Where the walk is on the x axis, if it is on this curve now.
    pub cursor: Option<f64>,
}

fn sample(curve: &Curve, scale: f64, offset: f64) -> Vec<(f64, f64)> {
    sample_fn(|x| curve.eval(x), (curve.x_start(), curve.x_end()), scale, offset)
}

/// `f` at 81 points over `x`, scaled and offset.
fn sample_fn(f: impl Fn(f64) -> f64, x: (f64, f64), scale: f64, offset: f64) -> Vec<(f64, f64)> {
    (0..=80).map(|i| x.0 + (x.1 - x.0) * f64::from(i) / 80.0).map(|x| (x, f(x) * scale + offset)).collect()
}

fn controls(curve: &Curve, scale: f64) -> Vec<(f64, f64)> {
    curve.points().iter().map(|p| (p.x, p.y * scale)).collect()
}

/// The data of `view` as the walk has it now.
#[must_use]
pub fn curve_data(app: &App, view: CurveView) -> CurveData {
    let w = &app.walker;
    let design = w.design_curves();
    let right_phase = app.frame.legs[0].phase;
    let deg = 180.0 / std::f64::consts::PI;
    let live = |name: CurveName, scale: f64, x_label| {
        let c = w.live_curve(name).expect("a cycle curve");
        // What the walk plays, a change blending over a cycle included (the control points
        // are the curve it goes to).
        let played = sample_fn(|x| w.live_value(name, x).expect("a cycle curve"), (0.0, 1.0), scale, 0.0);
        CurveData {
            title: view.title(),
            x_label,
            lines: vec![("live".into(), Color::Cyan, played)],
            control: controls(c, scale),
            cursor: Some(right_phase),
        }
    };
    // The swinging leg, if one is swinging, and how far through its swing it is.
    let swinging = Side::BOTH.into_iter().find(|s| w.leg(*s).phase == LegPhase::Swing);
    let r = w.resolved();
    let swing_s = swinging.map(|s| ((app.frame.legs[s.index()].phase - r.toe_off) / (1.0 - r.toe_off)).clamp(0.0, 1.0));
    let with_plan = |name: CurveName, scale: f64, pick: fn(&crate::model::walk::leg::SwingPlan) -> &Curve| {
        let d = design.get(name);
        let mut lines = Vec::new();
        let mut control = controls(d, scale);
        if let Some(plan) = swinging.and_then(|s| w.leg(s).swing.as_ref()) {
            let c = pick(plan);
            lines.push(("this step".into(), Color::Cyan, sample(c, scale, 0.0)));
            control = controls(c, scale);
        }
        lines.push(("design".into(), Color::DarkGray, sample(d, scale, 0.0)));
        CurveData { title: view.title(), x_label: "swing (0-1)", lines, control, cursor: swing_s }
    };
    match view {
        CurveView::PelvisRotation => live(CurveName::PelvisRotation, deg, "right cycle (0-1)"),
        CurveView::PelvisObliquity => live(CurveName::PelvisObliquity, deg, "right cycle (0-1)"),
        CurveView::PelvisTilt => live(CurveName::PelvisTilt, deg, "right cycle (0-1)"),
        CurveView::PelvisLateral => live(CurveName::PelvisLateral, 100.0, "right cycle (0-1)"),
        CurveView::Shoulder => live(CurveName::Shoulder, deg, "right cycle (0-1)"),
        CurveView::Elbow => live(CurveName::Elbow, deg, "right cycle (0-1)"),
        CurveView::PelvisVertical | CurveView::PelvisForward => {
            let names: &[CurveName] = if view == CurveView::PelvisVertical {
                &[CurveName::PelvisVerticalDsMs, CurveName::PelvisVertical]
            } else {
                &[CurveName::PelvisForwardDsMs, CurveName::PelvisForwardMsDs]
            };
            let colors = [Color::Cyan, Color::Magenta];
            let lines = names
                .iter()
                .zip(colors)
                .map(|(n, c)| (n.key().to_string(), c, sample(design.get(*n), 1.0, 0.0)))
                .collect();
            CurveData {
                title: view.title(),
                x_label: "between keys (0-1)",
                lines,
                control: controls(design.get(names[0]), 1.0),
                cursor: None,
            }
        }
        CurveView::SwingForward => with_plan(CurveName::SwingForward, 1.0, |p| &p.forward),
        CurveView::SwingLateral => with_plan(CurveName::SwingLateral, 1.0, |p| &p.lateral),
        CurveView::SwingHeelHeight => with_plan(CurveName::SwingHeelHeight, 100.0, |p| &p.heel_height),
        CurveView::Ankle => with_plan(CurveName::SwingAnkle, 1.0, |p| &p.ankle_deg),
        CurveView::HeelRise => {
            let d = design.get(CurveName::HeelRise);
            let rising = Side::BOTH.into_iter().find(|s| w.leg(*s).phase == LegPhase::HeelRise);
            let mut lines = Vec::new();
            let cursor = rising.map(|s| {
                let scale = w.leg(s).heel_rise_scale;
                lines.push(("this step".into(), Color::Cyan, sample(d, scale, 0.0)));
                ((app.frame.legs[s.index()].phase - r.heel_rise) / (r.toe_off - r.heel_rise)).clamp(0.0, 1.0)
            });
            lines.push(("design".into(), Color::DarkGray, sample(d, 1.0, 0.0)));
            CurveData { title: view.title(), x_label: "heel rise (0-1)", lines, control: controls(d, 1.0), cursor }
        }
    }
}

fn bounds(points: impl Iterator<Item = f64>) -> [f64; 2] {
    let (lo, hi) = points.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), y| (lo.min(y), hi.max(y)));
    if !lo.is_finite() {
        return [0.0, 1.0];
    }
    let pad = ((hi - lo) * 0.08).max(1e-3);
    [lo - pad, hi + pad]
}

fn label(x: f64) -> Span<'static> {
    Span::raw(if x.abs() >= 10.0 { format!("{x:.0}") } else { format!("{x:.2}") })
}

/// A chart whose point is being edited shows the design curve's points, which are the ones
/// edited (a swing chart otherwise shows this step's adapted curve's), and the edited shape
/// at once, even paused (a cycle curve's live line only takes it as the walk plays on).
/// Returns the selected point, to be drawn over the others.
fn show_edited(app: &App, view: CurveView, data: &mut CurveData) -> Option<Vec<(f64, f64)>> {
    let p = app.point.filter(|p| p.view == view)?;
    let map = app.edit_map(view);
    data.control = app.design_points(map.name).iter().map(|&(x, y)| (x, map.shown(y))).collect();
    let design = sample(app.walker.design_curves().get(map.name), map.a, map.b);
    // The two-curve pelvis charts draw the design curves themselves, named by key: the
    // edited one is updated in its own colour, not covered by a grey copy.
    match data.lines.iter_mut().find(|l| l.0 == "design" || l.0 == map.name.key()) {
        Some(line) => line.2 = design,
        None => data.lines.push(("design".into(), Color::DarkGray, design)),
    }
    Some(data.control.get(p.index).copied().map_or_else(Vec::new, |q| vec![q]))
}

/// Draws one curve chart.
pub(crate) fn draw_curve(f: &mut Frame, area: Rect, app: &App, view: CurveView, marker: Marker) {
    let mut data = curve_data(app, view);
    let selected = show_edited(app, view, &mut data);
    let y =
        bounds(data.lines.iter().flat_map(|(_, _, p)| p.iter().map(|q| q.1)).chain(data.control.iter().map(|q| q.1)));
    let x = data
        .lines
        .iter()
        .flat_map(|(_, _, p)| p.iter().map(|q| q.0))
        .fold([f64::INFINITY, f64::NEG_INFINITY], |b, v| [b[0].min(v), b[1].max(v)]);
    let x = if x[0] < x[1] { x } else { [0.0, 1.0] };
    let cursor: Vec<(f64, f64)> = data
        .cursor
        .map_or_else(Vec::new, |c| (0..=20).map(|i| (c, y[0] + (y[1] - y[0]) * f64::from(i) / 20.0)).collect());
    let mut datasets: Vec<Dataset> = data
        .lines
        .iter()
        .map(|(name, color, pts)| {
            Dataset::default()
                .name(name.clone())
                .marker(marker)
                .graph_type(GraphType::Line)
                .style(Style::new().fg(*color))
                .data(pts)
        })
        .collect();
    datasets.push(
        Dataset::default()
            .name("control pts")
            .marker(Marker::Dot)
            .graph_type(GraphType::Scatter)
            .style(Style::new().fg(Color::Yellow))
            .data(&data.control),
    );
    if let Some(selected) = &selected {
        datasets.push(
            Dataset::default()
                .marker(Marker::Block)
                .graph_type(GraphType::Scatter)
                .style(Style::new().fg(Color::LightRed))
                .data(selected),
        );
    }
    if !cursor.is_empty() {
        datasets.push(
            Dataset::default()
                .marker(marker)
                .graph_type(GraphType::Line)
                .style(Style::new().fg(Color::Red))
                .data(&cursor),
        );
    }
    // The x axis's name in the bottom border: ratatui draws an axis title on the chart's
    // lowest data row, where it hid the curve's minimum (the pelvic rotation at mid-cycle).
    let title = coloured_title(&data, &fitted_title(data.title, area.width.saturating_sub(2)));
    let inner = super::panel(f, area, title, Some(bottom_border(&data, area.width.saturating_sub(2))));
    let (x_labels, y_labels) = ([label(x[0]), label(x[1])], [label(y[0]), label(y[1])]);
    let graph = graph_area(inner, &x_labels, &y_labels);
    app.hits.borrow_mut().charts.push(ChartHit { view, graph, x, y });
    let chart = Chart::new(datasets)
        .x_axis(Axis::default().bounds(x).labels(x_labels))
        .y_axis(Axis::default().bounds(y).labels(y_labels))
        // The lines are named in the bottom border (see `bottom_border`): ratatui's legend
        // box hid itself in small charts and at 160x48 covered the curve's end.
        .legend_position(None);
    f.render_widget(chart, inner);
}

/// The chart's bottom border: the x axis's name, then the chart's lines named in their
/// colours and the control points' mark, as fully as `width` columns allow. The names are
/// the chart's kind's, not the lines drawn this frame: a swing chart draws "this step" only
/// while a leg swings, and naming what was drawn made the border change at every toe-off
/// and heel strike. The two-curve pelvis charts name theirs in the title.
fn bottom_border(data: &CurveData, width: u16) -> Line<'static> {
    let axis = Span::raw(format!(" x: {} ", data.x_label));
    let names: &[(&str, &str, Color)] = if data.lines.iter().any(|l| l.0 == "live") {
        &[("live", "live", Color::Cyan)]
    } else if data.lines.iter().any(|l| l.0 == "design") {
        &[("this step", "step", Color::Cyan), ("design", "design", Color::DarkGray)]
    } else {
        &[]
    };
    // The red cursor is where the walk is on the curve (the charts that have one: the same
    // kinds that name their lines): unnamed, it read as the right leg's red.
    let cursor = !names.is_empty();
    let spans = |short: bool, now: bool| {
        let mut spans = vec![axis.clone()];
        for &(long, brief, colour) in names {
            spans.push(Span::styled(format!("─ {}", if short { brief } else { long }), Style::new().fg(colour)));
            spans.push(Span::raw(" "));
        }
        spans.push(Span::styled(if short { "• pts" } else { "• points" }, Style::new().fg(Color::Yellow)));
        spans.push(Span::raw(" "));
        if now {
            spans.push(Span::styled("│ now", Style::new().fg(Color::Red)));
            spans.push(Span::raw(" "));
        }
        Line::from(spans)
    };
    [spans(false, cursor), spans(false, false), spans(true, cursor), spans(true, false)]
        .into_iter()
        .find(|line| line.width() <= usize::from(width))
        .unwrap_or_else(|| Line::from(vec![axis.clone()]))
}

/// The chart's title, its segment names ("ds>ms", "ms>ds") drawn in their lines' colours:
/// the pelvis charts draw two curves, and the legend that would name them fits only in a
/// chart far wider than the lab's (80x24 and 160x48 showed none), so the colours were
/// unexplained.
fn coloured_title(data: &CurveData, title: &str) -> Line<'static> {
    let mut spans = vec![Span::raw(" ")];
    let mut rest = title;
    while let Some((at, name, colour)) = [("ds>ms", 0), ("ms>ds", 1)]
        .iter()
        .filter_map(|(name, i)| Some((rest.find(name)?, *name, data.lines.get(*i)?.1)))
        .min_by_key(|(at, _, _)| *at)
    {
        spans.push(Span::raw(rest[..at].to_string()));
        spans.push(Span::styled(name, Style::new().fg(colour)));
        rest = &rest[at + name.len()..];
    }
    spans.push(Span::raw(format!("{rest} ")));
    Line::from(spans)
}

/// `title` as it fits `width` columns with a space either side: whole, else without the
/// clause between its first comma and its unit ("shoulder flexion, right (deg)" → "shoulder
/// flexion (deg)"; in the 2x2 grid at 160x48 it read "shoulder flexion, righ"), else the
/// name without its unit, else the name cut short. The pelvis charts' segment names are their legend and
/// stay.
fn fitted_title(title: &str, width: u16) -> String {
    let room = usize::from(width).saturating_sub(2);
    if title.chars().count() <= room {
        return title.to_string();
    }
    let (name, unit) = title.rfind(" (").map_or((title, ""), |at| title.split_at(at));
    let name = match name.find(", ") {
        Some(at) if !title.contains("ds>ms") => &name[..at],
        _ => name,
    };
    let keep = room.saturating_sub(unit.chars().count());
    if name.chars().count() <= keep {
        format!("{name}{unit}")
    } else if name.chars().count() <= room {
        // The name whole rather than its unit ("pelvic obliquity", not "pelvic obliqui… (deg)").
        name.to_string()
    } else {
        name.chars().take(room.saturating_sub(1)).chain(std::iter::once('…')).collect()
    }
}

/// The cells a `Chart` with these labels (and no axis titles) plots its data in, as
/// ratatui 0.30 lays it out: the x labels' row and the x axis at the bottom, the y labels
/// (at most a third of the width) and the y axis at the left.
fn graph_area(inner: Rect, x_labels: &[Span<'_>; 2], y_labels: &[Span<'_>; 2]) -> Rect {
    if inner.height <= 2 || inner.width < 3 {
        return Rect { x: inner.x, y: inner.y, width: 0, height: 0 };
    }
    let y_width = y_labels.iter().map(Span::width).max().unwrap_or(0) as u16;
    let left = y_width.max((x_labels[0].width() as u16).saturating_sub(1)).min(inner.width / 3) + 1;
    Rect { x: inner.x + left, y: inner.y, width: inner.width.saturating_sub(left), height: inner.height - 2 }
}

/// The curve panel: one chart, or a grid starting at the selected one — four where the
/// panel holds 2x2 readable charts, else two stacked or side by side, as the space allows
/// (a grid the size could not show would make `g` look dead).
pub fn draw_curves(f: &mut Frame, area: Rect, app: &App, marker: Marker) {
    let n = CurveView::ALL.len();
    // A chart stays readable down to about 24x10 cells (axis labels, a few points per cell).
    let (rows, cols) = match (app.grid, area.width >= 48, area.height >= 20) {
        (false, _, _) => (1, 1),
        (true, true, true) => (2, 2),
        (true, false, true) => (2, 1),
        (true, true, false) => (1, 2),
        (true, false, false) => (1, 1),
    };
    let row_areas = Layout::vertical(vec![Constraint::Fill(1); rows]).split(area);
    for (r, row) in row_areas.iter().enumerate() {
        let cells = Layout::horizontal(vec![Constraint::Fill(1); cols]).split(*row);
        for (c, cell) in cells.iter().enumerate() {
            draw_curve(f, *cell, app, CurveView::ALL[(app.curve + cols * r + c) % n], marker);
        }
    }
}

/// The norms band's colour: a background, so the walk's lines keep their own colours over
/// it, and a dark grey, so they stay the brightest thing in the panel.
pub const NORMS_BAND: Color = Color::Indexed(237);

/// The built-in reference as the joint panel's legend names it.
pub const NORMS_SOURCE: &str = "Fukuchi 2018 ±1 SD";

/// The reference's curves of the traced joints, in the traces' order.
const NORMS_STEMS: [&str; 3] = ["hip_flex", "knee_flex", "ankle_dorsi"];

/// The joint panel's bottom line: the legs' colours, then the band's swatch and source when
/// it is shown, else the key that shows it (as `[keys]` binds it). The legs shrink to their
/// initials where the source would not fit beside their names (a 60-column screen).
fn joints_legend(app: &App, band: bool, width: u16) -> Line<'static> {
    let legend = |right: &'static str, left: &'static str| {
        let mut spans = vec![
            Span::raw(" "),
            Span::styled(right, Style::new().fg(RIGHT)),
            Span::raw(" "),
            Span::styled(left, Style::new().fg(LEFT)),
        ];
        if band {
            spans.push(Span::styled("  ", Style::new().bg(NORMS_BAND)));
            spans.push(Span::raw(format!(" {NORMS_SOURCE} ")));
        } else if let Some(key) = app.keymap.first_key_of(Action::ToggleNorms) {
            spans.push(Span::styled(format!("{key}: norms "), Style::new().fg(Color::DarkGray)));
        }
        Line::from(spans)
    };
    let full = legend("right", "left ");
    if full.width() <= usize::from(width) { full } else { legend("R", "L ") }
}

/// The reference's mean and SD at `phase` (0..1) of the cycle, linear between its rows
/// (one a percent, 0 and 100 % both heel strike).
fn at_phase(mean: &[f64], sd: &[f64], phase: f64) -> (f64, f64) {
    let last = mean.len() - 1;
    let x = phase.clamp(0.0, 1.0) * last as f64;
    let i = (x.floor() as usize).min(last - 1);
    let s = x - i as f64;
    (mean[i] + (mean[i + 1] - mean[i]) * s, sd[i] + (sd[i + 1] - sd[i]) * s)
}

/// The joint panel's title for a panel `width` columns wide: the time the traces span, as
/// the walk's clock reads it (the traces had no time axis: "over time (s)" said the unit
/// of a scale nowhere drawn).
fn joints_title(traced: bool, [t0, t1]: [f64; 2], width: u16) -> String {
    if !traced {
        return " Joint angles (deg) ".into();
    }
    [format!(" Joint angles (deg), {t0:.1} to {t1:.1} s "), format!(" Joint angles (deg), to {t1:.1} s ")]
        .into_iter()
        .find(|t| t.chars().count() + 2 <= usize::from(width))
        .unwrap_or_else(|| " Joint angles (deg) ".into())
}

/// What the band is, said beside the hip trace's name as fully as the row allows: the
/// right leg's cycle, the norms at `norms_mps`, whether the walk (at `walk_mps`) is beyond the
/// norms' fastest or slowest block, which the band then stays at, and, for a walk off level
/// ground (`level` false), that the adults walked on level ground.
fn band_note(norms_mps: f64, walk_mps: f64, level: bool, room: usize) -> Option<String> {
    let beyond = if walk_mps > norms_mps + 1e-6 {
        (" (their fastest)", " max")
    } else if walk_mps < norms_mps - 1e-6 {
        (" (their slowest)", " min")
    } else {
        ("", "")
    };
    let (ground, short) = if level { ("", "") } else { (" on level ground", "level ") };
    [
        format!("band: right leg, adults{ground} at {norms_mps:.2} m/s{}", beyond.0),
        format!("{short}adults {norms_mps:.2} m/s{}", beyond.1),
    ]
    .into_iter()
    .find(|n| n.chars().count() <= room)
}

/// Hip, knee and ankle angles of both legs over the last cycles; with the norms on, the
/// measured adults' mean ± 1 SD behind them, following the right leg's cycle.
pub fn draw_joints(f: &mut Frame, area: Rect, app: &App, marker: Marker) {
    let reference = app.norms_band();
    let t0 = app.traces.front().map_or(0.0, |t| t.0);
    let t1 = app.traces.back().map_or(1.0, |t| t.0).max(t0 + 1e-3);
    let title = Line::raw(joints_title(app.traces.len() >= 2, [t0, t1], area.width));
    let legend = joints_legend(app, reference.is_some(), area.width.saturating_sub(2));
    let inner = super::panel(f, area, title, Some(legend));
    if app.traces.len() < 2 || inner.height < 3 {
        f.render_widget(Paragraph::new("collecting…"), inner);
        return;
    }
    let rows = Layout::vertical([Constraint::Fill(1); 3]).split(inner);
    // One point a cell column (lines join them): more would only cost drawing time.
    let stride = (app.traces.len() / usize::from(inner.width).max(1)).max(1);
    let samples: Vec<_> = app.traces.iter().step_by(stride).collect();
    let mut traces = Vec::with_capacity(3);
    for (j, name) in ["hip flexion", "knee flexion", "ankle dorsiflexion"].iter().enumerate() {
        let right: Vec<(f64, f64)> = samples.iter().map(|(t, a, _)| (*t, a[j])).collect();
        let left: Vec<(f64, f64)> = samples.iter().map(|(t, a, _)| (*t, a[j + 3])).collect();
        // Each sample carries the right leg's phase, 0 at its heel strike as is the
        // reference's 0 %: read there, the band follows the right leg's trace (the left
        // leg's runs half a cycle out of it).
        let band: Vec<(f64, f64, f64)> = reference
            .and_then(|r| r.curves.iter().find(|c| c.0 == NORMS_STEMS[j]))
            .map_or_else(Vec::new, |(_, mean, sd)| {
                samples
                    .iter()
                    .map(|(t, _, phase)| {
                        let (m, s) = at_phase(mean, sd, *phase);
                        (*t, m - s, m + s)
                    })
                    .collect()
            });
        let y = bounds(right.iter().chain(left.iter()).map(|p| p.1).chain(band.iter().flat_map(|b| [b.1, b.2])));
        let room = usize::from(inner.width).saturating_sub(name.chars().count() + 2);
        let level = app.params.terrain.kind().is_level();
        let note = reference.filter(|_| j == 0).and_then(|r| band_note(r.speed_mps, app.walk_speed_mps(), level, room));
        traces.push((name, note, right, left, band, y));
    }
    // One gutter for the three, so that they share a time axis: sized each to its own labels,
    // the knee's ("-8.05") started two columns right of the others.
    let gutter =
        traces.iter().map(|t| format!("{:.0}", t.5[0]).len().max(format!("{:.0}", t.5[1]).len())).max().unwrap_or(0)
            as u16
            + 1;
    for (j, (name, note, right, left, band, y)) in traces.into_iter().enumerate() {
        let trace = Trace { name, note, lines: [(&right, RIGHT), (&left, LEFT)], band: &band };
        draw_trace(f, rows[j], &trace, [t0, t1], y, gutter, marker);
    }
}

/// One joint's trace: its name, a note right of it, both legs' lines, and the norms band as
/// (time, low, high) — empty when not shown.
struct Trace<'a> {
    name: &'a str,
    note: Option<String>,
    lines: [(&'a [(f64, f64)], Color); 2],
    band: &'a [(f64, f64, f64)],
}

/// A small line chart: the name on its first row, the y range at the left in a column
/// `gutter` cells wide, both legs' lines on one canvas. A `Chart` would paint each line on its
/// own canvas layer over the whole area; one layer halves the joint panel's drawing time
/// (where the lines cross, the later one's colour shows, as with layers).
fn draw_trace(f: &mut Frame, area: Rect, trace: &Trace<'_>, x: [f64; 2], y: [f64; 2], gutter: u16, marker: Marker) {
    if area.height < 2 || area.width < 8 {
        return;
    }
    // Whole degrees: the curve charts' two decimals under 10 made one trace's labels wider
    // than the others' ("-1.44" beside "42") and jump as the scale moved.
    let (hi, lo) = (format!("{:.0}", y[1]), format!("{:.0}", y[0]));
    let [title, plot] = Layout::vertical([Constraint::Length(1), Constraint::Fill(1)]).areas(area);
    let mut heading = vec![Span::styled(trace.name.to_string(), Style::new().fg(Color::Gray))];
    if let Some(note) = &trace.note {
        let pad = usize::from(title.width).saturating_sub(trace.name.chars().count() + note.chars().count());
        heading.push(Span::raw(" ".repeat(pad)));
        heading.push(Span::styled(note.clone(), Style::new().fg(Color::DarkGray)));
    }
    f.render_widget(Paragraph::new(Line::from(heading)), title);
    let [labels, canvas] = Layout::horizontal([Constraint::Length(gutter), Constraint::Fill(1)]).areas(plot);
    let mut label_lines = vec![Line::raw(String::new()); usize::from(labels.height)];
    if let Some(first) = label_lines.first_mut() {
        *first = Line::raw(format!("{hi:>w$}│", w = usize::from(gutter - 1)));
    }
    for line in label_lines.iter_mut().skip(1) {
        *line = Line::raw(format!("{:>w$}│", "", w = usize::from(gutter - 1)));
    }
    if labels.height > 1 {
        let last = label_lines.len() - 1;
        label_lines[last] = Line::raw(format!("{lo:>w$}│", w = usize::from(gutter - 1)));
    }
    f.render_widget(Paragraph::new(label_lines), labels);
    let lines = trace.lines;
    let widget = Canvas::default().marker(marker).x_bounds(x).y_bounds(y).paint(move |ctx| {
        for (points, colour) in lines {
            for pair in points.windows(2) {
                ctx.draw(&CLine { x1: pair[0].0, y1: pair[0].1, x2: pair[1].0, y2: pair[1].1, color: colour });
            }
        }
    });
    f.render_widget(widget, canvas);
    let canvas = canvas.intersection(f.area());
    paint_band(f.buffer_mut(), canvas, x, y, trace.band);
}

/// The band in the canvas's cells after the lines are drawn, each cell column taking the
/// band at its middle time. A cell a line is drawn in gets the band as its background when
/// the band covers half of it or more; an empty cell gets it by half rows (`▀`, `▄`, or the
/// background), which doubles the band's resolution where no line hides it. A band thinner
/// than that still marks the half row of its middle. Backgrounds a half-block line already
/// uses are kept.
fn paint_band(buf: &mut Buffer, canvas: Rect, x: [f64; 2], y: [f64; 2], band: &[(f64, f64, f64)]) {
    if band.is_empty() || canvas.is_empty() || y[1] <= y[0] {
        return;
    }
    let row_of = |v: f64| (y[1] - v) / (y[1] - y[0]) * f64::from(canvas.height);
    for col in 0..canvas.width {
        let t = x[0] + (x[1] - x[0]) * (f64::from(col) + 0.5) / f64::from(canvas.width);
        let i = band.partition_point(|b| b.0 < t).min(band.len() - 1);
        let i = if i > 0 && t - band[i - 1].0 < band[i].0 - t { i - 1 } else { i };
        let (top, bottom) = (row_of(band[i].2), row_of(band[i].1));
        let covered = |from: f64, to: f64| (bottom.min(to) - top.max(from)).max(0.0) / (to - from) >= 0.5;
        // Half rows in the band, in rows from the top; a thin band's middle half row.
        let mut halves: Vec<u16> =
            (0..2 * canvas.height).filter(|h| covered(0.5 * f64::from(*h), 0.5 * f64::from(*h + 1))).collect();
        if halves.is_empty() {
            let middle = (top + bottom).clamp(0.0, f64::from(2 * canvas.height - 1));
            halves.push(middle as u16);
        }
        for r in 0..canvas.height {
            let (up, down) = (halves.contains(&(2 * r)), halves.contains(&(2 * r + 1)));
            let cell = &mut buf[(canvas.x + col, canvas.y + r)];
            if cell.symbol() == " " {
                match (up, down) {
                    (true, true) => cell.set_bg(NORMS_BAND),
                    (true, false) => cell.set_char('▀').set_fg(NORMS_BAND),
                    (false, true) => cell.set_char('▄').set_fg(NORMS_BAND),
                    (false, false) => cell,
                };
            } else if (up || down) && cell.bg == Color::Reset {
                let whole = covered(f64::from(r), f64::from(r + 1));
                if whole || (halves.len() == 1) {
                    cell.set_bg(NORMS_BAND);
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::normative::References;

    #[test]
    fn the_band_reads_the_reference_at_the_phase_in_percent_of_the_cycle() {
        let r = References::built_in().at(1.3);
        let (_, mean, sd) = r.curves.iter().find(|c| c.0 == "knee_flex").unwrap();
        assert_eq!(at_phase(mean, sd, 0.74), (mean[74], sd[74]));
        assert_eq!(at_phase(mean, sd, 0.0), (mean[0], sd[0]));
        assert_eq!(at_phase(mean, sd, 1.0), (mean[100], sd[100]));
        let (m, s) = at_phase(mean, sd, 0.745);
        assert!((m - 0.5 * (mean[74] + mean[75])).abs() < 1e-9 && (s - 0.5 * (sd[74] + sd[75])).abs() < 1e-9);
    }

    #[test]
    fn the_band_note_names_the_speed_as_fully_as_the_room_allows() {
        assert_eq!(band_note(1.2449, 1.2449, true, 60).unwrap(), "band: right leg, adults at 1.24 m/s");
        assert_eq!(band_note(1.2449, 1.2449, true, 20).unwrap(), "adults 1.24 m/s");
        assert_eq!(band_note(1.2449, 1.2449, true, 14), None);
        // A walk beyond the norms' ends: the band stays at the end block, and says so.
        assert_eq!(band_note(1.799, 2.0, true, 60).unwrap(), "band: right leg, adults at 1.80 m/s (their fastest)");
        assert_eq!(band_note(0.796, 0.5, true, 20).unwrap(), "adults 0.80 m/s min");
        // Off level ground (stairs, a slope, rough ground) the adults still walked on the level.
        assert_eq!(
            band_note(0.796, 0.5, false, 80).unwrap(),
            "band: right leg, adults on level ground at 0.80 m/s (their slowest)"
        );
        assert_eq!(band_note(0.796, 0.5, false, 26).unwrap(), "level adults 0.80 m/s min");
    }
}
