"""Experiment 1 (section 6.4.8) in ten lines: per script the published level mix and time
saved beside oflab's, counted as the dissertation counts (frames after the first)."""
import sys
import numpy as np
import oflab

quick = dict(frames=40, repeat_timing=1) if "--quick" in sys.argv else {}
levels = ["none", "translate", "affine", "perspective", "rerender"]
print(f"{'':28}" + "".join(f"{level:>12}" for level in levels) + f"{'time saved':>12}")
for row in oflab.published_experiment1():
    run = oflab.run(row["script"], "perspective", **quick)
    ours = [100 * np.mean(run.records["level"][1:] == level) for level in levels]
    print(f"{row['title'] + ', published':28}" + "".join(f"{p:12.1f}" for p in row["levels"].values())
          + f"{row['time_saved_percent']:11.0f}%")
    print(f"{row['script'] + ', oflab':28}" + "".join(f"{p:12.1f}" for p in ours)
          + f"{100 * run.summary['time_saved']:11.0f}%")
