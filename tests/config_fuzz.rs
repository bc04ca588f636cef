//! A config-mutation fuzzer over every shipped config (`configs/*.toml`): key lines deleted,
//! duplicated, given values of another type, extreme numbers or their key's range limits,
//! bytes flipped or inserted, the file cut short, CRLF line ends, a byte-order mark, and
//! random `--set`s. Each mutated file is written out and loaded through `config::load` (so
//! through `read_source` too).
//!
//! The property: the config is either refused, every error line `PATH:LINE:COL: ...` with
//! the place inside the file (or the `--set`) and no line over 300 characters, or accepted,
//! and then 1.5 gait cycles walk at the config's own frame rate (a fifth of a cycle with the
//! slow gradient IK solver) with every value finite and neither heel nor toe more than 1 mm
//! under the ground. Nothing panics (proptest catches a
//! panic as a failure and shrinks the input).
//!
//! Deterministic: a fixed ChaCha seed, no failure persistence. `GAITLAB_FUZZ_CASES`,
//! `GAITLAB_FUZZ_SEED` and `GAITLAB_FUZZ_CYCLES` run it longer, elsewhere or further by hand;
//! `GAITLAB_FUZZ_KEEP_GOING=1` prints every failure instead of stopping at the first.

use gaitlab::analysis;
use gaitlab::config::{self, schema::Kind, schema::PARAMS, schema::Value};
use gaitlab::model::gait_curves::CurveName;
use proptest::prelude::*;
use proptest::test_runner::{Config, RngAlgorithm, TestCaseError, TestRng, TestRunner};
use std::path::{Path, PathBuf};
use std::sync::Mutex;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::{Duration, Instant};

/// Cases in a default `cargo test` run.
const CASES: u32 = 5_000;
/// The seed of a default run.
const SEED: u64 = 2016;
/// Longest error line accepted.
const MAX_LINE: usize = 300;

/// Values of every TOML type, for a key's value to be swapped to.
const TYPE_SWAPS: &[&str] = &[
    "1.0",
    "-3",
    "7",
    "\"text\"",
    "\"\"",
    "\"auto\"",
    "\"stairs\"",
    "true",
    "false",
    "[1, 2]",
    "[]",
    "[[0, 0], [1, 1]]",
    "{ a = 1 }",
    "{}",
    "1979-05-27",
    "07:32:00",
    "'literal'",
    "\"\"\"multi\nline\"\"\"",
    "\"esc\\u001b[31mape\"",
];

/// Extreme numbers.
const EXTREMES: &[&str] = &[
    "0",
    "-0",
    "0.0",
    "-0.0",
    "1e308",
    "-1e308",
    "1.7976931348623157e308",
    "1e-308",
    "-1e-308",
    "5e-324",
    "1e999",
    "9223372036854775807",
    "-9223372036854775808",
    "99999999999999999999999999",
    "0x7fffffffffffffff",
    "0xffffffffffffffffffff",
    "0o777",
    "0b1",
    "nan",
    "+nan",
    "-nan",
    "inf",
    "+inf",
    "-inf",
];

/// Keys for `--set` that are not keys.
const JUNK_KEYS: &[&str] = &[
    "",
    " ",
    "walk",
    "walk.",
    ".speed_mps",
    "speed_mps",
    "foo.bar",
    "walk.speed_mps.x",
    "keys.quit",
    "curves",
    "curves.nope",
];

/// One change to a config.
#[derive(Clone, Debug)]
enum Mutation {
    /// Delete the n-th `key = value` line.
    DeleteKey(usize),
    /// Give the n-th key a value of another type.
    SwapType(usize, usize),
    /// Give the n-th key an extreme number.
    Extreme(usize, usize),
    /// Give the n-th key a value at or just past its range: which, fraction.
    Boundary(usize, u8, u16),
    /// Repeat the n-th key line (a duplicate key).
    Duplicate(usize),
    /// XOR the byte at a position (mod the length) with a non-zero mask.
    FlipByte(usize, u8),
    /// Insert a byte.
    InsertByte(usize, u8),
    /// Cut the file at a byte.
    Truncate(usize),
    /// `\n` to `\r\n`.
    Crlf,
    /// A UTF-8 byte-order mark in front.
    Bom,
    /// A `--set` of a real key: key index, which value, fraction.
    Set(usize, u8, u16),
    /// A `--set` of a junk key or junk text.
    SetJunk(usize, usize),
    /// A `--set` of a curve's points, one of them changed: curve, point, how, fraction.
    SetCurve(usize, usize, u8, u16),
}

