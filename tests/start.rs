//! Gait initiation (issue 14): a walk that begins standing sets off with a short first step,
//! walks, stops and sets off again, on flat ground, stairs and a slope, with no slide, no
//! jump and no joint faster or jerkier than in the steady walk.

mod common;
mod pace_common;

use common::{max_speed_changes, max_steps};
use gaitlab::analysis;
use gaitlab::config::{self, presets};
use gaitlab::model::params::WalkParams;
use gaitlab::model::schedule::PaceAction;
use gaitlab::model::walk::Walker;
use gaitlab::model::walk::frame::Frame;
use gaitlab::model::walk::leg::LegPhase;
use gaitlab::model::walk::pace::WalkState;
use pace_common::{Peaks, at_time, heel_strikes, max_pelvis_velocity_jump, steady_peaks, walk};

const FPS: f64 = 60.0;

/// Standing, set off at 0.5 s, stop asked at 6 s, set off again at 10 s, run to 14 s.
fn start_stop_start(name: &str) -> WalkParams {
    let mut p = presets::params(name).unwrap().unwrap();
    p.schedule =
        vec![at_time(0.5, PaceAction::Start), at_time(6.0, PaceAction::Stop), at_time(10.0, PaceAction::Start)];
    p
}

/// The time of the first step's toe-off.
fn e_first_step(w: &Walker) -> f64 {
    w.pace_events().iter().find(|e| e.kind.name() == "first_step").unwrap().time_s
}

/// The preset `name`, at `speed` if given.
fn steady(name: &str, speed: Option<f64>) -> WalkParams {
    let mut p = presets::params(name).unwrap().unwrap();
    if let Some(v) = speed {
        p.walk.speed_mps = v;
    }
    p
}

const TERRAINS: [&str; 3] = ["default", "stairs_up", "slope_up"];

#[test]
fn a_walk_that_begins_standing_sets_off_stops_and_sets_off_again_on_flat_stairs_and_slope() {
    for name in TERRAINS {
        let p = start_stop_start(name);
        let run = analysis::run(&p, 14.0 / p.resolve().cycle_s, FPS).unwrap();
        let frames = &run.frames;
        let c = analysis::checks(frames);
        assert_eq!(c.non_finite_values, 0, "{name}");
        assert_eq!(c.reach_failures, 0, "{name}: {c:?}");
        assert!(c.foot_skate_mm < 1.0, "{name}: {c:?}");
        assert!(c.terrain_penetration_mm < 1.0, "{name}: {c:?}");
        let kinds: Vec<&str> = run.pace_events.iter().map(|e| e.kind.name()).collect();
        let start = ["start_asked", "first_step", "walking"];
        let stop = ["stop_asked", "braking", "closing", "standing"];
        assert_eq!(kinds, [&start[..], &stop[..], &start[..]].concat(), "{name}");
        // The states in order, each once per start and stop.
        let mut states = run.states.clone();
        states.dedup();
        use WalkState::*;
        assert_eq!(states, [Standing, Starting, Walking, Stopping, Standing, Starting, Walking], "{name}");
        // Standing before the first start: nothing moves, both feet flat side by side.
        let asked = run.pace_events[0].time_s;
        let still: Vec<&Frame> = frames.iter().filter(|f| f.time_s <= asked).collect();
        assert!(still.len() >= 30, "{name}");
        for f in &still {
            assert!(f.pelvis.distance(frames[0].pelvis) < 1e-12, "{name}: moved at {:.2} s", f.time_s);
            assert!(f.legs.iter().all(|l| l.leg_phase == LegPhase::Midstance), "{name}");
        }
        assert!((frames[0].legs[0].heel.x - frames[0].legs[1].heel.x).abs() < 1e-9, "{name}");
        // Back at rest after the stop, until the second start: the pelvis still (velocity
        // zero), both feet flat on the ground side by side.
        let (rest_from, rest_to) = (run.pace_events[6].time_s, run.pace_events[7].time_s);
        let rest: Vec<&Frame> = frames.iter().filter(|f| f.time_s > rest_from + 0.05 && f.time_s <= rest_to).collect();
        assert!(rest.len() >= 30, "{name}: standing {rest_from:.2}-{rest_to:.2} s");
        for f in &rest {
            assert!(f.pelvis.distance(rest[0].pelvis) < 1e-12, "{name}: moved while standing at {:.2} s", f.time_s);
            for l in &f.legs {
                assert_eq!(l.leg_phase, LegPhase::Midstance, "{name}");
                assert!((l.heel.y - l.ground_under_heel).abs() < 1e-3, "{name}: a heel off the ground");
            }
        }
        let f = rest[0];
        assert!((f.legs[0].heel.x - f.legs[1].heel.x).abs() < 0.01, "{name}: feet not side by side");
        // The pelvis never goes back (its velocity changes are held to the steady walk's in
        // `starting_moves_no_joint_faster_or_jerkier_than_the_steady_walk`).
        for pair in frames.windows(2) {
            assert!(pair[1].pelvis.x >= pair[0].pelvis.x - 1e-9, "{name}: back at {:.2} s", pair[1].time_s);
        }
    }
}

