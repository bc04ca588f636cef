//! Stairs the config fuzzer and a sweep found broken: the trailing foot in heel rise could
//! not reach once the pelvis rose toward an upper landing, so its toe tore off the tread
//! into the next riser (75–111 mm under the steps). The pelvis reach guard now also keeps the
//! trailing leg's heel rise within reach up to its toe-off.
//!
//! Since session 23 the checks count swinging feet too; the tests below the first two hold
//! the swing clear of risers, nosings and the ground it leaves (rough ground included).

use gaitlab::analysis::{Keep, checks, record};

fn walk(text: &str, cycles: f64) -> gaitlab::analysis::Checks {
    walk_at(text, cycles, 60.0)
}

fn walk_at(text: &str, cycles: f64, fps: f64) -> gaitlab::analysis::Checks {
    let params = gaitlab::config::load_text(text, "stairs.toml", &[]).unwrap();
    let run = record(&params, cycles, fps, Keep::default()).unwrap();
    checks(&run.frames)
}

#[test]
fn the_fuzzers_stair_walks_stay_on_the_treads() {
    let cases = [
        // Ten steps at the default pace: 75 mm under the steps before.
        "[terrain]\nkind = \"stairs\"\ncount = 10\n",
        // The stairs_up preset at 1.6 m/s: 103 mm.
        "[terrain]\nkind = \"stairs\"\ndirection = \"up\"\ncount = 8\n[walk]\nspeed_mps = 1.6\n",
        // A long stride with a knee lift: 111 mm and 5 reach failures.
        "[terrain]\nkind = \"stairs\"\ndirection = \"up\"\ncount = 8\n[walk]\nstride_m = 1.8721904325932708\n[legs]\nknee_lift_cm = 4.0\n",
    ];
    for text in cases {
        let c = walk(text, 10.0);
        assert!(c.terrain_penetration_mm <= 1.0, "{text}: {c:?}");
        assert!(c.foot_skate_mm <= 0.5, "{text}: {c:?}");
        assert_eq!(c.reach_failures, 0, "{text}: {c:?}");
    }
}

#[test]
fn stairs_up_at_any_pace_and_length_stay_on_the_treads() {
    for count in [8, 14] {
        for speed in [0.9, 1.2, 1.5, 1.8] {
            let text = format!(
                "[terrain]\nkind = \"stairs\"\ndirection = \"up\"\ncount = {count}\n[walk]\nspeed_mps = {speed}\n"
            );
            let c = walk(&text, 4.0 + f64::from(count) * 0.34 / 1.2);
            assert!(
                c.terrain_penetration_mm <= 1.0 && c.foot_skate_mm <= 0.5 && c.reach_failures == 0,
                "{text}: {c:?}"
            );
        }
    }
}

/// The swinging feet count too (`checks` read stance feet only until session 23). The swing
/// toe, set off 1.5-6 cm short of the next riser, went into it in the first swing frames,
/// 95 mm at the default pace up 10 treads and 65-124 mm at 0.5-1.5 m/s; down a flight the
/// toe dipped 0.6-1.2 mm into the tread it left and the heel cut the nosing it came down
/// past (21 mm at 1.3 m/s). Every pace, both ways, a long and a short flight.
#[test]
fn swinging_feet_clear_risers_and_nosings_at_every_pace() {
    for direction in ["up", "down"] {
        for count in [6, 10] {
            for speed in [0.5_f64, 0.7, 0.9, 1.1, 1.3, 1.5] {
                let text = format!(
                    "[terrain]\nkind = \"stairs\"\ndirection = \"{direction}\"\ncount = {count}\n[walk]\nspeed_mps = {speed}\n"
                );
                let c = walk(&text, 4.0 + f64::from(count));
                assert!(c.terrain_penetration_mm < 0.01 && c.reach_failures == 0, "{text}: {c:?}");
            }
        }
    }
}

/// Between two frames a heel coming down onto a lower tread passed under the nosing (at 240
/// frames a second, 3.0 mm at 0.9 m/s and 21 mm at 1.3 m/s, where 60 showed none at 0.9): the
/// swing simulation now follows the heel between its samples, so a finer frame rate finds
/// nothing either.
#[test]
fn a_heel_does_not_cut_a_nosing_between_frames() {
    for speed in [0.9, 1.3] {
        let text =
            format!("[terrain]\nkind = \"stairs\"\ndirection = \"down\"\ncount = 10\n[walk]\nspeed_mps = {speed}\n");
        let c = walk_at(&text, 8.0, 240.0);
        assert!(c.terrain_penetration_mm < 0.05 && c.reach_failures == 0, "{text}: {c:?}");
    }
}

