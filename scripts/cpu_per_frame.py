#!/usr/bin/env python3
"""CPU per frame of `roadscale run`, by stage, against a reference measured in the same sitting.

Runs the default (the network on keyframes), the default without segmentation, and the
reference: the paper's frame-to-frame host without segmentation (`Mapping.mode:
frame_to_frame`), on the same frames, one after the other, `--repeat` times each in
alternation. Prints per run the stages' CPU per frame (the run's own frames.csv columns), the
process CPU per frame (user + system of the child process), the share of keyframes, the wall
frames/s, and the process CPU as a multiple of the reference's from the same round: a ratio that
another machine can check, where absolute milliseconds differ by 2-3x between 2-core machines.

  python3 scripts/cpu_per_frame.py ../shared/kitti/sequences/00 0:200 OUT [--repeat 2]
"""
import argparse
import csv
import os
import resource
import statistics
import subprocess
import sys
import time

RUNS = [
    ("default", [], None),
    ("no segmentation", ["--no-segmentation"], None),
    ("reference: frame-to-frame, no segmentation", ["--no-segmentation"],
     "Mapping:\n  mode: frame_to_frame\n"),
]


def cpu_model():
    try:
        for line in subprocess.run(["lscpu"], capture_output=True, text=True).stdout.splitlines():
            if line.startswith("Model name:"):
                return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return "unknown CPU (lscpu not found)"


def run_once(roadscale, sequence, frames, out, extra, config):
    args = [roadscale, "run", "--kitti", sequence, "--frames", frames, "--out", out] + extra
    if config is not None:
        path = out + ".yaml"
        with open(path, "w") as f:
            f.write(config)
        args += ["--config", path]
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.monotonic()
    with open(out + ".log", "w") as log:
        status = subprocess.run(args, stdout=log, stderr=subprocess.STDOUT).returncode
    wall = time.monotonic() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if status != 0:
        sys.exit(f"cpu_per_frame: {' '.join(args)} failed (exit {status}), see {out}.log")
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    with open(os.path.join(out, "frames.csv")) as f:
        rows = list(csv.DictReader(f))
    if not rows:
        sys.exit(f"cpu_per_frame: {out}/frames.csv has no frames")

    def mean(column):
        values = [float(r[column]) for r in rows if r.get(column) not in (None, "")]
        return statistics.fmean(values) if values else 0.0

    keyframes = sum(1 for r in rows if r.get("keyframe") == "1")
    return {
        "frames": len(rows),
        "segmentation": mean("segmentation_cpu_ms"),
        "frontend": mean("frontend_cpu_ms"),
        "scale and pose": mean("scale_cpu_ms"),
        "process": 1000.0 * cpu / len(rows),
        "keyframes": keyframes / len(rows),
        "fps": len(rows) / wall,
    }


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("sequence", help="KITTI sequence folder (.../sequences/NN)")
    parser.add_argument("frames", help="frame range as run's --frames, e.g. 0:200")
    parser.add_argument("out", help="folder for the runs' outputs")
    parser.add_argument("--repeat", type=int, default=1, help="rounds of the three runs")
    parser.add_argument("--roadscale", default=os.environ.get("ROADSCALE", "build/roadscale"))
    options = parser.parse_args()
    if options.repeat < 1:
        sys.exit("cpu_per_frame: --repeat must be >= 1")
    if not os.path.isfile(os.path.join(options.sequence, "times.txt")):
        sys.exit(f"cpu_per_frame: {options.sequence}: no times.txt, not a KITTI sequence folder")
    os.makedirs(options.out, exist_ok=True)

    print(f"CPU: {cpu_model()}, {os.cpu_count()} logical cores; {options.sequence} "
          f"frames {options.frames}")
    header = (f"{'round':>5}  {'run':<44} {'segm.':>7} {'frontend':>8} {'scale+pose':>10} "
              f"{'process':>8} {'x ref':>6} {'keyfr.':>6} {'fps':>6}")
    print("CPU ms per frame (stages: the run's frames.csv; process: user + system)")
    print(header)
    for round_index in range(1, options.repeat + 1):
        results = []
        for index, (name, extra, config) in enumerate(RUNS):
            out = os.path.join(options.out, f"round{round_index}_run{index}")
            results.append((name, run_once(options.roadscale, options.sequence, options.frames,
                                           out, extra, config)))
        reference = results[-1][1]["process"]
        for name, r in results:
            print(f"{round_index:>5}  {name:<44} {r['segmentation']:7.1f} {r['frontend']:8.1f} "
                  f"{r['scale and pose']:10.1f} {r['process']:8.1f} "
                  f"{r['process'] / reference:6.2f} {100 * r['keyframes']:5.0f}% {r['fps']:6.1f}")


if __name__ == "__main__":
    main()
