#!/usr/bin/env python3
"""How much of a run's drift is the direction of its steps and how much their length.

    scripts/error_split.py OUT [--roadscale build/roadscale]

Reads OUT/poses_kitti.txt and OUT/gt_poses_kitti.txt (one pose per frame), builds two hybrid
trajectories and evaluates all three with `roadscale eval`:

- *direction only*: every step's rotation and direction of travel from the estimate, its
  length from the ground truth;
- *length only*: every step's rotation and direction from the ground truth, its length from
  the estimate.

A run whose t_err comes back mostly in the second is limited by its scale (the road's
readings, the map carrying them), one whose t_err comes back mostly in the first by its
rotation. On the rendered hills the length held all of it before the keyframe back end let
consistent road pairs outvote the map (docs/benchmark-history.md, "The pairs outvote the map").
"""
import argparse
import json
import math
import os
import subprocess
import tempfile

from kitti_poses import fail, read_poses


def multiply(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(4)) for j in range(4)] for i in range(4)]


def inverse(pose):
    rotation_t = [[pose[j][i] for j in range(3)] for i in range(3)]
    translation = [-sum(rotation_t[i][k] * pose[k][3] for k in range(3)) for i in range(3)]
    return [rotation_t[i] + [translation[i]] for i in range(3)] + [[0.0, 0.0, 0.0, 1.0]]


def step(poses, i):
    return multiply(inverse(poses[i - 1]), poses[i])


def with_length(pose, length):
    """`pose` with its translation scaled to `length` (unchanged when it has none)."""
    norm = math.sqrt(sum(pose[i][3] ** 2 for i in range(3)))
    out = [row[:] for row in pose]
    if norm > 1e-12:
        for i in range(3):
            out[i][3] *= length / norm
    return out


def length(pose):
    return math.sqrt(sum(pose[i][3] ** 2 for i in range(3)))


def chain(steps):
    poses = [[[1.0 if i == j else 0.0 for j in range(4)] for i in range(4)]]
    for s in steps:
        poses.append(multiply(poses[-1], s))
    return poses


def write(poses, path):
    with open(path, "w") as out:
        for p in poses:
            out.write(" ".join(f"{p[i][j]:.9g}" for i in range(3) for j in range(4)) + "\n")


def evaluate(roadscale, gt_path, est_path):
    result = subprocess.run(
        [roadscale, "eval", "--gt", gt_path, "--est", est_path, "--json"],
        capture_output=True, text=True)
    if result.returncode != 0:
        fail(f"{roadscale} eval failed: {result.stderr.strip()}")
    metrics = json.loads(result.stdout)
    return metrics["kitti"]["t_err_pct"], metrics["ate_m"]["se3"]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("out", help="a `roadscale run` output folder")
    parser.add_argument("--roadscale", default="build/roadscale", help="the roadscale binary")
    args = parser.parse_args()
    estimate = read_poses(os.path.join(args.out, "poses_kitti.txt"))
    truth = read_poses(os.path.join(args.out, "gt_poses_kitti.txt"))
    if len(estimate) != len(truth) or len(estimate) < 2:
        fail(f"{args.out}: {len(estimate)} estimated and {len(truth)} true poses; "
                 "expected the same number, at least 2")
    frames = range(1, len(estimate))
    direction_only = chain(with_length(step(estimate, i), length(step(truth, i))) for i in frames)
    length_only = chain(with_length(step(truth, i), length(step(estimate, i))) for i in frames)
    with tempfile.TemporaryDirectory() as folder:
        gt_path = os.path.join(folder, "truth.txt")
        write(truth, gt_path)
        rows = [("estimate", estimate), ("direction only (true lengths)", direction_only),
                ("length only (true directions)", length_only)]
        print(f"{'trajectory':<32} {'t_err %':>8} {'ATE se3 m':>10}")
        for name, poses in rows:
            path = os.path.join(folder, "hybrid.txt")
            write(poses, path)
            t_err, ate = evaluate(args.roadscale, gt_path, path)
            t_text = "-" if t_err is None else f"{t_err:.3f}"
            print(f"{name:<32} {t_text:>8} {ate:>10.3f}")


if __name__ == "__main__":
    main()
