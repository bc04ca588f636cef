//! The terrain profile h(x): a 1-D height field the walker crosses along +x (spec §1).
//!
//! Every kind is stored the same way, as heights at the ends of segments of equal width
//! [6.2.1], except stairs, whose vertical risers a height field of finite segments would
//! smear into ramps: stairs keep their exact step function.

/// What the ground looks like.
#[derive(Clone, Debug, PartialEq)]
pub enum TerrainKind {
    /// Level ground at height 0.
    Flat,
    /// A flight of stairs starting at `start_x_m`.
    Stairs {
        /// Height of one step (m).
        rise_m: f64,
        /// Depth of one tread (m).
        run_m: f64,
        /// Number of steps; after the last one the ground is level again.
        count: u32,
        /// Going up (true) or down.
        up: bool,
        /// Where the first riser stands (m along x).
        start_x_m: f64,
    },
    /// A constant grade starting at `start_x_m`.
    Slope {
        /// Grade in per cent (rise over run × 100); negative goes downhill.
        grade_pct: f64,
        /// Where the slope begins (m along x).
        start_x_m: f64,
    },
    /// Midpoint-displacement noise [6.2.1, Martz].
    Random {
        /// Seed of the portable generator: the same seed gives the same ground everywhere.
        seed: u64,
        /// Roughness exponent H ∈ [0, 1]: the displacement range shrinks by 2^(−H) a level.
        roughness: f64,
        /// Range of the first displacement (m).
        amplitude_m: f64,
        /// Width of one final segment (m).
        segment_m: f64,
        /// Length of ground generated (m); beyond it the last height continues.
        length_m: f64,
        /// Level ground before the rough part starts (m), so the walk starts on the flat.
        start_x_m: f64,
    },
}

impl TerrainKind {
    /// Level ground throughout, as the normative adults walked: flat, or a slope of grade 0.
    #[must_use]
    pub fn is_level(&self) -> bool {
        match self {
            TerrainKind::Flat => true,
            TerrainKind::Slope { grade_pct, .. } => *grade_pct == 0.0,
            TerrainKind::Stairs { .. } | TerrainKind::Random { .. } => false,
        }
    }
}

/// A terrain profile, ready to be queried.
#[derive(Clone, Debug)]
pub struct Terrain {
    kind: TerrainKind,
    /// Heights at x = start + i·segment for the random kind.
    samples: Vec<f64>,
}

/// SplitMix64: a tiny, well-studied generator whose output is defined by integer arithmetic
/// alone, so a seed gives the same terrain on every platform and compiler (no `thread_rng`,
/// no dependence on a crate's algorithm choice across versions).
#[derive(Clone, Debug)]
pub struct SplitMix64(u64);

impl SplitMix64 {
    /// A generator started from `seed`.
    #[must_use]
    pub fn new(seed: u64) -> Self {
        SplitMix64(seed)
    }

    /// The next 64 random bits.
    pub(crate) fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// A uniform number in [−1, 1), from the top 53 bits.
    pub(crate) fn next_signed_unit(&mut self) -> f64 {
        let unit = (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64;
        2.0 * unit - 1.0
    }
}

impl Terrain {
    /// Builds the profile; the random kind is generated here, once.
    #[must_use]
    pub fn new(kind: TerrainKind) -> Self {
        let samples = match &kind {
            TerrainKind::Random { seed, roughness, amplitude_m, segment_m, length_m, .. } => {
                midpoint_displacement(*seed, *roughness, *amplitude_m, *segment_m, *length_m)
            }
            _ => Vec::new(),
        };
        Terrain { kind, samples }
    }

    /// Level ground.
    #[must_use]
    pub fn flat() -> Self {
        Terrain::new(TerrainKind::Flat)
    }

    /// The kind and its settings.
    #[must_use]
    pub fn kind(&self) -> &TerrainKind {
        &self.kind
    }

    /// Ground height at x (m).
    #[must_use]
    pub fn height(&self, x: f64) -> f64 {
        match &self.kind {
            TerrainKind::Flat => 0.0,
            TerrainKind::Stairs { rise_m, run_m, count, up, start_x_m } => {
                if x < *start_x_m {
                    return 0.0;
                }
                let steps = (((x - start_x_m) / run_m).floor() + 1.0).min(*count as f64);
                let sign = if *up { 1.0 } else { -1.0 };
                sign * steps * rise_m
            }
            TerrainKind::Slope { grade_pct, start_x_m } => (x - start_x_m).max(0.0) * grade_pct / 100.0,
            TerrainKind::Random { segment_m, start_x_m, .. } => {
                let u = (x - start_x_m) / segment_m;
                if u <= 0.0 {
                    return self.samples[0];
                }
                let i = u.floor() as usize;
                if i + 1 >= self.samples.len() {
                    return self.samples[self.samples.len() - 1];
                }
                let f = u - i as f64;
                self.samples[i] * (1.0 - f) + self.samples[i + 1] * f
            }
        }
    }