/// `checks` reads a swinging foot's heel and toe tip against the ground under them, as the
/// interface defines `terrain_penetration_mm` (the deepest any heel or toe tip goes).
#[test]
fn a_swinging_toe_under_the_ground_is_counted() {
    let params = gaitlab::config::load_text("", "flat.toml", &[]).unwrap();
    let mut run = record(&params, 3.0, 60.0, Keep::default()).unwrap();
    assert!(checks(&run.frames).terrain_penetration_mm < 1e-9);
    let (k, side) = (0..run.frames.len())
        .flat_map(|k| [(k, 0), (k, 1)])
        .find(|&(k, i)| run.frames[k].legs[i].leg_phase == gaitlab::model::walk::leg::LegPhase::Swing)
        .unwrap();
    let leg = &mut run.frames[k].legs[side];
    // Flat ground: the ground is at 0.
    leg.toe.y = -0.012;
    let c = checks(&run.frames);
    assert!((c.terrain_penetration_mm - 12.0).abs() < 1e-9, "{c:?}");
    assert_eq!(c.worst_penetration.map(|(frame, _)| frame), Some(run.frames[k].frame));
}

/// Stair walks two reviews found still under the treads (the first with the riser hold in the
/// swing target alone): a riser 10-11 cm ahead of the toe at fast paces (outside the hold's first
/// reach), and toes cutting nosings between two swing samples late in a swing up long treads.
/// `(sets, frames a second)`.
const REVIEWED_FLIGHTS: [(&str, f64); 10] = [
    ("terrain.count=10 walk.speed_mps=1.3", 60.0),
    ("terrain.count=10 walk.speed_mps=2.0 terrain.start_x_m=1.7", 60.0),
    ("terrain.count=6 walk.speed_mps=1.6", 240.0),
    ("terrain.count=1 walk.speed_mps=2.0", 60.0),
    ("terrain.count=3 walk.speed_mps=2.0 terrain.start_x_m=1.99", 240.0),
    ("terrain.count=6 walk.speed_mps=1.5 terrain.rise_m=0.2 terrain.run_m=0.8", 240.0),
    (
        "terrain.count=10 walk.speed_mps=1.6 body.height_m=1.9 legs.clearance_cm=0.5 terrain.rise_m=0.18 terrain.run_m=0.5 walk.stride_m=1.5",
        60.0,
    ),
    ("terrain.count=6 terrain.rise_m=0.10 terrain.run_m=0.5 walk.speed_mps=2.0", 60.0),
    // Down, fast, at 0.5 cm clearance: the heel landed two clearances (1 cm) past the nosing
    // and cut it coming down, 13.6 and 28.2 mm (a second review's find).
    (
        "terrain.direction=down terrain.count=6 walk.speed_mps=2.0 body.height_m=1.6 legs.knee_lift_cm=0 legs.clearance_cm=0.5 terrain.rise_m=0.1 terrain.run_m=0.4",
        60.0,
    ),
    (
        "terrain.direction=down terrain.count=20 walk.speed_mps=2.0 body.height_m=1.6 legs.knee_lift_cm=0 legs.clearance_cm=0.5 terrain.rise_m=0.2 terrain.run_m=0.5",
        60.0,
    ),
];

fn flight(sets: &str, fps: f64) -> gaitlab::analysis::Run {
    let sets: Vec<String> = ["terrain.kind=stairs"].into_iter().chain(sets.split(' ')).map(String::from).collect();
    let params = gaitlab::config::load_text("", "flight.toml", &sets).unwrap();
    record(&params, 12.0, fps, Keep::default()).unwrap()
}

#[test]
fn the_reviewed_flights_stay_on_the_treads() {
    for (sets, fps) in REVIEWED_FLIGHTS {
        let c = checks(&flight(sets, fps).frames);
        assert!(c.terrain_penetration_mm < 0.05 && c.reach_failures == 0, "{sets} at {fps} fps: {c:?}");
    }
}

