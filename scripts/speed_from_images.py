#!/usr/bin/env python3
"""A stretch's step lengths, relative to each other, from its images alone, beside the ground
truth's and a run's: which of the two speed profiles the images bear out.

    scripts/speed_from_images.py SEQUENCE OUT FIRST STEPS
    scripts/speed_from_images.py IMAGES OUT FIRST STEPS --camera CAMERA.yaml

With each frame's rotation and each step's direction of travel taken from the run
(OUT/poses_kitti.txt; a run's rotations and directions agree with its images), a static point
X_j seen along the ray r_jk from the camera centre C_k = l_1 d_1 + ... + l_k d_k satisfies
r_jk x (X_j - C_k) = 0, linear in the points and the step lengths l. Solved over every corner
KLT tracks through frames FIRST..FIRST+STEPS (there and back within 0.3 px), the smallest
solution gives the step lengths up to one scale: no road, no camera height, no ground truth in
them. Each equation is weighted by the inverse of the point's distance (an angle, not metres),
and points whose misfit is over three times the median are dropped, twice (cars that move).

Prints each step's share of the stretch for the images, the ground truth (OUT/gt_poses_kitti.txt,
when the run had one) and the run, then the misfit to the images of each profile (the solution's own is the least; a
profile the images bear out comes near it, a constant speed shows how far a wrong one lands).
A folder of images needs its camera (--camera: the YAML given to `roadscale run --images`).
In dense traffic the corners on moving cars outnumber the static ones: on the shared traffic
drive the images determine none of its 12-step stretches (a step of negative length, or a
misfit no better than a constant speed's). On a rendered drive the images' shares are the
ground truth's to about 1 %; on KITTI 00's first frames they bear out the run and not the
ground truth (docs/benchmark-history.md, "KITTI 00's
first frames against its images").
"""
import argparse
import os

import cv2
import numpy as np

from kitti_poses import fail, read_poses


def read_pose_array(path):
    return np.array(read_poses(path))[:, :3, :]


def frame_paths(frames, camera_yaml):
    """The frames' image files in order: a KITTI sequence's image_0/, or a folder of images."""
    folder = frames if camera_yaml else os.path.join(frames, "image_0")
    if not os.path.isdir(folder):
        fail(f"{folder}: no such folder")
    paths = sorted(os.path.join(folder, name) for name in os.listdir(folder)
                   if name.lower().endswith((".png", ".jpg", ".jpeg")))
    if not paths:
        fail(f"{folder}: no png or jpg images")
    return paths


def read_camera(frames, camera_yaml):
    """fx, cx, cy: from the camera YAML's Camera block, else from the sequence's calib.txt."""
    if camera_yaml:
        if not os.path.isfile(camera_yaml):
            fail(f"{camera_yaml}: no such file")
        values = {}
        with open(camera_yaml) as yaml:
            for line in yaml:
                key, _, value = line.split("#")[0].partition(":")
                if key.strip() in ("fx", "cx", "cy") and value.strip():
                    values[key.strip()] = float(value)
        if len(values) < 3:
            fail(f"{camera_yaml}: needs fx, cx and cy")
        return values["fx"], values["cx"], values["cy"]
    path = os.path.join(frames, "calib.txt")
    if not os.path.isfile(path):
        fail(f"{path}: no such file (a folder of images needs --camera)")
    with open(path) as calib:
        for line in calib:
            if line.startswith("P0:"):
                p = [float(v) for v in line.split()[1:]]
                return p[0], p[2], p[6]
    fail(f"{path}: no P0 row")


def read_image(paths, index):
    image = cv2.imread(paths[index], cv2.IMREAD_GRAYSCALE)
    if image is None:
        fail(f"{paths[index]}: cannot read the image")
    return image


def first_frame_of_run(out):
    """The frame the run began at (`--frames A:`), from the first row of OUT/frames.csv."""
    path = os.path.join(out, "frames.csv")
    if not os.path.isfile(path):
        return 0
    with open(path) as frames:
        header, first_row = frames.readline(), frames.readline()
    columns = header.strip().split(",")
    if "index" not in columns or not first_row:
        return 0
    return int(first_row.split(",")[columns.index("index")])


