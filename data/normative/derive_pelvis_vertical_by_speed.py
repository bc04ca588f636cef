#!/usr/bin/env python3
"""Derives pelvis_vertical_by_speed.csv from WBDS treadmill marker files.

Data: Fukuchi CA, Fukuchi RK, Duarte M (2018), "A public dataset of overground and
treadmill walking kinematics and kinetics in healthy individuals", PeerJ 6:e4640,
doi:10.7717/peerj.4640; files: figshare doi:10.6084/m9.figshare.5722711 (CC BY 4.0),
`WBDSascii.zip` members WBDS<ss>walkT<tt>mkr.txt (tab-separated, a header naming each marker
coordinate, 150 rows a second, millimetres, Y up).

Usage: python3 derive_pelvis_vertical_by_speed.py MARKER_DIR > pelvis_vertical_by_speed.csv

Trials: the rows of pelvis_vertical_trials.csv beside this script (subject, target speed,
trial, belt speed), a subset of wbds_trial_selection.csv. Per trial, the first 2.2 s of the
file (the part read, see pelvis_vertical_by_speed.md):

1. The pelvis centre's height: the mean of the four pelvis markers R.ASIS, L.ASIS, R.PSIS and
   L.PSIS (Y). Where a marker is missing (NaN), the centre is the mean of the others, each
   less its mean offset from the four-marker mean over the rows where all four are present.
2. Steps: the centre's lows (double support), each the lowest point of a 7-sample (47 ms)
   neighbourhood of the 5-sample moving average, at least 3 mm under the highest point within
   0.3 s and at least 0.3 s after the previous low. A step's vertical range is max - min of
   the (unsmoothed) centre from one low to the next.
3. The trial's range: the mean over its steps.

Per target speed: the mean and sample SD (n - 1) over the trials (one per subject), the mean
belt speed, and the number of subjects and steps. Standard library only; output rounded to
0.01 cm (speed 0.001 m/s), so the same inputs give the same bytes.
"""
import csv
import math
import os
import statistics
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
MARKERS = ("R.ASISY", "L.ASISY", "R.PSISY", "L.PSISY")
SECONDS = 2.2


def read_trial(path):
    with open(path, newline="") as f:
        rows = csv.reader(f, delimiter="\t")
        header = next(rows)
        cols = [header.index(m) for m in MARKERS]
        t_col = header.index("Time")
        out = []
        for r in rows:
            t = float(r[t_col])
            if t > SECONDS + 1e-9:
                break
            out.append((t, [float(r[c]) if r[c] != "NaN" else math.nan for c in cols]))
    return out


def centre(rows):
    full = [m for _, m in rows if not any(math.isnan(v) for v in m)]
    offsets = [statistics.fmean(m[k] - statistics.fmean(m) for m in full) for k in range(4)]
    out = []
    for _, m in rows:
        have = [k for k in range(4) if not math.isnan(m[k])]
        out.append(statistics.fmean(m[k] - offsets[k] for k in have) if have else math.nan)
    return out


def step_ranges(times, y):
    n = len(y)
    smooth = [statistics.fmean(y[max(0, i - 2):i + 3]) for i in range(n)]
    lows = []
    for i in range(3, n - 3):
        if smooth[i] != min(smooth[i - 3:i + 4]):
            continue
        if lows and times[i] - times[lows[-1]] < 0.3:
            continue
        near = [smooth[j] for j in range(n) if abs(times[j] - times[i]) <= 0.3]
        if max(near) - smooth[i] > 3.0:
            lows.append(i)
    return [(max(y[a:b + 1]) - min(y[a:b + 1])) / 10.0 for a, b in zip(lows, lows[1:])]


def main(marker_dir):
    with open(os.path.join(HERE, "pelvis_vertical_trials.csv"), newline="") as f:
        trials = [r for r in csv.DictReader(row for row in f if not row.startswith("#"))]
    blocks = {}
    for t in trials:
        rows = read_trial(os.path.join(marker_dir, t["file"]))
        ranges = step_ranges([r[0] for r in rows], centre(rows))
        if not ranges:
            sys.exit(f"{t['file']}: no whole step in the first {SECONDS} s")
        blocks.setdefault(t["target_m_s"], []).append((float(t["speed_m_s"]), statistics.fmean(ranges), len(ranges)))
    w = csv.writer(sys.stdout, lineterminator="\n")
    w.writerow(["target_m_s", "speed_m_s", "subjects", "steps", "vertical_range_mean_cm", "vertical_range_sd_cm"])
    for target in sorted(blocks, key=float):
        b = blocks[target]
        ranges = [r for _, r, _ in b]
        sd = statistics.stdev(ranges) if len(ranges) > 1 else 0.0
        w.writerow([target, f"{statistics.fmean(s for s, _, _ in b):.3f}", len(b), sum(n for _, _, n in b),
                    f"{statistics.fmean(ranges):.2f}", f"{sd:.2f}"])


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
