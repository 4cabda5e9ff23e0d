#!/usr/bin/env python3
"""Turns the JSON written by oflab-bench into the tables of manual/warping.md.

Usage (the pixman and OpenCV columns stay "-" when oflab-bench was built without them):
    for i in 1 2 3; do
      build/bench/oflab-bench --benchmark_out=warp-bench-$i.json --benchmark_out_format=json
    done
    python3 bench/summarise_bench.py warp-bench-*.json

Each case's time is the median over its repetitions, in milliseconds of CPU time (the
benchmark is single-threaded, so on an idle machine CPU and wall time agree). Given
several runs, the tables show the median of the runs' medians, and the last section the
spread (lowest and highest median) of every case. Ratios are taken between medians of
the same geometry (size and matrix).
"""
import json
import sys


def load_medians(path):
    with open(path) as f:
        data = json.load(f)
    medians = {}

    for b in data["benchmarks"]:
        if b.get("aggregate_name") != "median":
            continue
        name = b["run_name"].split("/repeats")[0]
        scale = {"ms": 1.0, "us": 1e-3, "ns": 1e-6, "s": 1e3}[b["time_unit"]]
        medians[name] = {
            "cpu": b["cpu_time"] * scale,
            "real": b["real_time"] * scale,
            "mpx": b.get("Mpx/s"),
            "agree": b.get("agree"),
            "frame_ms": b.get("frame_ms"),
            "kernel_ms": b.get("kernel_ms"),
        }
    return data.get("context", {}), medians


