//! Stairs the config fuzzer and a sweep found broken: the trailing foot in heel rise could
//! not reach once the pelvis rose toward an upper landing, so its toe tore off the tread
//! into the next riser (75–111 mm under the steps). The pelvis reach guard now also keeps the
//! trailing leg's heel rise within reach up to its toe-off.

use gaitlab::analysis::{Keep, checks, record};

fn walk(text: &str, cycles: f64) -> gaitlab::analysis::Checks {
    let params = gaitlab::config::load_text(text, "stairs.toml", &[]).unwrap();
    let run = record(&params, cycles, 60.0, Keep::default()).unwrap();
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
