//! The normative gait file in data/normative/ (Fukuchi et al. 2018, CC BY 4.0): it parses,
//! and its curves are those of adult walking, so the fidelity work can lean on it.

fn table() -> Vec<Vec<f64>> {
    let text = include_str!("../data/normative/normative_adult_walking.csv");
    let mut lines = text.lines().filter(|l| !l.starts_with('#'));
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    assert_eq!(header[0], "pct_cycle");
    assert_eq!(header.len(), 14);
    lines.map(|l| l.split(',').map(|v| v.parse().unwrap()).collect()).collect()
}

#[test]
fn the_normative_curves_are_adult_walking() {
    let rows = table();
    assert_eq!(rows.len(), 101);
    for (i, r) in rows.iter().enumerate() {
        assert_eq!(r[0], i as f64, "every 1 % of the cycle");
        assert!(r.iter().all(|v| v.is_finite()));
        assert!(r[3] > 0.0 && r[5] > 0.0 && r[7] > 0.0, "SDs positive at {i} %");
    }
    let peak = |col: usize, from: usize, to: usize| {
        rows[from..=to]
            .iter()
            .map(|r| (r[col], r[0]))
            .fold((f64::NEG_INFINITY, 0.0), |a, b| if b.0 > a.0 { b } else { a })
    };
    let low = |col: usize, from: usize, to: usize| {
        rows[from..=to].iter().map(|r| (r[col], r[0])).fold((f64::INFINITY, 0.0), |a, b| if b.0 < a.0 { b } else { a })
    };
    // Knee: loading-response peak 15-20 deg near 12-15 %, swing peak 55-65 deg at 70-75 %.
    let (k1, at1) = peak(4, 5, 25);
    assert!((14.0..=20.0).contains(&k1) && (10.0..=16.0).contains(&at1), "{k1} at {at1}");
    let (k2, at2) = peak(4, 60, 90);
    assert!((55.0..=66.0).contains(&k2) && (70.0..=76.0).contains(&at2), "{k2} at {at2}");
    // Ankle: push-off plantarflexion 12-20 deg just after toe-off (60-68 %).
    let (a, at) = low(6, 50, 80);
    assert!((-20.0..=-12.0).contains(&a) && (60.0..=68.0).contains(&at), "{a} at {at}");
    // Hip: terminal-stance extension around 50-56 %, flexion peak 30-35 deg late in swing.
    let (h, at) = low(2, 40, 70);
    assert!(h < -5.0 && (48.0..=58.0).contains(&at), "{h} at {at}");
}

/// The joint-angle norms by speed (`joint_angles_by_speed.csv`): six blocks from 0.58 to 1.80
/// m/s, speeds rising, the 0.583 m/s block (session 26: 24 adults' T01 / T02 trials at 0.51-0.69
/// m/s) the slowest. People flex the knee more in loading and in swing the faster they walk, and
/// the slowest block pushes off least: loading knee 6.4 / 8.3 / 11.3 / 16.5 / 19.9 / 22.0°,
/// swing knee 53.9 / 57.5 / 60.6 / 63.0 / 63.4 / 63.5°, push-off -4.6 / -7.9 / -10.7 / -14.5 /
/// -15.8 / -15.4°.
#[test]
fn the_joint_angle_norms_run_from_0_58_to_1_80_m_s_and_follow_speed() {
    let refs = gaitlab::normative::References::built_in();
    let speeds: Vec<f64> = refs.blocks.iter().map(|b| b.speed_mps).collect();
    assert_eq!(speeds, [0.583, 0.796, 0.997, 1.303, 1.593, 1.799]);
    let peak = |b: &gaitlab::normative::Reference, stem: &str, from: usize, to: usize, sign: f64| {
        let mean = &b.curves.iter().find(|c| c.0 == stem).unwrap().1;
        (from..=to).map(|i| sign * mean[i]).fold(f64::NEG_INFINITY, f64::max) * sign
    };
    let loading: Vec<f64> = refs.blocks.iter().map(|b| peak(b, "knee_flex", 0, 25, 1.0)).collect();
    let swing: Vec<f64> = refs.blocks.iter().map(|b| peak(b, "knee_flex", 60, 90, 1.0)).collect();
    let push_off: Vec<f64> = refs.blocks.iter().map(|b| peak(b, "ankle_dorsi", 55, 80, -1.0)).collect();
    for w in 0..5 {
        assert!(loading[w] < loading[w + 1] && swing[w] < swing[w + 1], "{loading:?} {swing:?}");
    }
    assert!((loading[0] - 6.38).abs() < 0.01 && (swing[0] - 53.85).abs() < 0.01, "{loading:?} {swing:?}");
    assert!(push_off[0] > push_off[1] && (push_off[0] + 4.60).abs() < 0.01, "{push_off:?}");
}