def combine(runs):
    """Median over runs of each case's median; keeps the spread of the CPU times."""
    combined = {}
    for name in runs[0]:
        values = [r[name] for r in runs if name in r]
        cpus = sorted(v["cpu"] for v in values)
        middle = sorted(values, key=lambda v: v["cpu"])[len(values) // 2]
        combined[name] = dict(middle, low=cpus[0], high=cpus[-1], runs=len(values))
    return combined


def fmt(value, digits=3):
    return "-" if value is None else f"{value:.{digits}f}"


def ratio(a, b):
    return None if a is None or b is None else a / b


def cpu(medians, name):
    entry = medians.get(name)
    return None if entry is None else entry["cpu"]


def main():
    loaded = [load_medians(path) for path in sys.argv[1:]]
    context = loaded[0][0]
    m = combine([medians for _, medians in loaded])
    print(f"{len(loaded)} run(s); host: {context.get('host_name', '?')}, {context.get('num_cpus', '?')} cpus at "
          f"{context.get('mhz_per_cpu', '?')} MHz, {context.get('date', '?')}\n")

    print("Appendix A.2 cases, nearest, median CPU ms\n")
    print("| image | matrix | affine | perspective | persp/affine | OpenCV affine "
          "| OpenCV persp | OpenCV/oflab | pixman | pixman/oflab | copy |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for size in ("243x198", "121x99"):
        for matrix in ("identity", "rot45", "M-affine", "M"):
            affine = cpu(m, f"warp/affine/nearest/{size}/{matrix}")
            persp = cpu(m, f"warp/perspective/nearest/{size}/{matrix}")
            cv_affine = cpu(m, f"opencv/affine/nearest/{size}/{matrix}")
            cv_persp = cpu(m, f"opencv/perspective/nearest/{size}/{matrix}")
            # oflab's own kernel for the matrix against OpenCV's matching function.
            own = affine if affine is not None else persp
            peer = cv_affine if cv_affine is not None else cv_persp
            pixman = cpu(m, f"pixman/nearest/{size}/{matrix}")
            print(f"| {size} | {matrix} | {fmt(affine)} | {fmt(persp)} | "
                  f"{fmt(ratio(persp, affine), 2)} | {fmt(cv_affine)} | {fmt(cv_persp)} | "
                  f"{fmt(ratio(peer, own), 1)} | {fmt(pixman)} | {fmt(ratio(pixman, own), 1)} | "
                  f"{fmt(cpu(m, f'copy/{size}/{matrix}'))} |")

    print("\nFrames, median CPU ms (Mpx/s over the polygon's pixels)\n")
    print("| case | kernel | nearest | bilinear | bilinear/nearest | OpenCV nearest "
          "| OpenCV bilinear | OpenCV/oflab nearest | pixman nearest | pixman bilinear "
          "| pixman/oflab nearest | warp/copy nearest |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    for size in ("1024x768", "1920x1080"):
        for matrix in ("rotation", "tilt"):
            copy = cpu(m, f"copy/{size}/{matrix}")
            for kernel in ("affine", "perspective"):
                near = m.get(f"warp/{kernel}/nearest/{size}/{matrix}")
                bil = m.get(f"warp/{kernel}/bilinear/{size}/{matrix}")
                if near is None:
                    continue
                cv_near = cpu(m, f"opencv/{kernel}/nearest/{size}/{matrix}")
                cv_bil = cpu(m, f"opencv/{kernel}/bilinear/{size}/{matrix}")
                px_near = cpu(m, f"pixman/nearest/{size}/{matrix}")
                px_bil = cpu(m, f"pixman/bilinear/{size}/{matrix}")
                near_cpu = near["cpu"]
                bil_cpu = None if bil is None else bil["cpu"]
                print(f"| {size} {matrix} | {kernel} | {fmt(near_cpu)} ({near['mpx']:.0f}) | "
                      f"{fmt(bil_cpu)} | {fmt(ratio(bil_cpu, near_cpu), 2)} | {fmt(cv_near)} | "
                      f"{fmt(cv_bil)} | {fmt(ratio(cv_near, near_cpu), 1)} | {fmt(px_near)} | "
                      f"{fmt(px_bil)} | {fmt(ratio(px_near, near_cpu), 1)} | "
                      f"{fmt(ratio(near_cpu, copy), 1)} |")

    print("\nPerspective kernel / affine kernel on the same (affine) matrix\n")
    print("| case | nearest | bilinear |")
    print("|---|---|---|")
    for size, matrix in (("243x198", "identity"), ("243x198", "rot45"), ("243x198", "M-affine"),
                         ("121x99", "identity"), ("121x99", "rot45"), ("121x99", "M-affine"),
                         ("1024x768", "rotation"), ("1920x1080", "rotation")):
        cells = []
        for sampling in ("nearest", "bilinear"):
            cells.append(fmt(ratio(cpu(m, f"warp/perspective/{sampling}/{size}/{matrix}"),
                                   cpu(m, f"warp/affine/{sampling}/{size}/{matrix}")), 2))
        print(f"| {size} {matrix} | {cells[0]} | {cells[1]} |")

    engines = [(n, e) for n, e in m.items() if n.startswith("engine/")]
    if engines:
        print("\nEngine cases: median frame (engine's timed part) and the bare kernel drawing "
              "the exact warp of the same poses, ms\n")
        print("| script | mode | engine frame | kernel frame | engine/kernel |")
        print("|---|---|---|---|---|")
        for name, e in engines:
            _, script, mode = name.split("/")
            print(f"| {script} | {mode} | {fmt(e['frame_ms'], 4)} | {fmt(e['kernel_ms'], 4)} | "
                  f"{fmt(ratio(e['frame_ms'], e['kernel_ms']), 2)} |")

    print("\nSpread over the runs (lowest - highest median CPU ms)\n")
    for name, e in m.items():
        print(f"- {name}: {e['low']:.3f} - {e['high']:.3f} ({e['runs']} runs)")

    agree = [(n, e["agree"]) for n, e in m.items()
             if n.startswith(("opencv/", "pixman/")) and e["agree"] is not None]
    if agree:
        print("\nPeer pixels agreeing with oflab's (fraction of the polygon's pixels)\n")
        for name, value in agree:
            print(f"- {name}: {value:.4f}")


if __name__ == "__main__":
    main()
