#!/usr/bin/env python3
"""Derives joint_angles_by_speed.csv from the WBDS per-trial angle files.

Data: Fukuchi CA, Fukuchi RK, Duarte M (2018), "A public dataset of overground and
treadmill walking kinematics and kinetics in healthy individuals", PeerJ 6:e4640,
doi:10.7717/peerj.4640; files: figshare doi:10.6084/m9.figshare.5722711 (CC BY 4.0),
`WBDSascii.zip` members WBDS<ss>walkT<tt>ang.txt.

Usage: python3 derive_joint_angles_by_speed.py ASCII_DIR > joint_angles_by_speed.csv

Which trial each subject gives to each speed block is in wbds_trial_selection.csv beside
this script (young adults WBDS01-24; per subject and target speed, the one treadmill trial
whose belt speed in WBDSinfo.xlsx is nearest the target, kept if within 0.10 m/s).

Per trial, the same steps as normative_adult_walking.csv's derivation (see its .md):
hip, knee and ankle = mean of the R and L `<Joint>AngleZ` columns; pelvis tilt = mean of
R and L `PelvisAngleZ`; obliquity = `RPelvisAngleX`; rotation = `RPelvisAngleY`. Per block
and per 1 % of the cycle: the mean over subjects and the sample SD (n - 1). A block's
speed_m_s is the mean belt speed of its trials. Standard library only; output rounded to
0.01 deg (speed to 0.001 m/s), so the same inputs give the same bytes.
"""
import csv
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))

# (output stem, how a trial's curve is made from its columns)
CURVES = [
    ("hip_flex", lambda d: mean2(d["RHipAngleZ"], d["LHipAngleZ"])),
    ("knee_flex", lambda d: mean2(d["RKneeAngleZ"], d["LKneeAngleZ"])),
    ("ankle_dorsi", lambda d: mean2(d["RAnkleAngleZ"], d["LAnkleAngleZ"])),
    ("pelvis_tilt_ant", lambda d: mean2(d["RPelvisAngleZ"], d["LPelvisAngleZ"])),
    ("pelvis_obliq_up", lambda d: d["RPelvisAngleX"]),
    ("pelvis_rot_fwd", lambda d: d["RPelvisAngleY"]),
]


def mean2(a, b):
    return [(x + y) / 2.0 for x, y in zip(a, b)]


def read_trial(path):
    with open(path, encoding="utf-8") as f:
        lines = [line.rstrip("\r\n") for line in f if line.strip()]
    head = lines[0].split("\t")
    rows = [[float(v) for v in line.split("\t")] for line in lines[1:]]
    if len(rows) != 101 or any(len(r) != len(head) for r in rows):
        sys.exit(f"{path}: expected 101 rows of {len(head)} numbers")
    if any(not math.isfinite(v) for r in rows for v in r):
        sys.exit(f"{path}: a value is not finite")
    return {h: [r[i] for r in rows] for i, h in enumerate(head)}


def mean_sd(values):
    m = sum(values) / len(values)
    return m, math.sqrt(sum((v - m) ** 2 for v in values) / (len(values) - 1))


def main():
    ascii_dir = sys.argv[1]
    with open(os.path.join(HERE, "wbds_trial_selection.csv"), encoding="utf-8") as f:
        selection = list(csv.DictReader(row for row in f if not row.startswith("#")))
    targets = sorted({float(r["target_m_s"]) for r in selection})
    out = csv.writer(sys.stdout, lineterminator="\n")
    header = ["pct_cycle", "speed_m_s"]
    for stem, _ in CURVES:
        header += [f"{stem}_mean_deg", f"{stem}_sd_deg"]
    out.writerow(header)
    for target in targets:
        trials = [r for r in selection if float(r["target_m_s"]) == target]
        speed = sum(float(r["speed_m_s"]) for r in trials) / len(trials)
        per_trial = [read_trial(os.path.join(ascii_dir, r["file"])) for r in trials]
        curves = [[make(d) for d in per_trial] for _, make in CURVES]
        for pct in range(101):
            row = [str(pct), f"{speed:.3f}"]
            for subjects in curves:
                m, sd = mean_sd([c[pct] for c in subjects])
                row += [f"{m:.2f}", f"{sd:.2f}"]
            out.writerow(row)


if __name__ == "__main__":
    main()