#[test]
fn the_first_step_is_short_and_the_walk_is_steady_from_the_second() {
    for speed in [0.8, 1.0, 1.3, 1.6] {
        let mut p = start_stop_start("default");
        p.walk.speed_mps = speed;
        p.schedule.truncate(1);
        let (frames, w) = walk(&p, 8.0, FPS);
        let step = 0.5 * w.resolved().stride_m;
        let f = w.footfalls();
        // Numbered in order (the initiating foot may be either: the other is renumbered to
        // stand before the first step), each side keeping its parity.
        assert!(
            f.windows(2).all(|p| p[1].step == p[0].step + 1),
            "{speed}: {:?}",
            f.iter().map(|f| f.step).collect::<Vec<_>>()
        );
        assert!(f.iter().all(|f| (f.step.rem_euclid(2) == 0) == (f.side == gaitlab::model::body::Side::Right)));
        let first = (f[2].heel.x - f[1].heel.x) / step;
        assert!((0.6..=0.8).contains(&first), "{speed}: first step {first:.2} of a steady one");
        for pair in f[2..].windows(2) {
            let share = (pair[1].heel.x - pair[0].heel.x) / step;
            assert!((share - 1.0).abs() < 1e-6, "{speed}: step {} is {share:.3} of a steady one", pair[1].step);
        }
        // Steady speed from the second step's landing on: every stride (two steps) within 3 %.
        let strikes = heel_strikes(&frames);
        for s in strikes[1..].windows(3) {
            let v = (s[2].pelvis.x - s[0].pelvis.x) / (s[2].time_s - s[0].time_s);
            assert!((v / speed - 1.0).abs() < 0.03, "{speed}: {v:.3} m/s from {:.2} s", s[0].time_s);
        }
        // The weight shift: by the first toe-off the pelvis is over the foot that stays, 2 cm
        // or more toward it (half the walk's sideways sway).
        let toe_off = frames.iter().find(|f| f.time_s >= e_first_step(&w)).unwrap();
        let stance_z = f[1].heel.z;
        assert!(
            toe_off.pelvis.z * stance_z.signum() > 0.02,
            "{speed}: pelvis z {:.4} at the first toe-off, stance foot at {stance_z:.3}",
            toe_off.pelvis.z
        );
        // The first step's toe-off comes within 1.1 s of the ask (0.7-1.05 s measured).
        let e = w.pace_events();
        assert!(
            e[1].time_s - e[0].time_s < 1.1,
            "{speed}: first step {:.2} s after the ask",
            e[1].time_s - e[0].time_s
        );
    }
}

/// Measured: joint speed at most 1.08x the steady walk's largest, joint jerk 1.14x, pelvis
/// velocity change per frame 1.10x, at 0.8 to 1.6 m/s, on stairs and on a slope; in session
/// 11, against the steady walk at eight sampling phases, 1.08x, 1.12x and 1.13x.
#[test]
fn starting_moves_no_joint_faster_or_jerkier_than_the_steady_walk() {
    let cases: Vec<(&str, Option<f64>)> = [0.8, 1.0, 1.3, 1.6]
        .into_iter()
        .map(|v| ("default", Some(v)))
        .chain([("stairs_up", None), ("slope_up", None)])
        .collect();
    for (name, speed) in cases {
        let mut p = start_stop_start(name);
        if let Some(v) = speed {
            p.walk.speed_mps = v;
        }
        p.schedule.truncate(1);
        let (frames, _) = walk(&p, 5.0, FPS);
        let Peaks { speed: usual, jerk: usual_jerk, pelvis: usual_pelvis } =
            steady_peaks(&steady(name, speed), 8.0, FPS);
        let (seen, seen_jerk) = (max_steps(&frames), max_speed_changes(&frames));
        for i in 0..4 {
            assert!(seen[i] <= usual[i] * 1.2, "{name} {speed:?} joint {i}: {:.2} vs {:.2}°/frame", seen[i], usual[i]);
            assert!(
                seen_jerk[i] <= usual_jerk[i] * 1.2,
                "{name} {speed:?} joint {i}: {:.2} vs {:.2}°/frame²",
                seen_jerk[i],
                usual_jerk[i]
            );
        }
        let pelvis = max_pelvis_velocity_jump(&frames, FPS);
        assert!(pelvis <= usual_pelvis * 1.2, "{name} {speed:?}: pelvis {pelvis:.3} vs {usual_pelvis:.3}");
    }
}

