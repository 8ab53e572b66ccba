#!/usr/bin/env python3
"""scripts/speed_from_images.py on a rendered drive that speeds up: the step lengths it reads
from the images alone are the ground truth's, and a constant speed misfits them.

Usage: speed_from_images_test.py ROADSCALE_BINARY REPO_ROOT
"""
import importlib.util
import os
import subprocess
import sys
import tempfile

import numpy as np


def main():
    roadscale, root = sys.argv[1], sys.argv[2]
    # As when the script runs on its own: its folder's modules (kitti_poses) importable.
    sys.path.insert(0, os.path.join(root, "scripts"))
    spec = importlib.util.spec_from_file_location(
        "speed_from_images", os.path.join(root, "scripts", "speed_from_images.py"))
    script = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(script)
    steps = 15
    with tempfile.TemporaryDirectory() as scratch:
        data, out = os.path.join(scratch, "data"), os.path.join(scratch, "run")
        sequence = os.path.join(data, "sequences", "00")
        subprocess.run([roadscale, "synth", "--preset", "urban", "--frames", str(steps + 1),
                        "--seed", "1", "--out", data], check=True, stdout=subprocess.DEVNULL)
        subprocess.run([roadscale, "run", "--kitti", sequence, "--scale", "oracle", "--labels",
                        os.path.join(sequence, "semantic"), "--out", out],
                       check=True, stdout=subprocess.DEVNULL)
        run = script.read_pose_array(os.path.join(out, "poses_kitti.txt"))
        truth = script.step_lengths(script.read_pose_array(os.path.join(out, "gt_poses_kitti.txt")),
                                    0, steps)
        positions = script.track_corners(script.frame_paths(sequence, None), 0, steps)
        rays, directions = script.rays_and_directions(positions, run, 0,
                                                      script.read_camera(sequence, None))
        images, systems = script.image_lengths(rays, directions)
    error = np.max(np.abs(images - truth / truth.mean()))
    own, of_truth, of_constant = (np.sqrt(np.sum(script.misfits(systems, lengths) ** 2))
                                  for lengths in (images, truth, np.ones(steps)))
    speed_up = truth[-1] / truth[0]
    print(f"{len(systems)} corners; the truth speeds up {speed_up:.2f} times; largest step share "
          f"error {error:.4f}; misfit: the images' own {own:.4f}, the truth's {of_truth:.4f}, "
          f"a constant speed's {of_constant:.4f}")
    if speed_up < 1.2:
        sys.exit("FAIL: the rendered stretch does not speed up: the check would not tell")
    # A constant speed is up to 0.17 off here; the run's rotations leave about 0.006.
    if error > 0.015:
        sys.exit(f"FAIL: the images' step shares are up to {error:.4f} off the truth's")
    if of_truth > 1.02 * own or of_constant < 2 * own:
        sys.exit("FAIL: the misfits do not tell the truth from a constant speed")


if __name__ == "__main__":
    main()