fn mutation() -> impl Strategy<Value = Mutation> {
    let n = 0..10_000usize;
    prop_oneof![
        3 => n.clone().prop_map(Mutation::DeleteKey),
        3 => (n.clone(), 0..TYPE_SWAPS.len()).prop_map(|(i, v)| Mutation::SwapType(i, v)),
        3 => (n.clone(), 0..EXTREMES.len()).prop_map(|(i, v)| Mutation::Extreme(i, v)),
        6 => (n.clone(), any::<u8>(), any::<u16>()).prop_map(|(i, w, f)| Mutation::Boundary(i, w, f)),
        1 => n.clone().prop_map(Mutation::Duplicate),
        3 => (n.clone(), 1..=255u8).prop_map(|(i, m)| Mutation::FlipByte(i, m)),
        2 => (n.clone(), any::<u8>()).prop_map(|(i, b)| Mutation::InsertByte(i, b)),
        2 => n.clone().prop_map(Mutation::Truncate),
        1 => Just(Mutation::Crlf),
        1 => Just(Mutation::Bom),
        6 => (0..PARAMS.len(), any::<u8>(), any::<u16>()).prop_map(|(i, w, f)| Mutation::Set(i, w, f)),
        1 => (0..JUNK_KEYS.len() + TYPE_SWAPS.len(), 0..EXTREMES.len()).prop_map(|(k, v)| Mutation::SetJunk(k, v)),
        3 => (0..CurveName::ALL.len(), 0..32usize, any::<u8>(), any::<u16>())
            .prop_map(|(c, p, w, f)| Mutation::SetCurve(c, p, w, f)),
    ]
}

/// Extreme curve control-point heights.
const EXTREME_YS: &[f64] = &[1e308, -1e308, 1e6, -1e6, 100.0, -100.0, 5e-324, -0.0];

/// A shipped config and the changes made to it.
#[derive(Clone, Debug)]
struct Case {
    config: usize,
    mutations: Vec<Mutation>,
}

/// The byte ranges of the `key = value` lines, and the group each is in.
fn key_lines(bytes: &[u8]) -> Vec<(usize, usize, String)> {
    let mut out = Vec::new();
    let mut group = String::new();
    let mut start = 0;
    for line in bytes.split(|&b| b == b'\n') {
        let end = start + line.len();
        let text = String::from_utf8_lossy(line);
        let t = text.trim();
        if let Some(g) = t.strip_prefix('[').and_then(|g| g.split(']').next()) {
            group = g.trim().to_string();
        } else if !t.starts_with('#') && t.contains('=') {
            out.push((start, end, group.clone()));
        }
        start = end + 1;
    }
    out
}

/// A value for `spec` at (or past) its limits: `which` picks min, max, the middle, a point
/// inside by `fraction`, or just outside either end.
fn boundary_value(kind: Kind, which: u8, fraction: u16) -> String {
    let f = f64::from(fraction) / f64::from(u16::MAX);
    match kind {
        Kind::Real { min, max, .. } => {
            let x = match which % 7 {
                0 => min,
                1 => max,
                2 => (min + max) / 2.0,
                3 => min - (max - min) * 1e-3,
                4 => max + (max - min) * 1e-3,
                _ => min + (max - min) * f,
            };
            format!("{x:?}")
        }
        Kind::Int { min, max } => {
            let n = match which % 7 {
                0 => min,
                1 => max,
                2 => min + (max - min) / 2,
                3 => min - 1,
                4 => max.saturating_add(1),
                _ => min + ((max - min) as f64 * f) as i64,
            };
            n.to_string()
        }
        Kind::Choice(words) => format!("\"{}\"", words[usize::from(which) % words.len()]),
        Kind::Bool => which.is_multiple_of(2).to_string(),
    }
}

/// Replaces the value of a key line.
fn replace_value(bytes: &mut Vec<u8>, (start, end): (usize, usize), value: &str) {
    let line = &bytes[start..end];
    let Some(eq) = line.iter().position(|&b| b == b'=') else { return };
    let mut new = line[..=eq].to_vec();
    new.push(b' ');
    new.extend_from_slice(value.as_bytes());
    if line.ends_with(b"\r") {
        new.push(b'\r');
    }
    bytes.splice(start..end, new);
}

