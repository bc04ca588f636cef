//! The parameter editor, the optimiser panel, the status bar and the overlays.

use crate::config::schema::{Kind, PARAMS};
use crate::tui::app::{App, Overlay, PickKind};
use crate::tui::keys::{Action, HELP};
use crate::tui::text_input::TextInput;
use ratatui::prelude::*;
use ratatui::symbols::Marker;
use ratatui::widgets::{Axis, Block, Chart, Clear, Dataset, GraphType, List, ListItem, ListState, Paragraph, Wrap};

/// The parameter names' column: the longest name and a space, so that no name runs into its
/// value (checked by a test against the key table).
pub const NAME_COLUMN: usize = 26;

/// The editor: every key by group, value, unit, a `*` on changed ones; the selected key's
/// range and doc under the list.
pub fn draw_editor(f: &mut Frame, area: Rect, app: &App) {
    let inner = super::panel(f, area, Line::raw(" Parameters (enter: type, x: default) "), Some(editor_legend(app)));
    let (doc, doc_lines) = selected_doc(app, inner);
    let [list_area, doc_area] = Layout::vertical([Constraint::Min(3), Constraint::Length(doc_lines)]).areas(inner);
    // Rows are group headers (None) or keys; only the rows that fit are built, in a window
    // that keeps the selected key in view.
    let mut rows: Vec<Option<usize>> = Vec::with_capacity(PARAMS.len() + 10);
    for (i, spec) in PARAMS.iter().enumerate() {
        if i == 0 || spec.group() != PARAMS[i - 1].group() {
            rows.push(None);
        }
        rows.push(Some(i));
    }
    let selected_row = rows.iter().position(|r| *r == Some(app.selected)).unwrap_or(0);
    let height = usize::from(list_area.height).max(1);
    let first = selected_row.saturating_sub(height / 2).min(rows.len().saturating_sub(height));
    let saved = &app.saved;
    // One name column for the rows in view, as wide as the widest value on them allows.
    let value_len = |spec: &crate::config::schema::ParamSpec| {
        app.value_text(spec).chars().count() + if spec.unit.is_empty() { 0 } else { 1 + spec.unit.len() }
    };
    let widest = rows[first..(first + height).min(rows.len())].iter().flatten().map(|&i| value_len(&PARAMS[i])).max();
    let column = NAME_COLUMN.min(usize::from(list_area.width).saturating_sub(2 + widest.unwrap_or(0)));
    // Written straight into the buffer: the same cells a `List` of styled `Line`s gives, at
    // well under half the cost (the editor was the lab's most expensive panel to draw).
    let buf = f.buffer_mut();
    let end = list_area.x + list_area.width;
    for (k, row) in rows[first..(first + height).min(rows.len())].iter().enumerate() {
        let y = list_area.y + k as u16;
        let x = list_area.x;
        match row {
            None => {
                let group = PARAMS[rows[first + k + 1].unwrap_or(0)].group();
                put(buf, x, y, &format!("[{group}]"), end, Style::new().fg(Color::Yellow).bold());
            }
            Some(i) => {
                app.hits.borrow_mut().rows.push((Rect { x: list_area.x, y, width: list_area.width, height: 1 }, *i));
                let spec = &PARAMS[*i];
                let now = (spec.get)(&app.params);
                let mark = if now == (spec.get)(saved) { " " } else { "*" };
                let derived = matches!(now, crate::config::schema::Value::Auto);
                let value_style = if derived { Style::new().fg(Color::DarkGray) } else { Style::new().fg(Color::Cyan) };
                let x = put(buf, x, y, mark, end, Style::new().fg(Color::LightRed).bold());
                // The value is always shown: the name column gives way first, cut with `…`.
                let value = app.value_text(spec);
                let room = usize::from(end.saturating_sub(x)).saturating_sub(value_len(spec) + 1);
                let name = spec.name();
                // A name longer than the shared column but with room on its own row is shown
                // whole, its value a little right of the others': `rotation_range_deg` at
                // 80x24 read `rotation_range_d…` beside a short value.
                let column =
                    if name.len() + 1 > column && name.len() < room { name.len() + 1 } else { column.min(room) };
                let shown = if name.len() <= column.saturating_sub(1) || column == 0 {
                    format!("{name:<column$}")
                } else {
                    format!("{}… ", &name[..column.saturating_sub(2)])
                };
                let x = put(buf, x, y, &shown, end, Style::new());
                let x = put(buf, x, y, &value, end, value_style);
                if !spec.unit.is_empty() {
                    put(buf, x, y, &format!(" {}", spec.unit), end, Style::new());
                }
            }
        }
        if k + first == selected_row {
            buf.set_style(Rect { x: list_area.x, y, width: list_area.width, height: 1 }, Style::new().reversed());
        }
    }
    scroll_marks(buf, list_area, first > 0, first + height < rows.len());
    f.render_widget(doc, doc_area);
}

