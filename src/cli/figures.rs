//! `gaitlab figures`: the seed thesis's figures and table 6.1 regenerated into a folder. The
//! figures are the library's (`report::figures`); the lab's draw, which table 6.1 sets
//! beside the walk's parts, is measured here, where the terminal code may be used.

use crate::analysis::frame_cost;
use crate::config::{self, presets};
use crate::error::{Error, Result};
use crate::model::params::WalkParams;
use crate::output;
use crate::report::figures::{self, FiguresInput, LabDraw};
use std::io::{self, IsTerminal};
use std::path::{Path, PathBuf};
use std::time::Instant;

/// `gaitlab figures`' arguments.
pub(super) struct Args<'a> {
    pub(super) config: Option<&'a Path>,
    pub(super) out: Option<&'a Path>,
    pub(super) force: bool,
    pub(super) sets: &'a [String],
}

/// Gait cycles and paired runs of table 6.1's measurement: about 0.2 s on the default walk.
const COST_CYCLES: f64 = 20.0;
const COST_REPEATS: usize = 9;

/// The screen the lab's draw is measured on: the smallest that shows every panel.
const LAB_SIZE: (u16, u16) = (140, 40);

pub(super) fn run(args: &Args<'_>) -> Result<()> {
    let (name, text, params) = match args.config {
        Some(path) => {
            let (text, params) = config::load_with_text(path, args.sets)?;
            (path.file_stem().map_or("config".into(), |s| s.to_string_lossy().into_owned()), text, params)
        }
        None => {
            let text = presets::default_text().to_string();
            ("default".to_string(), text.clone(), config::load_text(&text, "(embedded default)", args.sets)?)
        }
    };
    let blame = args.config.map_or_else(|| PathBuf::from("(embedded default)"), Path::to_path_buf);
    let app = crate::tui::app::App::new(params.clone(), text, args.config.map(Path::to_path_buf))
        .map_err(|source| Error::Walk { config: blame.clone(), source })?;
    let out = args.out.map_or_else(|| figures::default_out(args.config), Path::to_path_buf);
    let target = figures::resolve_out(&out, args.force)?;
    output::pending::remove_on_signal()
        .map_err(|e| Error::Output(output::OutputError::Failed(format!("cannot watch signals: {e}"))))?;
    let tty = io::stderr().is_terminal();
    let mut progress = |stage: &str| {
        if tty {
            eprintln!("gaitlab figures: {stage}");
        }
    };
    progress("measuring each part of a frame (table 6.1)");
    let costs = measure_walk(&params).map_err(|source| Error::Walk { config: blame, source })?;
    progress("measuring the lab's draw");
    let lab_draw = Some(lab_draw(app));
    let input = FiguresInput { name, params: &params, costs: &costs, lab_draw };
    figures::write_figures(&input, &target, &mut progress)?;
    println!("{}", out.display());
    Ok(())
}

fn measure_walk(params: &WalkParams) -> std::result::Result<frame_cost::FrameCosts, crate::model::walk::ModelError> {
    frame_cost::measure(params, COST_CYCLES, params.sim.fps, COST_REPEATS)
}

/// The lab's draw of every panel into ratatui's TestBackend (no terminal's bytes): the
/// median of 31 draws, each after a frame of walking.
fn lab_draw(mut app: crate::tui::app::App) -> LabDraw {
    use ratatui::Terminal;
    use ratatui::backend::TestBackend;
    let (w, h) = LAB_SIZE;
    let mut times = Vec::with_capacity(31);
    let Ok(mut terminal) = Terminal::new(TestBackend::new(w, h));
    for _ in 0..60 {
        app.tick(1.0 / 60.0);
    }
    for _ in 0..31 {
        app.tick(1.0 / 60.0);
        let started = Instant::now();
        // TestBackend's draw writes into its buffer: it cannot fail.
        let Ok(_) = terminal.draw(|f| crate::tui::ui::draw(f, &app, ratatui::symbols::Marker::Braille));
        times.push(started.elapsed().as_secs_f64() * 1e6);
    }
    times.sort_by(f64::total_cmp);
    LabDraw { us: times.get(times.len() / 2).copied().unwrap_or(0.0), size: LAB_SIZE }
}