/// The spatiotemporal norms by speed (`spatiotemporal_by_speed.csv`, Fukuchi et al. 2018 via
/// BMClab/h2a_age_spt): six treadmill blocks whose figures agree with their own speeds, and
/// which rise with speed as cadence and stride do in every adult gait study.
#[test]
fn the_spatiotemporal_norms_by_speed_are_adult_walking_at_six_speeds() {
    use gaitlab::normative::SpeedNorms;
    let text = include_str!("../data/normative/spatiotemporal_by_speed.csv");
    let header = text.lines().find(|l| !l.starts_with('#')).unwrap();
    assert_eq!(
        header,
        "trial,pct_of_comfortable,n_subjects,speed_m_s,speed_sd_m_s,cadence_mean_spm,cadence_sd_spm,stride_length_mean_m,stride_length_sd_m"
    );
    let norms = SpeedNorms::built_in();
    let speeds: Vec<f64> = norms.blocks.iter().map(|b| b.speed_mps).collect();
    assert_eq!(speeds, [0.493, 0.678, 0.862, 1.048, 1.232, 1.417]);
    for w in norms.blocks.windows(2) {
        assert!(w[1].cadence_spm.0 > w[0].cadence_spm.0 + 5.0, "cadence rises with speed: {w:?}");
        assert!(w[1].stride_length_m.0 > w[0].stride_length_m.0 + 0.08, "stride rises with speed: {w:?}");
    }
    for b in &norms.blocks {
        // Units: steps/min and metres, so speed = stride x cadence / 120 (two steps a stride).
        let implied = b.stride_length_m.0 * b.cadence_spm.0 / 120.0;
        assert!((implied / b.speed_mps - 1.0).abs() < 0.01, "{b:?}: {implied}");
        assert!((5.0..8.0).contains(&b.cadence_spm.1) && (0.07..0.14).contains(&b.stride_length_m.1), "{b:?}");
    }
}

/// Which blocks a walk's speed takes: the two around it, interpolated; the end block beyond
/// the data (never extrapolated); a block's own speed gives that block.
#[test]
fn a_walks_speed_takes_the_blocks_around_it() {
    use gaitlab::normative::SpeedNorms;
    let norms = SpeedNorms::built_in();
    let pick = |v: f64| {
        let n = norms.at(v);
        (n.from_block_mps, n.to_block_mps)
    };
    assert_eq!(pick(0.8), (0.678, 0.862));
    assert_eq!(pick(1.3), (1.232, 1.417));
    assert_eq!(pick(1.6), (1.417, 1.417));
    assert_eq!(pick(0.3), (0.493, 0.493));
    assert_eq!(pick(1.048), (1.048, 1.232));
    let exact = norms.at(1.048);
    assert!((exact.cadence_spm.0 - 107.5).abs() < 1e-9 && (exact.stride_length_m.0 - 1.169).abs() < 1e-9);
    // Halfway between T05 and T06: the means' and SDs' midpoints.
    let mid = norms.at((1.232 + 1.417) / 2.0);
    assert!((mid.cadence_spm.0 - (115.8 + 123.1) / 2.0).abs() < 1e-9, "{mid:?}");
    assert!((mid.stride_length_m.1 - (0.122 + 0.134) / 2.0).abs() < 1e-9, "{mid:?}");
    assert_eq!(norms.at(1.6).cadence_spm, (123.1, 6.7), "the fastest block, unchanged");
    assert!(norms.at(1.6).blocks_used().contains("the 1.417 m/s block, the fastest"));
    assert!(norms.at(0.8).blocks_used().contains("between the 0.678 and 0.862 m/s blocks"));
    assert!(norms.at(f64::NAN).cadence_spm.0.is_finite(), "never NaN norms");
}

#[test]
fn a_bad_speed_table_is_refused_with_its_place() {
    use gaitlab::normative::SpeedNorms;
    let text = include_str!("../data/normative/spatiotemporal_by_speed.csv");
    let swapped = text.replace("T02,55,22,0.678", "T02,55,22,0.400");
    let e = SpeedNorms::parse(&swapped, "s.csv").unwrap_err().to_string();
    assert!(e.starts_with("s.csv:5:") && e.contains("speeds must rise"), "{e}");
    let e = SpeedNorms::parse(&text.replace("cadence_sd_spm", "cad_sd"), "s.csv").unwrap_err().to_string();
    assert!(e.contains("no column `cadence_sd_spm`"), "{e}");
    let e = SpeedNorms::parse(&text.replace(",72.7,", ",nan,"), "s.csv").unwrap_err().to_string();
    assert!(e.starts_with("s.csv:4:") && e.contains("positive numbers"), "{e}");
}
