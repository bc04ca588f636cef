//! The lab's joint panel against measured adults: `n` draws the normative mean ± 1 SD behind
//! the walk's joint traces (issue 12, point 3), at every size the panel appears at.

mod lab_state;

use gaitlab::tui::app::{App, Overlay, Panel};
use gaitlab::tui::keys::Action;
use gaitlab::tui::ui;
use gaitlab::tui::ui::curves::{NORMS_BAND, NORMS_SOURCE};
use lab_state::load_app;
use ratatui::Terminal;
use ratatui::backend::TestBackend;
use ratatui::buffer::Buffer;
use ratatui::crossterm::event::{KeyCode, KeyEvent, KeyModifiers};
use ratatui::layout::Rect;
use ratatui::style::Color;
use ratatui::symbols::Marker;
use std::path::Path;

fn render(app: &App, width: u16, height: u16) -> Buffer {
    let mut terminal = Terminal::new(TestBackend::new(width, height)).unwrap();
    terminal.draw(|f| ui::draw(f, app, Marker::Braille)).unwrap();
    terminal.backend().buffer().clone()
}

fn text(buffer: &Buffer) -> String {
    let area = buffer.area;
    (0..area.height)
        .map(|y| {
            (0..area.width).map(|x| buffer[(x, y)].symbol().to_string()).collect::<String>().trim_end().to_string()
        })
        .collect::<Vec<_>>()
        .join("\n")
}

fn key(app: &mut App, c: char) {
    gaitlab::tui::effects::step(app, gaitlab::tui::app::Msg::Key(KeyEvent::new(KeyCode::Char(c), KeyModifiers::NONE)));
}

/// The default walk, three cycles in (the traces hold about four seconds).
fn walked(config: Option<&Path>) -> App {
    let mut app = load_app(config, &[]).unwrap();
    for _ in 0..240 {
        app.tick(1.0 / 60.0);
    }
    app
}

/// The joint panel's box on screen, found by its title's corner.
fn joint_panel(buffer: &Buffer) -> Rect {
    let area = buffer.area;
    let screen = text(buffer);
    let (y, line) = screen.lines().enumerate().find(|(_, l)| l.contains("┌ Joint angles")).expect("the joint panel");
    let x = line[..line.find("┌ Joint angles").unwrap()].chars().count() as u16;
    let y = y as u16;
    let right = (x + 1..area.width).find(|&c| buffer[(c, y)].symbol() == "┐").expect("its top right corner");
    let bottom = (y + 1..area.height).find(|&r| buffer[(x, r)].symbol() == "└").expect("its bottom left corner");
    Rect { x, y, width: right - x + 1, height: bottom - y + 1 }
}

/// The cells drawn in the band's colour: behind a line, or filling a cell or half of it.
fn band_cells(buffer: &Buffer) -> Vec<(u16, u16)> {
    let area = buffer.area;
    let in_band = |p: (u16, u16)| {
        let cell = &buffer[p];
        cell.bg == NORMS_BAND || (cell.fg == NORMS_BAND && ["▀", "▄"].contains(&cell.symbol()))
    };
    (0..area.height).flat_map(|y| (0..area.width).map(move |x| (x, y))).filter(|&p| in_band(p)).collect()
}

/// Of the cells a leg's line is drawn in (its colour in front), the share with the band
/// behind them.
fn share_in_band(buffer: &Buffer, panel: Rect, colour: Color) -> f64 {
    let cells: Vec<(u16, u16)> = (panel.y + 1..panel.bottom() - 1)
        .flat_map(|y| (panel.x + 1..panel.right() - 1).map(move |x| (x, y)))
        .filter(|&p| {
            buffer[p].fg == colour && buffer[p].symbol().chars().all(|c| ('\u{2801}'..='\u{28ff}').contains(&c))
        })
        .collect();
    assert!(cells.len() > 20, "the leg's line is drawn: {} cells", cells.len());
    cells.iter().filter(|&&p| buffer[p].bg == NORMS_BAND).count() as f64 / cells.len() as f64
}

