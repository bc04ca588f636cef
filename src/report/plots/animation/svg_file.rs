//! `walk.svg`: the same frames as the GIF, as vector shapes, one `<g>` a frame shown in
//! turn by a SMIL `<animate>` of its `visibility` (discrete, looping), timed to the GIF's
//! hundredths of a second. The first frame is visible by default, so a viewer that does not
//! animate SVG shows a still of the walk rather than an empty panel.

use super::clip::Clip;
use super::scene::{BAND_PX, HEIGHT, Ink, Panel, SIDE_W, WIDTH};
use std::fmt::Write as _;

/// The SVG's class of each ink a shape is drawn in: stroke colour and width.
fn class(ink: Ink) -> &'static str {
    match ink {
        Ink::Trunk => "t",
        Ink::Right => "r",
        Ink::Left => "l",
        Ink::RightArm => "ra",
        Ink::LeftArm => "la",
        Ink::Ground => "g",
        Ink::Mark => "m",
        _ => "x",
    }
}

fn hex(ink: Ink) -> String {
    let [r, g, b] = ink.rgb();
    format!("#{r:02x}{g:02x}{b:02x}")
}

/// The document's head: size, styles, the panels' clips, the paper, the caption texts
/// (`(x px, text)`) and the rule between the panels.
fn head(svg: &mut String, title: &str, captions: &[(f64, String)]) {
    use super::scene::{ARM_PX, CAPTION_PX, GROUND_PX, HEAD_PX, LEG_PX, MARK_PX};
    let (w, h) = (WIDTH, HEIGHT);
    let _ = writeln!(
        svg,
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}\" height=\"{h}\" viewBox=\"0 0 {w} {h}\">"
    );
    let _ = writeln!(svg, "<title>{}</title>", escape(title));
    let mut style = String::from("polyline,circle{fill:none;stroke-linecap:round;stroke-linejoin:round}");
    for (ink, width) in [
        (Ink::Trunk, LEG_PX),
        (Ink::Right, LEG_PX),
        (Ink::Left, LEG_PX),
        (Ink::RightArm, ARM_PX),
        (Ink::LeftArm, ARM_PX),
        (Ink::Ground, GROUND_PX),
        (Ink::Mark, MARK_PX),
    ] {
        let _ = write!(style, ".{}{{stroke:{};stroke-width:{width}}}", class(ink), hex(ink));
    }
    let _ = write!(
        style,
        "circle{{stroke:{};stroke-width:{HEAD_PX}}}.e{{fill:{};stroke:none}}text{{font-family:'DejaVu Sans',sans-serif;font-size:{CAPTION_PX}px;fill:{}}}",
        hex(Ink::Trunk),
        hex(Ink::Earth),
        hex(Ink::Text)
    );
    let _ = writeln!(svg, "<style>{style}</style>");
    let _ = writeln!(
        svg,
        "<defs><clipPath id=\"side\"><rect x=\"0\" y=\"{BAND_PX}\" width=\"{SIDE_W}\" height=\"{}\"/></clipPath>\
         <clipPath id=\"front\"><rect x=\"{SIDE_W}\" y=\"{BAND_PX}\" width=\"{}\" height=\"{}\"/></clipPath></defs>",
        f64::from(h) - BAND_PX,
        f64::from(w) - SIDE_W,
        f64::from(h) - BAND_PX
    );
    let _ = writeln!(svg, "<rect width=\"{w}\" height=\"{h}\" fill=\"#ffffff\"/>");
    for (x, text) in captions {
        let _ = writeln!(svg, "<text x=\"{x}\" y=\"{}\">{}</text>", BAND_PX - 7.0, escape(text));
    }
    let _ = writeln!(
        svg,
        "<line x1=\"{SIDE_W}\" y1=\"{BAND_PX}\" x2=\"{SIDE_W}\" y2=\"{h}\" stroke=\"{}\"/>",
        hex(Ink::Rule)
    );
}

/// The whole document: `frames` are the panels of each of `clip`'s frames.
pub(super) fn document(
    clip: &Clip,
    title: &str,
    captions: &[(f64, String)],
    frames: impl Iterator<Item = [Panel; 2]>,
) -> String {
    let mut svg = String::with_capacity(2048 * clip.frames);
    head(&mut svg, title, captions);
    let total = f64::from(clip.total_cs());
    for (k, panels) in frames.enumerate() {
        let hidden = if k == 0 { "" } else { " visibility=\"hidden\"" };
        let _ = writeln!(svg, "<g id=\"f{k}\"{hidden}>");
        if clip.frames > 1 {
            let (on, off) = (f64::from(clip.start_cs(k)) / total, f64::from(clip.start_cs(k + 1)) / total);
            let (values, times) = match (k, k + 1 == clip.frames) {
                (0, _) => ("visible;hidden".to_string(), format!("0;{off:.6}")),
                (_, true) => ("hidden;visible".to_string(), format!("0;{on:.6}")),
                _ => ("hidden;visible;hidden".to_string(), format!("0;{on:.6};{off:.6}")),
            };
            let _ = writeln!(
                svg,
                "<animate attributeName=\"visibility\" values=\"{values}\" keyTimes=\"{times}\" dur=\"{}s\" \
                 calcMode=\"discrete\" repeatCount=\"indefinite\"/>",
                total / 100.0
            );
        }
        for (panel, id) in panels.iter().zip(["side", "front"]) {
            self::panel(&mut svg, panel, id);
        }
        svg.push_str("</g>\n");
    }
    svg.push_str("</svg>\n");
    svg
}

/// One view: the earth under the ground line, the ground line, the marks and the body,
/// then the head, clipped to its panel.
fn panel(svg: &mut String, p: &Panel, clip: &str) {
    let _ = write!(svg, "<g clip-path=\"url(#{clip})\">");
    let bottom = f64::from(HEIGHT);
    let (first, last) = (p.ground.first().map_or(p.x0, |q| q.0), p.ground.last().map_or(p.x1, |q| q.0));
    let _ =
        write!(svg, "<polygon class=\"e\" points=\"{} {last:.1},{bottom} {first:.1},{bottom}\"/>", points(&p.ground));
    let _ = write!(svg, "<polyline class=\"g\" points=\"{}\"/>", points(&p.ground));
    for s in &p.strokes {
        let _ = write!(svg, "<polyline class=\"{}\" points=\"{}\"/>", class(s.ink), points(&s.points));
    }
    let ((x, y), r) = p.head;
    let _ = writeln!(svg, "<circle cx=\"{x:.1}\" cy=\"{y:.1}\" r=\"{r:.1}\"/></g>");
}

/// `x,y x,y …` to a tenth of a pixel.
fn points(points: &[(f64, f64)]) -> String {
    let mut s = String::with_capacity(12 * points.len());
    for (i, (x, y)) in points.iter().enumerate() {
        let _ = write!(s, "{}{x:.1},{y:.1}", if i == 0 { "" } else { " " });
    }
    s
}

/// Text for XML: the five characters that must be escaped.
fn escape(text: &str) -> String {
    text.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;").replace('"', "&quot;").replace('\'', "&apos;")
}