/// The editor's bottom line: what `*` and grey mean, and where in the list the selection is
/// (the list scrolls, and a newcomer saw no sign of the keys above and below the rows in view).
fn editor_legend(app: &App) -> Line<'static> {
    Line::from(vec![
        Span::styled(" * ", Style::new().fg(Color::LightRed).bold()),
        Span::raw("unsaved "),
        Span::styled("grey", Style::new().fg(Color::DarkGray)),
        Span::raw(" derived "),
        Span::styled(format!(" {}/{} ", app.selected + 1, PARAMS.len()), Style::new().fg(Color::DarkGray)),
    ])
}

/// More rows above or below the ones in view: an arrow at the list's right edge.
fn scroll_marks(buf: &mut Buffer, list: Rect, above: bool, below: bool) {
    if list.width == 0 || list.height == 0 {
        return;
    }
    let (x, end) = (list.x + list.width - 1, list.x + list.width);
    if above {
        put(buf, x, list.y, "▲", end, Style::new().fg(Color::Yellow));
    }
    if below {
        put(buf, x, list.y + list.height - 1, "▼", end, Style::new().fg(Color::Yellow));
    }
}

/// The selected key's range and description, whole: the paragraph and the lines it takes
/// wrapped at the panel's width, up to half the panel.
fn selected_doc(app: &App, inner: Rect) -> (Paragraph<'static>, u16) {
    let spec = &PARAMS[app.selected];
    let step = match spec.kind {
        Kind::Real { .. } => format!("; step {} (shift: x10)", App::fine_step(spec)),
        _ => String::new(),
    };
    let range_line = format!("{}: {}{step}", spec.key, spec.valid_range());
    let width = usize::from(inner.width.max(1));
    let wrapped = |text: &str| text.chars().count().div_ceil(width).max(1);
    let lines = (wrapped(&range_line) + wrapped(spec.doc) + 1).min(usize::from(inner.height / 2)).max(2);
    let doc = Paragraph::new(vec![Line::styled(range_line, Style::new().fg(Color::Yellow)), Line::raw(spec.doc)])
        .wrap(Wrap { trim: true });
    (doc, lines as u16)
}

/// Writes `text` from `x` on row `y`, stopping before column `end`; returns the column after
/// it. ASCII goes cell by cell: `Buffer::set_stringn` segments every string into graphemes and
/// measures each one, which made up most of the editor's drawing time.
fn put(buf: &mut Buffer, x: u16, y: u16, text: &str, end: u16, style: Style) -> u16 {
    if !text.is_ascii() {
        let (x, _) = buf.set_stringn(x, y, text, usize::from(end.saturating_sub(x)), style);
        return x;
    }
    let mut x = x;
    for b in text.bytes() {
        if x >= end {
            break;
        }
        buf[(x, y)].set_char(char::from(b)).set_style(style);
        x += 1;
    }
    x
}

