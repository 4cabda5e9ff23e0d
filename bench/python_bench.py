#!/usr/bin/env python3
"""The Python module's speed (manual/python.md, "Speed"): the time to hand a kept 1920 x 1080
frame to numpy (a view of the run's memory, so microseconds whatever the size; a copy of the
same frame for contrast), and a run's overhead through the module against oflab-cli's.

    PYTHONPATH=build/python python3 bench/python_bench.py [--cli build/analysis/oflab-cli]

Not a test: it prints what it measured (medians over repetitions) and checks nothing."""

import argparse
import json
import os
import statistics
import subprocess
import tempfile
import time

import numpy as np
import oflab


def median_seconds(action, repetitions):
    times = []
    for _ in range(repetitions):
        start = time.perf_counter()
        action()
        times.append(time.perf_counter() - start)
    return statistics.median(times)


def full_hd_script(folder):
    """The shipped rotation script seen by a 1920 x 1080 camera (focal length scaled alike)."""
    with open(os.path.join(os.path.dirname(oflab.__file__), "..", "..", "..", "datasets",
                           "scripts", "rotation.json"), encoding="utf-8") as f:
        script = json.load(f)
    script["name"] = "rotation-1080p"
    script["camera"] = {"focal_px": script["camera"]["focal_px"] * 3, "image": [1920, 1080]}
    path = os.path.join(folder, "rotation-1080p.json")
    with open(path, "w", encoding="utf-8") as f:
        json.dump(script, f)
    return path


def frame_handover(script):
    run = oflab.run(script, "perspective", keep_frames=True, frames=3, repeat_timing=1,
                    warm_up=False)
    assert run.frames.shape[1:] == (1080, 1920, 4)
    assert np.shares_memory(run.frames[1], run.frames[1])
    view = median_seconds(lambda: run.frames[1], 2000)
    copy = median_seconds(lambda: np.array(run.frames[1]), 50)
    print(f"1920x1080 frame to numpy: view {view * 1e6:.1f} us, copy {copy * 1e6:.0f} us "
          f"({run.frames[1].nbytes / 1e6:.1f} MB)")


def run_overhead(cli):
    settings = {"repeat_timing": 1, "warm_up": False}
    module = median_seconds(lambda: oflab.run("rotation", "perspective", **settings), 15)
    summary = oflab.run("rotation", "perspective", **settings).summary
    inside = (summary["time_ms"] + summary["baseline_time_ms"]) / 1e3
    line = (f"rotation, perspective, 150 frames, one pass: module {module * 1e3:.1f} ms, "
            f"of which engine and re-render {inside * 1e3:.1f} ms")
    if cli:
        args = [cli, "animate", "--script", "rotation", "--mode", "perspective", "--json",
                "--quiet", "--repeat-timing", "1", "--no-warm-up"]
        whole = median_seconds(lambda: subprocess.run(args, capture_output=True, check=True), 15)
        start_up = median_seconds(lambda: subprocess.run([cli, "policies", "--json"],
                                                         capture_output=True, check=True), 15)
        line += (f"; oflab-cli {whole * 1e3:.1f} ms, of which {start_up * 1e3:.1f} ms start-up "
                 f"(oflab-cli policies): the run itself {(whole - start_up) * 1e3:.1f} ms")
    print(line)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cli", help="oflab-cli, for the run's overhead against it")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as folder:
        frame_handover(full_hd_script(folder))
    run_overhead(args.cli)


if __name__ == "__main__":
    main()
