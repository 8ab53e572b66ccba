#!/usr/bin/env python3
"""The Python module against the command line on the same rendered frames: Odometry gives
`roadscale run`'s poses, rescale() `roadscale rescale`'s.

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
        if odometry.latest() is not None:
            fail("latest() before any frame: %s" % odometry.latest())
        for name, timestamp in zip(images, times):
            path = os.path.join(sequence, "image_0", name)
            frames += odometry.track(cv2.imread(path, cv2.IMREAD_GRAYSCALE), float(timestamp),
                                     path)
        frames += odometry.finish()
        latest = odometry.latest()
        if latest is None or latest["index"] != len(images) - 1 or not latest["metric"]:
            fail("latest() after the last frame: %s" % latest)
        # The map's localisation of the last frame, which the window refined since.
        offset = np.linalg.norm(latest["world_from_cam"][:3, 3] - expected[-1][:, 3])
        if offset > 0.3:
            fail("latest() is %.2f m from the last frame's final pose" % offset)

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
        check_rescale(roadscale, cli, data, sequence, labels, config, scratch)
    print("python module: %d frames, the run's poses (to %.1e), %.1f m travelled"
          % (len(frames), difference, travelled))


def check_rescale(roadscale, cli, data, sequence, labels, camera, scratch):
    """The true trajectory at a third of its size, rescaled by the module and by the CLI."""
    truth = np.loadtxt(os.path.join(data, "poses", "00.txt")).reshape(-1, 3, 4)
    shrunk = truth.copy()
    shrunk[:, :, 3] *= 0.3
    trajectory = os.path.join(scratch, "shrunk.txt")
    np.savetxt(trajectory, shrunk.reshape(-1, 12), fmt="%.9e")
    out = os.path.join(scratch, "rescale")
    subprocess.run([cli, "rescale", "--trajectory", trajectory, "--kitti", sequence, "--labels",
                    labels, "--out", out], check=True, stdout=subprocess.DEVNULL)
    expected = np.loadtxt(os.path.join(out, "poses_kitti.txt")).reshape(-1, 3, 4)

    names = sorted(os.listdir(os.path.join(sequence, "image_0")))
    images = (cv2.imread(os.path.join(sequence, "image_0", name), cv2.IMREAD_GRAYSCALE)
              for name in names)
    times = np.loadtxt(os.path.join(sequence, "times.txt")).tolist()
    result = roadscale.rescale(np.loadtxt(trajectory).reshape(-1, 3, 4), images, camera,
                               labels=labels, timestamps=times)
    poses = result["poses"][:, :3]
    if poses.shape != expected.shape:
        fail("rescale: %s poses, the CLI wrote %s" % (poses.shape, expected.shape))
    difference = np.abs(poses - expected).max()
    if difference > 1e-6 * max(1.0, np.abs(expected).max()):
        fail("rescale: poses differ from the CLI's by up to %g" % difference)
    if len(result["status"]) != len(poses) or result["status"][0] != "first":
        fail("rescale: statuses %s" % result["status"][:3])
    steps = lambda p: np.linalg.norm(np.diff(p[:, :, 3], axis=0), axis=1).sum()
    ratio = steps(poses) / steps(truth)
    if abs(ratio - 1.0) > 0.03:
        fail("rescale: the path is %.3f of the truth's (input 0.3)" % ratio)
    bad_calls = [
        ("no images", lambda: roadscale.rescale(shrunk, iter([]), camera), "images came"),
        ("images of another size",
         lambda: roadscale.rescale(shrunk, (np.zeros((10, 10), np.uint8) for _ in names), camera),
         "10x10"),
        ("too few timestamps",
         lambda: roadscale.rescale(shrunk, iter([]), camera, timestamps=[0.0, 0.1]), "timestamps"),
    ]
    for what, call, expected_text in bad_calls:
        try:
            call()
            fail("rescale took %s" % what)
        except roadscale.Error as error:
            if expected_text not in str(error):
                fail("rescale, %s: unclear error: %s" % (what, error))


if __name__ == "__main__":
    main()
