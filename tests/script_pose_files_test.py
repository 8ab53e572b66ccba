#!/usr/bin/env python3
"""The analysis scripts read KITTI pose files through scripts/kitti_poses.py: the poses come
back as 4x4 matrices, and a missing, malformed or empty file stops every script with one line
on stderr that names the script and the file, and a non-zero exit.

Usage: script_pose_files_test.py REPO_ROOT
"""
import os
import subprocess
import sys
import tempfile

IDENTITY_ROW = "1 0 0 0 0 1 0 0 0 0 1 0\n"
# Scripts that take a run's output folder (scale_errors.py reads the ground truth only).
SCRIPTS = ["error_split.py", "scale_errors.py", "turn_errors.py", "step_checks.py"]


def check(condition, message):
    if not condition:
        sys.exit(f"FAIL: {message}")


def run_script(root, script, out):
    return subprocess.run([sys.executable, os.path.join(root, "scripts", script), out],
                          capture_output=True, text=True)


def main():
    root = sys.argv[1]
    sys.path.insert(0, os.path.join(root, "scripts"))
    import kitti_poses

    with tempfile.TemporaryDirectory() as scratch:
        good = os.path.join(scratch, "good.txt")
        with open(good, "w") as f:
            f.write(IDENTITY_ROW + "\n" + "1 0 0 2 0 1 0 3 0 0 1 4\n")
        poses = kitti_poses.read_poses(good)
        check(len(poses) == 2, f"two poses expected (a blank line is no pose), got {len(poses)}")
        check(poses[1][0][3] == 2.0 and poses[1][1][3] == 3.0 and poses[1][2][3] == 4.0,
              f"the second pose's translation is (2, 3, 4), got {poses[1]}")
        check(poses[1][3] == [0.0, 0.0, 0.0, 1.0], "the fourth row is 0 0 0 1")

        cases = {
            "short row": (IDENTITY_ROW + "1 0 0 0 0 1 0 0 0 0 1\n", ":2: 11 numbers"),
            "a word": (IDENTITY_ROW + "1 0 0 0 0 1 0 0 0 0 1 x\n", ":2: not a KITTI pose row"),
            "empty": ("", ": no poses"),
        }
        for name, (text, expected) in cases.items():
            out = os.path.join(scratch, name.replace(" ", "_"))
            os.makedirs(out)
            for file in ("poses_kitti.txt", "gt_poses_kitti.txt"):
                with open(os.path.join(out, file), "w") as f:
                    f.write(text)
            with open(os.path.join(out, "frames.csv"), "w") as f:
                f.write("index,step_length_m\n")
            for script in SCRIPTS:
                result = run_script(root, script, out)
                lines = result.stderr.strip().splitlines()
                check(result.returncode != 0, f"{script} on a file with {name}: exit 0")
                check(len(lines) == 1, f"{script} on a file with {name}: {len(lines)} stderr "
                      f"lines, one expected: {result.stderr!r}")
                check(lines[0].startswith(script + ": " + out) and expected in lines[0],
                      f"{script} on a file with {name}: {lines[0]!r} does not name the script, "
                      f"the file and '{expected}'")

        missing = os.path.join(scratch, "no_run_here")
        for script in SCRIPTS:
            result = run_script(root, script, missing)
            lines = result.stderr.strip().splitlines()
            check(result.returncode != 0 and len(lines) == 1 and missing in lines[0],
                  f"{script} on a missing folder: exit {result.returncode}, {result.stderr!r}")
    print(f"{len(SCRIPTS)} scripts: one line naming the file for every bad pose file")


if __name__ == "__main__":
    main()
