//! `[[walk.schedule]]`: the walk's pace schedule, one table per entry, in file order:
//!
//! ```toml
//! [[walk.schedule]]
//! time_s = 4.0        # or distance_m = 5.0: when
//! speed_mps = 1.6     # or stop = true, or start = true: what
//! ```
//!
//! Each entry takes exactly one of `time_s` / `distance_m` and one of `speed_mps` / `stop` /
//! `start`; entries fire in file order, so the times (and the distances) must not go back. A
//! start sets off from standing: it is the first entry (the walk then begins standing) or
//! follows a stop, and takes a time (a body at rest travels no distance to trigger it).

use super::{Loader, Place, in_file_order, number};
use crate::model::schedule::{PaceAction, PaceEntry, PaceTrigger};
use toml::Spanned;
use toml::de::{DeTable, DeValue};

/// Latest time an entry may name (s): a day.
pub const MAX_TIME_S: f64 = 86_400.0;
/// Farthest distance an entry may name (m).
pub const MAX_DISTANCE_M: f64 = 100_000.0;
/// Most entries a schedule may have.
pub const MAX_ENTRIES: usize = 1000;

/// The keys an entry takes, with what each needs.
const ENTRY_KEYS: [(&str, &str); 5] = [
    ("time_s", "a number from 0 to 86400 s"),
    ("distance_m", "a number from 0 to 100000 m"),
    ("speed_mps", "a number from 0.4 to 2 m/s"),
    ("stop", "true"),
    ("start", "true"),
];

/// What one entry's table gave, before it is checked whole.
#[derive(Default)]
struct Parts {
    time_s: Option<f64>,
    distance_m: Option<f64>,
    speed_mps: Option<f64>,
    stop: bool,
    start: bool,
}

impl Loader {
    /// Reads `walk.schedule`: an array of tables.
    pub(super) fn read_schedule(&mut self, value: &Spanned<DeValue<'_>>, at: &Place, place: &dyn Fn(usize) -> Place) {
        let DeValue::Array(items) = value.get_ref() else {
            self.error(
                at,
                "walk.schedule",
                "expected [[walk.schedule]] tables (time_s or distance_m; speed_mps, stop or start)",
            );
            return;
        };
        if items.len() > MAX_ENTRIES {
            self.error(at, "walk.schedule", format!("at most {MAX_ENTRIES} entries, not {}", items.len()));
            return;
        }
        let mut entries = Vec::with_capacity(items.len());
        for (n, item) in items.iter().enumerate() {
            let key = format!("walk.schedule[{}]", n + 1);
            let item_at = place(item.span().start);
            let DeValue::Table(table) = item.get_ref() else {
                self.error(
                    &item_at,
                    &key,
                    "expected a table: time_s or distance_m, and speed_mps, stop = true or start = true",
                );
                continue;
            };
            if let Some(entry) = self.read_entry(&key, table, &item_at, place) {
                entries.push((entry, item_at, n + 1));
            }
        }
        self.check_order(&entries);
        self.params.schedule = entries.into_iter().map(|(e, _, _)| e).collect();
        self.places.insert("walk.schedule".into(), at.clone());
    }