def track_corners(paths, first, steps):
    """Image positions (steps + 1, corners, 2) of the corners tracked through the stretch."""
    klt = dict(winSize=(21, 21), maxLevel=4,
               criteria=(cv2.TERM_CRITERIA_COUNT | cv2.TERM_CRITERIA_EPS, 40, 0.01))
    image = read_image(paths, first)
    height, width = image.shape
    mask = np.zeros_like(image)
    mask[10:height - 10, 10:width - 10] = 255
    corners = cv2.goodFeaturesToTrack(image, 2000, 0.005, 6, mask=mask)
    if corners is None:
        fail(f"no corners in frame {first}")
    positions = [corners[:, 0].copy()]
    alive = np.ones(len(corners), bool)
    for index in range(first + 1, first + steps + 1):
        following = read_image(paths, index)
        ahead, found, _ = cv2.calcOpticalFlowPyrLK(image, following, corners, None, **klt)
        back, found_back, _ = cv2.calcOpticalFlowPyrLK(following, image, ahead, None, **klt)
        alive &= (found[:, 0] == 1) & (found_back[:, 0] == 1)
        alive &= np.linalg.norm((back - corners)[:, 0], axis=1) < 0.3
        inside = (ahead[:, 0, 0] > 3) & (ahead[:, 0, 0] < width - 3)
        alive &= inside & (ahead[:, 0, 1] > 3) & (ahead[:, 0, 1] < height - 3)
        positions.append(ahead[:, 0].copy())
        image, corners = following, ahead
    positions = np.array(positions)[:, alive]
    # A corner that hardly moves is too far away to say anything about the lengths.
    return positions[:, np.linalg.norm(positions[-1] - positions[0], axis=1) > 3.0]


def rays_and_directions(positions, poses, first, camera):
    """Unit rays (steps + 1, corners, 3) and step directions (steps, 3), both in the first
    frame's orientation, from the run's rotations and positions."""
    focal, cx, cy = camera
    steps = positions.shape[0] - 1
    first_rotation = poses[first, :, :3]
    rays = np.zeros(positions.shape[:2] + (3,))
    for k in range(steps + 1):
        pixels = np.c_[(positions[k, :, 0] - cx) / focal, (positions[k, :, 1] - cy) / focal,
                       np.ones(positions.shape[1])]
        turned = pixels @ (first_rotation.T @ poses[first + k, :, :3]).T
        rays[k] = turned / np.linalg.norm(turned, axis=1)[:, None]
    travel = np.diff(poses[first:first + steps + 1, :, 3], axis=0) @ first_rotation
    lengths = np.linalg.norm(travel, axis=1)
    if np.any(lengths < 1e-9):
        fail(f"the run stands still at step {first + int(np.argmin(lengths))}: no direction")
    return rays, travel / lengths[:, None]


def skew(v):
    return np.array([[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]])


def corner_systems(rays, directions, weights):
    """For each corner, the matrix M_j with l' M_j l its least misfit over X_j for lengths l."""
    steps = directions.shape[0]
    systems = []
    for j in range(rays.shape[1]):
        point_rows, length_rows = [], []
        for k in range(steps + 1):
            cross = skew(rays[k, j]) * weights[k, j]
            lengths = np.zeros((3, steps))
            lengths[:, :k] = -(cross @ directions[:k].T)
            point_rows.append(cross)
            length_rows.append(lengths)
        a, b = np.vstack(point_rows), np.vstack(length_rows)
        residual_maker = np.eye(len(a)) - a @ np.linalg.pinv(a)
        systems.append(b.T @ residual_maker @ b)
    return np.array(systems)


def solve_lengths(systems):
    _, vectors = np.linalg.eigh(systems.sum(axis=0))
    lengths = vectors[:, 0]
    return lengths * np.sign(lengths.sum())


def misfits(systems, lengths):
    unit = lengths / np.linalg.norm(lengths)
    return np.sqrt(np.maximum(np.einsum("i,jik,k->j", unit, systems, unit), 0.0))


