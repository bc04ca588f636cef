//! The report's plots read back from their SVGs as text boxes: no text written over other
//! text or a tick label, every axis's tick labels distinct, the stick figure at 1:1 (in both
//! its views), in every SVG of a one-walk report and of a `--compare` report.
//!
//! A text box is estimated from the SVG's `<text>`: its anchor point, font size, the anchors
//! plotters writes (`text-anchor`, and `dy` for the vertical one) and any `rotate(270, ..)`.
//!
//! Tolerance, checked against the PNGs (the embedded DejaVu Sans at the SVG's font size): a
//! character is 0.6 em wide, a little more than the ink ("4300.0" inks 57 px at 16.1 px where
//! this says 58, and 45 px at 14.5 px where it says 52), so a box errs on the large side;
//! the optimisation plot's rotated "cost" name and its tick labels are 7 px apart in the PNG
//! and 6 px by this estimate. A line is 0.75 em tall, the font's cap height (0.73 em):
//! descenders and the space above capitals are left out, so that the rows of a dense axis
//! (the log scale's 7 and 8, 25 px apart) do not count as touching where their ink is apart.
//! Two boxes overlap when they share more than 1 px each way (the SVG places text on whole
//! pixels; the PNG's edge pixels are antialiased). A box off the image by more than 1 px
//! counts too: the last "100" of a chart at the right edge was cut in half.

use std::path::{Path, PathBuf};

/// How far two boxes may share pixels, each way, and not count as overlapping.
const SLACK_PX: f64 = 1.0;
/// Width of a character, in em.
const CHAR_EM: f64 = 0.6;
/// Height of a line of text, in em.
const LINE_EM: f64 = 0.75;

/// One `<text>` as a box on the image: left, top, right, bottom in pixels.
#[derive(Clone, Debug)]
struct TextBox {
    text: String,
    x0: f64,
    y0: f64,
    x1: f64,
    y1: f64,
    /// The anchor point, before any rotation.
    at: (f64, f64),
    anchor: String,
    dy: String,
}

/// The angle and centre of `rotate(270, cx, cy)`, the one rotation plotters writes.
fn rotation(transform: &str) -> Option<(f64, f64)> {
    let inner = transform.trim().strip_prefix("rotate(")?.strip_suffix(')')?;
    let parts: Vec<f64> = inner.split(',').map(|p| p.trim().parse().ok()).collect::<Option<_>>()?;
    assert_eq!(parts.first(), Some(&270.0), "a rotation this test does not know: {transform}");
    Some((parts[1], parts[2]))
}

/// Every non-empty `<text>` of `svg` as a box.
fn text_boxes(svg: &str) -> Vec<TextBox> {
    let doc = roxmltree::Document::parse(svg).unwrap();
    doc.descendants()
        .filter(|n| n.has_tag_name("text"))
        .filter_map(|n| {
            let text = n.text()?.trim().to_string();
            if text.is_empty() {
                return None;
            }
            let num = |name: &str| n.attribute(name).and_then(|v| v.parse::<f64>().ok());
            let (x, y, size) = (num("x")?, num("y")?, num("font-size")?);
            let width = CHAR_EM * size * text.chars().count() as f64;
            let height = LINE_EM * size;
            let anchor = n.attribute("text-anchor").unwrap_or("start").to_string();
            let dy = n.attribute("dy").unwrap_or("0").to_string();
            let left = match anchor.as_str() {
                "middle" => x - width / 2.0,
                "end" => x - width,
                _ => x,
            };
            // plotters' vertical anchors: 0.76em puts the top at y, 0.5ex the middle, -0.5ex
            // the bottom (an unknown one fails the test rather than guess).
            let top = match dy.as_str() {
                "0.76em" => y,
                "0.5ex" => y - height / 2.0,
                "-0.5ex" => y - height,
                other => panic!("`{text}`: a vertical anchor this test does not know: dy={other}"),
            };
            let (mut x0, mut y0, mut x1, mut y1) = (left, top, left + width, top + height);
            if let Some((cx, cy)) = n.attribute("transform").and_then(rotation) {
                // Rotated by 270 degrees about (cx, cy): (dx, dy) goes to (dy, -dx).
                (x0, y0, x1, y1) = (cx + (y0 - cy), cy - (x1 - cx), cx + (y1 - cy), cy - (x0 - cx));
            }
            Some(TextBox { text, x0, y0, x1, y1, at: (x, y), anchor, dy })
        })
        .collect()
}

