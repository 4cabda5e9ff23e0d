"""Frames as numpy views: depth reprojection on the four cubes, its holes and where the
shown frame differs most from the exact one, saved as PNG files."""
import os
import sys
import tempfile
import numpy as np
import oflab

frames = 8 if "--quick" in sys.argv else 60
run = oflab.run("compound", "depth-reprojection", scene="four-cubes", keep_frames=True,
                frames=frames, repeat_timing=1)
worst = int(np.argmax(run.differences.reshape(frames, -1).max(axis=1)))
print(f"{run.holes.sum()} hole pixels over {frames} frames; largest difference at frame {worst}")
print("the frames are a view of the run, not a copy:", np.shares_memory(run.frames, run.frames[worst]))
out = tempfile.mkdtemp(prefix="oflab-")
for name, picture in [("shown", run.frames[worst]), ("exact", run.exact_frames[worst]),
                      ("difference", run.differences[worst]), ("holes", run.holes[worst] * 255)]:
    with open(os.path.join(out, f"{name}.png"), "wb") as f:
        f.write(picture._repr_png_())
print("wrote", ", ".join(sorted(os.listdir(out))), "in", out)