/// The mutated file and `--set`s of a case.
fn build(shipped: &[(String, Vec<u8>)], case: &Case) -> (Vec<u8>, Vec<String>) {
    let mut bytes = shipped[case.config].1.clone();
    let mut sets = Vec::new();
    for m in &case.mutations {
        let lines = key_lines(&bytes);
        let pick = |i: usize| lines.get(i % lines.len().max(1)).cloned();
        match *m {
            Mutation::DeleteKey(i) => {
                if let Some((s, e, _)) = pick(i) {
                    bytes.drain(s..(e + 1).min(bytes.len()));
                }
            }
            Mutation::SwapType(i, v) => {
                if let Some((s, e, _)) = pick(i) {
                    replace_value(&mut bytes, (s, e), TYPE_SWAPS[v]);
                }
            }
            Mutation::Extreme(i, v) => {
                if let Some((s, e, _)) = pick(i) {
                    replace_value(&mut bytes, (s, e), EXTREMES[v]);
                }
            }
            Mutation::Boundary(i, which, f) => {
                if let Some((s, e, group)) = pick(i) {
                    let line = String::from_utf8_lossy(&bytes[s..e]).into_owned();
                    let name = line.split('=').next().unwrap_or("").trim().to_string();
                    if let Some(spec) = config::schema::spec(&format!("{group}.{name}")) {
                        replace_value(&mut bytes, (s, e), &boundary_value(spec.kind, which, f));
                    }
                }
            }
            Mutation::Duplicate(i) => {
                if let Some((s, e, _)) = pick(i) {
                    let mut copy = bytes[s..e].to_vec();
                    copy.push(b'\n');
                    let at = (e + 1).min(bytes.len());
                    if at == bytes.len() && !bytes.ends_with(b"\n") {
                        bytes.push(b'\n');
                    }
                    let at = at.min(bytes.len());
                    bytes.splice(at..at, copy);
                }
            }
            Mutation::FlipByte(i, mask) => {
                if !bytes.is_empty() {
                    let at = i % bytes.len();
                    bytes[at] ^= mask;
                }
            }
            Mutation::InsertByte(i, b) => {
                let at = i % (bytes.len() + 1);
                bytes.insert(at, b);
            }
            Mutation::Truncate(i) => bytes.truncate(i % (bytes.len() + 1)),
            Mutation::Crlf => {
                let mut out = Vec::with_capacity(bytes.len() + 300);
                for (k, &b) in bytes.iter().enumerate() {
                    if b == b'\n' && (k == 0 || bytes[k - 1] != b'\r') {
                        out.push(b'\r');
                    }
                    out.push(b);
                }
                bytes = out;
            }
            Mutation::Bom => bytes.splice(0..0, *b"\xEF\xBB\xBF").for_each(drop),
            Mutation::Set(k, which, f) => {
                let spec = &PARAMS[k];
                sets.push(format!("{}={}", spec.key, boundary_value(spec.kind, which, f)));
            }
            Mutation::SetJunk(k, v) => {
                let key =
                    if k < JUNK_KEYS.len() { JUNK_KEYS[k].to_string() } else { PARAMS[k % PARAMS.len()].key.into() };
                let value = if k < JUNK_KEYS.len() { EXTREMES[v] } else { TYPE_SWAPS[k - JUNK_KEYS.len()] };
                sets.push(format!("{key}={value}"));
            }
            Mutation::SetCurve(c, p, which, f) => {
                let name = CurveName::ALL[c];
                let limits = config::schema::curve_limits(name);
                let mut points: Vec<(f64, f64)> = name.default_curve().points().iter().map(|q| (q.x, q.y)).collect();
                let n = points.len();
                let i = p % n;
                let span = limits.hi - limits.lo;
                let t = f64::from(f) / f64::from(u16::MAX);
                let y = match which % 8 {
                    0 => limits.lo,
                    1 => limits.hi,
                    2 => limits.lo + span * t,
                    3 => limits.lo - span * 1e-3,
                    4 => limits.hi + span * 1e-3,
                    5 => EXTREME_YS[usize::from(f) % EXTREME_YS.len()],
                    // A control point moved along x, past its neighbours if far enough.
                    6 => {
                        points[i].0 += (t - 0.5) * 0.2;
                        points[i].1
                    }
                    _ => points[i].1 * (t * 4.0 - 2.0),
                };
                points[i].1 = y;
                // Cycle curves keep their ends together (mostly; which 7 may part them).
                if name.is_cyclic() && which % 8 != 7 && (i == 0 || i == n - 1) {
                    points[0].1 = y;
                    points[n - 1].1 = y;
                }
                let text: Vec<String> = points.iter().map(|(x, y)| format!("[{x:?}, {y:?}]")).collect();
                sets.push(format!("curves.{}.points=[{}]", name.key(), text.join(", ")));
            }
        }
    }
    (bytes, sets)
}