/// The pixels two boxes share each way.
fn shared(a: &TextBox, b: &TextBox) -> (f64, f64) {
    (a.x1.min(b.x1) - a.x0.max(b.x0), a.y1.min(b.y1) - a.y0.max(b.y0))
}

/// Every pair of boxes sharing more than [`SLACK_PX`] each way, and every box not wholly on
/// the image.
fn collisions(boxes: &[TextBox], size: (f64, f64)) -> Vec<String> {
    let mut found = Vec::new();
    for (i, a) in boxes.iter().enumerate() {
        if a.x0 < -SLACK_PX || a.y0 < -SLACK_PX || a.x1 > size.0 + SLACK_PX || a.y1 > size.1 + SLACK_PX {
            found.push(format!("`{}` runs off the image: {a:?}", a.text));
        }
        for b in &boxes[i + 1..] {
            let (w, h) = shared(a, b);
            if w > SLACK_PX && h > SLACK_PX {
                found.push(format!("`{}` and `{}` overlap by {w:.1} x {h:.1} px", a.text, b.text));
            }
        }
    }
    found
}

/// A tick label: its place along its axis (px), its value, its text.
type Tick = (f64, f64, String);

/// Tick labels, axis by axis: numbers right-aligned and centred on their tick (a y axis) in
/// columns of one x, numbers centred under their tick (an x axis) in rows of one y. A column
/// or row holds the axes of charts side by side or stacked; it is cut where the value falls
/// (the next chart starts again low) or the gap to the next label is more than twice the
/// last one (the space between charts), so that a repeated label stays in its axis.
fn tick_axes(boxes: &[TextBox]) -> Vec<Vec<String>> {
    let numeric = |b: &&TextBox| b.text.parse::<f64>().is_ok();
    let mut lines: std::collections::BTreeMap<(bool, i64), Vec<Tick>> = Default::default();
    for b in boxes.iter().filter(numeric) {
        let value: f64 = b.text.parse().unwrap();
        let line = match (b.anchor.as_str(), b.dy.as_str()) {
            // Upwards is along a y axis, so its position is -y.
            ("end", "0.5ex") => (false, b.at.0.round() as i64, -b.at.1),
            ("middle", "0.76em") => (true, b.at.1.round() as i64, b.at.0),
            _ => continue,
        };
        lines.entry((line.0, line.1)).or_default().push((line.2, value, b.text.clone()));
    }
    let mut axes = Vec::new();
    for mut labels in lines.into_values() {
        labels.sort_by(|a, b| a.0.total_cmp(&b.0));
        let mut axis: Vec<Tick> = Vec::new();
        for label in labels {
            let cut = match axis.as_slice() {
                [.., before, last] => label.1 < last.1 || label.0 - last.0 > 2.0 * (last.0 - before.0),
                [last] => label.1 < last.1,
                [] => false,
            };
            if cut {
                axes.push(axis.drain(..).map(|(_, _, t)| t).collect());
            }
            axis.push(label);
        }
        axes.push(axis.into_iter().map(|(_, _, t)| t).collect());
    }
    axes
}

/// Axes whose tick labels repeat, or that hold a single label.
fn repeated_ticks(boxes: &[TextBox]) -> Vec<String> {
    let mut found = Vec::new();
    for axis in tick_axes(boxes) {
        let texts: Vec<&str> = axis.iter().map(String::as_str).collect();
        let mut distinct = texts.clone();
        distinct.dedup();
        if texts.len() < 2 || distinct.len() != texts.len() {
            found.push(format!("tick labels {texts:?}"));
        }
    }
    found
}