/// The optimiser: recent choices as a table, and the last step's cost landscape.
pub fn draw_optimiser(f: &mut Frame, area: Rect, app: &App, marker: Marker) {
    let o = &app.params.optimiser;
    let method = if o.enabled { o.method.name() } else { "off" };
    // The landscape's x-axis name in the bottom border: ratatui draws an axis title on the
    // chart's lowest data row, where it hid the cheapest candidates.
    // The landscape is its own scan of the range, finer than most methods' candidates: a
    // reader saw cheaper reachable positions beside the one the method chose from its nine.
    let axis = app.landscape.as_ref().map(|(step, scan)| {
        let long = format!(" x: step {step}'s pelvis x (m), {} scanned ", scan.len());
        let fits = long.chars().count() + 2 <= usize::from(area.width);
        Line::raw(if fits { long } else { format!(" x: step {step}'s pelvis x (m) ") })
    });
    let inner = super::panel(f, area, Line::raw(optimiser_title(method, area.width)), axis);
    let [table_area, chart_area, key_area] =
        Layout::vertical([Constraint::Percentage(45), Constraint::Fill(1), Constraint::Length(1)]).areas(inner);
    draw_step_table(f, table_area, app);
    draw_landscape(f, chart_area, app, marker);
    let rerun_shown = app.rerun.as_ref().zip(app.landscape.as_ref()).is_some_and(|(r, (step, _))| r.step == *step);
    f.render_widget(Paragraph::new(landscape_key(key_area.width, rerun_shown)), key_area);
}

/// The optimiser panel's title for a panel `width` columns wide: the keys said in words, in
/// fewer words where the panel is narrow (at 80 columns the full title lost "method)").
fn optimiser_title(method: &str, width: u16) -> String {
    [
        format!(" Optimiser: {method} (o: re-run, m: method) "),
        format!(" Optimiser: {method} (o run, m method) "),
        format!(" Optimiser: {method} "),
    ]
    .into_iter()
    // The border's corners take two columns.
    .find(|t| t.chars().count() + 2 <= usize::from(width))
    .unwrap_or_else(|| " Optimiser ".into())
}

/// What the landscape's marks are, one line under it. ratatui's own legend box hides itself
/// where it would take more than a third of the chart — at 80 columns always — and at 160x48
/// it covered the cheapest candidates; the line is always there and covers nothing.
fn landscape_key(width: u16, rerun: bool) -> Line<'static> {
    // With a re-run on the chart its mark takes the unit's room.
    let cost = if width >= 36 && !rerun { " cost rad²/s³" } else { " cost" };
    let unreachable = if width >= 29 { " unreachable " } else { " no reach " };
    let mut spans = vec![
        Span::styled("•", Style::new().fg(Color::LightRed)),
        Span::raw(unreachable),
        Span::styled("█", Style::new().fg(Color::Yellow)),
        Span::raw(" chosen "),
    ];
    if rerun {
        spans.push(Span::styled("█", Style::new().fg(Color::LightMagenta)));
        spans.push(Span::raw(" re-run "));
    }
    spans.push(Span::styled("─", Style::new().fg(Color::Cyan)));
    spans.push(Span::raw(cost));
    Line::from(spans)
}

/// A line of the optimiser's table under its header.
enum TableLine<'a> {
    /// Words saying what the records below it are.
    Caption(String),
    Record(&'a crate::model::optimise::StepRecord),
}