/// The toe held behind a riser by the swing target alone built up a debt while the heel's
/// planned way went on, paid back in one frame as it passed the nosing: the heel stepped back up
/// to 49 mm in a frame and then jumped 10-18 cm, the knee straight for a frame at 2.0 m/s. The
/// swing now lags on such a step (the foot goes up before it goes forward): over these flights
/// the heel steps back at most 3 mm in a frame, and no frame's toe step is more than 30 mm
/// longer than both its neighbours' at 60 fps (94 with the debt; 20-31 before any hold) or
/// 6 mm at 240 (46-84 with the debt).
#[test]
fn a_foot_held_behind_a_riser_is_not_let_go_in_a_jump() {
    // Up: the hold is for risers ahead (a fast swing down a flight of long treads swings its
    // foot 40 cm up, as it did before any hold: noted, not held here).
    for (sets, fps) in REVIEWED_FLIGHTS.into_iter().filter(|(sets, _)| !sets.contains("direction=down")) {
        let run = flight(sets, fps);
        let (mut heel_back_mm, mut toe_jump_mm) = (0.0_f64, 0.0_f64);
        for i in 0..2 {
            let step = |k: usize| run.frames[k].legs[i].toe.distance(run.frames[k - 1].legs[i].toe) * 1000.0;
            for k in 2..run.frames.len() - 1 {
                let back = run.frames[k - 1].legs[i].heel.x - run.frames[k].legs[i].heel.x;
                heel_back_mm = heel_back_mm.max(back * 1000.0);
                toe_jump_mm = toe_jump_mm.max(step(k) - step(k - 1).max(step(k + 1)));
            }
        }
        let allowed_mm = if fps > 100.0 { 8.0 } else { 32.0 };
        assert!(
            heel_back_mm < 5.0 && toe_jump_mm < allowed_mm,
            "{sets} at {fps} fps: heel back {heel_back_mm:.1} mm, toe jump {toe_jump_mm:.1} mm"
        );
    }
}

/// On rough ground the swing toe dipped up to 2.2 mm back into the ground it left in the
/// first swing frames (seen at 240 frames a second; 48 of a reviewer's 120 random grounds):
/// the toe's floor follows the piece of ground under it, sloped as it is.
#[test]
fn a_swing_toe_does_not_dip_into_rough_ground() {
    for (seed, amplitude, speed) in [(1, 0.2, 1.0), (7, 0.2, 0.4), (42, 0.2, 1.0), (942451, 0.2, 0.4), (99, 0.05, 1.0)]
    {
        let text = format!(
            "[terrain]\nkind = \"random\"\nseed = {seed}\namplitude_m = {amplitude}\nroughness = 0.3\nsegment_m = 0.5\n[walk]\nspeed_mps = {speed}\n"
        );
        let c = walk_at(&text, 8.0, 240.0);
        assert!(c.terrain_penetration_mm < 0.01 && c.reach_failures == 0, "{text}: {c:?}");
    }
}

/// `legs.clearance_cm = 0` is a valid setting, and the walk keeps 2 mm all the same
/// (`terrain::LEAST_CLEARANCE_M`). At none, up 20 tall treads a planted toe stood on the riser's
/// plane (200 mm under the upper tread by the checks) and the swing simulation lifted a heel
/// 1.5 m (18 reach failures); down a flight at 0-0.5 cm a heel landing 1 cm past a nosing was
/// thrown up to 75 cm over the tread, the hip flexing 60° in a frame, and came down through
/// the nosing (43 and 114 mm under it).
#[test]
fn a_clearance_of_none_walks_the_stairs_as_a_small_one() {
    let flights = [
        "terrain.count=20 terrain.rise_m=0.2 terrain.run_m=0.31 walk.speed_mps=0.4 body.height_m=1.5 legs.clearance_cm=0 legs.knee_lift_cm=2",
        "terrain.direction=down terrain.count=10 terrain.rise_m=0.15 terrain.run_m=0.31 walk.speed_mps=2.0 legs.clearance_cm=0.2 legs.knee_lift_cm=2",
        "terrain.direction=down terrain.count=10 terrain.rise_m=0.15 terrain.run_m=0.31 walk.speed_mps=1.5 body.height_m=1.9 legs.clearance_cm=0 legs.knee_lift_cm=0",
    ];
    for sets in flights {
        let run = flight(sets, 60.0);
        let c = checks(&run.frames);
        assert!(c.terrain_penetration_mm < 0.05 && c.reach_failures == 0, "{sets}: {c:?}");
        let mut hip_step_deg = 0.0_f64;
        for i in 0..2 {
            for k in 1..run.frames.len() {
                let step = run.frames[k].legs[i].hip_flex_deg - run.frames[k - 1].legs[i].hip_flex_deg;
                hip_step_deg = hip_step_deg.max(step.abs());
            }
        }
        // 14-19° a frame at 60 fps over these flights (before: 360 up the tall treads, the leg
        // turned over; 55 and 63 thrown down the two flights).
        assert!(hip_step_deg < 25.0, "{sets}: the hip flexed {hip_step_deg:.1}° in a frame");
    }
}
