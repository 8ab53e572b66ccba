"""KITTI pose files for the scripts: one pose a line, the 3x4 matrix world_from_cam row by row.

Every script that reads a run's poses_kitti.txt or gt_poses_kitti.txt reads it here, so that a
missing or malformed file stops each of them with the same one line naming the file and the
problem.
"""
import os
import sys


def fail(message):
    """Stops the calling script with one line on stderr, prefixed with its name."""
    sys.exit(f"{os.path.basename(sys.argv[0])}: {message}")


def read_poses(path):
    """The poses as 4x4 matrices (lists of rows); stops at a missing, empty or malformed file."""
    if not os.path.isfile(path):
        fail(f"{path}: no such file")
    poses = []
    with open(path) as lines:
        for number, line in enumerate(lines, 1):
            values = line.split()
            if not values:
                continue
            if len(values) != 12:
                fail(f"{path}:{number}: {len(values)} numbers where a KITTI pose row has 12")
            try:
                v = [float(x) for x in values]
            except ValueError:
                fail(f"{path}:{number}: not a KITTI pose row of numbers")
            poses.append([v[0:4], v[4:8], v[8:12], [0.0, 0.0, 0.0, 1.0]])
    if not poses:
        fail(f"{path}: no poses")
    return poses