/// Why an error line is malformed, if it is.
fn bad_line(line: &str, label: &str, bytes: &[u8], sets: &[String]) -> Option<String> {
    if line.chars().count() > MAX_LINE {
        return Some(format!("longer than {MAX_LINE} characters"));
    }
    let (path, rest) = line.split_once(':')?;
    let mut parts = rest.splitn(3, ':');
    let (l, c, tail) = (parts.next()?, parts.next()?, parts.next().unwrap_or(""));
    let (Ok(l), Ok(c)) = (l.parse::<usize>(), c.parse::<usize>()) else {
        return Some("no LINE:COL after the path".into());
    };
    if !tail.starts_with(' ') || tail.len() < 2 {
        return Some("no message after the place".into());
    }
    if l == 0 || c == 0 {
        return Some("line and column count from 1".into());
    }
    if path == label {
        let lines: Vec<&[u8]> = bytes.split(|&b| b == b'\n').collect();
        let Some(text) = lines.get(l - 1) else {
            return Some(format!("line {l} past the file's {} lines", lines.len()));
        };
        // Columns count characters, which are never more than bytes (plus one past the end).
        if c > text.len() + 1 {
            return Some(format!("column {c} past the line's {} bytes", text.len()));
        }
    } else if let Some(n) = path.strip_prefix("--set #") {
        let Some(set) = n.parse::<usize>().ok().and_then(|n| sets.get(n.wrapping_sub(1))) else {
            return Some("names a --set that was not given".into());
        };
        if l != 1 || c > set.chars().count() + 1 {
            return Some(format!("place {l}:{c} outside the --set"));
        }
    } else {
        return Some("names neither the file nor a --set".into());
    }
    None
}

#[derive(Default)]
struct Tally {
    accepted: AtomicUsize,
    refused: AtomicUsize,
    walked_frames: AtomicUsize,
    /// Failures let through by `GAITLAB_FUZZ_KEEP_GOING`.
    failed: AtomicUsize,
    /// The slowest case: time and what it was.
    slowest: Mutex<(Duration, String)>,
}

fn check(
    shipped: &[(String, Vec<u8>)],
    file: &Path,
    case: &Case,
    cycles: f64,
    tally: &Tally,
) -> Result<(), TestCaseError> {
    let started = Instant::now();
    let result = check_case(shipped, file, case, cycles, tally);
    let took = started.elapsed();
    let mut slowest = tally.slowest.lock().unwrap();
    if took > slowest.0 {
        *slowest = (took, format!("{case:?}"));
    }
    // A hunt by hand (`GAITLAB_FUZZ_KEEP_GOING=1`) counts failures and goes on, printing each.
    if let Err(e) = &result
        && std::env::var_os("GAITLAB_FUZZ_KEEP_GOING").is_some()
    {
        eprintln!("FAILURE {case:?}\n{e}\n");
        tally.failed.fetch_add(1, Ordering::Relaxed);
        return Ok(());
    }
    result
}