/// The optimiser's last steps, a re-run on top with captions setting it apart from the walk's
/// own steps: side, ratio, cost against the fixed rule's, feasible candidates, search time.
fn draw_step_table(f: &mut Frame, table_area: Rect, app: &App) {
    let plans = app.walker.step_plans();
    let walk_steps = plans.iter().rev().map(|p| TableLine::Record(&p.optimisation));
    // The re-run is named in words: a method letter after its step number ("525t") was not
    // explained anywhere, and the step's own row below it looked like a second re-run.
    let mut lines: Vec<TableLine> = Vec::new();
    if let Some(r) = &app.rerun {
        let method = r.method.map_or(String::new(), |m| format!(" with {}", m.name()));
        lines.push(TableLine::Caption(format!("re-run{method}:")));
        lines.push(TableLine::Record(r));
        lines.push(TableLine::Caption("the walk's steps:".into()));
    }
    let room = usize::from(table_area.height.saturating_sub(1));
    lines.extend(walk_steps.take(room.saturating_sub(lines.len())));
    lines.truncate(room);
    if matches!(lines.last(), Some(TableLine::Caption(_))) {
        lines.pop();
    }
    // "none": no leg reached there, so no cost (the column is six cells wide).
    let cost = |c: Option<f64>| c.map_or("none".into(), |c| format!("{c:.0}"));
    // Written cell by cell (see `put`): the cells a `Table` with these column widths and one
    // space between columns gives. 38 cells, the 80-column panel's width: at 41 the search
    // time was dropped there without a word.
    const WIDTHS: [u16; 7] = [4, 1, 5, 6, 6, 5, 5];
    let buf = f.buffer_mut();
    let end = table_area.x + table_area.width;
    let row_at = |buf: &mut Buffer, y: u16, cells: &[String], style: Style| {
        buf.set_style(Rect { x: table_area.x, y, width: table_area.width, height: 1 }, style);
        let mut x = table_area.x;
        // A column is shown whole or not at all: a number cut at the edge reads as another
        // (at 80 columns the search time 162 us showed as 16).
        for (text, width) in cells.iter().zip(WIDTHS) {
            if x + width > end {
                break;
            }
            put(buf, x, y, text, x + width, style);
            x += width + 1;
        }
    };
    if table_area.height > 0 {
        // "rule": the fixed rule's cost ("fixed" read as a yes or no); "s": the side.
        let header = ["step", "s", "ratio", "cost", "rule", "feas", "µs"].map(String::from);
        row_at(buf, table_area.y, &header, Style::new().bold());
    }
    for (line, y) in lines.iter().zip(table_area.y + 1..) {
        let r = match line {
            TableLine::Caption(text) => {
                put(buf, table_area.x, y, text, end, Style::new().fg(Color::Yellow));
                continue;
            }
            TableLine::Record(r) => r,
        };
        let style = if r.fallback { Style::new().fg(Color::LightRed) } else { Style::new() };
        // A step whose double support is not chosen nor costed (a start's first step, whose
        // pelvis launches onto the fixed rule's key, and a stop's closing step) is no
        // unreachable one: it says so.
        let uncosted = r.method.is_none() && r.evaluations == 0 && r.chosen.cost.is_none();
        let (chosen_cost, fixed_cost) = if uncosted {
            ("fixed".to_string(), "-".to_string())
        } else {
            (cost(r.chosen.cost), cost(r.fixed_rule.cost))
        };
        let cells = [
            r.step.to_string(),
            r.side.suffix().to_string(),
            format!("{:.3}", r.chosen_ratio()),
            chosen_cost,
            fixed_cost,
            format!("{}/{}", r.feasible, r.evaluations),
            if app.show_timings { format!("{:.0}", r.elapsed_us) } else { "-".into() },
        ];
        row_at(buf, y, &cells, style);
    }
}

