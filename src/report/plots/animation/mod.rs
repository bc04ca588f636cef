//! The walk for slides: `walk.gif` and `walk.svg`, the stick figure over the terrain in a
//! loop of whole gait cycles at the walk's own pace, 640x360, the side view (the camera
//! travelling with the walker) beside the frontal view (from ahead), drawn from the report's
//! recording (no second walk) with the stick-figure plot's geometry and colours.
//!
//! `clip` picks the stretch and the frame times, `scene` turns each frame into shapes in
//! pixels, which `raster` draws into palette indices for `gif_file` and `svg_file`
//! writes as vector shapes.

mod clip;
mod gif_file;
mod lzw;
mod raster;
mod scene;
mod svg_file;

pub use clip::{Clip, FPS, TARGET_S};
pub use scene::{HEIGHT, WIDTH};

use super::common::{FONT, err};
use super::data::Data;
use crate::analysis::Run;
use plotters::prelude::*;
use raster::Canvas;
use scene::{BAND_PX, Ink, SIDE_W, Stage};

/// The animation's files' contents.
pub struct Animation {
    /// The stretch looped.
    pub clip: Clip,
    /// `walk.gif`.
    pub gif: Vec<u8>,
    /// `walk.svg`.
    pub svg: String,
}

/// Left margin of the captions (px).
const CAPTION_X: f64 = 8.0;

/// Draws `run`'s walk (named `name` in the caption) as [`Animation`].
pub fn animate(name: &str, run: &Run) -> Result<Animation, String> {
    super::register_font();
    let d = Data::new(run);
    let clip = Clip::new(&d);
    if run.poses.len() <= clip.end {
        return Err("walk.gif: the recording kept no poses".into());
    }
    let stage = Stage::new(run, &clip);
    let scenes: Vec<_> = (0..clip.frames).map(|k| stage.scene(k)).collect();
    let speed = (run.frames[clip.end].pelvis.x - run.frames[clip.start].pelvis.x) / clip.duration_s.max(1e-9);
    let captions = [
        (CAPTION_X, format!("{name}, {speed:.2} m/s, side (right limbs red, left blue)")),
        (SIDE_W + CAPTION_X, "from ahead".to_string()),
    ];
    let base = base(&captions)?;
    let draw = |k: usize| {
        let mut canvas = base.clone();
        for p in &scenes[k] {
            canvas.panel(p);
        }
        canvas.rule(SIDE_W as i32, Ink::Rule);
        canvas
    };
    let gif = gif_file::encode(clip.frames, &draw, &|k| clip.delay_cs(k))?;
    let title = format!("{name}: {}, looping at the walk's pace", clip.describe());
    let svg = svg_file::document(&clip, &title, &captions, scenes.into_iter());
    Ok(Animation { clip, gif, svg })
}

/// What every frame starts from: paper and the captions in the band.
fn base(captions: &[(f64, String)]) -> Result<Canvas, String> {
    let mut canvas = Canvas::blank();
    let band = (scene::WIDTH, BAND_PX as u32);
    let mut rgb = vec![255u8; band.0 as usize * band.1 as usize * 3];
    {
        let area = BitMapBackend::with_buffer(&mut rgb, band).into_drawing_area();
        for (x, text) in captions {
            let style = TextStyle::from((FONT, scene::CAPTION_PX)).color(&BLACK);
            area.draw(&Text::new(text.as_str(), (*x as i32, 4), style)).map_err(err)?;
        }
        area.present().map_err(err)?;
    }
    canvas.text(&rgb);
    Ok(canvas)
}
