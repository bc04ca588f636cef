//! Every config in `configs/` is a test case (a glob: a new file is a new test): the walk runs
//! 20 cycles with no non-finite value, no reach failure, no stance-foot slide over 0.5 mm
//! within a phase, heel and toe never more than 1 mm under the ground, a knee that never
//! flips, and a snapshot of a compact per-cycle summary so an unintended change to the
//! walk's numbers shows up in review.

use gaitlab::analysis::{self, CycleSummary};
use gaitlab::config;
use std::fmt::Write as _;

fn compact(c: &CycleSummary) -> String {
    let mut s = String::new();
    let _ = write!(
        s,
        "{:>2} T {:.3}s stride {:.3}m v {:.3} | stance {:.1}/{:.1}% ds {:.1}% | pelvis v {:.1} l {:.1}cm | knee st {:.0}/{:.0} sw {:.0}/{:.0} | hip {:.0}..{:.0} | ankle {:.0}..{:.0} | toe clear {:.1}/{:.1}cm",
        c.cycle,
        c.duration_s,
        c.stride_m,
        c.speed_mps,
        c.stance_pct[0],
        c.stance_pct[1],
        c.double_support_pct,
        c.pelvis_vertical_cm,
        c.pelvis_lateral_cm,
        c.knee_max_stance_deg[0],
        c.knee_max_stance_deg[1],
        c.knee_max_swing_deg[0],
        c.knee_max_swing_deg[1],
        c.hip_flex_deg[0].0,
        c.hip_flex_deg[0].1,
        c.ankle_deg[0].0,
        c.ankle_deg[0].1,
        c.min_toe_clearance_cm[0],
        c.min_toe_clearance_cm[1],
    );
    // "-0" and "0" must not differ between platforms.
    s.replace("-0 ", "0 ").replace("-0.0 ", "0.0 ")
}

#[test]
fn every_config_walks_cleanly() {
    insta::glob!("..", "configs/*.toml", |path| {
        let params = config::load(path, &[]).unwrap_or_else(|e| panic!("{e}"));
        let run = analysis::run(&params, 20.0, 60.0).expect("the walk builds");
        let checks = analysis::checks(&run.frames);
        let name = path.file_name().unwrap().to_string_lossy();
        assert_eq!(checks.non_finite_values, 0, "{name}");
        assert_eq!(checks.reach_failures, 0, "{name}: {checks:?}");
        assert!(checks.foot_skate_mm <= 0.5, "{name}: foot skate {checks:?}");
        assert!(checks.terrain_penetration_mm <= 1.0, "{name}: penetration {checks:?}");
        // The knee never flips: its direction about the hip→ankle axis, measured as the angle
        // ψ from the walking direction (+x projected onto the plane normal to the axis), stays
        // forward and changes by less than 2° a frame.
        for side in 0..2 {
            let psi = |f: &gaitlab::model::walk::frame::Frame| {
                let l = &f.legs[side];
                let a = (l.ankle - l.hip).normalize();
                let forward = (glam::DVec3::X - a * a.x).normalize();
                let u = l.knee_swivel;
                a.cross(forward).dot(u).atan2(forward.dot(u)).to_degrees()
            };
            for w in run.frames.windows(2) {
                let (p0, p1) = (psi(&w[0]), psi(&w[1]));
                assert!(p1.abs() < 45.0, "{name}: knee points {p1:.1}° off forward at frame {}", w[1].frame);
                assert!((p1 - p0).abs() < 2.0, "{name}: knee swivel jumped {:.2}° at frame {}", p1 - p0, w[1].frame);
            }
        }
        let summaries = analysis::cycle_summaries(&run.frames);
        // A walk that stops (pace.toml) has cycles up to its last heel strike, none while it
        // stands; one that begins standing and stops on the way (start_stop.toml) fewer than
        // its 20; every other walks its 20.
        use gaitlab::model::walk::pace::WalkState;
        let standing_from = run.states.iter().rposition(|s| *s != WalkState::Standing).map(|i| i + 1);
        match standing_from {
            _ if !run.states.contains(&WalkState::Standing) => {
                assert!(summaries.len() >= 19, "{name}: {} cycles", summaries.len())
            }
            Some(i) if i < run.states.len() => {
                let end: f64 = summaries.iter().map(|c| c.duration_s).sum();
                assert!(end <= run.frames[i].time_s, "{name}: a cycle ends at {end:.2} s, standing from frame {i}");
                assert!(summaries.len() >= 10, "{name}: {} cycles", summaries.len());
            }
            _ => assert!(summaries.len() >= 10, "{name}: {} cycles", summaries.len()),
        }
        let text: Vec<String> = summaries.iter().map(compact).collect();
        insta::assert_snapshot!(text.join("\n"));
    });
}