/// The last step's cost across its search range, the chosen position marked.
fn draw_landscape(f: &mut Frame, chart_area: Rect, app: &App, marker: Marker) {
    let plans = app.walker.step_plans();
    let Some((step, landscape)) = &app.landscape else {
        f.render_widget(Paragraph::new("no step planned yet"), chart_area);
        return;
    };
    let (lo, hi) = (landscape.first().map_or(0.0, |c| c.x), landscape.last().map_or(1.0, |c| c.x));
    let feasible: Vec<(f64, f64)> = landscape.iter().filter_map(|c| c.cost.map(|k| (c.x - lo, k))).collect();
    let unreachable_x: Vec<f64> = landscape.iter().filter(|c| c.cost.is_none()).map(|c| c.x - lo).collect();
    let chosen: Vec<(f64, f64)> = plans
        .iter()
        .rev()
        .find(|p| p.step == *step)
        .and_then(|p| p.optimisation.chosen.cost.map(|k| vec![(p.optimisation.chosen.x - lo, k)]))
        .unwrap_or_default();
    // A re-run of this step, chosen by the method it ran with.
    let rerun: Vec<(f64, f64)> = app
        .rerun
        .as_ref()
        .filter(|r| r.step == *step)
        .and_then(|r| r.chosen.cost.map(|k| vec![(r.chosen.x - lo, k)]))
        .unwrap_or_default();
    let (ymin, ymax) = feasible.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| (a.min(p.1), b.max(p.1)));
    let y = if ymin.is_finite() { [ymin * 0.95, ymax * 1.05 + 1e-9] } else { [0.0, 1.0] };
    let span = (hi - lo).max(1e-6);
    // On the top row: on the bottom one, beside the lowest cost's label, they read as the
    // cheapest positions, where an unreachable one has no cost at all.
    let unreachable: Vec<(f64, f64)> = unreachable_x.iter().map(|x| (*x, y[1])).collect();
    let chart = Chart::new(vec![
        Dataset::default()
            .name("unreachable")
            .marker(Marker::Dot)
            .graph_type(GraphType::Scatter)
            .style(Style::new().fg(Color::LightRed))
            .data(&unreachable),
        Dataset::default()
            .name("cost rad²/s³")
            .marker(marker)
            .graph_type(GraphType::Line)
            .style(Style::new().fg(Color::Cyan))
            .data(&feasible),
        Dataset::default()
            .name("chosen")
            .marker(Marker::Block)
            .graph_type(GraphType::Scatter)
            .style(Style::new().fg(Color::Yellow))
            .data(&chosen),
        Dataset::default()
            .name("re-run")
            .marker(Marker::Block)
            .graph_type(GraphType::Scatter)
            .style(Style::new().fg(Color::LightMagenta))
            .data(&rerun),
    ])
    .x_axis(Axis::default().bounds([0.0, span]).labels(["0".to_string(), format!("{span:.2}")]))
    .y_axis(Axis::default().bounds(y).labels([format!("{:.0}", y[0]), format!("{:.0}", y[1])]))
    .legend_position(None);
    f.render_widget(chart, chart_area);
}

/// One line: file and saved state, speed, frame rate, terrain, the walk's state, the last
/// message. The message is what the user just asked about, so where the line is too narrow
/// the other parts give way first — the frame rate, the terrain, the speed, then the file's
/// folders (its name stays, and the others come back beside it where they fit), then the
/// name — and only then is the message cut, with an ellipsis.
pub(crate) fn draw_status(f: &mut Frame, area: Rect, app: &App) {
    f.render_widget(Paragraph::new(status_line(app, usize::from(area.width))), area);
}

