//! The report records its walk once and reads everything from that recording: tables, BVH,
//! stick figure, optimisation landscape, IK section. Alone in its own test binary, because
//! the count of walkers built is process-wide.

#[test]
fn the_default_report_walks_its_config_exactly_once() {
    let text = gaitlab::config::presets::default_text();
    let params = gaitlab::config::load_text(text, "default.toml", &[]).unwrap();
    let dir = std::env::temp_dir().join(format!("gaitlab-walks-once-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    let target = gaitlab::report::resolve_out(&dir.join("r"), false).unwrap();
    let input = gaitlab::report::ReportInput {
        name: "default".into(),
        source_text: text,
        params: &params,
        cycles: 4,
        fps: params.sim.fps,
        compare: Vec::new(),
        ik_solvers: Vec::new(),
    };
    let before = gaitlab::model::walk::walkers_built();
    gaitlab::report::write_report(&input, &target, &mut |_| {}).unwrap();
    assert_eq!(gaitlab::model::walk::walkers_built() - before, 1, "walkers built by one report");
    assert!(dir.join("r/walk.bvh").is_file() && dir.join("r/plots/optimisation.png").is_file());
    std::fs::remove_dir_all(&dir).unwrap();
}
