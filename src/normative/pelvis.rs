//! How far people's pelvis rises and falls at a walking speed: the built-in table
//! `data/normative/pelvis_vertical_by_speed.csv` (the centre of the four pelvis markers, WBDS
//! young adults on a treadmill at 0.6 to 1.6 m/s; source, licence, derivation and its limits
//! beside it), read at the walk's speed as the other norms are.
//!
//! Why a measured pelvis and not Orendurff et al. 2004's centre-of-mass figures: those come
//! from other people and another marker model, and the walk's pelvis is a pelvis. These are the
//! same adults whose joint angles the walk is compared with.

use super::blocks::{beyond_blocks, blocks_used, bracket, parse_rows};
use crate::error::Result;

/// How the built-in pelvis norms are named.
pub const PELVIS_NORMS_SOURCE: &str =
    "Fukuchi, Fukuchi & Duarte 2018 (5 young adults' pelvis markers, treadmill, CC BY 4.0)";

/// The built-in pelvis norms by speed (source, licence and derivation beside the file).
pub const BUILT_IN_PELVIS_NORMS: &str = include_str!("../../data/normative/pelvis_vertical_by_speed.csv");

/// One speed block: the pelvis centre's vertical range per step, mean and between-subject SD.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PelvisBlock {
    /// The block's mean walking speed (m/s).
    pub speed_mps: f64,
    /// Vertical range of the pelvis centre over a step (cm): mean, SD.
    pub vertical_range_cm: (f64, f64),
}

/// Pelvis norms at several speeds, slowest first.
#[derive(Clone, Debug, PartialEq)]
pub struct PelvisNorms {
    /// The blocks, speeds strictly rising.
    pub blocks: Vec<PelvisBlock>,
}

/// The pelvis norms at one walk's speed, and which blocks they came from.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct PelvisAtSpeed {
    /// The speed asked for (m/s).
    pub speed_mps: f64,
    /// The speeds of the blocks interpolated between (m/s); equal when one block was taken.
    pub from_block_mps: f64,
    /// See `from_block_mps`.
    pub to_block_mps: f64,
    /// Vertical range of the pelvis centre (cm): mean, SD.
    pub vertical_range_cm: (f64, f64),
}

impl PelvisNorms {
    /// The built-in table, parsed (a test checks that it does).
    #[must_use]
    pub fn built_in() -> PelvisNorms {
        PelvisNorms::parse(BUILT_IN_PELVIS_NORMS, "built-in pelvis norms").expect("the built-in table parses")
    }

    /// Parses the built-in file's format: `#` comments, a header, one row a speed block.
    pub fn parse(text: &str, label: &str) -> Result<PelvisNorms> {
        let wanted = ["speed_m_s", "vertical_range_mean_cm", "vertical_range_sd_cm"];
        let blocks = parse_rows(text, label, &wanted)?
            .into_iter()
            .map(|v| PelvisBlock { speed_mps: v[0], vertical_range_cm: (v[1], v[2]) })
            .collect();
        Ok(PelvisNorms { blocks })
    }

    /// The norms at `speed_mps`: linear interpolation (mean and SD) between the two blocks
    /// around it, or the end block beyond either end (never extrapolated).
    #[must_use]
    pub fn at(&self, speed_mps: f64) -> PelvisAtSpeed {
        let speeds: Vec<f64> = self.blocks.iter().map(|b| b.speed_mps).collect();
        let (lo, hi, t) = bracket(&speeds, speed_mps);
        let (lo, hi) = (self.blocks[lo], self.blocks[hi]);
        let (a, b) = (lo.vertical_range_cm, hi.vertical_range_cm);
        PelvisAtSpeed {
            speed_mps,
            from_block_mps: lo.speed_mps,
            to_block_mps: hi.speed_mps,
            vertical_range_cm: (a.0 + t * (b.0 - a.0), a.1 + t * (b.1 - a.1)),
        }
    }
}

impl PelvisAtSpeed {
    /// Where the norms came from, in words, as the spatiotemporal norms say it.
    #[must_use]
    pub fn blocks_used(&self) -> String {
        blocks_used(self.speed_mps, (self.from_block_mps, self.to_block_mps))
    }

    /// "fastest" or "slowest" where the walk is faster or slower than every block and the end
    /// block was taken (the table is not extrapolated); `None` where the range is read at the
    /// walk's speed.
    #[must_use]
    pub fn beyond_measured(&self) -> Option<&'static str> {
        beyond_blocks(self.speed_mps, (self.from_block_mps, self.to_block_mps))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_built_in_table_parses_and_people_s_pelvis_rises_more_the_faster_they_walk() {
        let norms = PelvisNorms::built_in();
        assert_eq!(norms.blocks.len(), 5);
        let ranges: Vec<f64> = norms.blocks.iter().map(|b| b.vertical_range_cm.0).collect();
        assert!(ranges.windows(2).all(|w| w[1] > w[0]), "{ranges:?}");
        // Between two blocks, linear; beyond the ends, the end block.
        let (slow, fast) = (norms.blocks[0], norms.blocks[4]);
        assert!((0.55..0.62).contains(&slow.speed_mps), "{slow:?}");
        assert_eq!(norms.at(0.5).vertical_range_cm, slow.vertical_range_cm);
        assert_eq!(norms.at(2.0).vertical_range_cm, fast.vertical_range_cm);
        let (a, b) = (norms.blocks[1], norms.blocks[2]);
        let mid = norms.at(0.5 * (a.speed_mps + b.speed_mps)).vertical_range_cm.0;
        assert!((mid - 0.5 * (a.vertical_range_cm.0 + b.vertical_range_cm.0)).abs() < 1e-9);
    }

    #[test]
    fn a_table_without_its_columns_or_with_falling_speeds_is_refused_naming_the_line() {
        let err = PelvisNorms::parse("speed_m_s,x\n0.8,1\n", "t.csv").unwrap_err().to_string();
        assert!(err.contains("t.csv:1") && err.contains("vertical_range_mean_cm"), "{err}");
        let text = "speed_m_s,vertical_range_mean_cm,vertical_range_sd_cm\n1.0,2.5,0.3\n0.8,2.0,0.3\n";
        let err = PelvisNorms::parse(text, "t.csv").unwrap_err().to_string();
        assert!(err.contains("t.csv:3") && err.contains("rise"), "{err}");
    }
}