/// The status line for a terminal `width` columns wide (see [`draw_status`]).
fn status_line(app: &App, width: usize) -> Line<'static> {
    let saved = if app.is_modified() {
        Span::styled(
            format!(" modified ({}) ", app.unsaved_keys().len()),
            Style::new().fg(Color::Black).bg(Color::LightRed),
        )
    } else {
        Span::styled(" saved ", Style::new().fg(Color::Black).bg(Color::Green))
    };
    let run = if app.paused { "paused".to_string() } else { format!("x{}", app.speed()) };
    // A paused lab draws only on keys: its frame rate says nothing.
    let fps =
        if app.paused { String::new() } else { app.measured_fps.map_or(String::new(), |f| format!(" {f:.0} fps")) };
    let terrain = format!("{} ", app.value_text(crate::config::schema::spec("terrain.kind").expect("a key")));
    let state = Span::styled(format!("{} ", app.walker.walk_state().name()), Style::new().fg(Color::Cyan));
    let tail = match &app.message {
        Some(m) => Span::styled(m.clone(), Style::new().fg(Color::Yellow)),
        None => {
            // The hint follows the bindings (`[keys]` may move help and quit elsewhere).
            let first = |action| app.keymap.keys_of(action).split(' ').next().unwrap_or_default().to_string();
            let hint = format!("{} help  {} quit", first(Action::Help), first(Action::Quit));
            Span::styled(hint, Style::new().fg(Color::DarkGray))
        }
    };
    let full_label = app.file_label();
    let name = app.path.as_ref().and_then(|p| p.file_name()).map(|n| n.to_string_lossy().into_owned());
    // From the fullest line to the barest, the first that leaves the message whole: (file
    // label, with speed, with frame rate, with terrain). Widths are counted before anything
    // is built: the line is drawn every frame.
    // Display columns, as the terminal counts them (`Span::raw` borrows: nothing allocated).
    let columns = |text: &str| Span::raw(text).width();
    let label_width = |label: &str| columns(label) + 2;
    let run_width = columns(&run) + 2;
    // With the folders gone, the speed, terrain and frame rate come back where they fit.
    let levels: [(Option<&str>, bool, bool, bool); 9] = [
        (Some(&full_label), true, true, true),
        (Some(&full_label), true, false, true),
        (Some(&full_label), true, false, false),
        (Some(&full_label), false, false, false),
        (name.as_deref(), true, true, true),
        (name.as_deref(), true, false, true),
        (name.as_deref(), true, false, false),
        (name.as_deref(), false, false, false),
        (None, false, false, false),
    ];
    let level_width = |&(label, with_run, with_fps, with_terrain): &(Option<&str>, bool, bool, bool)| {
        label.map_or(0, label_width)
            + saved.width()
            + if with_run { run_width + if with_fps { columns(&fps) } else { 0 } } else { 1 }
            + if with_terrain { columns(&terrain) } else { 0 }
    };
    let fixed = state.width() + tail.width();
    let (label, with_run, with_fps, with_terrain) =
        levels.iter().find(|level| level_width(level) + fixed <= width).copied().unwrap_or(levels[levels.len() - 1]);
    let mut spans = Vec::with_capacity(6);
    if let Some(label) = label {
        spans.push(Span::styled(format!(" {label} "), Style::new().bold()));
    }
    spans.push(saved);
    spans.push(match (with_run, with_fps) {
        (true, true) => Span::raw(format!(" {run}{fps} ")),
        (true, false) => Span::raw(format!(" {run} ")),
        _ => Span::raw(" "),
    });
    if with_terrain {
        spans.push(Span::styled(terrain, Style::new().fg(Color::Green)));
    }
    spans.push(state);
    let room = width.saturating_sub(spans.iter().map(Span::width).sum::<usize>());
    if tail.width() > room && room > 0 {
        let cut: String = tail.content.chars().take(room - 1).collect();
        spans.push(Span::styled(format!("{cut}…"), tail.style));
    } else {
        spans.push(tail);
    }
    Line::from(spans)
}

/// A text field after `prefix`: the selected pre-filled text reversed, or the cursor as a
/// reversed character (an underscore at the end).
fn input_line(prefix: &str, input: &TextInput) -> Line<'static> {
    let reversed = Style::new().reversed();
    let mut spans = vec![Span::raw(prefix.to_string())];
    if input.is_selected() {
        spans.push(Span::styled(input.text().to_string(), reversed));
        spans.push(Span::raw("_"));
        return Line::from(spans);
    }
    let (before, after) = input.split_at_cursor();
    spans.push(Span::raw(before.to_string()));
    let mut rest = after.chars();
    match rest.next() {
        Some(c) => {
            spans.push(Span::styled(c.to_string(), reversed));
            spans.push(Span::raw(rest.as_str().to_string()));
        }
        None => spans.push(Span::raw("_")),
    }
    Line::from(spans)
}

fn centered(area: Rect, width: u16, height: u16) -> Rect {
    let w = width.min(area.width);
    let h = height.min(area.height);
    Rect { x: area.x + (area.width - w) / 2, y: area.y + (area.height - h) / 2, width: w, height: h }
}