    /// The x positions where the ground has a corner (stair nosings and riser feet, slope
    /// start, random-terrain vertices) between `x0` and `x1`: the places a foot can catch on.
    #[must_use]
    pub fn corners_between(&self, x0: f64, x1: f64) -> Vec<f64> {
        self.corners(x0, x1).collect()
    }

    /// [`Self::corners_between`] without the allocation, for the swing simulation, which asks
    /// several times a sample (on stairs_up the `Vec`s cost its planning 100 µs's last few).
    pub(crate) fn corners(&self, x0: f64, x1: f64) -> impl Iterator<Item = f64> + use<> {
        let (lo, hi) = (x0.min(x1), x0.max(x1));
        // Every kind's corners are `start + i · step` for i in a range; where the range is
        // worked out from lo and hi a step wide either side, the filter keeps exactly those
        // in lo..=hi, as the listing of every corner did.
        let (start, step, first, last, filtered) = match &self.kind {
            TerrainKind::Flat => (0.0, 1.0, 1, 0, false),
            TerrainKind::Stairs { run_m, count, start_x_m, .. } => {
                let first = (((lo - start_x_m) / run_m).floor() as i64).saturating_sub(1);
                let last = (((hi - start_x_m) / run_m).ceil() as i64).saturating_add(1);
                (*start_x_m, *run_m, first.max(0), last.min(*count as i64 - 1), true)
            }
            TerrainKind::Slope { start_x_m, .. } => (*start_x_m, 1.0, 0, 0, true),
            TerrainKind::Random { segment_m, start_x_m, .. } => {
                let first = ((lo - start_x_m) / segment_m).ceil().max(0.0) as i64;
                let last = ((hi - start_x_m) / segment_m).floor().max(-1.0) as i64;
                (*start_x_m, *segment_m, first, last, false)
            }
        };
        (first..=last).map(move |i| start + i as f64 * step).filter(move |x| !filtered || (lo..=hi).contains(x))
    }

    /// The higher of the two heights a riser has at its x (m), the nosing's: read just
    /// either side, as `start + i · run` can round to either tread.
    #[must_use]
    pub(crate) fn corner_top(&self, x: f64) -> f64 {
        self.height(x - 1e-9).max(self.height(x)).max(self.height(x + 1e-9))
    }

    /// How far the ground jumps at `x` (m): a riser's height at a stair's corner, 0 where the
    /// ground is continuous (a slope's start, rough ground's vertices).
    #[must_use]
    pub(crate) fn riser_height_at(&self, x: f64) -> f64 {
        let below = self.height(x - 1e-9).min(self.height(x)).min(self.height(x + 1e-9));
        self.corner_top(x) - below
    }

    /// Highest ground between `x0` and `x1` (corners included).
    #[must_use]
    pub(crate) fn max_height_between(&self, x0: f64, x1: f64) -> f64 {
        let mut h = self.height(x0).max(self.height(x1));
        for c in self.corners(x0, x1) {
            // A riser has two heights at one x: take the upper one.
            h = h.max(self.corner_top(c));
        }
        h
    }

    /// Slope angle of the ground line between the points under `x_heel` and `x_toe` (rad,
    /// positive uphill along +x).
    #[must_use]
    pub fn angle_between(&self, x_heel: f64, x_toe: f64) -> f64 {
        let dx = x_toe - x_heel;
        if dx.abs() < 1e-9 {
            return 0.0;
        }
        ((self.height(x_toe) - self.height(x_heel)) / dx).atan()
    }

