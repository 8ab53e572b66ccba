#!/usr/bin/env python3
"""roadscale from Python: a KITTI odometry sequence's frames through roadscale.Odometry, the
metric poses collected and, with ground truth, evaluated as `roadscale eval` does.

Usage: python_odometry.py BUILD_DIR SEQUENCE [FRAMES]
  BUILD_DIR  holds python/roadscale*.so (scripts/setup.sh builds it into build/)
  SEQUENCE   a KITTI odometry sequence folder (image_0/, calib.txt, times.txt; ground truth
             from ../../poses/NN.txt when present)
  FRAMES     how many frames from the first (default: all)
Segmentation from the shared network when its model file is there, else none.
"""
import os
import sys

import cv2
import numpy as np


def kitti_camera(sequence, h0=1.65):
    """The grey left camera's intrinsics from calib.txt (row P0), KITTI's camera height."""
    with open(os.path.join(sequence, "calib.txt")) as calib:
        p0 = next(line for line in calib if line.startswith("P0:")).split()[1:]
    p0 = np.array(p0, dtype=float).reshape(3, 4)
    first = cv2.imread(os.path.join(sequence, "image_0", "000000.png"), cv2.IMREAD_GRAYSCALE)
    return {"fx": p0[0, 0], "fy": p0[1, 1], "cx": p0[0, 2], "cy": p0[1, 2],
            "width": first.shape[1], "height": first.shape[0], "h0": h0}


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    build, sequence = sys.argv[1], sys.argv[2]
    sys.path.insert(0, os.path.join(build, "python"))
    import roadscale

    images = sorted(os.listdir(os.path.join(sequence, "image_0")))
    times = np.loadtxt(os.path.join(sequence, "times.txt"))
    count = int(sys.argv[3]) if len(sys.argv) > 3 else len(images)
    model = os.path.join(os.path.dirname(__file__), "..", "config", "models",
                         "espnetv2_512x256.yaml")
    try:
        odometry = roadscale.Odometry(camera=kitti_camera(sequence), model=model)
    except roadscale.Error as error:
        print("no segmentation (%s)" % error)
        odometry = roadscale.Odometry(camera=kitti_camera(sequence))
    for name, timestamp in zip(images[:count], times[:count]):
        path = os.path.join(sequence, "image_0", name)
        odometry.track(cv2.imread(path), float(timestamp), path)
    odometry.finish()
    poses = odometry.poses()
    print(odometry.summary)
    print("%d poses, %.2f m travelled" % (len(poses), np.linalg.norm(poses[-1, :3, 3])))

    number = os.path.basename(os.path.normpath(sequence))
    ground_truth = os.path.join(sequence, "..", "..", "poses", number + ".txt")
    if os.path.exists(ground_truth):
        gt = np.loadtxt(ground_truth)[:count].reshape(-1, 3, 4)
        metrics = roadscale.evaluate(gt, poses)
        print("against the ground truth: length ratio %.4f, ATE (se3) %.3f m"
              % (metrics["length_ratio"], metrics["ate_m"]["se3"]))


if __name__ == "__main__":
    main()
