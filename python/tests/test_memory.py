"""Memory stays flat over many runs: a run's records, summary and kept frames are freed
with the run object (resident set size from /proc/self/statm)."""

import gc
import json
import os

import oflab
import pytest

PAGE = os.sysconf("SC_PAGE_SIZE")
SMALL = {"frames": 1, "repeat_timing": 1, "warm_up": False}


def resident_bytes():
    with open("/proc/self/statm", encoding="ascii") as f:
        return int(f.read().split()[1]) * PAGE


def small_script(folder):
    """The shipped rotation script seen by an 80 x 60 camera (focal length scaled alike): a
    small run, whose engine allocates little, so a thousand of them are quick."""
    here = os.path.dirname(os.path.abspath(__file__))
    with open(os.path.join(here, "..", "..", "datasets", "scripts", "rotation.json"),
              encoding="utf-8") as f:
        script = json.load(f)
    script["camera"] = {"focal_px": script["camera"]["focal_px"] / 8, "image": [80, 60]}
    path = os.path.join(folder, "small-rotation.json")
    with open(path, "w", encoding="utf-8") as f:
        json.dump(script, f)
    return path


@pytest.mark.skipif(not os.path.exists("/proc/self/statm"), reason="needs /proc")
def test_a_thousand_small_runs_leave_memory_flat(tmp_path):
    script = small_script(str(tmp_path))
    for _ in range(50):  # allocator pools, caches
        oflab.run(script, "affine", keep_frames=True, **SMALL).summary
    gc.collect()
    before = resident_bytes()
    for k in range(1000):
        run = oflab.run(script, "affine", keep_frames=(k % 2 == 0), **SMALL)
        run.summary
        run.records
        if k % 2 == 0:
            run_frames_shape = run.frames.shape
            run.frames[0].sum()
    del run
    gc.collect()
    grown = resident_bytes() - before
    assert run_frames_shape == (1, 60, 80, 4)
    # Generous: a leak of a run's engine (its layer images, about 0.1 MB here) or of its
    # kept frames would be 100 MB over the thousand runs.
    assert grown < 16 * 1024 * 1024, f"{grown / 1e6:.1f} MB more after 1000 runs"


@pytest.mark.skipif(not os.path.exists("/proc/self/statm"), reason="needs /proc")
def test_runs_kept_alive_do_show_in_the_measure(tmp_path):
    """Negative control: the same measure sees runs that are not freed (their kept frames,
    two RGBA frames and two maps of 80 x 60 pixels each)."""
    script = small_script(str(tmp_path))
    kept_bytes = 80 * 60 * (4 + 4 + 1 + 1)
    gc.collect()
    before = resident_bytes()
    alive = [oflab.run(script, "affine", keep_frames=True, **SMALL) for _ in range(300)]
    grown = resident_bytes() - before
    assert len(alive) == 300
    assert grown > 0.9 * 300 * kept_bytes, f"{grown / 1e6:.1f} MB"
