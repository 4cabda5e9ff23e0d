"""Memory stays flat over many runs: a run's records, summary and kept frames are freed
with the run object (resident set size from /proc/self/statm)."""

import gc
import os

import oflab
import pytest

PAGE = os.sysconf("SC_PAGE_SIZE")
SMALL = {"frames": 1, "repeat_timing": 1, "warm_up": False}


def resident_bytes():
    with open("/proc/self/statm", encoding="ascii") as f:
        return int(f.read().split()[1]) * PAGE


@pytest.mark.skipif(not os.path.exists("/proc/self/statm"), reason="needs /proc")
def test_a_thousand_small_runs_leave_memory_flat():
    for _ in range(50):  # allocator pools, caches, the shipped script read once
        oflab.run("rotation", "affine", keep_frames=True, **SMALL).summary
    gc.collect()
    before = resident_bytes()
    for k in range(1000):
        run = oflab.run("rotation", "affine", keep_frames=(k % 2 == 0), **SMALL)
        run.summary
        run.records
        if k % 2 == 0:
            run.frames[0].sum()
    del run
    gc.collect()
    grown = resident_bytes() - before
    # Generous: one kept frame pair of the run is ~2 MB; a leak of it per run would be ~1 GB.
    assert grown < 32 * 1024 * 1024, f"{grown / 1e6:.1f} MB more after 1000 runs"
