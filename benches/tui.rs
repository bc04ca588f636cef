//! Speed of the lab: one full frame (walk update at 60 fps + drawing every panel into a
//! 160x48 buffer, as the wide layout does), and the same at 80x24. Figures in
//! `benches/README.md`; bytes written to a real terminal are measured by
//! `cargo bench --bench tui_bytes`.

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

criterion_group!(benches, full_frame);
criterion_main!(benches);
