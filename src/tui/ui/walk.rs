//! The stick figure over the terrain, side or frontal view, with the camera on the walker.

use crate::model::body::{Bone, Side};
use crate::model::terrain::Terrain;
use crate::tui::app::{App, View};
use glam::DVec3;
use ratatui::prelude::*;
use ratatui::symbols::Marker;
use ratatui::widgets::Paragraph;
use ratatui::widgets::canvas::{Canvas, Context, Line as CLine, Points};

/// Right limbs are drawn in this colour, left in [`LEFT`].
pub(crate) const RIGHT: Color = Color::LightRed;
/// Left limbs.
pub(crate) const LEFT: Color = Color::LightBlue;

/// Draws the walk panel: canvas and, under it, each leg's phase and the support.
pub fn draw(f: &mut Frame, area: Rect, app: &App, marker: Marker) {
    let view = match app.view {
        View::Side => "side",
        View::Front => "front",
    };
    let inner = super::panel(f, area, Line::raw(format!(" Walk: {view} view (v) ")), Some(legend()));
    let [canvas_area, info_area] = Layout::vertical([Constraint::Min(3), Constraint::Length(3)]).areas(inner);
    draw_canvas(f, canvas_area, app, marker);
    let fr = &app.frame;
    // Standing legs hold their midstance for good: the walk's clock runs on, but a phase
    // fraction cycling under a body at rest would say they were walking.
    let standing = app.walker.walk_state() == crate::model::walk::pace::WalkState::Standing;
    let leg = |s: Side| {
        let l = &fr.legs[s.index()];
        let name = if s == Side::Right { "R" } else { "L" };
        if standing { format!("{name} standing") } else { format!("{name} {} {:.2}", l.leg_phase.name(), l.phase) }
    };
    let info = vec![
        Line::from(vec![
            Span::styled(leg(Side::Right), Style::new().fg(RIGHT)),
            Span::raw("  "),
            Span::styled(leg(Side::Left), Style::new().fg(LEFT)),
        ]),
        Line::from(fit_fields(
            &[
                format!("support {}", fr.support.name()),
                format!("step {}", app.walker.footfalls().last().map_or(0, |f| f.step)),
                format!("t {:.2}s", fr.time_s),
                format!("x {:.2}m", fr.pelvis.x),
            ],
            usize::from(info_area.width),
        )),
        ik_line(app),
    ];
    f.render_widget(Paragraph::new(info), info_area);
}

/// `fields` joined by two spaces, else by one, else the leading ones that fit: a field is
/// shown whole or not at all, since a number cut at the panel's edge reads as another number
/// (at 80 columns "step 10" was cut to "step 1").
fn fit_fields(fields: &[String], width: usize) -> String {
    for separator in ["  ", " "] {
        let joined = fields.join(separator);
        if joined.chars().count() <= width {
            return joined;
        }
    }
    let mut shown = String::new();
    for field in fields {
        let gap = usize::from(!shown.is_empty());
        if shown.chars().count() + gap + field.chars().count() > width {
            break;
        }
        if gap == 1 {
            shown.push(' ');
        }
        shown.push_str(field);
    }
    shown
}

/// The legs' IK this frame: solver, ankle error (µm, to fit 80 columns) and iterations, a
/// miss marked.
fn ik_line(app: &App) -> Line<'static> {
    let ik = app.walker.last_ik();
    let leg = |s: Side| {
        let a = &ik[s.index()];
        let text = format!(
            "{} {:.0}µm {}it{}",
            if s == Side::Right { "R" } else { "L" },
            a.position_error * 1e6,
            a.iterations,
            if a.reached { "" } else { " MISS" }
        );
        let colour = if s == Side::Right { RIGHT } else { LEFT };
        Span::styled(text, Style::new().fg(if a.reached { colour } else { Color::Yellow }))
    };
    Line::from(vec![
        Span::raw(format!("IK {} ", app.params.ik.solver.name())),
        leg(Side::Right),
        Span::raw(" "),
        leg(Side::Left),
    ])
}

fn legend() -> Line<'static> {
    Line::from(vec![
        Span::raw(" "),
        Span::styled("right", Style::new().fg(RIGHT)),
        Span::raw(" "),
        Span::styled("left", Style::new().fg(LEFT)),
        Span::raw(" x footfall "),
    ])
}

/// The ground under the figure: the terrain profile with the footfalls in view (side), or
/// the ground line (front).
fn draw_ground(ctx: &mut Context, view: View, x_bounds: [f64; 2], terrain: &Terrain, ground: f64, footfalls: &[DVec3]) {
    match view {
        View::Side => {
            let n = 120;
            let mut prev: Option<(f64, f64)> = None;
            for i in 0..=n {
                let x = x_bounds[0] + (x_bounds[1] - x_bounds[0]) * f64::from(i) / f64::from(n);
                let y = terrain.height(x);
                if let Some((px, py)) = prev {
                    ctx.draw(&CLine { x1: px, y1: py, x2: x, y2: y, color: Color::Green });
                }
                prev = Some((x, y));
            }
            let marks: Vec<(f64, f64)> = footfalls.iter().map(|h| (h.x, h.y)).collect();
            ctx.draw(&Points { coords: &marks, color: Color::Yellow });
        }
        View::Front => {
            ctx.draw(&CLine { x1: x_bounds[0], y1: ground, x2: x_bounds[1], y2: ground, color: Color::Green });
        }
    }
}

