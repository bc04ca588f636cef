//! The report's walk for slides (issue 15, point 4): `walk.gif` decoded by the `image` crate
//! (frames, size, timing, colours, motion, a seamless loop) and `walk.svg` parsed by
//! roxmltree (one group a frame, timed as the GIF). Byte-for-byte repeatability is checked
//! with every other report file in `tests/report.rs`.

use image::AnimationDecoder;
use std::path::{Path, PathBuf};
use std::process::Command;

/// 640x360, 25 frames a second, about 4 s.
const SIZE: (u32, u32) = (640, 360);
const FPS: f64 = 25.0;
const TARGET_S: f64 = 4.0;

/// The report's colours of the right and left legs.
const RIGHT: [u8; 3] = [200, 40, 40];
const LEFT: [u8; 3] = [30, 80, 200];

fn report(config: &str, name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("gaitlab-walk-anim-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let out = Command::new(env!("CARGO_BIN_EXE_gaitlab"))
        .args(["report", config, "--out", dir.to_str().unwrap()])
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0), "{}", String::from_utf8_lossy(&out.stderr));
    dir
}

/// The steady cycle's length the report measured (s).
fn cycle_s(dir: &Path) -> f64 {
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.join("summary.json")).unwrap()).unwrap();
    json["cycle_s"].as_f64().unwrap()
}

/// The decoded frames (each composed over the ones before, as a viewer shows it) and their
/// delays in seconds.
fn frames(gif: &[u8]) -> Vec<(image::RgbaImage, f64)> {
    let decoder = image::codecs::gif::GifDecoder::new(gif).unwrap();
    let frames = decoder.into_frames().collect_frames().unwrap();
    frames
        .into_iter()
        .map(|f| {
            let (n, d) = f.delay().numer_denom_ms();
            (f.into_buffer(), f64::from(n) / f64::from(d) / 1e3)
        })
        .collect()
}

/// Pixels of exactly `rgb` in the columns `x0..x1`.
fn count(img: &image::RgbaImage, rgb: [u8; 3], xs: std::ops::Range<u32>) -> usize {
    img.enumerate_pixels().filter(|(x, _, p)| xs.contains(x) && p.0[..3] == rgb).count()
}

/// Pixels that differ between two frames.
fn changed(a: &image::RgbaImage, b: &image::RgbaImage) -> usize {
    a.pixels().zip(b.pixels()).filter(|(p, q)| p != q).count()
}

/// Mean column of `rgb`'s pixels in `xs`.
fn mean_x(img: &image::RgbaImage, rgb: [u8; 3], xs: std::ops::Range<u32>) -> f64 {
    let hits: Vec<u32> =
        img.enumerate_pixels().filter(|(x, _, p)| xs.contains(x) && p.0[..3] == rgb).map(|p| p.0).collect();
    hits.iter().map(|&x| f64::from(x)).sum::<f64>() / hits.len().max(1) as f64
}

