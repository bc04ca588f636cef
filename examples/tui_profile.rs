//! Time of each panel's drawing at the wide layout's sizes (a development probe).
use gaitlab::tui::{load_app, ui};
use ratatui::Terminal;
use ratatui::layout::Rect;
use ratatui::symbols::Marker;
use std::time::Instant;

fn main() {
    let mut app = load_app(None, &[]).unwrap();
    for _ in 0..200 {
        app.tick(1.0 / 60.0);
    }
    let mut t = Terminal::with_options(
        ratatui::backend::CrosstermBackend::new(std::io::sink()),
        ratatui::TerminalOptions { viewport: ratatui::Viewport::Fixed(Rect::new(0, 0, 160, 48)) },
    )
    .unwrap();
    let m = Marker::Braille;
    type Draw = Box<dyn Fn(&mut ratatui::Frame, &gaitlab::tui::app::App)>;
    let panels: Vec<(&str, Draw)> = vec![
        ("walk 64x27", Box::new(move |f, a| ui::walk::draw(f, Rect::new(0, 0, 64, 27), a, m))),
        ("joints 64x20", Box::new(move |f, a| ui::curves::draw_joints(f, Rect::new(0, 0, 64, 20), a, m))),
        ("curves 51x26", Box::new(move |f, a| ui::curves::draw_curves(f, Rect::new(0, 0, 51, 26), a, m))),
        ("optimiser 51x21", Box::new(move |f, a| ui::panels::draw_optimiser(f, Rect::new(0, 0, 51, 21), a, m))),
        ("editor 45x47", Box::new(move |f, a| ui::panels::draw_editor(f, Rect::new(0, 0, 45, 47), a))),
        ("tick only", Box::new(|_, _| {})),
        ("full 160x48", Box::new(move |f, a| ui::draw(f, a, m))),
    ];
    // `tui_profile PANEL N`: only that panel, N frames (for callgrind's instruction counts,
    // which, unlike this VM's wall clock, repeat).
    let args: Vec<String> = std::env::args().collect();
    if let [_, only, n] = args.as_slice() {
        let n: u32 = n.parse().unwrap();
        let (_, draw) = panels.iter().find(|(name, _)| name.starts_with(only.as_str())).expect("a panel name");
        for _ in 0..n {
            app.tick(1.0 / 60.0);
            t.draw(|f| draw(f, &app)).unwrap();
        }
        return;
    }
    let start = Instant::now();
    for _ in 0..300 {
        app.tick(1.0 / 60.0);
    }
    println!("{:<18} {:>7.1} us", "tick, no draw", start.elapsed().as_secs_f64() * 1e6 / 300.0);
    let start = Instant::now();
    for _ in 0..300 {
        t.draw(|_| {}).unwrap();
    }
    println!("{:<18} {:>7.1} us", "empty draw", start.elapsed().as_secs_f64() * 1e6 / 300.0);
    for (name, draw) in &panels {
        let n = 300;
        let start = Instant::now();
        for _ in 0..n {
            app.tick(1.0 / 60.0);
            t.draw(|f| draw(f, &app)).unwrap();
        }
        println!("{name:<18} {:>7.1} us", start.elapsed().as_secs_f64() * 1e6 / f64::from(n));
    }
}
