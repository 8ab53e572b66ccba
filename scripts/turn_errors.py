#!/usr/bin/env python3
"""How much of each turn a `roadscale run` output folder measured, against its ground truth.

    scripts/turn_errors.py OUT [--segment 25]

Reads OUT/poses_kitti.txt and OUT/gt_poses_kitti.txt and prints, per segment of frames, the
mean yaw per frame (the rotation about the camera's vertical axis, degrees) of the ground
truth and of the estimate and their ratio, then the whole drive's accumulated yaw. A ratio
below 1 in every curve is a rotation that is under-measured, not noise: on the rendered
highways it was 0.65-0.75 before the keyframe back end's ground check
(docs/benchmark-history.md, "Tracks that caught the next post").
"""
import argparse
import math

from kitti_poses import fail, read_poses


def read_rotations(path):
    return [[row[0:3] for row in pose[0:3]] for pose in read_poses(path)]


def step_yaw_deg(before, after):
    """Yaw of after relative to before, in before's camera frame (y down: about -y)."""
    # relative = before^T * after; yaw from its third column's x and z.
    r02 = sum(before[k][0] * after[k][2] for k in range(3))
    r22 = sum(before[k][2] * after[k][2] for k in range(3))
    return math.degrees(math.atan2(r02, r22))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("out", help="output folder of roadscale run (with gt_poses_kitti.txt)")
    parser.add_argument("--segment", type=int, default=25, help="frames per segment")
    args = parser.parse_args()
    if args.segment < 1:
        fail("--segment must be at least 1")
    estimate = read_rotations(f"{args.out}/poses_kitti.txt")
    truth = read_rotations(f"{args.out}/gt_poses_kitti.txt")
    if len(estimate) != len(truth) or len(truth) < 2:
        fail(f"{args.out}: {len(estimate)} estimated and {len(truth)} true poses; "
                 "expected the same number, at least 2")
    est_steps = [step_yaw_deg(estimate[i - 1], estimate[i]) for i in range(1, len(truth))]
    gt_steps = [step_yaw_deg(truth[i - 1], truth[i]) for i in range(1, len(truth))]
    print("frames      true yaw/frame  estimated  ratio")
    for start in range(0, len(gt_steps), args.segment):
        gt = gt_steps[start:start + args.segment]
        est = est_steps[start:start + args.segment]
        gt_mean = sum(gt) / len(gt)
        est_mean = sum(est) / len(est)
        # A ratio says nothing on a straight segment (a few thousandths of a degree a frame).
        ratio = f"{est_mean / gt_mean:6.2f}" if abs(gt_mean) > 0.01 else "     -"
        print(f"{start + 1:4d}-{start + len(gt):4d}  {gt_mean:+14.4f}  {est_mean:+9.4f}  {ratio}")
    print(f"accumulated yaw: true {sum(gt_steps):+.2f} deg, estimated {sum(est_steps):+.2f} deg")


if __name__ == "__main__":
    main()