def corner_distances(rays, directions, lengths):
    """Each corner's distance from each camera, triangulated with the given lengths."""
    centres = np.vstack([np.zeros(3), np.cumsum(lengths[:, None] * directions, axis=0)])
    distances = np.zeros(rays.shape[:2])
    for j in range(rays.shape[1]):
        a = np.vstack([skew(rays[k, j]) for k in range(len(centres))])
        b = np.concatenate([skew(rays[k, j]) @ centres[k] for k in range(len(centres))])
        point = np.linalg.lstsq(a, b, rcond=None)[0]
        distances[:, j] = np.linalg.norm(point - centres, axis=1)
    return distances


def image_lengths(rays, directions):
    """The step lengths (mean 1) the images give, the corners kept and their systems."""
    keep = np.ones(rays.shape[1], bool)
    weights = np.ones(rays.shape[:2])
    for _ in range(3):
        systems = corner_systems(rays[:, keep], directions, weights[:, keep])
        lengths = solve_lengths(systems)
        misfit = misfits(systems, lengths)
        outliers = np.where(keep)[0][misfit > 3 * np.median(misfit)]
        keep[outliers] = False
        scale = np.median(corner_distances(rays[:, keep], directions, lengths))
        weights[:, keep] = scale / np.maximum(
            corner_distances(rays[:, keep], directions, lengths), 0.1 * scale)
    systems = corner_systems(rays[:, keep], directions, weights[:, keep])
    lengths = solve_lengths(systems)
    return lengths / lengths.mean(), systems


def step_lengths(poses, first, steps):
    return np.linalg.norm(np.diff(poses[first:first + steps + 1, :, 3], axis=0), axis=1)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("frames", help="KITTI sequence folder (calib.txt, image_0/), or a folder "
                        "of images with --camera")
    parser.add_argument("out", help="the run's output folder (poses_kitti.txt; "
                        "gt_poses_kitti.txt when it had ground truth)")
    parser.add_argument("first", type=int, help="first pose of the stretch (0 = the run's first "
                        "frame, whatever its --frames)")
    parser.add_argument("steps", type=int, help="steps in the stretch (3 or more)")
    parser.add_argument("--camera", help="camera YAML (Camera: fx, cx, cy) of a folder of images")
    args = parser.parse_args()
    if args.steps < 3:
        fail("STEPS must be 3 or more")
    run = read_pose_array(os.path.join(args.out, "poses_kitti.txt"))
    truth_path = os.path.join(args.out, "gt_poses_kitti.txt")
    truth = read_pose_array(truth_path) if os.path.isfile(truth_path) else None
    # The run's pose k is image first_frame + k.
    paths = frame_paths(args.frames, args.camera)[first_frame_of_run(args.out):]
    last = args.first + args.steps
    if args.first < 0 or last >= min(len(run), len(paths)):
        fail(f"frames {args.first}..{last} are not all in the run ({len(run)} poses) and the "
             f"images ({len(paths)} from the run's first)")
    positions = track_corners(paths, args.first, args.steps)
    if positions.shape[1] < 20:
        fail(f"{positions.shape[1]} corners tracked through the stretch; 20 or more needed")
    rays, directions = rays_and_directions(positions, run, args.first,
                                           read_camera(args.frames, args.camera))
    images, systems = image_lengths(rays, directions)
    if np.any(images <= 0.0):
        fail(f"the images give a step of no or negative length in frames {args.first}-{last}: "
             "they do not determine this stretch (too few static corners, or motion the run's "
             "directions do not describe); try another FIRST")
    profiles = {"images": images}
    if truth is not None and last < len(truth):
        profiles["ground truth"] = step_lengths(truth, args.first, args.steps)
    profiles["run"] = step_lengths(run, args.first, args.steps)
    print(f"frames {args.first}-{last}, {len(systems)} corners")
    print("each step's share of the stretch (mean 1):")
    for name, lengths in profiles.items():
        print(f"  {name:13s}" + " ".join(f"{v / lengths.mean():.3f}" for v in lengths))
    profiles["constant"] = np.ones(args.steps)
    print("misfit to the images (root of the summed squares):")
    for name, lengths in profiles.items():
        print(f"  {name:13s}{np.sqrt(np.sum(misfits(systems, lengths) ** 2)):.4f}")


if __name__ == "__main__":
    main()