    /// The angle between a foot (heel → toe, in the sagittal plane) and the ground under it,
    /// by the dot product of the two directions [6.3.2]; positive when the toe points above
    /// the ground line.
    #[must_use]
    #[cfg(test)]
    pub(crate) fn foot_angle(&self, heel_x: f64, heel_y: f64, toe_x: f64, toe_y: f64) -> f64 {
        let foot = glam::DVec2::new(toe_x - heel_x, toe_y - heel_y);
        let ground = glam::DVec2::new(toe_x - heel_x, self.height(toe_x) - self.height(heel_x));
        let cos = (foot.dot(ground) / (foot.length() * ground.length()).max(1e-12)).clamp(-1.0, 1.0);
        let unsigned = cos.acos();
        if ground.perp_dot(foot) >= 0.0 { unsigned } else { -unsigned }
    }

    /// The x of a place where a foot from `heel_x` to `heel_x + foot_m` lies on one flat
    /// piece of ground, as near to `heel_x` as possible: on stairs a foot must not straddle a
    /// nosing. Other kinds return `heel_x` unchanged.
    #[must_use]
    pub(crate) fn settle_footfall(&self, heel_x: f64, foot_m: f64, margin_m: f64) -> f64 {
        let TerrainKind::Stairs { run_m, count, start_x_m, up, .. } = &self.kind else {
            return heel_x;
        };
        let last_nosing = start_x_m + (*count as f64 - 1.0) * run_m;
        // Down a flight the heel lands further onto the tread where it fits: it comes down
        // past the nosing and needs room to (15 cm in the last 1.5 cm of its way). A step
        // whose own place is nearer the nosing than that moves too: at a clearance of 2 mm
        // the nominal heel landed 1 cm past a nosing and the swing simulation, lifting the
        // heel over the corner pass after pass, threw the foot 75 cm up and back down through
        // the nosing (43 mm under it at 2.0 m/s).
        let heel_past_nosing = if *up {
            margin_m
        } else {
            (2.0 * margin_m).max(DOWN_HEEL_PAST_MIN_M).min(run_m - foot_m - margin_m).max(margin_m)
        };
        let crosses_with = |x: f64, behind: f64| {
            // A corner exactly at the edge does not cross (a candidate is set there).
            self.corners(x - behind, x + foot_m + margin_m)
                .any(|c| c > x - behind + EDGE_M && c < x + foot_m + margin_m - EDGE_M)
        };
        let crosses = |x: f64| crosses_with(x, heel_past_nosing);
        if !crosses(heel_x) {
            return heel_x;
        }
        // Candidates: the heel just past a nosing, or the toe just short of the next one.
        let mut best = heel_x;
        let mut best_d = f64::INFINITY;
        for i in -1..=(*count as i64) {
            let nosing = start_x_m + i as f64 * run_m;
            // The corner before the first (i = -1) is no nosing.
            let heel_past = if i < 0 { margin_m } else { heel_past_nosing };
            for cand in [nosing + heel_past, nosing - foot_m - margin_m] {
                if cand > last_nosing + margin_m && i < *count as i64 - 1 {
                    continue;
                }
                let clear = if i < 0 { !crosses_with(cand, margin_m) } else { !crosses(cand) };
                if clear && (cand - heel_x).abs() < best_d {
                    best = cand;
                    best_d = (cand - heel_x).abs();
                }
            }
        }
        best
    }
}

/// The least distance a heel lands past the nosing down a flight, where the tread has room
/// (m): at a clearance of 0.5 cm two clearances left it 1 cm, and a fast swing cut the nosing
/// 14-28 mm coming down (a reviewer's find).
const DOWN_HEEL_PAST_MIN_M: f64 = 0.03;

/// The least clearance (m) the walk keeps, whatever `legs.clearance_cm` asks (0 is valid
/// there). At none, a foot set against a riser stands on the riser's plane, where the ground
/// reads the upper tread (a planted toe read 200 mm under it through every stance up 20 cm
/// rises), and the swing simulation's path check, which lifts the heel curve where a chord
/// between two samples crosses a nosing, never lifts it clear of a corner it must only graze:
/// pass after pass it asked 12-17 cm more until the heel stood 1.5 m up (18 reach failures up 20
/// tall treads at 0.4 m/s, a 1.5 m body). At 0.5 / 1 mm the toe still went 0.31 / 0.12 mm
/// under a tread landing on it; at 2 mm, none.
pub const LEAST_CLEARANCE_M: f64 = 0.002;

/// How near (m) a corner may be to a foot's edge and still not count as under it: a candidate
/// set at `nosing + past` reads the nosing at `x - past` give or take a rounding.
const EDGE_M: f64 = 1e-9;

/// 1-D midpoint displacement: heights at `2^k + 1` points spaced `segment_m`, enough to
/// cover `length_m`. The ends start at 0; each level displaces every midpoint by a uniform
/// value in ±range, and range shrinks by 2^(−H) per level.
fn midpoint_displacement(seed: u64, roughness: f64, amplitude_m: f64, segment_m: f64, length_m: f64) -> Vec<f64> {
    let needed = (length_m / segment_m).ceil().max(1.0) as usize;
    let mut size = 1usize;
    while size < needed {
        size *= 2;
    }
    let mut h = vec![0.0; size + 1];
    let mut rng = SplitMix64::new(seed);
    let mut range = amplitude_m;
    let mut step = size;
    let decay = 2f64.powf(-roughness);
    while step > 1 {
        let half = step / 2;
        let mut i = half;
        while i < size {
            h[i] = 0.5 * (h[i - half] + h[i + half]) + range * rng.next_signed_unit();
            i += step;
        }
        range *= decay;
        step = half;
    }
    // Start at ground level so the walk's first steps are on height 0 like every other kind.
    let h0 = h[0];
    h.iter().map(|v| v - h0).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn stairs_step_up_at_each_riser() {
        let t = Terrain::new(TerrainKind::Stairs { rise_m: 0.17, run_m: 0.3, count: 3, up: true, start_x_m: 1.0 });
        assert_eq!(t.height(0.99), 0.0);
        assert!((t.height(1.0) - 0.17).abs() < 1e-12);
        assert!((t.height(1.31) - 0.34).abs() < 1e-12);
        assert!((t.height(9.0) - 0.51).abs() < 1e-12);
        assert!((t.max_height_between(0.9, 1.1) - 0.17).abs() < 1e-12);
    }

    #[test]
    fn slope_grade_and_foot_angle() {
        let t = Terrain::new(TerrainKind::Slope { grade_pct: 10.0, start_x_m: 0.0 });
        assert!((t.height(2.0) - 0.2).abs() < 1e-12);
        assert!((t.angle_between(1.0, 1.2) - 0.1f64.atan()).abs() < 1e-12);
        // A horizontal foot on a 10 % uphill points into the ground.
        let a = t.foot_angle(1.0, 0.1, 1.2, 0.1);
        assert!((a + 0.1f64.atan()).abs() < 1e-9, "{a}");
    }

    #[test]
    fn random_terrain_is_reproducible_and_seed_dependent() {
        let kind = |seed| TerrainKind::Random {
            seed,
            roughness: 0.6,
            amplitude_m: 0.08,
            segment_m: 0.25,
            length_m: 60.0,
            start_x_m: 2.0,
        };
        let a = Terrain::new(kind(7));
        let b = Terrain::new(kind(7));
        let c = Terrain::new(kind(8));
        let xs: Vec<f64> = (0..400).map(|i| i as f64 * 0.13).collect();
        let ha: Vec<f64> = xs.iter().map(|&x| a.height(x)).collect();
        let hb: Vec<f64> = xs.iter().map(|&x| b.height(x)).collect();
        let hc: Vec<f64> = xs.iter().map(|&x| c.height(x)).collect();
        assert_eq!(ha, hb);
        assert_ne!(ha, hc);
        assert_eq!(a.height(0.0), 0.0);
        assert!(ha.iter().any(|h| h.abs() > 0.005));
        // Portable generator: the first outputs of SplitMix64 seeded with 0 are published.
        let mut rng = SplitMix64::new(0);
        assert_eq!(rng.next_u64(), 0xE220_A839_7B1D_CDAF);
    }

    #[test]
    fn footfalls_settle_onto_one_tread() {
        let t = Terrain::new(TerrainKind::Stairs { rise_m: 0.17, run_m: 0.3, count: 5, up: true, start_x_m: 1.0 });
        let x = t.settle_footfall(1.2, 0.26, 0.015);
        assert!(t.corners_between(x - 0.015 + 1e-9, x + 0.275 - 1e-9).is_empty(), "{x}");
        assert_eq!(t.settle_footfall(0.5, 0.26, 0.015), 0.5);
    }

    #[test]
    fn a_riser_reads_its_nosing_whichever_tread_its_x_rounds_to() {
        let up = Terrain::new(TerrainKind::Stairs { rise_m: 0.15, run_m: 0.34, count: 8, up: true, start_x_m: 2.0 });
        let riser = up.corners_between(2.3, 2.4)[0];
        // 2.0 + 1 · 0.34 rounds down to the lower tread: its nosing is the upper one's height.
        assert!((up.height(riser) - 0.15).abs() < 1e-12);
        assert!((up.corner_top(riser) - 0.30).abs() < 1e-12);
        assert!((up.riser_height_at(riser) - 0.15).abs() < 1e-12);
        let down = Terrain::new(TerrainKind::Stairs { rise_m: 0.15, run_m: 0.34, count: 8, up: false, start_x_m: 2.0 });
        assert!((down.corner_top(riser) + 0.15).abs() < 1e-12);
        assert!((down.riser_height_at(riser) - 0.15).abs() < 1e-12);
        // A slope's start and rough ground's vertices are corners without a riser.
        let slope = Terrain::new(TerrainKind::Slope { grade_pct: 10.0, start_x_m: 2.0 });
        assert!(slope.riser_height_at(2.0).abs() < 1e-6);
    }

    #[test]
    fn corners_are_every_stair_nosing_and_slope_start_in_the_range() {
        let stairs =
            Terrain::new(TerrainKind::Stairs { rise_m: 0.15, run_m: 0.34, count: 8, up: true, start_x_m: 2.0 });
        let slope = Terrain::new(TerrainKind::Slope { grade_pct: 10.0, start_x_m: 2.0 });
        for k in 0..400 {
            let (a, b) = (f64::from(k) * 0.013, f64::from(k) * 0.029 - 1.0);
            let listed: Vec<f64> =
                (0..8).map(|i| 2.0 + f64::from(i) * 0.34).filter(|x| (a.min(b)..=a.max(b)).contains(x)).collect();
            assert_eq!(stairs.corners_between(a, b), listed, "{a} {b}");
            assert_eq!(slope.corners_between(a, b).len(), usize::from((a.min(b)..=a.max(b)).contains(&2.0)));
        }
        // Exactly on a nosing, either end.
        assert_eq!(stairs.corners_between(2.34, 2.68), vec![2.0 + 0.34, 2.0 + 2.0 * 0.34]);
        assert!(stairs.corners_between(f64::NEG_INFINITY, f64::INFINITY).len() == 8);
    }

    #[test]
    fn down_a_flight_a_heel_lands_further_past_the_nosing() {
        let kind = |up| TerrainKind::Stairs { rise_m: 0.15, run_m: 0.34, count: 8, up, start_x_m: 2.0 };
        // Nominally the heel would land 1 cm past the second nosing, the foot fitting nowhere nearer.
        let nosing = 2.34;
        let up = Terrain::new(kind(true)).settle_footfall(nosing + 0.01, 0.26, 0.015);
        let down = Terrain::new(kind(false)).settle_footfall(nosing + 0.01, 0.26, 0.015);
        assert!((up - (nosing + 0.015)).abs() < 1e-9, "{up}");
        assert!((down - (nosing + 0.03)).abs() < 1e-9, "{down}");
        // Where the tread has no room for two clearances, as far as it has.
        let short = Terrain::new(TerrainKind::Stairs { rise_m: 0.15, run_m: 0.3, count: 8, up: false, start_x_m: 2.0 });
        let x = short.settle_footfall(2.31, 0.26, 0.015);
        assert!((x - (2.3 + 0.025)).abs() < 1e-9, "{x}");
        // At a small clearance a heel 1 cm past the nosing clears it by more than the margin:
        // down a flight it moves on all the same; up, it stays.
        for (heel_past, up_x, down_x) in [(0.01, nosing + 0.01, nosing + 0.03), (0.035, nosing + 0.035, nosing + 0.035)]
        {
            let up = Terrain::new(kind(true)).settle_footfall(nosing + heel_past, 0.26, 0.002);
            let down = Terrain::new(kind(false)).settle_footfall(nosing + heel_past, 0.26, 0.002);
            assert!((up - up_x).abs() < 1e-9 && (down - down_x).abs() < 1e-9, "{heel_past}: {up} {down}");
        }
    }

    #[test]
    fn only_flat_ground_and_a_level_slope_are_level() {
        assert!(TerrainKind::Flat.is_level());
        assert!(TerrainKind::Slope { grade_pct: 0.0, start_x_m: 2.0 }.is_level());
        assert!(!TerrainKind::Slope { grade_pct: -0.5, start_x_m: 2.0 }.is_level());
        let stairs = TerrainKind::Stairs { rise_m: 0.15, run_m: 0.34, count: 8, up: true, start_x_m: 2.0 };
        assert!(!stairs.is_level());
    }
}
