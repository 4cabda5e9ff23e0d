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


@pytest.mark.parametrize("name", sorted(f for f in os.listdir(EXAMPLES) if f.endswith(".py")))
def test_every_example_runs(name):
    assert run_example(name, "--quick").strip()


def test_the_experiment_1_table_lists_every_script_beside_the_published_row():
    out = run_example("experiment1_table.py", "--quick")
    for script in ("stationary", "translation-1", "translation-2", "zoom", "zoom-rotation",
                   "rotation", "loop"):
        assert script in out
    assert "published" in out
