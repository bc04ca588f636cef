//! Steady-state figures on the steady part only (issue 14, point 5): a scheduled walk's
//! plateaus are measured apart from its speed changes, stop and standing; standing has no
//! cycles; the report's *Pace* table has a row per plateau with those figures and the
//! headline names the part measured; `gaitlab compare` says which part it compared; a walk
//! without a schedule is one steady part and its snapshot bytes are unchanged.

use gaitlab::analysis::steady::{self, Part, PartKind};
use gaitlab::analysis::{self, Run};
use gaitlab::model::params::TerrainChoice;
use gaitlab::model::walk::leg::LegPhase;
use gaitlab::model::walk::pace::{PaceEventKind, WalkState};
use gaitlab::report::metrics;
use std::path::{Path, PathBuf};
use std::process::Command;

/// 0.8 m/s, 1.6 from 6 s, 1.0 from 12 s, a stop at 18 s: plateaus long enough for whole
/// gait cycles, then about 3 s standing (18 cycles of the first speed's, 1.285 s).
const SCHEDULED: &str = "[walk]\nspeed_mps = 0.8\n\n\
    [[walk.schedule]]\ntime_s = 6.0\nspeed_mps = 1.6\n\n\
    [[walk.schedule]]\ntime_s = 12.0\nspeed_mps = 1.0\n\n\
    [[walk.schedule]]\ntime_s = 18.0\nstop = true\n";
const CYCLES: u32 = 18;
const ASKED: [f64; 3] = [0.8, 1.6, 1.0];

fn temp(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("gaitlab-steady-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn gaitlab(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_gaitlab")).args(args).current_dir(env!("CARGO_MANIFEST_DIR")).output().unwrap()
}

/// The scheduled config written to `dir`, and its walk.
fn scheduled(dir: &Path) -> (PathBuf, Run) {
    let path = dir.join("scheduled.toml");
    std::fs::write(&path, SCHEDULED).unwrap();
    let params = gaitlab::config::load(&path, &[]).unwrap();
    let run = analysis::run(&params, f64::from(CYCLES), params.sim.fps).unwrap();
    (path, run)
}

fn plateaus(parts: &[Part]) -> Vec<&Part> {
    parts.iter().filter(|p| p.kind == PartKind::Plateau).collect()
}

/// When the `n`th speed change (from 1) was asked (s).
fn ramp_asked(run: &Run, n: usize) -> f64 {
    let mut asked = run.pace_events.iter().filter(|e| matches!(e.kind, PaceEventKind::SpeedAsked(_)));
    asked.nth(n - 1).expect("a speed asked for each plateau after the first").time_s
}

