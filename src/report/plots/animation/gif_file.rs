//! `walk.gif`: the frames in one global palette, looping forever. After the first, a frame
//! holds only the rectangle that changed since the one before, its unchanged pixels
//! transparent (the frame before is kept under it): most of a frame is the same paper,
//! caption and earth as the last, and leaving it out keeps the file small and the LZW
//! encoder's work to the moving figure and ground. The LZW is [`lzw`]'s.

use super::lzw;
use super::raster::{CODE_SIZE, Canvas, TRANSPARENT, palette};
use super::scene::{HEIGHT, WIDTH};
use gif::{DisposalMethod, Encoder, Frame, Repeat};
use std::borrow::Cow;

/// The GIF of `frames` frames, frame `k` drawn by `draw(k)` and shown for `delay(k)`
/// hundredths of a second. The frames are drawn and LZW-compressed on the machine's cores
/// in contiguous runs (each run draws the frame before its first, to diff against), then
/// written in order: the bytes do not depend on how the work was split.
pub(super) fn encode(
    frames: usize,
    draw: &(dyn Fn(usize) -> Canvas + Sync),
    delay: &dyn Fn(usize) -> u16,
) -> Result<Vec<u8>, String> {
    let err = |e: gif::EncodingError| format!("walk.gif: {e}");
    let workers = std::thread::available_parallelism().map_or(1, |n| n.get()).clamp(1, 4);
    let run = frames.div_ceil(workers).max(1);
    let compressed: Vec<Frame<'static>> = std::thread::scope(|scope| {
        let handles: Vec<_> = (0..frames)
            .step_by(run)
            .map(|first| scope.spawn(move || compress(first..(first + run).min(frames), draw)))
            .collect();
        handles.into_iter().flat_map(|h| h.join().unwrap_or_default()).collect()
    });
    if compressed.len() != frames {
        return Err("walk.gif: a drawing thread failed".into());
    }
    let mut out = Vec::new();
    {
        let mut encoder = Encoder::new(&mut out, WIDTH as u16, HEIGHT as u16, &palette()).map_err(err)?;
        encoder.set_repeat(Repeat::Infinite).map_err(err)?;
        for (k, mut frame) in compressed.into_iter().enumerate() {
            frame.delay = delay(k);
            encoder.write_lzw_pre_encoded_frame(&frame).map_err(err)?;
        }
    }
    Ok(out)
}

/// Frames `ks`, each as its change from the frame before (the first frame whole),
/// LZW-compressed.
fn compress(ks: std::ops::Range<usize>, draw: &(dyn Fn(usize) -> Canvas + Sync)) -> Vec<Frame<'static>> {
    let mut last = ks.start.checked_sub(1).map(draw);
    ks.map(|k| {
        let canvas = draw(k);
        let mut frame = match &last {
            None => whole(&canvas),
            Some(before) => changes(before, &canvas),
        };
        frame.buffer = Cow::Owned(lzw::encode(&frame.buffer, CODE_SIZE));
        last = Some(canvas);
        frame
    })
    .collect()
}

/// The first frame: every pixel.
fn whole(canvas: &Canvas) -> Frame<'static> {
    Frame {
        dispose: DisposalMethod::Keep,
        width: WIDTH as u16,
        height: HEIGHT as u16,
        buffer: Cow::Owned(canvas.pixels.clone()),
        ..Frame::default()
    }
}

/// The rectangle where `now` differs from `before`, unchanged pixels transparent; a single
/// transparent pixel when nothing changed.
fn changes(before: &Canvas, now: &Canvas) -> Frame<'static> {
    let w = WIDTH as usize;
    let (mut x0, mut y0, mut x1, mut y1) = (w, HEIGHT as usize, 0, 0);
    for (y, (a, b)) in before.pixels.chunks_exact(w).zip(now.pixels.chunks_exact(w)).enumerate() {
        // Most rows are unchanged: a slice comparison passes them at memory speed.
        if a == b {
            continue;
        }
        let Some(first) = a.iter().zip(b).position(|(p, q)| p != q) else { continue };
        let last = w - 1 - a.iter().rev().zip(b.iter().rev()).position(|(p, q)| p != q).unwrap_or(0);
        (x0, x1, y0, y1) = (x0.min(first), x1.max(last + 1), y0.min(y), y + 1);
    }
    if x1 <= x0 {
        (x0, y0, x1, y1) = (0, 0, 1, 1);
    }
    let mut buffer = Vec::with_capacity((x1 - x0) * (y1 - y0));
    for y in y0..y1 {
        let span = y * w + x0..y * w + x1;
        let (a, b) = (&before.pixels[span.clone()], &now.pixels[span]);
        buffer.extend(a.iter().zip(b).map(|(&p, &q)| if p == q { TRANSPARENT } else { q }));
    }
    Frame {
        dispose: DisposalMethod::Keep,
        transparent: Some(TRANSPARENT),
        left: x0 as u16,
        top: y0 as u16,
        width: (x1 - x0) as u16,
        height: (y1 - y0) as u16,
        buffer: Cow::Owned(buffer),
        ..Frame::default()
    }
}