#[test]
fn a_start_is_deterministic() {
    let p = start_stop_start("slope_up");
    let (a, _) = walk(&p, 12.0, FPS);
    let (b, _) = walk(&p, 12.0, FPS);
    assert_eq!(format!("{a:?}"), format!("{b:?}"));
}

#[test]
fn the_config_reads_start_entries_and_names_each_problem() {
    let good = "[[walk.schedule]]\ntime_s = 0.5\nstart = true\n[[walk.schedule]]\ntime_s = 6\nstop = true\n[[walk.schedule]]\ntime_s = 9\nstart = true\n";
    let p = config::load_text(good, "t.toml", &[]).unwrap();
    let wanted = [at_time(0.5, PaceAction::Start), at_time(6.0, PaceAction::Stop), at_time(9.0, PaceAction::Start)];
    assert_eq!(p.schedule, wanted);
    for (text, wanted) in [
        (
            "[[walk.schedule]]\ntime_s = 1\nspeed_mps = 1.0\n[[walk.schedule]]\ntime_s = 2\nstart = true\n",
            "walk.schedule[2].start: a start must be the first entry (the walk then begins standing) or follow a stop",
        ),
        (
            "[[walk.schedule]]\ndistance_m = 1\nstart = true\n",
            "walk.schedule[1]: a start takes time_s, not distance_m: a body at rest travels no distance",
        ),
        (
            "[[walk.schedule]]\ntime_s = 1\nstart = true\nstop = true\n",
            "walk.schedule[1]: takes one of speed_mps, stop and start, not two",
        ),
        ("[[walk.schedule]]\ntime_s = 1\nstart = false\n", "walk.schedule[1].start needs true"),
    ] {
        let err = config::load_text(text, "t.toml", &[]).unwrap_err().to_string();
        assert!(err.contains(wanted), "{text}\n{err}");
    }
}

/// A hostile sweep: every preset at its own speed, 0.4 and 2.0 m/s, under four schedules —
/// a start at 0 s and two more after stops, a stop during the first step, a speed change
/// during the start, a stop and a start in the same frame, a long walk. Found a slowdown's
/// landed leg out of reach (2.0 to 0.5 m/s, 1-2 mm of slide; see `reach_guard.rs`).
#[test]
fn every_preset_starts_stops_and_changes_pace_at_any_moment_without_a_slide() {
    let mut report = Vec::new();
    for name in [
        "default",
        "stroll",
        "brisk",
        "elderly",
        "wide_sway",
        "long_stride",
        "stairs_up",
        "stairs_down",
        "slope_up",
        "slope_down",
        "rough",
    ] {
        for speed in [None, Some(0.4), Some(2.0)] {
            for sched in 0..4 {
                let mut p = presets::params(name).unwrap().unwrap();
                if let Some(v) = speed {
                    p.walk.speed_mps = v;
                }
                p.schedule = match sched {
                    0 => vec![
                        at_time(0.0, PaceAction::Start),
                        at_time(4.0, PaceAction::Stop),
                        at_time(6.0, PaceAction::Start),
                        at_time(9.0, PaceAction::Stop),
                        at_time(9.5, PaceAction::Start),
                    ],
                    1 => vec![
                        at_time(0.2, PaceAction::Start),
                        at_time(0.9, PaceAction::Stop),
                        at_time(4.0, PaceAction::Start),
                        at_time(4.3, PaceAction::Speed(1.8)),
                    ],
                    2 => vec![
                        at_time(1.0, PaceAction::Start),
                        at_time(1.2, PaceAction::Speed(0.5)),
                        at_time(7.0, PaceAction::Stop),
                        at_time(7.0, PaceAction::Start),
                    ],
                    _ => vec![
                        at_time(0.5, PaceAction::Start),
                        at_time(12.0, PaceAction::Stop),
                        at_time(13.0, PaceAction::Start),
                    ],
                };
                let r = std::panic::catch_unwind(|| walk(&p, 16.0, FPS));
                match r {
                    Err(_) => report.push(format!("{name} {speed:?} {sched}: PANIC")),
                    Ok((frames, w)) => {
                        let c = analysis::checks(&frames);
                        if c.non_finite_values > 0
                            || c.reach_failures > 0
                            || c.foot_skate_mm > 1.0
                            || c.terrain_penetration_mm > 1.0
                        {
                            report.push(format!(
                                "{name} {speed:?} {sched}: {c:?} events {:?}",
                                w.pace_events()
                                    .iter()
                                    .map(|e| format!("{:.2} {}", e.time_s, e.kind.name()))
                                    .collect::<Vec<_>>()
                            ));
                        }
                        let back = frames.windows(2).filter(|p| p[1].pelvis.x < p[0].pelvis.x - 1e-9).count();
                        if back > 0 {
                            report.push(format!("{name} {speed:?} {sched}: pelvis back in {back} frames"));
                        }
                    }
                }
            }
        }
    }
    for l in &report {
        println!("{l}");
    }
    println!("{} problems", report.len());
}