#[test]
fn walk_gif_loops_whole_gait_cycles_at_the_walks_pace() {
    let dir = report("configs/default.toml", "default");
    let bytes = std::fs::read(dir.join("walk.gif")).unwrap();
    assert!(bytes.len() < 2_000_000, "walk.gif is {} bytes", bytes.len());
    let repeat = gif::DecodeOptions::new().read_info(&bytes[..]).unwrap().repeat();
    assert_eq!(repeat, gif::Repeat::Infinite);
    let frames = frames(&bytes);
    // The whole cycles nearest 4 s: default's 1.09 s cycle makes 4 (4.34 s).
    let cycle = cycle_s(&dir);
    let cycles = (TARGET_S / cycle).round();
    assert_eq!(cycles, 4.0);
    let total: f64 = frames.iter().map(|f| f.1).sum();
    assert!((total - cycles * cycle).abs() <= 1.0 / FPS, "{total} s for {cycles} cycles of {cycle} s");
    assert_eq!(frames.len() as f64, (total * FPS).round(), "{} frames in {total} s", frames.len());
    assert!(frames.iter().all(|f| (0.03..=0.05).contains(&f.1)), "a delay is not 4 ± 1 cs");
    for (k, (img, _)) in frames.iter().enumerate() {
        assert_eq!(img.dimensions(), SIZE, "frame {k}");
        // Both legs in both views: the side view left of x = 424, the frontal view right of it.
        for (view, xs) in [("side", 0..424), ("front", 424..640)] {
            for (leg, rgb) in [("right", RIGHT), ("left", LEFT)] {
                let n = count(img, rgb, xs.clone());
                assert!(n > 40, "frame {k}: {n} px of the {leg} leg in the {view} view");
            }
        }
    }
    // The figure moves every frame, and half a cycle on the legs have swapped places in the
    // side view (the camera travels with the pelvis, so the legs swing about its middle).
    let consecutive: Vec<usize> = frames.windows(2).map(|w| changed(&w[0].0, &w[1].0)).collect();
    assert!(consecutive.iter().all(|&n| n > 200), "a frame repeats the last: {consecutive:?}");
    let half = (0.5 * cycle * FPS).round() as usize;
    let (a, b) = (&frames[0].0, &frames[half].0);
    let swap = |img| mean_x(img, RIGHT, 0..424) - mean_x(img, LEFT, 0..424);
    assert!(swap(a) * swap(b) < 0.0, "legs did not change places: {} then {}", swap(a), swap(b));
    // Seamless: from the last frame back to the first changes no more than a step between
    // neighbours does.
    let seam = changed(&frames[frames.len() - 1].0, &frames[0].0);
    let most = *consecutive.iter().max().unwrap();
    assert!(seam <= most, "the loop jumps: {seam} px change at the seam, at most {most} elsewhere");
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn walk_svg_has_a_group_per_gif_frame_timed_as_the_gif() {
    let dir = report("configs/stairs_up.toml", "stairs");
    let gif = frames(&std::fs::read(dir.join("walk.gif")).unwrap());
    let text = std::fs::read_to_string(dir.join("walk.svg")).unwrap();
    assert!(text.len() < 1_000_000, "walk.svg is {} bytes", text.len());
    let doc = roxmltree::Document::parse(&text).unwrap();
    let root = doc.root_element();
    assert_eq!((root.attribute("width"), root.attribute("height")), (Some("640"), Some("360")));
    let groups: Vec<_> = root.children().filter(|n| n.has_tag_name("g")).collect();
    assert_eq!(groups.len(), gif.len(), "one group a GIF frame");
    let total: f64 = gif.iter().map(|f| f.1).sum();
    let mut start = 0.0;
    for (k, (g, (_, delay))) in groups.iter().zip(&gif).enumerate() {
        assert_eq!(g.attribute("id"), Some(format!("f{k}").as_str()));
        assert_eq!(g.attribute("visibility"), if k == 0 { None } else { Some("hidden") }, "frame {k}");
        let animate = g.children().find(|n| n.has_tag_name("animate")).unwrap();
        assert_eq!(animate.attribute("calcMode"), Some("discrete"));
        assert_eq!(animate.attribute("repeatCount"), Some("indefinite"));
        let dur: f64 = animate.attribute("dur").unwrap().trim_end_matches('s').parse().unwrap();
        assert!((dur - total).abs() < 1e-9, "frame {k}: dur {dur} s, the GIF {total} s");
        // Visible from the GIF frame's start to the next one's.
        let values: Vec<&str> = animate.attribute("values").unwrap().split(';').collect();
        let times: Vec<f64> = animate.attribute("keyTimes").unwrap().split(';').map(|t| t.parse().unwrap()).collect();
        let on = values.iter().position(|v| *v == "visible").unwrap();
        assert!((times[on] * total - start).abs() < 1e-5, "frame {k} shows at {} s, not {start}", times[on] * total);
        if let Some(off) = times.get(on + 1) {
            assert!((off * total - (start + delay)).abs() < 1e-5, "frame {k} hides at {} s", off * total);
        }
        start += delay;
        let classes: Vec<&str> = g.descendants().filter_map(|n| n.attribute("class")).collect();
        for class in ["r", "l", "t", "g", "e"] {
            assert!(classes.contains(&class), "frame {k} lacks class {class}");
        }
    }
    std::fs::remove_dir_all(dir).unwrap();
}
