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
