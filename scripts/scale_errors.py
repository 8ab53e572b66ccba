#!/usr/bin/env python3
"""Per-frame scale error of a `roadscale run` output folder against its ground truth.

    scripts/scale_errors.py OUT [--skip-until 14]

Reads OUT/frames.csv and OUT/gt_poses_kitti.txt (written when the input has ground truth) and
prints, over the moving frames (true step >= 5 cm): the raw road-plane scale of the frames
with their own plane (status ok) and the applied step length, each against the true step
length: the median of the absolute error, its mean (the bias) and its 90th percentile; then
the raw scale again from frame --skip-until on (KITTI 00's ground truth has a constant speed in
frames 1-13 that the images do not show), and the path-length ratio, over all frames and from
frame --skip-until on.
"""
import argparse
import csv
import math
import os

from kitti_poses import fail, read_poses


def read_positions(path):
    return [(pose[0][3], pose[1][3], pose[2][3]) for pose in read_poses(path)]


def summary(errors):
    if not errors:
        return "no frames"
    absolute = sorted(abs(e) for e in errors)
    median = absolute[len(absolute) // 2]
    p90 = absolute[int(0.9 * (len(absolute) - 1))]
    mean = sum(errors) / len(errors)
    return (f"median |error| {100 * median:.2f} %, mean {100 * mean:+.2f} %, "
            f"p90 {100 * p90:.2f} % ({len(errors)} frames)")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("out", help="output folder of roadscale run")
    parser.add_argument("--skip-until", type=int, default=14,
                        help="first frame of the last summary line (default 14)")
    args = parser.parse_args()
    gt_path = os.path.join(args.out, "gt_poses_kitti.txt")
    frames_path = os.path.join(args.out, "frames.csv")
    for path in (gt_path, frames_path):
        if not os.path.isfile(path):
            fail(f"{path}: missing (a run on an input with ground truth writes it)")
    truth = read_positions(gt_path)
    with open(frames_path, newline="") as frames:
        rows = list(csv.DictReader(frames))
    if len(rows) > len(truth):
        fail(f"{frames_path}: {len(rows)} frames but {len(truth)} ground-truth poses")

    raw, applied, late = [], [], []
    estimated_path = true_path = late_estimated_path = late_true_path = 0.0
    for index in range(1, len(rows)):
        row = rows[index]
        true_step = math.dist(truth[index], truth[index - 1])
        step = float(row["step_length_m"])
        estimated_path += step
        true_path += true_step
        if index >= args.skip_until:
            late_estimated_path += step
            late_true_path += true_step
        if true_step < 0.05:
            continue
        applied.append(step / true_step - 1.0)
        raw_scale = row.get("road_raw_scale", "")
        if row["status"] == "ok" and raw_scale not in ("", "nan"):
            raw.append(float(raw_scale) / true_step - 1.0)
            if index >= args.skip_until:
                late.append(raw[-1])
    print(f"raw road-plane scale:            {summary(raw)}")
    print(f"applied step length:             {summary(applied)}")
    print(f"raw, frames >= {args.skip_until:<4}:            {summary(late)}")
    if true_path > 0.0:
        print(f"path length ratio (est / true):  {estimated_path / true_path:.4f}")
    if late_true_path > 0.0:
        print(f"path length ratio, frames >= {args.skip_until:<4}: "
              f"{late_estimated_path / late_true_path:.4f}")


if __name__ == "__main__":
    main()