/// Pixels per unit of the stick figure's x and y axes in each of its views (the side view
/// in the top half, the frontal view in the bottom half), from the first and last tick
/// label of each (the x labels along the bottom, the y labels down the left).
fn stick_figure_scales(boxes: &[TextBox]) -> Vec<(f64, f64)> {
    [true, false]
        .into_iter()
        .map(|upper| {
            let half: Vec<TextBox> = boxes.iter().filter(|b| (b.at.1 < 500.0) == upper).cloned().collect();
            let axes = tick_axes(&half);
            assert_eq!(axes.len(), 2, "each view of the stick figure has one x and one y axis: {axes:?}");
            let scale = |horizontal: bool| {
                let axis = half
                    .iter()
                    .filter(|b| b.text.parse::<f64>().is_ok() && (b.anchor == "middle") == horizontal)
                    .map(|b| (if horizontal { b.at.0 } else { b.at.1 }, b.text.parse::<f64>().unwrap()))
                    .collect::<Vec<_>>();
                let (lo, hi) = axis.iter().fold((axis[0], axis[0]), |(lo, hi), p| {
                    (if p.1 < lo.1 { *p } else { lo }, if p.1 > hi.1 { *p } else { hi })
                });
                ((hi.0 - lo.0) / (hi.1 - lo.1)).abs()
            };
            (scale(true), scale(false))
        })
        .collect()
}