fn check_case(
    shipped: &[(String, Vec<u8>)],
    file: &Path,
    case: &Case,
    cycles: f64,
    tally: &Tally,
) -> Result<(), TestCaseError> {
    let (bytes, sets) = build(shipped, case);
    std::fs::write(file, &bytes).map_err(|e| TestCaseError::fail(format!("cannot write the case: {e}")))?;
    let shown = || {
        let text = String::from_utf8_lossy(&bytes);
        let text: String = text.chars().take(3000).collect();
        format!("from {}, sets {sets:?}, text:\n{text}", shipped[case.config].0)
    };
    let label = file.display().to_string();
    match config::load(file, &sets) {
        Err(errors) => {
            tally.refused.fetch_add(1, Ordering::Relaxed);
            prop_assert!(!errors.0.is_empty(), "refused with no error; {}", shown());
            for line in errors.to_string().lines() {
                if let Some(why) = bad_line(line, &label, &bytes, &sets) {
                    return Err(TestCaseError::fail(format!("bad error line ({why}):\n{line}\n{}", shown())));
                }
            }
            prop_assert_eq!(errors.to_string().lines().count(), errors.0.len(), "one line per problem; {}", shown());
        }
        Ok(params) => {
            tally.accepted.fetch_add(1, Ordering::Relaxed);
            // The gradient solver descends from 100 random poses every frame: 1.5 cycles of it
            // take ~6 s in a debug build, a third of the whole run for one case, so its walks
            // are cut to a fifth of a cycle (still a dozen frames or more).
            let gradient = (config::schema::spec("ik.solver").unwrap().get)(&params) == Value::Word("gradient");
            let cycles = if gradient { cycles.min(0.2) } else { cycles };
            let run = analysis::run(&params, cycles, params.sim.fps)
                .map_err(|e| TestCaseError::fail(format!("accepted, but the walk does not start: {e}; {}", shown())))?;
            tally.walked_frames.fetch_add(run.frames.len(), Ordering::Relaxed);
            let checks = analysis::checks(&run.frames);
            prop_assert_eq!(checks.non_finite_values, 0, "accepted, but the walk has non-finite values; {}", shown());
            prop_assert!(
                checks.terrain_penetration_mm <= 1.0,
                "accepted, but the foot goes {:.3} mm under the ground at {:?}; {}",
                checks.terrain_penetration_mm,
                checks.worst_penetration,
                shown()
            );
        }
    }
    Ok(())
}

fn shipped_configs() -> Vec<(String, Vec<u8>)> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("configs");
    let mut paths: Vec<PathBuf> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "toml"))
        .collect();
    paths.sort();
    paths.iter().map(|p| (p.file_name().unwrap().to_string_lossy().into_owned(), std::fs::read(p).unwrap())).collect()
}

fn env_or<T: std::str::FromStr>(name: &str, default: T) -> T {
    std::env::var(name).ok().and_then(|v| v.parse().ok()).unwrap_or(default)
}

#[test]
fn mutated_configs_are_refused_cleanly_or_walk_cleanly() {
    let shipped = shipped_configs();
    assert!(shipped.len() >= 10, "{} shipped configs", shipped.len());
    let dir = std::env::temp_dir().join(format!("gaitlab-config-fuzz-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("case.toml");
    let cases = env_or("GAITLAB_FUZZ_CASES", CASES);
    let seed = env_or("GAITLAB_FUZZ_SEED", SEED);
    let config = Config {
        cases,
        failure_persistence: None,
        max_shrink_iters: 4096,
        rng_algorithm: RngAlgorithm::ChaCha,
        ..Config::default()
    };
    let mut seed_bytes = [0u8; 32];
    seed_bytes[..8].copy_from_slice(&seed.to_le_bytes());
    let mut runner = TestRunner::new_with_rng(config, TestRng::from_seed(RngAlgorithm::ChaCha, &seed_bytes));
    let strategy = (0..shipped.len(), prop::collection::vec(mutation(), 1..=3))
        .prop_map(|(config, mutations)| Case { config, mutations });
    let cycles = env_or("GAITLAB_FUZZ_CYCLES", 1.5);
    let tally = Tally::default();
    let start = Instant::now();
    let result = runner.run(&strategy, |case| check(&shipped, &file, &case, cycles, &tally));
    let _ = std::fs::remove_dir_all(&dir);
    let (accepted, refused) = (tally.accepted.load(Ordering::Relaxed), tally.refused.load(Ordering::Relaxed));
    let slowest = tally.slowest.lock().unwrap().clone();
    eprintln!(
        "config fuzz: {} cases ({accepted} accepted and walked {cycles} cycles, {} frames; {refused} refused) in {:.1?}; slowest {:.1?}: {}",
        accepted + refused,
        tally.walked_frames.load(Ordering::Relaxed),
        start.elapsed(),
        slowest.0,
        slowest.1
    );
    if let Err(e) = result {
        panic!("{e}");
    }
    assert_eq!(tally.failed.load(Ordering::Relaxed), 0, "failures, printed above");
    // Both sides of the property are exercised.
    let total = (accepted + refused) as f64;
    assert!(accepted as f64 > 0.2 * total && refused as f64 > 0.2 * total, "{accepted} accepted, {refused} refused");
    assert!(start.elapsed() < Duration::from_secs(60), "the fuzzer took {:.1?}", start.elapsed());
}
