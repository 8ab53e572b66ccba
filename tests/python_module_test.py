#!/usr/bin/env python3
"""The Python module against `roadscale run` on the same rendered frames: the same poses.

Usage: python_module_test.py BUILD_DIR   (BUILD_DIR holds roadscale and python/roadscale*.so)
"""
import os
import subprocess
import sys
import tempfile

import cv2
import numpy as np


def fail(message):
    print("FAIL: " + message, file=sys.stderr)
    sys.exit(1)


def main():
    build = os.path.abspath(sys.argv[1])
    sys.path.insert(0, os.path.join(build, "python"))
    import roadscale

    cli = os.path.join(build, "roadscale")
    with tempfile.TemporaryDirectory() as scratch:
        data = os.path.join(scratch, "data")
        subprocess.run([cli, "synth", "--preset", "urban", "--frames", "40", "--seed", "1",
                        "--out", data], check=True, stdout=subprocess.DEVNULL)
        sequence = os.path.join(data, "sequences", "00")
        labels = os.path.join(sequence, "semantic")
        run = os.path.join(scratch, "run")
        subprocess.run([cli, "run", "--kitti", sequence, "--labels", labels, "--out", run],
                       check=True, stdout=subprocess.DEVNULL)
        expected = np.loadtxt(os.path.join(run, "poses_kitti.txt")).reshape(-1, 3, 4)

        # config_used.yaml is a camera YAML and the run's config at once.
        config = os.path.join(run, "config_used.yaml")
        odometry = roadscale.Odometry(camera=config, config=config, labels=labels)
        try:
            odometry.track(np.zeros((10, 10), np.uint8), 0.0)
            fail("an image of the wrong size was taken")
        except roadscale.Error as error:
            if "10x10" not in str(error):
                fail("unclear error: %s" % error)
        times = np.loadtxt(os.path.join(sequence, "times.txt"))
        images = sorted(os.listdir(os.path.join(sequence, "image_0")))
        frames = []
        for name, timestamp in zip(images, times):
            path = os.path.join(sequence, "image_0", name)
            frames += odometry.track(cv2.imread(path, cv2.IMREAD_GRAYSCALE), float(timestamp),
                                     path)
        frames += odometry.finish()

        if [frame["index"] for frame in frames] != list(range(len(images))):
            fail("frames out of order or missing: %s" % [frame["index"] for frame in frames])
        poses = np.stack([frame["world_from_cam"][:3] for frame in frames])
        # The run's file holds 9 significant digits.
        difference = np.abs(poses - expected).max()
        if difference > 1e-6 * max(1.0, np.abs(expected).max()):
            fail("poses differ from the run's by up to %g" % difference)
        travelled = np.linalg.norm(poses[-1][:, 3] - poses[0][:, 3])
        if travelled < 5.0:
            fail("the drive moved only %.2f m" % travelled)
        if not np.array_equal(odometry.poses()[:, :3], poses):
            fail("poses() differs from the frames' world_from_cam")
        metrics = roadscale.evaluate(expected, odometry.poses())
        if metrics["frames"] != 40 or abs(metrics["length_ratio"] - 1.0) > 1e-9:
            fail("evaluate() of the run's own poses: %s" % metrics)
        if "Frames: 40" not in odometry.summary:
            fail("summary: %s" % odometry.summary)
    print("python module: %d frames, the run's poses (to %.1e), %.1f m travelled"
          % (len(frames), difference, travelled))


if __name__ == "__main__":
    main()
