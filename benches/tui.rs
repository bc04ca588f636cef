//! Speed of the lab: one full frame (walk update at 60 fps + drawing every panel into a
//! 160x48 buffer, as the wide layout does), and the same at 80x24. Figures in
//! `benches/README.md`; bytes written to a real terminal are measured by
//! `cargo bench --bench tui_bytes`. A drag of a curve's control point: one mouse event
//! through the lab (the curve moved and checked, the walk's parameters changed live) and the
//! redraw at 160x48 — issue 15 asks for both within 1 ms.

use criterion::{Criterion, criterion_group, criterion_main};
use gaitlab::tui::{load_app, ui};
use ratatui::Terminal;
use ratatui::backend::TestBackend;
use ratatui::symbols::Marker;
use std::hint::black_box;

fn full_frame(c: &mut Criterion) {
    for (w, h) in [(160u16, 48u16), (80, 24)] {
        let mut app = load_app(None, &[]).unwrap();
        for _ in 0..120 {
            app.tick(1.0 / 60.0);
        }
        let mut terminal = Terminal::new(TestBackend::new(w, h)).unwrap();
        c.bench_function(&format!("lab frame: walk update + render {w}x{h}"), |b| {
            b.iter(|| {
                app.tick(1.0 / 60.0);
                terminal.draw(|f| ui::draw(f, black_box(&app), Marker::Braille)).unwrap();
            });
        });
    }
}

fn drag_frame(c: &mut Criterion) {
    use gaitlab::tui::app::{CurveView, Msg};
    use ratatui::crossterm::event::{KeyModifiers, MouseButton, MouseEvent, MouseEventKind};
    let mut app = load_app(None, &[]).unwrap();
    for _ in 0..120 {
        app.tick(1.0 / 60.0);
    }
    app.paused = true;
    app.curve = CurveView::ALL.iter().position(|v| *v == CurveView::SwingHeelHeight).unwrap();
    let mut terminal = Terminal::new(TestBackend::new(160, 48)).unwrap();
    terminal.draw(|f| ui::draw(f, &app, Marker::Braille)).unwrap();
    let map = app.edit_map(CurveView::SwingHeelHeight);
    let (x, y) = app.design_points(map.name)[6];
    let start = app.chart_drawn(CurveView::SwingHeelHeight).unwrap().cell_of(x, map.shown(y)).unwrap();
    let event = |kind, column, row| Msg::Mouse(MouseEvent { kind, column, row, modifiers: KeyModifiers::NONE });
    gaitlab::tui::effects::step(&mut app, event(MouseEventKind::Down(MouseButton::Left), start.x, start.y));
    assert!(app.point.is_some(), "the press found the point");
    let mut up = false;
    c.bench_function("lab drag: one drag event + render 160x48", |b| {
        b.iter(|| {
            // Between two cells, so that every event moves the curve.
            up = !up;
            let row = if up { start.y - 2 } else { start.y };
            gaitlab::tui::effects::step(&mut app, event(MouseEventKind::Drag(MouseButton::Left), start.x, row));
            terminal.draw(|f| ui::draw(f, black_box(&app), Marker::Braille)).unwrap();
        });
    });
}

criterion_group!(benches, full_frame, drag_frame);
criterion_main!(benches);