#[test]
fn n_draws_the_norms_band_behind_the_joint_traces_at_every_size_and_n_again_hides_it() {
    for (width, height) in [(160, 48), (100, 30), (80, 24), (60, 20)] {
        let mut app = walked(None);
        assert!(!app.norms, "off at start");
        key(&mut app, 'n');
        assert!(app.norms);
        assert_eq!(app.panel, Panel::Joints, "on a small screen n shows the joint panel");
        let on = render(&app, width, height);
        let shown = text(&on);
        let panel = joint_panel(&on);
        let band = band_cells(&on);
        // Three traces, with band cells in most columns of each.
        let columns = usize::from(panel.width - 2);
        assert!(band.len() > 2 * columns, "{width}x{height}: {} band cells:\n{shown}", band.len());
        // Inside the panel, but for the legend's swatch in its bottom border.
        let (swatch, inside): (Vec<_>, Vec<_>) = band.into_iter().partition(|(_, y)| *y == panel.bottom() - 1);
        assert_eq!(swatch.len(), 2, "{width}x{height}: the legend's swatch");
        for (x, y) in &inside {
            assert!(
                (panel.x + 1..panel.right() - 1).contains(x) && (panel.y + 1..panel.bottom() - 1).contains(y),
                "{width}x{height}: a band cell at ({x}, {y}) outside the joint panel {panel:?}"
            );
        }
        // The source is named in the panel's bottom line.
        let bottom: String =
            shown.lines().nth(usize::from(panel.bottom() - 1)).unwrap().chars().skip(usize::from(panel.x)).collect();
        assert!(bottom.contains(NORMS_SOURCE), "{width}x{height}: {bottom}");
        // Behind the walk's lines, which keep their colours: the right leg's trace is read
        // against the band of its own cycle, so it sits in the band more than the left leg's
        // does (half a cycle out).
        let (right, left) = (share_in_band(&on, panel, Color::LightRed), share_in_band(&on, panel, Color::LightBlue));
        // (0.35 and 0.18 at 60x20 today: at four or five rows a trace, the band is a row or
        // two.)
        assert!(right > 0.3 && right > left + 0.15, "{width}x{height}: right {right:.2}, left {left:.2}:\n{shown}");

        key(&mut app, 'n');
        assert!(!app.norms);
        let off = render(&app, width, height);
        assert!(band_cells(&off).is_empty(), "{width}x{height}: n again hides the band");
        assert!(!text(&off).contains(NORMS_SOURCE) && text(&off).contains("n: norms"), "{}", text(&off));
    }
}

#[test]
fn the_band_names_the_walks_speed_where_the_panel_has_room() {
    let mut app = walked(None);
    key(&mut app, 'n');
    let wide = text(&render(&app, 160, 48));
    assert!(wide.contains("band: right leg, adults at 1.30 m/s"), "{wide}");
    let narrow = text(&render(&app, 80, 24));
    assert!(narrow.contains("adults 1.30 m/s"), "{narrow}");
    // `+` asks 1.4 m/s, reached over two steps: the band follows the pace the walk reaches
    // (the norms are read again when it changes, not every frame).
    key(&mut app, '+');
    for _ in 0..150 {
        app.tick(1.0 / 60.0);
    }
    let wide = text(&render(&app, 160, 48));
    assert!(wide.contains("band: right leg, adults at 1.40 m/s"), "{wide}");
}

#[test]
fn a_keys_table_rebinds_the_norms_band_and_the_help_and_hint_follow() {
    let dir = std::env::temp_dir().join(format!("gaitlab-norms-keys-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("norms.toml");
    std::fs::write(&path, "[keys]\ntoggle_norms = \"N\"\n").unwrap();
    let mut app = walked(Some(&path));
    assert_eq!(app.keymap.keys_of(Action::ToggleNorms), "N");
    key(&mut app, 'n');
    assert!(!app.norms, "n is no longer bound");
    assert!(text(&render(&app, 160, 48)).contains("N: norms"), "the panel's hint names the bound key");
    key(&mut app, 'N');
    assert!(app.norms);
    assert!(!band_cells(&render(&app, 160, 48)).is_empty());
    key(&mut app, '?');
    assert_eq!(app.overlay, Some(Overlay::Help));
    let help = text(&render(&app, 80, 24));
    assert!(help.contains("g / N") && help.contains("adult norms band on the joints"), "{help}");
    let _ = std::fs::remove_dir_all(&dir);
}