fn report(dir: &Path, extra: &[&str]) -> Vec<(String, String)> {
    let mut args = vec!["report", "configs/default.toml", "--cycles", "4", "--out", dir.to_str().unwrap()];
    args.extend(extra);
    let o = std::process::Command::new(env!("CARGO_BIN_EXE_gaitlab"))
        .args(&args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let mut svgs: Vec<(String, String)> = std::fs::read_dir(dir.join("plots"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "svg"))
        .map(|p| (p.file_name().unwrap().to_string_lossy().into_owned(), std::fs::read_to_string(&p).unwrap()))
        .collect();
    svgs.sort();
    svgs
}

fn temp(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("gaitlab-plot-text-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    dir
}

#[test]
fn no_text_overlaps_other_text_and_every_axis_reads_distinct_ticks() {
    let (one, two) = (temp("one"), temp("compare"));
    let reports = [(report(&one, &[]), "default"), (report(&two, &["--compare", "configs/elderly.toml"]), "compare")];
    let mut problems = Vec::new();
    for (svgs, name) in &reports {
        assert!(svgs.len() >= 7, "{name}: {} SVGs", svgs.len());
        for (file, svg) in svgs {
            let boxes = text_boxes(svg);
            let doc = roxmltree::Document::parse(svg).unwrap();
            let root = doc.root_element();
            let size = |a: &str| root.attribute(a).and_then(|v| v.parse::<f64>().ok()).unwrap();
            let found = collisions(&boxes, (size("width"), size("height")));
            problems.extend(found.into_iter().chain(repeated_ticks(&boxes)).map(|p| format!("{name} {file}: {p}")));
            if file == "stick_figure.svg" {
                for (sx, sy) in stick_figure_scales(&boxes) {
                    if (sx / sy - 1.0).abs() >= 0.03 {
                        problems.push(format!("{name} {file}: x {sx:.1} px/m, y {sy:.1} px/m"));
                    }
                }
            }
        }
    }
    assert!(problems.is_empty(), "{}", problems.join("\n"));
    std::fs::remove_dir_all(one).unwrap();
    std::fs::remove_dir_all(two).unwrap();
}

/// The estimate can fail: text over text, a label over a tick label, a repeated tick and a
/// label off the edge are found; tick labels side by side with a gap, and a rotated axis
/// name beside its tick labels, are not.
#[test]
fn the_text_box_estimate_finds_overlaps_and_passes_neighbours() {
    let text = |x: u32, y: u32, anchor: &str, dy: &str, size: f64, body: &str| {
        format!(r#"<text x="{x}" y="{y}" dy="{dy}" text-anchor="{anchor}" font-size="{size}">{body}</text>"#)
    };
    let svg = |texts: &[String]| {
        format!(r#"<svg width="400" height="300" xmlns="http://www.w3.org/2000/svg">{}</svg>"#, texts.concat())
    };
    // x ticks 36 px apart at 16 px (the pelvis plot's are 41): "90" and "100" 12 px apart.
    let ticks: Vec<String> =
        (0..=10).map(|i| text(20 + 36 * i, 250, "middle", "0.76em", 16.0, &(10 * i).to_string())).collect();
    let clean = text_boxes(&svg(&ticks));
    assert!(collisions(&clean, (400.0, 300.0)).is_empty(), "{:?}", collisions(&clean, (400.0, 300.0)));
    assert!(repeated_ticks(&clean).is_empty());
    // A y axis at 25 px steps (the log scale's top rows) and its name, rotated, beside it.
    let mut column: Vec<String> =
        (1..=8).map(|i| text(60, 280 - 25 * i, "end", "0.5ex", 16.0, &i.to_string())).collect();
    column.push(r#"<text x="12" y="150" dy="0.76em" text-anchor="middle" font-size="19.4" transform="rotate(270, 12, 150)">iterations</text>"#.into());
    let clean = text_boxes(&svg(&column));
    assert!(collisions(&clean, (400.0, 300.0)).is_empty(), "{:?}", collisions(&clean, (400.0, 300.0)));
    // A legend entry written over an event name, and the axis name over wide tick labels.
    let over = text_boxes(&svg(&[
        text(200, 100, "start", "0.5ex", 16.0, "elderly"),
        text(230, 96, "start", "0.76em", 13.0, "LTO"),
    ]));
    assert_eq!(collisions(&over, (400.0, 300.0)).len(), 1);
    let mut crowded = column.clone();
    crowded.push(text(60, 142, "end", "0.5ex", 16.0, "4300.0"));
    assert_eq!(collisions(&text_boxes(&svg(&crowded)), (400.0, 300.0)).len(), 1);
    // Repeated ticks (one exact IK solver: 0.001 five times) and a title off the top.
    let repeated: Vec<String> = (0..5).map(|i| text(60, 250 - 40 * i, "end", "0.5ex", 16.0, "0.001")).collect();
    assert_eq!(repeated_ticks(&text_boxes(&svg(&repeated))).len(), 1);
    let off = text_boxes(&svg(&[text(200, 5, "middle", "-0.5ex", 27.0, "Title")]));
    assert_eq!(collisions(&off, (400.0, 300.0)).len(), 1);
}

/// `gaitlab figures`' SVGs pass the same checks: no text over text or off the image, every
/// axis's tick labels distinct.
#[test]
fn the_thesis_figures_read_cleanly() {
    let dir = temp("figures");
    let o = std::process::Command::new(env!("CARGO_BIN_EXE_gaitlab"))
        .args(["figures", "--out", dir.to_str().unwrap()])
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let mut problems = Vec::new();
    let mut count = 0;
    for path in std::fs::read_dir(&dir).unwrap().map(|e| e.unwrap().path()) {
        if path.extension().is_none_or(|e| e != "svg") {
            continue;
        }
        count += 1;
        let svg = std::fs::read_to_string(&path).unwrap();
        let boxes = text_boxes(&svg);
        let file = path.file_name().unwrap().to_string_lossy().into_owned();
        let found = collisions(&boxes, (1600.0, 1000.0));
        problems.extend(found.into_iter().chain(repeated_ticks(&boxes)).map(|p| format!("{file}: {p}")));
    }
    assert_eq!(count, 5);
    assert!(problems.is_empty(), "{}", problems.join("\n"));
    std::fs::remove_dir_all(dir).unwrap();
}