/// Whatever overlay is open.
pub(crate) fn draw_overlay(f: &mut Frame, area: Rect, app: &App) {
    let Some(overlay) = &app.overlay else { return };
    let error_line =
        |error: &Option<String>| error.as_ref().map(|e| Line::styled(e.clone(), Style::new().fg(Color::LightRed)));
    match overlay {
        Overlay::Help => {
            // The keys column as wide as its widest entry, which rebinding can change.
            let keys: Vec<String> = HELP.iter().map(|(actions, _)| app.keymap.help_keys(actions)).collect();
            let column = keys.iter().map(|k| k.chars().count()).max().unwrap_or(0);
            let lines: Vec<Line> = keys
                .iter()
                .zip(HELP)
                .map(|(keys, (_, what))| {
                    Line::from(vec![
                        Span::styled(format!("{keys:<column$} "), Style::new().fg(Color::Yellow)),
                        Span::raw(*what),
                    ])
                })
                .collect();
            // All of it where it fits; else a window that up/down scroll (clamped at the end).
            let fits = area.height.saturating_sub(2).max(1);
            let total = lines.len() as u16;
            let title =
                if total > fits { " Keys (up/down: scroll, other keys close) " } else { " Keys (any key closes) " };
            let first = usize::from(app.help_scroll.min(total.saturating_sub(fits)));
            let shown: Vec<Line> = lines.into_iter().skip(first).collect();
            dialog(f, centered(area, 76, total.min(fits) + 2), title, shown, false);
        }
        Overlay::Typing { text, error } => {
            let spec = &PARAMS[app.selected];
            let mut lines = vec![
                input_line(&format!("{} = ", spec.key), text),
                Line::styled(format!("valid: {}", spec.valid_range()), Style::new().fg(Color::DarkGray)),
            ];
            lines.extend(error_line(error));
            dialog(f, centered(area, 76, 6), " Type a value (enter: set, esc: cancel) ", lines, true);
        }
        Overlay::SavePath { text, error } => {
            let mut lines = vec![input_line("", text)];
            lines.extend(error_line(error));
            dialog(f, centered(area, 70, 5), " Save as (enter: save, esc: cancel) ", lines, true);
        }
        Overlay::ConfirmQuit => {
            let lines = vec![
                Line::raw(format!("{} edited key(s) are not saved.", app.unsaved_keys().len())),
                Line::styled("s: save and quit   y: quit anyway   esc: stay", Style::new().fg(Color::Yellow)),
            ];
            dialog(f, centered(area, 52, 5), " Quit? ", lines, false);
        }
        Overlay::Recovery { found, error } => {
            let mut lines = vec![
                // Two short lines: one long first line wrapped at 80 columns left "edits,"
                // alone on the next.
                Line::raw(format!("A lab on this config was cut off {}.", found.age)),
                Line::raw(format!("Its unsaved edits are kept in {}.", found.path.display())),
                Line::styled("l: load them   d: discard them   esc: decide later", Style::new().fg(Color::Yellow)),
            ];
            lines.extend(error_line(error));
            let height = lines.len() as u16 + 4;
            dialog(f, centered(area, 76, height), " Unsaved edits found ", lines, true);
        }
        Overlay::Pick { what, items, selected } => {
            let title = match what {
                PickKind::Preset => " Preset (enter: load, esc: cancel) ",
                PickKind::Terrain => " Terrain (enter: pick, esc: cancel) ",
            };
            let list =
                List::new(items.iter().map(|i| ListItem::new(i.as_str()))).highlight_style(Style::new().reversed());
            let r = centered(area, 72, items.len() as u16 + 2);
            f.render_widget(Clear, r);
            let mut state = ListState::default().with_selected(Some(*selected));
            f.render_stateful_widget(list.block(Block::bordered().title(title)), r, &mut state);
        }
    }
}

/// A bordered box of `lines` over whatever is under `r`, wrapped at its width or not.
fn dialog(f: &mut Frame, r: Rect, title: &str, lines: Vec<Line<'_>>, wrap: bool) {
    f.render_widget(Clear, r);
    let paragraph = Paragraph::new(lines);
    let paragraph = if wrap { paragraph.wrap(Wrap { trim: true }) } else { paragraph };
    f.render_widget(paragraph.block(Block::bordered().title(title)), r);
}