/// A pelvis-forward curve edited flat at the double support (the keyed path nearly still
/// where the launch hands over) must not make a start wait for ever or fail: the launch is
/// capped at 1.5 cycles.
#[test]
fn a_start_onto_a_nearly_still_keyed_path_sets_off_within_two_cycles() {
    let text = "[[walk.schedule]]\ntime_s = 0.3\nstart = true\n[curves.pelvis_forward_ds_ms]\npoints = [[0.0, 0.0], [0.33, 0.0], [0.66, 0.7], [1.0, 1.0]]\n";
    let p = config::load_text(text, "t.toml", &[]).unwrap();
    let (frames, w) = walk(&p, 6.0, FPS);
    let c = analysis::checks(&frames);
    assert_eq!(c.non_finite_values, 0, "{c:?}");
    let e = w.pace_events();
    assert_eq!(e[1].kind.name(), "first_step", "{:?}", e.iter().map(|e| e.kind.name()).collect::<Vec<_>>());
    let cycle_s = w.resolved().cycle_s;
    assert!(e[1].time_s - e[0].time_s < 2.0 * cycle_s, "first step {:.2} s after the ask", e[1].time_s - e[0].time_s);
}

/// A speed asked while standing is the speed the walk sets off at (the schedule's
/// stop, speed, start), and a start then walks it.
#[test]
fn a_speed_asked_while_standing_is_the_speed_the_walk_sets_off_at() {
    let mut p = presets::params("default").unwrap().unwrap();
    p.schedule = vec![
        at_time(0.2, PaceAction::Start),
        at_time(4.0, PaceAction::Stop),
        at_time(6.5, PaceAction::Speed(0.8)),
        at_time(7.0, PaceAction::Start),
    ];
    let (frames, w) = walk(&p, 14.0, FPS);
    let c = analysis::checks(&frames);
    assert!(c.foot_skate_mm < 1.0 && c.reach_failures == 0 && c.non_finite_values == 0, "{c:?}");
    assert!((w.params().walk.speed_mps - 0.8).abs() < 1e-12);
    let kinds: Vec<&str> = w.pace_events().iter().map(|e| e.kind.name()).collect();
    assert!(kinds.windows(3).any(|k| k == ["speed_asked", "speed_reached", "start_asked"]), "{kinds:?}");
    // The last three seconds walk 0.8 m/s.
    let tail = &frames[frames.len() - 181..];
    let v = (tail[180].pelvis.x - tail[0].pelvis.x) / (tail[180].time_s - tail[0].time_s);
    assert!((v - 0.8).abs() < 0.05, "{v}");
}

/// A swing toe stays above the flat ground it leaves, through a start, a stop and a start again,
/// at several speeds and two body heights. `analysis::checks` measures penetration on stance
/// feet only, so this looks at the swinging ones: session 22's first pitch carry (the swing foot
/// carrying its toe-off pitch rate on) dipped a start's first swing toe 3-7 mm into the ground
/// (start_stop at 1.3 m/s 5.0 mm, a 2.0 m body 7.3). Measured after the fix: at most 0.6 mm, at
/// the first swing frame of a start (older, and under the 1 mm held here).
#[test]
fn a_swing_toe_does_not_dip_into_the_flat_ground_it_leaves() {
    for (speed, height) in [(0.7, 1.75), (1.0, 1.75), (1.3, 1.75), (1.6, 1.75), (1.3, 2.0), (1.6, 2.0), (1.3, 1.5)] {
        let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("configs/default.toml");
        let sets = [format!("walk.speed_mps={speed}"), format!("body.height_m={height}")];
        let mut p = config::load(&path, &sets).unwrap();
        p.schedule = start_stop_start("default").schedule;
        let (frames, _) = walk(&p, 14.0, FPS);
        let deepest = frames
            .iter()
            .flat_map(|f| {
                f.legs.iter().filter(|l| l.leg_phase == LegPhase::Swing).map(|l| l.ground_under_heel - l.toe.y)
            })
            .fold(0.0_f64, f64::max);
        assert!(deepest < 0.001, "{speed} m/s, {height} m: a swing toe {:.2} mm under the ground", deepest * 1000.0);
    }
}
