//! The report's plots read back from their SVGs: axes a paper can use.

use std::path::Path;

fn report(dir: &Path) {
    report_of(dir, &["configs/default.toml", "--cycles", "4"]);
}

/// `gaitlab report ARGS --out DIR`, which must succeed.
fn report_of(dir: &Path, args: &[&str]) {
    let o = std::process::Command::new(env!("CARGO_BIN_EXE_gaitlab"))
        .arg("report")
        .args(args)
        .args(["--out", dir.to_str().unwrap()])
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
}

/// Numeric text labels of an SVG with their positions: (x, y, value).
fn numeric_labels(svg: &str) -> Vec<(f64, f64, f64, String)> {
    let doc = roxmltree::Document::parse(svg).unwrap();
    doc.descendants()
        .filter(|n| n.has_tag_name("text"))
        .filter_map(|n| {
            let text = n.text()?.trim().to_string();
            let value: f64 = text.parse().ok()?;
            let x: f64 = n.attribute("x")?.parse().ok()?;
            let y: f64 = n.attribute("y")?.parse().ok()?;
            Some((x, y, value, text))
        })
        .collect()
}

#[test]
fn the_stick_figure_is_drawn_at_one_metre_per_metre_and_steps_are_whole_numbers() {
    let dir = std::env::temp_dir().join(format!("gaitlab-plots-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    report(&dir);
    // Stick figure: in each view (side above, frontal below), pixels per metre from the x
    // tick labels (under the chart) and the y tick labels (left), equal within 3 %.
    let svg = std::fs::read_to_string(dir.join("plots/stick_figure.svg")).unwrap();
    let labels = numeric_labels(&svg);
    for (top, bottom) in [(0.0, 500.0), (500.0, 1000.0)] {
        // The x tick labels sit in the panel's bottom 60 px, under the plotting area; the y
        // tick labels left of it, above them (the first x label is left of x 100 too).
        let in_panel = |l: &&(f64, f64, f64, String)| l.1 >= top && l.1 < bottom;
        let x_row = |l: &&(f64, f64, f64, String)| l.1 > bottom - 60.0;
        let mut x_ticks: Vec<(f64, f64)> = labels.iter().filter(in_panel).filter(x_row).map(|l| (l.0, l.2)).collect();
        let mut y_ticks: Vec<(f64, f64)> =
            labels.iter().filter(in_panel).filter(|l| !x_row(l) && l.0 < 100.0).map(|l| (l.1, l.2)).collect();
        x_ticks.sort_by(|a, b| a.0.total_cmp(&b.0));
        y_ticks.sort_by(|a, b| b.0.total_cmp(&a.0));
        assert!(x_ticks.len() >= 2 && y_ticks.len() >= 2, "panel from y {top}: {x_ticks:?} {y_ticks:?}");
        let per_m = |t: &[(f64, f64)]| ((t[t.len() - 1].0 - t[0].0) / (t[t.len() - 1].1 - t[0].1)).abs();
        let (sx, sy) = (per_m(&x_ticks), per_m(&y_ticks));
        assert!((sx / sy - 1.0).abs() < 0.03, "panel from y {top}: x {sx:.1} px/m, y {sy:.1} px/m");
    }
    // Optimisation: the step axes read 0, 2, 4 …, every label distinct.
    let svg = std::fs::read_to_string(dir.join("plots/optimisation.svg")).unwrap();
    let doc = roxmltree::Document::parse(&svg).unwrap();
    let texts: Vec<String> = doc
        .descendants()
        .filter(|n| n.has_tag_name("text"))
        .filter_map(|n| n.text())
        .map(|t| t.trim().to_string())
        .collect();
    assert!(texts.iter().any(|t| t == "step"), "the step axis is labelled");
    assert!(!texts.iter().any(|t| t == "2.0" || t == "4.0"), "steps are whole numbers: {texts:?}");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn the_ik_plot_has_distinct_ticks_and_says_exact_for_an_exact_solver() {
    let dir = std::env::temp_dir().join(format!("gaitlab-plots-ik-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    report(&dir);
    let svg = std::fs::read_to_string(dir.join("plots/ik.svg")).unwrap();
    // The default walk's solver is the analytic one alone: its error is zero to rounding.
    assert!(svg.contains("exact (every solve within 1 nm)"), "the caption says the solver is exact");
    let labels = numeric_labels(&svg);
    // The error axis's labels (left, upper half): no tick label repeated.
    let mut error_ticks: Vec<String> =
        labels.iter().filter(|l| l.0 < 120.0 && l.1 < 480.0).map(|l| l.3.clone()).collect();
    let count = error_ticks.len();
    error_ticks.sort();
    error_ticks.dedup();
    assert!(
        count >= 3 && error_ticks.len() == count,
        "repeated tick labels: {count} labels, {} distinct",
        error_ticks.len()
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn cycle_charts_keep_their_last_label_inside_and_no_legend_covers_a_lone_curve() {
    let dir = std::env::temp_dir().join(format!("gaitlab-plots-cycle-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    report(&dir);
    for plot in ["pelvis", "joints"] {
        let svg = std::fs::read_to_string(dir.join(format!("plots/{plot}.svg"))).unwrap();
        let hundreds: Vec<f64> = numeric_labels(&svg).iter().filter(|l| l.3 == "100").map(|l| l.0).collect();
        assert!(!hundreds.is_empty());
        // Centred text of three digits at 20 px: about 17 px each side of x.
        assert!(hundreds.iter().all(|x| x + 20.0 <= 1600.0), "{plot}: a '100' runs off the image at x {hundreds:?}");
    }
    // One walk: the pelvis curves carry no legend box over them (the walk's name is the
    // report's own); the joints plot keeps its right / left legend, above the data.
    let pelvis = std::fs::read_to_string(dir.join("plots/pelvis.svg")).unwrap();
    let doc = roxmltree::Document::parse(&pelvis).unwrap();
    assert!(!doc.descendants().any(|n| n.has_tag_name("text") && n.text().is_some_and(|t| t.trim() == "default")));
    // The vertical panel's grey band is people's measured range at the walk's speed, named
    // with its height (data/normative/pelvis_vertical_by_speed.csv read at 1.30 m/s).
    let people = gaitlab::normative::PelvisNorms::built_in().at(1.3).vertical_range_cm.0;
    let name = format!("adults' range, {people:.1} cm at 1.30 m/s");
    assert!(doc.descendants().filter_map(|n| n.text()).any(|t| t.trim() == name), "no '{name}' in pelvis.svg");
    assert!(doc.descendants().filter_map(|n| n.text()).any(|t| t.trim() == "centred on the walk's mean (WBDS)"));
    std::fs::remove_dir_all(&dir).unwrap();
    // A walk faster than every measured block is shown the fastest block's range, and the
    // legend names that block's speed, not the walk's (it read "4.5 cm at 1.75 m/s").
    report_of(&dir, &["configs/brisk.toml", "--cycles", "4"]);
    let pelvis = std::fs::read_to_string(dir.join("plots/pelvis.svg")).unwrap();
    let doc = roxmltree::Document::parse(&pelvis).unwrap();
    let people = gaitlab::normative::PelvisNorms::built_in().at(1.75).vertical_range_cm.0;
    let name = format!("adults' range, {people:.1} cm at 1.57 m/s");
    assert!(doc.descendants().filter_map(|n| n.text()).any(|t| t.trim() == name), "no '{name}' in pelvis.svg");
    assert!(doc.descendants().filter_map(|n| n.text()).any(|t| t.trim() == "(the fastest measured)"));
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn the_joint_plot_draws_measured_adult_gait_behind_the_walk() {
    let dir = std::env::temp_dir().join(format!("gaitlab-plots-norm-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    report(&dir);
    let svg = std::fs::read_to_string(dir.join("plots/joints.svg")).unwrap();
    let doc = roxmltree::Document::parse(&svg).unwrap();
    let legends = doc
        .descendants()
        .filter(|n| n.has_tag_name("text") && n.text().is_some_and(|t| t.contains("Fukuchi 2018")))
        .count();
    assert_eq!(legends, 3, "the normative band is named in the hip, knee and ankle charts");
    let texts: Vec<&str> = doc.descendants().filter_map(|n| n.text()).collect();
    assert!(texts.iter().all(|t| !t.contains("level ground")), "a level walk's band needs no ground named");
    // The event lines' letters are explained under the charts.
    assert!(doc.descendants().filter_map(|n| n.text()).any(|t| t.contains("LTO left toe-off, LHS left heel strike")));
    // Over 4 cycles (2 measured) the legs differ by 0.5 deg or more somewhere: plain "left".
    assert!(doc.descendants().filter_map(|n| n.text()).all(|t| !t.contains("under right")));
    assert!(doc.descendants().any(|n| n.text().is_some_and(|t| t.trim() == "left")));
    std::fs::remove_dir_all(&dir).unwrap();
    // Over the default 10 cycles the left leg lies under the right (within 0.2-0.5 deg, the label
    // rounding a difference under its 0.5 deg threshold to one decimal): each
    // chart's legend says so and by how much, so the left curve does not look missing.
    report_of(&dir, &["configs/default.toml"]);
    let svg = std::fs::read_to_string(dir.join("plots/joints.svg")).unwrap();
    let doc = roxmltree::Document::parse(&svg).unwrap();
    let under: Vec<f64> = doc
        .descendants()
        .filter(|n| n.has_tag_name("text"))
        .filter_map(|n| n.text().and_then(|t| t.trim().strip_prefix("left (under right, within ")))
        .filter_map(|t| t.strip_suffix(" deg)")?.parse().ok())
        .collect();
    assert!(under.len() == 3 && under.iter().all(|d| (0.0..=0.5).contains(d)), "{under:?}");
    std::fs::remove_dir_all(&dir).unwrap();
}

/// Off level ground the bands are still level walkers': each legend says so (a stairs walk's
/// knee against a band named only "adults at 0.80 m/s" read as a 40° error).
#[test]
fn the_bands_of_a_walk_off_level_ground_say_the_adults_walked_on_level_ground() {
    let dir = std::env::temp_dir().join(format!("gaitlab-plots-stairs-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    report_of(&dir, &["configs/stairs_up.toml", "--cycles", "6"]);
    for (plot, bands) in [("joints", 3), ("pelvis", 4)] {
        let svg = std::fs::read_to_string(dir.join(format!("plots/{plot}.svg"))).unwrap();
        let doc = roxmltree::Document::parse(&svg).unwrap();
        let named = doc
            .descendants()
            .filter(|n| n.has_tag_name("text"))
            .filter_map(|n| n.text())
            .filter(|t| t.trim() == "walking on level ground")
            .count();
        assert_eq!(named, bands, "{plot}: every band names the level ground");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

/// The pelvis plot draws measured adults' mean +- 1 SD (grey) behind the walk's tilt,
/// obliquity and rotation, their measured vertical range (a band that tall about the walk's
/// mean height) behind its vertical displacement, and no band under the lateral displacement
/// and velocity (no reference has them); the tilt band is a shape about the walk's mean, and
/// the legend says so.
#[test]
fn the_pelvis_plot_draws_measured_adult_gait_behind_the_angles() {
    let dir = std::env::temp_dir().join(format!("gaitlab-plots-pelvis-norm-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    report(&dir);
    let svg = std::fs::read_to_string(dir.join("plots/pelvis.svg")).unwrap();
    let doc = roxmltree::Document::parse(&svg).unwrap();
    let shapes: Vec<roxmltree::Node<'_, '_>> =
        doc.descendants().filter(|n| n.has_tag_name("polygon") || n.has_tag_name("polyline")).collect();
    let grey = |n: &roxmltree::Node<'_, '_>| n.attribute("fill") == Some("#787878");
    let bands: Vec<usize> = shapes.iter().enumerate().filter(|(_, n)| grey(n)).map(|(i, _)| i).collect();
    assert_eq!(bands.len(), 4, "a grey band in the tilt, obliquity, rotation and vertical panels");
    // The panel of a shape (column, row), from its points; the walk (red, band and line)
    // comes after the grey band of its panel, so it is drawn over it.
    let panel = |n: &roxmltree::Node<'_, '_>| {
        let points: Vec<(f64, f64)> = n
            .attribute("points")
            .unwrap()
            .split_whitespace()
            .map(|p| p.split_once(',').map(|(x, y)| (x.parse().unwrap(), y.parse().unwrap())).unwrap())
            .collect();
        let cell = |(x, y): (f64, f64)| ((x / (1600.0 / 3.0)) as u32, u32::from(y > 500.0));
        let first = cell(points[0]);
        assert!(points.iter().all(|p| cell(*p) == first), "a shape across panels");
        first
    };
    let red = |n: &roxmltree::Node<'_, '_>| {
        n.attribute("fill") == Some("#C82828") || n.attribute("stroke") == Some("#C82828")
    };
    let mut panels: Vec<(u32, u32)> = bands.iter().map(|&i| panel(&shapes[i])).collect();
    for (&i, at) in bands.iter().zip(&panels) {
        let walk: Vec<usize> = (0..shapes.len()).filter(|&k| red(&shapes[k]) && panel(&shapes[k]) == *at).collect();
        assert!(!walk.is_empty() && walk.iter().all(|&k| k > i), "panel {at:?}: the walk is drawn under the band");
    }
    panels.sort_unstable();
    assert_eq!(panels, [(0, 0), (0, 1), (1, 0), (2, 0)], "bands in the angles' panels and the vertical's");
    let texts: Vec<&str> = doc.descendants().filter(|n| n.has_tag_name("text")).filter_map(|n| n.text()).collect();
    assert_eq!(
        texts.iter().filter(|t| t.contains("Fukuchi 2018")).count(),
        3,
        "the source named in each band's legend"
    );
    assert_eq!(texts.iter().filter(|t| t.contains("about the walk's mean")).count(), 1, "the tilt band is a shape");
    std::fs::remove_dir_all(&dir).unwrap();
}

/// A pixel box: left, top, right, bottom.
type PxBox = (f64, f64, f64, f64);
/// A text and its anchor (px).
type Label = (String, f64, f64);

/// The points of a `<polyline>`, or the extremes of a `<circle>`.
fn shape_points(n: &roxmltree::Node<'_, '_>) -> Vec<(f64, f64)> {
    let num = |a: &str| n.attribute(a).unwrap().parse::<f64>().unwrap();
    if n.has_tag_name("circle") {
        let (x, y, r) = (num("cx"), num("cy"), num("r"));
        return vec![(x - r, y - r), (x + r, y + r)];
    }
    n.attribute("points")
        .unwrap()
        .split_whitespace()
        .map(|p| p.split_once(',').map(|(x, y)| (x.parse().unwrap(), y.parse().unwrap())).unwrap())
        .collect()
}

fn bounds(points: &[(f64, f64)]) -> PxBox {
    points.iter().fold((f64::INFINITY, f64::INFINITY, f64::NEG_INFINITY, f64::NEG_INFINITY), |b, p| {
        (b.0.min(p.0), b.1.min(p.1), b.2.max(p.0), b.3.max(p.1))
    })
}

/// One panel of the stick-figure SVG (rows `top..bottom`): each figure's box, inferred by
/// slot (a stick figure is connected, so its shapes' x extents chain into one interval:
/// figures apart give one interval each, overlapping figures merge), the ground pieces'
/// boxes, and the labels (text, x, y).
fn stick_panel(svg: &str, top: f64, bottom: f64) -> (Vec<PxBox>, Vec<PxBox>, Vec<Label>) {
    let doc = roxmltree::Document::parse(svg).unwrap();
    let in_panel = |b: &PxBox| b.1 >= top && b.3 < bottom;
    let body = ["#141414", "#C82828", "#1E50C8"];
    let mut shapes: Vec<PxBox> = doc
        .descendants()
        .filter(|n| n.has_tag_name("polyline") || n.has_tag_name("circle"))
        .filter(|n| n.attribute("stroke").is_some_and(|s| body.contains(&s)))
        .map(|n| bounds(&shape_points(&n)))
        .filter(in_panel)
        .collect();
    shapes.sort_by(|a, b| a.0.total_cmp(&b.0));
    let mut figures: Vec<PxBox> = Vec::new();
    for s in shapes {
        match figures.last_mut() {
            Some(f) if s.0 <= f.2 => *f = (f.0.min(s.0), f.1.min(s.1), f.2.max(s.2), f.3.max(s.3)),
            _ => figures.push(s),
        }
    }
    let grounds: Vec<PxBox> = doc
        .descendants()
        .filter(|n| n.has_tag_name("polyline") && n.attribute("stroke") == Some("#3C8C3C"))
        .map(|n| bounds(&shape_points(&n)))
        .filter(in_panel)
        .collect();
    let labels = doc
        .descendants()
        .filter(|n| n.has_tag_name("text"))
        .filter_map(|n| {
            let (x, y) = (n.attribute("x")?.parse().ok()?, n.attribute("y")?.parse::<f64>().ok()?);
            let text = n.text()?.trim().to_string();
            (y >= top && y < bottom).then_some((text, x, y))
        })
        .collect();
    (figures, grounds, labels)
}

/// The stick figure is a chronophotograph: in the side view and the frontal view, figures
/// side by side with no two boxes overlapping, a ground line under each (the stairs' steps
/// on a climb), the % of the cycle under each, and each gait event named once per view.
#[test]
fn the_stick_figures_stand_apart_each_on_its_ground_with_its_events() {
    let dir = std::env::temp_dir().join(format!("gaitlab-plots-chrono-{}", std::process::id()));
    for config in ["configs/default.toml", "configs/stairs_up.toml"] {
        let _ = std::fs::remove_dir_all(&dir);
        report_of(&dir, &[config]);
        let svg = std::fs::read_to_string(dir.join("plots/stick_figure.svg")).unwrap();
        for (view, top, bottom) in [("side", 0.0, 500.0), ("frontal", 500.0, 1000.0)] {
            let at = format!("{config} {view}");
            let (figures, grounds, labels) = stick_panel(&svg, top, bottom);
            let pcts: Vec<&Label> = labels.iter().filter(|l| l.0.ends_with(" %")).collect();
            assert_eq!(figures.len(), 8, "{at}: 8 figures apart, found {} groups: {figures:?}", figures.len());
            assert_eq!(pcts.len(), figures.len(), "{at}: a % label per figure");
            for pair in figures.windows(2) {
                assert!(pair[0].2 + 4.0 < pair[1].0, "{at}: figures closer than 4 px: {pair:?}");
            }
            for (k, f) in figures.iter().enumerate() {
                let under: Vec<&PxBox> = grounds.iter().filter(|g| g.0 < f.2 && g.2 > f.0).collect();
                assert_eq!(under.len(), 1, "{at}: figure {k} {f:?} has one ground line under it: {under:?}");
                let g = under[0];
                assert!(g.0 <= f.0 && g.2 >= f.2, "{at}: figure {k}'s ground {g:?} spans it {f:?}");
                // Pixels grow downwards: the ground reaches the figure's lowest point (its
                // standing foot) and no lower than a step under it.
                assert!((g.3 - f.3).abs() < 40.0 && g.3 >= f.3 - 3.0, "{at}: figure {k} {f:?} on its ground {g:?}");
                let pct = pcts.iter().filter(|l| l.1 > f.0 && l.1 < f.2 && l.2 >= g.3).count();
                assert_eq!(pct, 1, "{at}: figure {k}'s % label under it");
            }
            assert_eq!(pcts[0].0, "0 %", "{at}: the cycle starts at its heel strike");
            for event in ["RHS", "LTO", "LHS", "RTO"] {
                let named: Vec<_> = labels.iter().filter(|l| l.0 == event).collect();
                assert_eq!(named.len(), 1, "{at}: {event} named once: {named:?}");
                let (x, y) = (named[0].1, named[0].2);
                let f = figures.iter().find(|f| x > f.0 && x < f.2);
                assert!(f.is_some_and(|f| y > f.3), "{at}: {event} under a figure");
            }
        }
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

/// The cost-per-step line breaks at steps with no cost: in start_stop.toml the start's first
/// steps and the stop's closing step are not costed, so the optimised cost is two lines (the
/// two walking stretches), not one drawn across the stop as if it had been walked.
#[test]
fn the_cost_per_step_line_breaks_where_no_step_was_costed() {
    let dir = std::env::temp_dir().join(format!("gaitlab-plots-costline-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    report_of(&dir, &["configs/start_stop.toml"]);
    let svg = std::fs::read_to_string(dir.join("plots/optimisation.svg")).unwrap();
    let doc = roxmltree::Document::parse(&svg).unwrap();
    // The optimised cost's lines (the legend's sample is a two-point line).
    let lines: Vec<usize> = doc
        .descendants()
        .filter(|n| n.has_tag_name("polyline") && n.attribute("stroke") == Some("#C82828"))
        .map(|n| shape_points(&n).len())
        .filter(|&points| points > 2)
        .collect();
    assert_eq!(lines.len(), 2, "{lines:?}");
    std::fs::remove_dir_all(&dir).unwrap();
}

/// The ankle plot draws each swing as walked beside each step's planned curve: at brisk the
/// planned curve dips to -23 deg after toe-off, where the foot, easing from its toe-off pitch
/// into it, takes the ankle to -17 to -20.5 only, and the plot alone had read as the push-off.
#[test]
fn the_ankle_plot_shows_each_swing_as_walked_beside_the_plan() {
    let dir = std::env::temp_dir().join(format!("gaitlab-plots-ankle-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    report_of(&dir, &["configs/brisk.toml"]);
    let svg = std::fs::read_to_string(dir.join("plots/ankle.svg")).unwrap();
    let doc = roxmltree::Document::parse(&svg).unwrap();
    let texts: Vec<&str> = doc.descendants().filter_map(|n| n.text()).map(str::trim).collect();
    assert!(texts.contains(&"planned, each step") && texts.contains(&"walked, each swing"), "{texts:?}");
    // The heel rise as walked beside its design at this walk's stride; its angle kept in
    // (-180, 180] (past 60 deg the heel's direction crossed atan2's cut: a -300 deg spike).
    assert!(texts.contains(&"walked, each heel rise"), "{texts:?}");
    let lowest = numeric_labels(&svg).iter().map(|l| l.2).fold(f64::INFINITY, f64::min);
    assert!(lowest > -50.0, "an axis reaches {lowest}");
    // The walked swings in the left leg's blue: one line a whole swing, both legs.
    let walked =
        doc.descendants().filter(|n| n.has_tag_name("polyline") && n.attribute("stroke") == Some("#1E50C8")).count();
    assert!(walked >= 10, "{walked} walked swings drawn");
    std::fs::remove_dir_all(&dir).unwrap();
}