fn draw_canvas(f: &mut Frame, area: Rect, app: &App, marker: Marker) {
    if area.width < 2 || area.height < 2 {
        return;
    }
    let pose = app.walker.pose();
    let dims = &app.walker.resolved().dims;
    let pelvis = app.frame.pelvis;
    // Metres per cell: a cell is about twice as tall as wide, so the x span is set from the
    // height span to keep the figure's proportions.
    let height_m = 2.3;
    let width_m = height_m * f64::from(area.width) / (2.0 * f64::from(area.height));
    let ground = app.walker.terrain().height(pelvis.x);
    let y0 = ground - 0.25;
    type Projection = fn(DVec3) -> (f64, f64);
    let (cx, project): (f64, Projection) = match app.view {
        View::Side => (pelvis.x, |p| (p.x, p.y)),
        // Facing the walker: its right (+z) on the viewer's left.
        View::Front => (-pelvis.z, |p| (-p.z, p.y)),
    };
    let x_bounds = [cx - 0.5 * width_m, cx + 0.5 * width_m];
    let end = |b: Bone| pose.point(b, dims.end_offset(b));
    let view = app.view;
    let terrain = app.walker.terrain();
    // Only the footfalls in view: the list grows with every step of a long session, and
    // copying all of it each frame would make frames slower the longer the lab runs.
    let footfalls: Vec<DVec3> =
        app.walker.footfalls().iter().rev().take_while(|f| f.heel.x >= x_bounds[0] - 1.0).map(|f| f.heel).collect();
    let legs = app.frame.legs;
    let canvas = Canvas::default().marker(marker).x_bounds(x_bounds).y_bounds([y0, y0 + height_m]).paint(move |ctx| {
        draw_ground(ctx, view, x_bounds, terrain, ground, &footfalls);
        ctx.layer();
        let seg = |ctx: &mut Context, a: DVec3, b: DVec3, color: Color| {
            let (x1, y1) = project(a);
            let (x2, y2) = project(b);
            ctx.draw(&CLine { x1, y1, x2, y2, color });
        };
        // Trunk and head.
        let body = Color::White;
        seg(ctx, pose.pos(Bone::Pelvis), pose.pos(Bone::Spine), body);
        seg(ctx, pose.pos(Bone::Spine), pose.pos(Bone::Chest), body);
        seg(ctx, pose.pos(Bone::Chest), pose.pos(Bone::Neck), body);
        seg(ctx, pose.pos(Bone::Neck), end(Bone::Head), body);
        let head = end(Bone::Head);
        let (hx, hy) = project(pose.pos(Bone::Head).lerp(head, 0.6));
        ctx.draw(&ratatui::widgets::canvas::Circle { x: hx, y: hy, radius: 0.09, color: body });
        for side in Side::BOTH {
            let color = if side == Side::Right { RIGHT } else { LEFT };
            // Hip line and shoulder girdle.
            seg(ctx, pose.pos(Bone::Pelvis), pose.pos(Bone::thigh(side)), body);
            seg(ctx, pose.pos(Bone::Neck), pose.pos(Bone::shoulder(side)), body);
            seg(ctx, pose.pos(Bone::shoulder(side)), pose.pos(Bone::upper_arm(side)), body);
            seg(ctx, pose.pos(Bone::upper_arm(side)), pose.pos(Bone::forearm(side)), color);
            seg(ctx, pose.pos(Bone::forearm(side)), pose.pos(Bone::hand(side)), color);
            seg(ctx, pose.pos(Bone::hand(side)), end(Bone::hand(side)), color);
            let l = &legs[side.index()];
            seg(ctx, l.hip, l.knee, color);
            seg(ctx, l.knee, l.ankle, color);
            seg(ctx, l.ankle, l.heel, color);
            seg(ctx, l.heel, pose.pos(Bone::toe(side)), color);
            seg(ctx, pose.pos(Bone::toe(side)), l.toe, color);
        }
    });
    f.render_widget(canvas, area);
}

#[cfg(test)]
mod tests {
    use super::fit_fields;

    #[test]
    fn fields_are_shown_whole_or_not_at_all() {
        let fields = ["support double".to_string(), "step 10".to_string(), "t 4.36s".to_string()];
        assert_eq!(fit_fields(&fields, 40), "support double  step 10  t 4.36s");
        assert_eq!(fit_fields(&fields, 30), "support double step 10 t 4.36s");
        assert_eq!(fit_fields(&fields, 29), "support double step 10");
        assert_eq!(fit_fields(&fields, 20), "support double");
        assert_eq!(fit_fields(&fields, 5), "");
    }
}
