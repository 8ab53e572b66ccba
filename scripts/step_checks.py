#!/usr/bin/env python3
"""Each step's direction of travel, and the lengths the map carried between road fixes.

    scripts/step_checks.py OUT [--min-step M]

Reads OUT/poses_kitti.txt, OUT/gt_poses_kitti.txt and OUT/frames.csv of a `roadscale run`
with ground truth and prints:

- the direction error of every step of at least --min-step metres of true travel (default
  0.01): the angle between the estimated and the true direction of travel, both in the
  earlier frame's camera, so that the drift of the heading before it does not count; the
  largest, the 99th percentile and the steps more than 5 degrees off;
- every run of frames whose scale the map carried (`map_scale` carried in frames.csv, the
  keyframe back end) or whose length was held (`status` held, the frame-to-frame host): its
  frames, the change of the true speed across it (the fastest true step of the run against the
  slowest, for steps of at least --min-step) and the length it came out with against the true
  length. A held length is the last step's: across a change of speed it is wrong by that change.
  A carried scale is the map's: its steps follow the speed.

Issue 11 asks of the rendered traffic jams: no step more than 5 degrees off, and no held
scale across a change of speed of more than 20 %.
"""
import argparse
import csv
import math
import os

from error_split import length, step
from kitti_poses import fail, read_poses


def translation(pose):
    return [pose[i][3] for i in range(3)]


def angle_deg(u, v):
    cosine = sum(x * y for x, y in zip(u, v)) / math.sqrt(
        sum(x * x for x in u) * sum(y * y for y in v))
    return math.degrees(math.acos(max(-1.0, min(1.0, cosine))))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("out")
    parser.add_argument("--min-step", type=float, default=0.01)
    args = parser.parse_args()
    estimate = read_poses(os.path.join(args.out, "poses_kitti.txt"))
    truth = read_poses(os.path.join(args.out, "gt_poses_kitti.txt"))
    if len(estimate) != len(truth):
        fail(f"{args.out}: {len(estimate)} poses against {len(truth)} of the ground truth")
    frames_csv = os.path.join(args.out, "frames.csv")
    if not os.path.isfile(frames_csv):
        fail(f"{frames_csv}: no such file")
    with open(frames_csv) as f:
        rows = list(csv.DictReader(f))
    if len(rows) != len(estimate):
        fail(f"{frames_csv}: {len(rows)} rows against {len(estimate)} poses")

    errors = []
    true_lengths, estimated_lengths = [0.0], [0.0]
    for k in range(1, len(estimate)):
        # Both steps in the earlier frame's camera: the heading's drift before them does not count.
        true_step, estimated_step = step(truth, k), step(estimate, k)
        true_lengths.append(length(true_step))
        estimated_lengths.append(length(estimated_step))
        if true_lengths[-1] >= args.min_step and estimated_lengths[-1] > 0.0:
            errors.append((angle_deg(translation(true_step), translation(estimated_step)), k))
    if errors:
        ordered = sorted(e for e, _ in errors)
        worst, worst_frame = max(errors)
        off = [k for e, k in errors if e > 5.0]
        print(f"steps of >= {args.min_step} m: {len(errors)}; direction error median "
              f"{ordered[len(ordered) // 2]:.2f} deg, 99th percentile "
              f"{ordered[min(len(ordered) - 1, int(0.99 * len(ordered)))]:.2f} deg, largest "
              f"{worst:.2f} deg (frame {worst_frame}); more than 5 deg off: {len(off)}"
              + (f" (frames {', '.join(map(str, off[:20]))})" if off else ""))
    else:
        print(f"no step of >= {args.min_step} m")

    def carried(row):
        return row.get("map_scale") == "carried" or row.get("status") == "held"

    spans = []
    k = 0
    while k < len(rows):
        if not carried(rows[k]):
            k += 1
            continue
        start = k
        while k < len(rows) and carried(rows[k]):
            k += 1
        spans.append((start, k - 1))
    worst_change = 0.0
    for start, end in spans:
        moving = [true_lengths[i] for i in range(start, end + 1) if true_lengths[i] >= args.min_step]
        change = (max(moving) / min(moving) - 1.0) if len(moving) >= 2 else 0.0
        worst_change = max(worst_change, change)
        true_length = sum(true_lengths[start:end + 1])
        estimated_length = sum(estimated_lengths[start:end + 1])
        ratio = estimated_length / true_length if true_length > 0.0 else float("nan")
        print(f"carried or held: frames {start}-{end} ({end - start + 1}), true speed change "
              f"{100.0 * change:.0f} %, length {estimated_length:.2f} m against {true_length:.2f} m "
              f"(ratio {ratio:.3f})")
    print(f"carried or held runs: {len(spans)}; largest true speed change across one: "
          f"{100.0 * worst_change:.0f} %")


if __name__ == "__main__":
    main()
