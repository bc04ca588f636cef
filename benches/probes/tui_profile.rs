//! Probe: the time of each of the lab's panels drawn alone at the wide layout's sizes, after
//! 200 frames of walking, through the real crossterm backend into a sink — plus a tick with
//! no drawing, an empty draw and the full 160x48 screen. 300 frames each; mean µs a frame.
//!
//! ```text
//! cargo bench --bench tui_profile
//! ```
//!
//! With `PANEL N` it draws only the panels whose name starts with PANEL (`walk`, `joints`,
//! `curves`, `optimiser`, `editor`, `tick`, `full`), N frames, and prints nothing: for
//! callgrind's instruction counts, which repeat where this VM's wall clock drifts. The
//! instructions per frame in benches/README.md, "Terminal lab", were counted with `full 200`:
//!
//! ```text
//! cargo bench --bench tui_profile --no-run    # prints: Executable ... (target/release/deps/tui_profile-HASH)
//! valgrind --tool=callgrind target/release/deps/tui_profile-HASH full 200
//! valgrind --tool=callgrind target/release/deps/tui_profile-HASH full 0     # start-up alone
//! callgrind_annotate callgrind.out.PID | head -40
//! ```
//!
//! Per frame: the difference of the two totals over 200.
//!
//! Not run by a plain `cargo bench` (`bench = false` in Cargo.toml).

mod common;

use gaitlab::tui::{load_app, ui};
use ratatui::Terminal;
use ratatui::layout::Rect;
use ratatui::symbols::Marker;
use std::time::Instant;

const USAGE: &str =
    "cargo bench --bench tui_profile -- [PANEL N]   (PANEL: walk, joints, curves, optimiser, editor, tick, full)";

type Draw = Box<dyn Fn(&mut ratatui::Frame, &gaitlab::tui::app::App)>;

fn main() {
    let args = common::args(USAGE, 2);
    let only = match args.as_slice() {
        [] => None,
        [panel, n] => match n.parse::<u32>() {
            Ok(n) => Some((panel.as_str(), n)),
            Err(_) => common::usage_exit(USAGE, &format!("N must be a frame count, not {n:?}")),
        },
        _ => common::usage_exit(USAGE, "give both PANEL and N, or neither"),
    };
    let mut app = load_app(None, &[]).expect("the embedded default loads");
    for _ in 0..200 {
        app.tick(1.0 / 60.0);
    }
    let mut t = Terminal::with_options(
        ratatui::backend::CrosstermBackend::new(std::io::sink()),
        ratatui::TerminalOptions { viewport: ratatui::Viewport::Fixed(Rect::new(0, 0, 160, 48)) },
    )
    .expect("a terminal on a sink");
    let m = Marker::Braille;
    let panels: Vec<(&str, Draw)> = vec![
        ("walk 64x27", Box::new(move |f, a| ui::walk::draw(f, Rect::new(0, 0, 64, 27), a, m))),
        ("joints 64x20", Box::new(move |f, a| ui::curves::draw_joints(f, Rect::new(0, 0, 64, 20), a, m))),
        ("curves 51x26", Box::new(move |f, a| ui::curves::draw_curves(f, Rect::new(0, 0, 51, 26), a, m))),
        ("optimiser 51x21", Box::new(move |f, a| ui::panels::draw_optimiser(f, Rect::new(0, 0, 51, 21), a, m))),
        ("editor 45x47", Box::new(move |f, a| ui::panels::draw_editor(f, Rect::new(0, 0, 45, 47), a))),
        ("tick only", Box::new(|_, _| {})),
        ("full 160x48", Box::new(move |f, a| ui::draw(f, a, m))),
    ];
    if let Some((only, n)) = only {
        let Some((_, draw)) = panels.iter().find(|(name, _)| name.starts_with(only)) else {
            common::usage_exit(USAGE, &format!("no panel {only:?}"));
        };
        for _ in 0..n {
            app.tick(1.0 / 60.0);
            t.draw(|f| draw(f, &app)).expect("drawing into a sink");
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
        t.draw(|_| {}).expect("drawing into a sink");
    }
    println!("{:<18} {:>7.1} us", "empty draw", start.elapsed().as_secs_f64() * 1e6 / 300.0);
    for (name, draw) in &panels {
        let n = 300;
        let start = Instant::now();
        for _ in 0..n {
            app.tick(1.0 / 60.0);
            t.draw(|f| draw(f, &app)).expect("drawing into a sink");
        }
        println!("{name:<18} {:>7.1} us", start.elapsed().as_secs_f64() * 1e6 / f64::from(n));
    }
}
