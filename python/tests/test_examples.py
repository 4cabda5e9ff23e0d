"""The examples of python/examples run and print what they promise."""

import os
import subprocess
import sys

import pytest

EXAMPLES = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "examples")


def run_example(name, *args):
    done = subprocess.run([sys.executable, os.path.join(EXAMPLES, name), *args],
                          capture_output=True, text=True, env=os.environ.copy(), check=False,
                          timeout=120)
    assert done.returncode == 0, done.stderr
    return done.stdout


# What each example's output must hold.
PROMISES = {
    "experiment1_table.py": ["stationary, oflab", "translation-1, oflab", "translation-2, oflab",
                             "zoom, oflab", "zoom-rotation, oflab", "rotation, oflab",
                             "loop, oflab", "published"],
    "compare_policies.py": ["perspective", "talisman", "timewarp", "work saved"],
    "flow_and_explain.py": ["coefficients:", "flow field (", "solution 1:", "solution 2:"],
    "frames_and_holes.py": ["hole pixels", "not a copy: True", "difference.png"],
    "lesson_claims.py": ["flow-of-a-plane:", "engine claims hold"],
}


def test_every_example_is_checked():
    assert sorted(f for f in os.listdir(EXAMPLES) if f.endswith(".py")) == sorted(PROMISES)


@pytest.mark.parametrize("name", sorted(PROMISES))
def test_every_example_runs_and_prints_what_it_promises(name):
    out = run_example(name, "--quick")
    for words in PROMISES[name]:
        assert words in out, words
