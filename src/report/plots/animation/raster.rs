//! Frames drawn straight into palette indices: every ink of [`Ink::ALL`] in four strengths
//! (a quarter to all of the ink over the paper), so that edges are smoothed without a
//! colour quantiser and every frame shares one small palette.
//!
//! Lines are round-capped: a pixel takes the share of it a line of the stroke's width covers,
//! measured by its centre's distance to the segment, in quarters. A partly covered pixel
//! shows the ink over the paper; over another ink it is drawn only where the new ink covers
//! more than the old, so edges never leave light fringes on the ground or another limb.

use super::scene::{BAND_PX, HEIGHT, Ink, Panel, Stroke, WIDTH};

/// Strengths of each ink in the palette.
const LEVELS: u8 = 4;

/// The palette index of `ink` at `level` (1..=[`LEVELS`]).
fn index(ink: Ink, level: u8) -> u8 {
    ink as u8 * LEVELS + level - 1
}

/// The palette (RGB triples): each ink at each strength over white paper.
pub(super) fn palette() -> Vec<u8> {
    let paper = Ink::Paper.rgb();
    Ink::ALL
        .iter()
        .flat_map(|ink| {
            let rgb = ink.rgb();
            (1..=LEVELS).flat_map(move |level| {
                let share = f64::from(level) / f64::from(LEVELS);
                (0..3).map(move |c| {
                    (f64::from(paper[c]) + (f64::from(rgb[c]) - f64::from(paper[c])) * share).round() as u8
                })
            })
        })
        .collect()
}

/// An index no ink uses: the GIF's "unchanged since the last frame".
pub(super) const TRANSPARENT: u8 = Ink::ALL.len() as u8 * LEVELS;

/// The LZW's minimum code size: bits enough for every index, [`TRANSPARENT`] the largest.
pub(super) const CODE_SIZE: u8 = 6;
const _: () = assert!((TRANSPARENT as u32) < 1 << CODE_SIZE);

/// A frame's palette indices, row by row.
#[derive(Clone, PartialEq, Eq)]
pub(super) struct Canvas {
    pub(super) pixels: Vec<u8>,
}

/// The rectangle a shape may touch: x from `x0` to `x1`, below the band.
#[derive(Clone, Copy)]
struct Clip {
    x0: i32,
    x1: i32,
    y0: i32,
    y1: i32,
}

impl Canvas {
    /// White paper.
    pub(super) fn blank() -> Canvas {
        Canvas { pixels: vec![index(Ink::Paper, LEVELS); WIDTH as usize * HEIGHT as usize] }
    }

    /// Sets `(x, y)` to `ink` covering `share` (0..1) of it, by the rule in the module doc.
    fn put(&mut self, x: i32, y: i32, ink: Ink, share: f64) {
        // Rounded to the nearest quarter (share is never negative).
        let level = (share * f64::from(LEVELS) + 0.5) as u8;
        if level == 0 {
            return;
        }
        let at = y as usize * WIDTH as usize + x as usize;
        let old = self.pixels[at];
        let (old_ink, old_level) = (old / LEVELS, old % LEVELS + 1);
        let new = if old_ink == Ink::Paper as u8 {
            level
        } else if old_ink == ink as u8 {
            level.max(old_level)
        } else if level > old_level || level == LEVELS {
            level
        } else {
            return;
        };
        self.pixels[at] = index(ink, new);
    }

    /// Writes `(x, y)` in full strength, whatever was there.
    fn set(&mut self, x: i32, y: i32, ink: Ink) {
        self.pixels[y as usize * WIDTH as usize + x as usize] = index(ink, LEVELS);
    }

    /// Draws a panel: earth under the ground line, the ground line, the strokes, the head.
    pub(super) fn panel(&mut self, p: &Panel) {
        let clip = Clip { x0: p.x0.round() as i32, x1: p.x1.round() as i32, y0: BAND_PX as i32, y1: HEIGHT as i32 };
        self.earth(&p.ground, clip);
        let ground = Stroke { points: p.ground.clone(), width: super::scene::GROUND_PX, ink: Ink::Ground };
        self.stroke(&ground, clip);
        for s in &p.strokes {
            self.stroke(s, clip);
        }
        self.ring(p.head.0, p.head.1, super::scene::HEAD_PX, Ink::Trunk, clip);
    }