    /// One entry; `None` (with its problems recorded) if it is not whole.
    fn read_entry(
        &mut self,
        key: &str,
        table: &DeTable<'_>,
        at: &Place,
        place: &dyn Fn(usize) -> Place,
    ) -> Option<PaceEntry> {
        let mut parts = Parts::default();
        let mut sound = true;
        for (k, v) in in_file_order(table) {
            let name = k.get_ref().as_ref();
            let kat = place(k.span().start);
            let full = format!("{key}.{name}");
            let Some(&(_, needs)) = ENTRY_KEYS.iter().find(|(n, _)| *n == name) else {
                let names: Vec<&str> = ENTRY_KEYS.iter().map(|(n, _)| *n).collect();
                let hint = crate::config::schema::did_you_mean(name, names.iter().copied())
                    .map_or(String::new(), |w| format!("; did you mean `{w}`?"));
                self.error(
                    &kat,
                    &full,
                    format!("unknown key{hint} (an entry takes time_s or distance_m, and speed_mps, stop or start)"),
                );
                sound = false;
                continue;
            };
            let value = v.get_ref();
            let ok = match name {
                "stop" => matches!(value, DeValue::Boolean(true)).then(|| parts.stop = true).is_some(),
                "start" => matches!(value, DeValue::Boolean(true)).then(|| parts.start = true).is_some(),
                _ => {
                    let (min, max) = match name {
                        "time_s" => (0.0, MAX_TIME_S),
                        "distance_m" => (0.0, MAX_DISTANCE_M),
                        _ => (0.4, 2.0),
                    };
                    let x = number(value).filter(|x| (min..=max).contains(x));
                    let slot = match name {
                        "time_s" => &mut parts.time_s,
                        "distance_m" => &mut parts.distance_m,
                        _ => &mut parts.speed_mps,
                    };
                    *slot = x;
                    x.is_some()
                }
            };
            if !ok {
                self.error(&place(v.span().start), &full, format!("needs {needs}"));
                sound = false;
            }
        }
        let trigger = match (parts.time_s, parts.distance_m) {
            (Some(t), None) => Some(PaceTrigger::TimeS(t)),
            (None, Some(d)) => Some(PaceTrigger::DistanceM(d)),
            (Some(_), Some(_)) => {
                self.error(at, key, "takes time_s or distance_m, not both");
                None
            }
            (None, None) => {
                if sound {
                    self.error(at, key, "needs a time_s or a distance_m: when the entry takes effect");
                }
                None
            }
        };
        let action = self.entry_action(key, &parts, at, sound);
        Some(PaceEntry { trigger: trigger?, action: action? }).filter(|_| sound)
    }

    /// What an entry asks for, from its parts; `None` (with the problem recorded) if it
    /// names none, or more than one.
    fn entry_action(&mut self, key: &str, parts: &Parts, at: &Place, sound: bool) -> Option<PaceAction> {
        let action = match (parts.speed_mps, parts.stop, parts.start) {
            (Some(v), false, false) => Some(PaceAction::Speed(v)),
            (None, true, false) => Some(PaceAction::Stop),
            (None, false, true) => Some(PaceAction::Start),
            (None, false, false) => {
                if sound {
                    self.error(at, key, "needs a speed_mps, stop = true or start = true: what the entry asks for");
                }
                None
            }
            _ => {
                self.error(at, key, "takes one of speed_mps, stop and start, not two");
                None
            }
        };
        if action == Some(PaceAction::Start) && parts.distance_m.is_some() {
            self.error(at, key, "a start takes time_s, not distance_m: a body at rest travels no distance");
            return None;
        }
        action
    }

    /// Entries fire in file order: a time (or a distance) before the previous one's would
    /// never be noticed.
    fn check_order(&mut self, entries: &[(PaceEntry, Place, usize)]) {
        let (mut last_time, mut last_distance) = (f64::NEG_INFINITY, f64::NEG_INFINITY);
        for (k, (entry, at, n)) in entries.iter().enumerate() {
            let after_stop = k > 0 && entries[k - 1].0.action == PaceAction::Stop;
            if entry.action == PaceAction::Start && k > 0 && !after_stop {
                let message = "a start must be the first entry (the walk then begins standing) or follow a stop";
                self.error(at, &format!("walk.schedule[{n}].start"), message);
            }
            let (last, now, name, unit) = match entry.trigger {
                PaceTrigger::TimeS(t) => (&mut last_time, t, "time_s", "s"),
                PaceTrigger::DistanceM(d) => (&mut last_distance, d, "distance_m", "m"),
            };
            if now < *last {
                let message = format!(
                    "must not be earlier than the entry before it ({} {unit}): entries fire in file order",
                    crate::config::echo::number(*last)
                );
                self.error(at, &format!("walk.schedule[{n}].{name}"), message);
            }
            *last = now;
        }
    }
}