#[test]
fn each_plateau_is_measured_after_its_speed_was_reached_and_within_3_percent() {
    let dir = temp("plateaus");
    let (_, run) = scheduled(&dir);
    let parts = steady::parts(&run);
    let plateaus = plateaus(&parts);
    assert_eq!(plateaus.iter().map(|p| p.asked_mps).collect::<Vec<_>>(), ASKED);
    let reached: Vec<f64> =
        run.pace_events.iter().filter(|e| matches!(e.kind, PaceEventKind::SpeedReached(_))).map(|e| e.time_s).collect();
    assert_eq!(reached.len(), 2);
    for (n, p) in plateaus.iter().enumerate() {
        let figures = steady::step_figures(&run.frames, p).expect("whole steps on every plateau");
        let asked = ASKED[n];
        assert!((figures.speed_mps / asked - 1.0).abs() < 0.03, "plateau {n}: {:.3} m/s of {asked}", figures.speed_mps);
        assert!(p.cycles() >= 2, "plateau {n}: {} whole cycles", p.cycles());
        // Over whole cycles, as the headline figures are measured, too.
        let first = (p.strikes[0], *p.strikes.last().unwrap());
        let cycle_speed = (run.frames[first.1].pelvis.x - run.frames[first.0].pelvis.x)
            / (run.frames[first.1].time_s - run.frames[first.0].time_s);
        assert!((cycle_speed / asked - 1.0).abs() < 0.03, "plateau {n}: {cycle_speed:.3} m/s over cycles");
        if n > 0 {
            // After the ramp: later than the heel strike that reached the speed, at the step
            // after it, and no heel strike between.
            let from = run.frames[p.first].time_s;
            assert!(from > reached[n - 1] + 0.1, "plateau {n} from {from:.2} s, reached at {:.2} s", reached[n - 1]);
            let ramp = &parts[parts.iter().position(|q| q.first == p.first).unwrap() - 1];
            assert_eq!(ramp.kind, PartKind::SpeedChange);
            // Both heel strikes that take a step of the ramp, and the one the cadence blend
            // after it ends at (a gait cycle after the reaching strike), are the speed
            // change's, not the plateau's; the plateau starts at the blend's end. A speed
            // asked during a swing waits for the next toe-off to plan with it: the strike
            // that swing lands at takes no step of the ramp and is the change's too.
            let asked = ramp_asked(&run, n);
            let first_strike = run.frames[ramp.steps[0]].time_s;
            let planned = run.frames.windows(2).any(|w| {
                (asked..first_strike).contains(&w[1].time_s)
                    && w[1]
                        .legs
                        .iter()
                        .zip(&w[0].legs)
                        .any(|(b, a)| b.leg_phase == LegPhase::Swing && a.leg_phase != LegPhase::Swing)
            });
            let waited = usize::from(!planned);
            assert_eq!(ramp.steps.len(), 3 + waited, "heel strikes in the speed change: {:?}", ramp.steps);
            assert_eq!(p.steps[0], p.first, "a plateau starts at a heel strike");
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn standing_after_the_stop_has_no_cycle_and_no_step() {
    let dir = temp("standing");
    let (_, run) = scheduled(&dir);
    let parts = steady::parts(&run);
    let standing = parts.last().unwrap();
    assert_eq!(standing.kind, PartKind::NotWalking(WalkState::Standing));
    let (from, to) = standing.span_s(&run.frames);
    assert!(to - from > 2.0, "standing {from:.2}-{to:.2} s");
    // The legs' cycle phases run on while the walker stands (so a phase wrap alone would count
    // cycles there): both wrap at least once.
    let stand = &run.frames[standing.first..standing.end];
    for side in 0..2 {
        assert!(stand.windows(2).any(|w| w[1].legs[side].phase < w[0].legs[side].phase), "leg {side}");
    }
    assert!(standing.strikes.is_empty() && standing.steps.is_empty(), "{:?} {:?}", standing.strikes, standing.steps);
    let cycles = analysis::cycle_summaries(&run.frames);
    let last_end: f64 = cycles.iter().map(|c| c.duration_s).sum::<f64>();
    assert!(last_end <= from + 1e-9, "a cycle ends at {last_end:.2} s, standing from {from:.2} s");
    // The stop's own parts are transitions, never a plateau: the step under way when it is
    // asked, the braking step, the closing step and settle.
    let kinds: Vec<PartKind> = parts.iter().map(|p| p.kind).collect();
    let stop_kinds = [PartKind::NotWalking(WalkState::Stopping), PartKind::Braking, PartKind::Closing];
    assert_eq!(kinds[kinds.len() - 4..kinds.len() - 1], stop_kinds, "{kinds:?}");
    let window = metrics::steady_window(&run).unwrap();
    let stopping = &parts[parts.len() - 4];
    assert!(window.last < stopping.first, "measured up to frame {}, stopping from {}", window.last, stopping.first);
    let _ = std::fs::remove_dir_all(&dir);
}

/// Row cells of the *Pace* section's plateau table.
fn plateau_rows(md: &str) -> Vec<Vec<String>> {
    let pace = &md[md.find("## Pace").expect("a Pace section")..];
    pace.lines()
        .skip_while(|l| !l.starts_with("| plateau |"))
        .skip(2)
        .take_while(|l| l.starts_with('|'))
        .map(|l| l.trim_matches('|').split('|').map(|c| c.trim().to_string()).collect())
        .collect()
}

#[test]
fn the_report_tables_each_plateau_and_names_the_part_its_figures_are_from() {
    let dir = temp("report");
    let (config, run) = scheduled(&dir);
    let out_dir = dir.join("report");
    let cycles = CYCLES.to_string();
    let out = gaitlab(&["report", config.to_str().unwrap(), "--out", out_dir.to_str().unwrap(), "--cycles", &cycles]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let md = std::fs::read_to_string(out_dir.join("summary.md")).unwrap();
    let rows = plateau_rows(&md);
    assert_eq!(rows.len(), 3, "{md}");
    let parts = steady::parts(&run);
    let plateaus = plateaus(&parts);
    let most = plateaus.iter().map(|p| p.cycles()).max().unwrap();
    for ((row, asked), p) in rows.iter().zip(ASKED).zip(&plateaus) {
        let number = |i: usize| row[i].parse::<f64>().unwrap_or_else(|_| panic!("{row:?}"));
        assert_eq!(number(1), asked);
        assert!((number(2) / asked - 1.0).abs() < 0.03, "{row:?}");
        let f = steady::step_figures(&run.frames, p).unwrap();
        assert_eq!(
            row[2..6],
            [
                format!("{:.3}", f.speed_mps),
                format!("{:.1}", f.cadence_spm),
                format!("{:.3}", f.stride_m),
                format!("{:.1}", f.stance_pct)
            ]
        );
        let span: Vec<f64> = row[6].split('–').map(|t| t.parse().unwrap()).collect();
        assert!(span[0] < span[1] && span[1] <= run.frames[p.end - 1].time_s + 0.005, "{row:?}");
        assert_eq!((row[7].parse::<usize>().unwrap(), row[8].parse::<usize>().unwrap()), (p.whole_steps(), p.cycles()));
        // The one measured is the one with the most whole cycles (the later on a tie).
        let measured = row[0].ends_with("measured");
        assert_eq!(measured, p.cycles() == most && !plateaus.iter().any(|q| q.first > p.first && q.cycles() == most));
    }
    let window = metrics::steady_window(&run).unwrap();
    let part = window.plateau.expect("a scheduled walk names its steady part");
    let headline = format!("Steady part: {}.", part.describe());
    assert!(md.contains(&headline), "{headline} missing");
    for part in ["speed change", "stopping", "braking step", "closing step and settle", "standing"] {
        assert!(md.contains(&format!("| {part} |")), "{part} missing from the transitions");
    }
    // summary.json's speed is the measured plateau's.
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out_dir.join("summary.json")).unwrap()).unwrap();
    assert!((json["speed_mps"].as_f64().unwrap() / part.asked_mps - 1.0).abs() < 0.03);

    // compare compares the same part, and says so.
    let out = gaitlab(&["compare", config.to_str().unwrap(), "--set", &format!("sim.cycles={CYCLES}")]);
    assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(text.contains(&format!("# steady part compared: {}", part.describe())), "{text}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_walk_without_a_schedule_is_one_steady_part_and_its_snapshots_keep_their_bytes() {
    let params = gaitlab::config::load(Path::new("configs/default.toml"), &[]).unwrap();
    let run = analysis::run(&params, 8.0, params.sim.fps).unwrap();
    let parts = steady::parts(&run);
    assert_eq!(parts.iter().map(|p| p.kind).collect::<Vec<_>>(), [PartKind::StartUp, PartKind::Plateau]);
    let plateau = &parts[1];
    assert_eq!(plateau.end, run.frames.len(), "the plateau runs to the end");
    assert_eq!(plateau.first, plateau.strikes[0], "from the first right heel strike");
    let window = metrics::steady_window(&run).unwrap();
    assert_eq!(window.plateau, None);
    assert_eq!(window.strikes, plateau.strikes[1..], "the whole-walk figures leave out the first whole cycle");
    // Every shipped config's snapshot is, byte for byte, what the walk measures now (the
    // scheduled pace.toml's included: rewritten on purpose for its steady part).
    for entry in std::fs::read_dir("configs").unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_none_or(|e| e != "toml") {
            continue;
        }
        let params = gaitlab::config::load(&path, &[]).unwrap();
        let snapshot = gaitlab::snapshot::measure::measure(&path, &params).unwrap();
        let stored = std::fs::read_to_string(path.with_extension("snap.json")).unwrap();
        assert_eq!(gaitlab::snapshot::format::render(&snapshot), stored, "{}", path.display());
        // A schedule's plateau, or the cycles on stairs or a slope: a part of the walk, named.
        let feature = matches!(params.terrain.kind, TerrainChoice::Stairs | TerrainChoice::Slope);
        assert_eq!(snapshot.steady_part.is_some(), !params.schedule.is_empty() || feature, "{}", path.display());
    }
}

/// On stairs the figures are the stair cycles': configs/stairs_up.toml's right heel strikes at
/// 4.08 / 5.45 / 6.80 / 8.17 s land on treads 0.15 / 0.45 / 0.75 / 1.05 m up, the level
/// approach and landing (0 and 1.2 m) left out; each measured cycle climbs two rises, and the
/// report, compare and the snapshot name the part.
#[test]
fn a_stairs_walk_is_measured_on_its_stair_cycles() {
    let path = Path::new("configs/stairs_up.toml");
    let params = gaitlab::config::load(path, &[]).unwrap();
    let run = analysis::run(&params, f64::from(params.sim.cycles), params.sim.fps).unwrap();
    let window = metrics::steady_window(&run).unwrap();
    let part = window.terrain.expect("the stair cycles");
    assert_eq!((part.cycles, part.on), (3, "on the stairs"));
    let heights: Vec<f64> = window.strikes.iter().map(|&s| run.frames[s].legs[0].heel.y).collect();
    for pair in heights.windows(2) {
        assert!((pair[1] - pair[0] - 0.30).abs() < 1e-6, "each cycle climbs two 15 cm rises: {heights:?}");
    }
    let parts = steady::parts(&run);
    let all = &parts.iter().find(|p| p.kind == PartKind::Plateau).unwrap().strikes;
    assert!(all.len() > window.strikes.len() + 4, "level cycles before and after are left out: {all:?}");
    let snapshot = gaitlab::snapshot::measure::measure(path, &params).unwrap();
    assert_eq!(snapshot.steady_part.as_deref(), Some(part.describe().as_str()));
    assert!(part.describe().contains("3 cycles on the stairs (level walking left out)"), "{}", part.describe());
    // Level ground: every cycle after start-up, no part.
    let level = gaitlab::config::load(Path::new("configs/default.toml"), &[]).unwrap();
    let run = analysis::run(&level, 8.0, level.sim.fps).unwrap();
    let window = metrics::steady_window(&run).unwrap();
    assert_eq!((window.terrain, window.terrain_missed, window.describe()), (None, None, None));
    // Told by where the feet land, not by how far a cycle climbs: treads longer than a step
    // (0.5 m) are still the stairs (5 cycles), and a flight too short for a whole cycle (two
    // treads) leaves every cycle measured, said so.
    let on_stairs = |sets: &[&str]| {
        let sets: Vec<String> = sets.iter().map(|s| (*s).to_string()).collect();
        let p = gaitlab::config::load(path, &sets).unwrap();
        metrics::steady_window(&analysis::run(&p, f64::from(p.sim.cycles), p.sim.fps).unwrap()).unwrap()
    };
    assert_eq!(on_stairs(&["terrain.run_m=0.5"]).terrain.map(|t| t.cycles), Some(5));
    let short = on_stairs(&["terrain.count=2"]);
    assert_eq!((short.terrain, short.terrain_missed), (None, Some("on the stairs")));
    let said = short.describe().unwrap();
    assert!(said.contains("none lies whole on the stairs, so level cycles are averaged in"), "{said}");
}

/// A scheduled walk up stairs: the plateau holds level cycles too, and the figures, the speed
/// plot's shading and the headline are all the stair cycles' (the plot had shaded the whole
/// plateau, 4.00–17.60 s, while the figures were taken on its cycles on the stairs).
#[test]
fn a_scheduled_stairs_walk_shades_and_heads_its_stair_cycles() {
    let dir = temp("stairs-schedule");
    let config = dir.join("stairs_schedule.toml");
    let stairs =
        std::fs::read_to_string("configs/stairs_up.toml").unwrap().replace("start_x_m = 2.0", "start_x_m = 3.0");
    let schedule =
        "\n[[walk.schedule]]\ntime_s = 1.0\nspeed_mps = 0.55\n\n[[walk.schedule]]\ntime_s = 18.0\nstop = true\n";
    std::fs::write(&config, format!("{stairs}{schedule}").replace("cycles = 10", "cycles = 14")).unwrap();
    let params = gaitlab::config::load(&config, &[]).unwrap();
    let run = analysis::run(&params, f64::from(params.sim.cycles), params.sim.fps).unwrap();
    let window = metrics::steady_window(&run).unwrap();
    let (plateau, part) = (window.plateau.expect("the pace changed"), window.terrain.expect("stairs in it"));
    assert!(part.from_s > plateau.from_s && part.cycles < plateau.cycles, "{part:?} inside {plateau:?}");
    let out = dir.join("report");
    let o = gaitlab(&["report", config.to_str().unwrap(), "--out", out.to_str().unwrap()]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let md = std::fs::read_to_string(out.join("summary.md")).unwrap();
    let span = format!("{:.2}–{:.2} s", part.from_s, part.to_s);
    assert!(md.contains(&format!("Steady part: {span}, the 0.55 m/s plateau, {} cycles", part.cycles)), "{md}");
    assert!(md.contains(&format!("Measured on the terrain: {span}, {} cycles on the stairs", part.cycles)), "{md}");
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    assert!(json["steady_part"].as_str().unwrap().starts_with(&span), "{}", json["steady_part"]);
    let svg = std::fs::read_to_string(out.join("plots/speed.svg")).unwrap();
    assert!(svg.contains("summary figures measured here"), "the speed plot shades the measured cycles");
    let _ = std::fs::remove_dir_all(&dir);
}