    /// Fills each column of `clip` from the ground line down with earth.
    fn earth(&mut self, ground: &[(f64, f64)], clip: Clip) {
        for x in clip.x0..clip.x1 {
            let Some(top) = height_at(ground, f64::from(x) + 0.5) else { continue };
            for y in (top.ceil() as i32).max(clip.y0)..clip.y1 {
                self.set(x, y, Ink::Earth);
            }
        }
    }

    /// A stroke: each segment as a round-capped line of the stroke's width.
    fn stroke(&mut self, s: &Stroke, clip: Clip) {
        for w in s.points.windows(2) {
            self.segment(w[0], w[1], s.width, s.ink, clip);
        }
    }

    fn segment(&mut self, a: (f64, f64), b: (f64, f64), width: f64, ink: Ink, clip: Clip) {
        let reach = 0.5 * width + 1.0;
        let (xs, ys) = (a.0.min(b.0) - reach..a.0.max(b.0) + reach, a.1.min(b.1) - reach..a.1.max(b.1) + reach);
        let (d, len2) = ((b.0 - a.0, b.1 - a.1), (b.0 - a.0).powi(2) + (b.1 - a.1).powi(2));
        // Pixels whose centres lie this far (squared) or further are not touched.
        let outer2 = (0.5 * width + 0.5).powi(2);
        for y in (ys.start.floor() as i32).max(clip.y0)..(ys.end.ceil() as i32).min(clip.y1) {
            for x in (xs.start.floor() as i32).max(clip.x0)..(xs.end.ceil() as i32).min(clip.x1) {
                let p = (f64::from(x) + 0.5 - a.0, f64::from(y) + 0.5 - a.1);
                let t = if len2 > 0.0 { ((p.0 * d.0 + p.1 * d.1) / len2).clamp(0.0, 1.0) } else { 0.0 };
                let dist2 = (p.0 - t * d.0).powi(2) + (p.1 - t * d.1).powi(2);
                if dist2 < outer2 {
                    self.put(x, y, ink, (0.5 * width + 0.5 - dist2.sqrt()).min(1.0));
                }
            }
        }
    }

    /// A circle's outline of `width` px.
    fn ring(&mut self, c: (f64, f64), radius: f64, width: f64, ink: Ink, clip: Clip) {
        let reach = radius + 0.5 * width + 1.0;
        for y in ((c.1 - reach).floor() as i32).max(clip.y0)..((c.1 + reach).ceil() as i32).min(clip.y1) {
            for x in ((c.0 - reach).floor() as i32).max(clip.x0)..((c.0 + reach).ceil() as i32).min(clip.x1) {
                let dist = ((f64::from(x) + 0.5 - c.0).hypot(f64::from(y) + 0.5 - c.1) - radius).abs();
                self.put(x, y, ink, (0.5 * width + 0.5 - dist).clamp(0.0, 1.0));
            }
        }
    }

    /// Writes a vertical rule of full `ink` at column `x` below the band.
    pub(super) fn rule(&mut self, x: i32, ink: Ink) {
        for y in BAND_PX as i32..HEIGHT as i32 {
            self.set(x, y, ink);
        }
    }

    /// Copies `rgb` (the band's text, dark on white, `WIDTH` wide) in as text ink of the
    /// strength nearest each pixel's darkness.
    pub(super) fn text(&mut self, rgb: &[u8]) {
        for (i, px) in rgb.chunks_exact(3).enumerate() {
            let dark = 1.0 - f64::from(px[0].min(px[1]).min(px[2])) / 255.0;
            let level = (dark * f64::from(LEVELS)).round() as u8;
            if level > 0 {
                self.pixels[i] = index(Ink::Text, level);
            }
        }
    }
}

/// The ground line's height (px) at `x`: on the segment that spans `x`, and where a riser
/// stands at `x` (two points at one x), the step to the right of it.
fn height_at(ground: &[(f64, f64)], x: f64) -> Option<f64> {
    ground.windows(2).find(|w| w[0].0 <= x && x < w[1].0).map(|w| {
        let s = (x - w[0].0) / (w[1].0 - w[0].0);
        w[0].1 + (w[1].1 - w[0].1) * s
    })
}
