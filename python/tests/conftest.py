"""Shared fixtures of the oflab module's tests (ctest label "python", python/CMakeLists.txt).

The tests import the package from the build tree (PYTHONPATH=build/python) and run the
real oflab-cli (OFLAB_CLI) for the parity tests.
"""

import json
import os
import subprocess

import pytest

# The Experiment 1 scripts in the dissertation's order (experiment1_scripts() in
# analysis/experiments/experiments_single_plane.cpp) and the compound viewer script through
# the four cubes, which Experiment 2 and the policies experiment play.
EXPERIMENT1_SCRIPTS = ["stationary", "translation-1", "translation-2", "zoom",
                       "zoom-rotation", "rotation", "loop"]
COMPOUND = {"source": "compound", "scene": "four-cubes"}

# Short, single-pass runs: parity holds for any length, and the suite stays fast.
QUICK = {"frames": 12, "repeat_timing": 1, "warm_up": False}


def is_time_name(name):
    """A key or column that holds a time (the golden tests' rule,
    tests/analysis/runs/golden_outputs_test.cpp): it differs from run to run."""
    return "time" in name or "_ms" in name or "fps" in name


def without_times(value):
    if isinstance(value, dict):
        return {k: without_times(v) for k, v in value.items() if not is_time_name(k)}
    if isinstance(value, list):
        return [without_times(v) for v in value]
    return value


def cli_options(settings):
    """The settings of a module call as oflab-cli's options."""
    args = []
    for name, value in settings.items():
        option = "--" + name.replace("_", "-")
        if value is False:
            args.append("--no-" + option[2:])
        elif value is True:
            args.append(option)
        elif isinstance(value, (list, tuple)):
            args += [option] + [str(v) for v in value]
        else:
            args += [option, str(value)]
    return args


@pytest.fixture(scope="session")
def cli():
    path = os.environ.get("OFLAB_CLI")
    if not path:
        pytest.skip("OFLAB_CLI names no oflab-cli")

    def run_cli(*args, expect=0):
        return started_cli(path, args, expect)()
    return run_cli


@pytest.fixture(scope="session")
def cli_started():
    """oflab-cli started now, its result (as the cli fixture's) when the returned function is
    called: the module's side of a parity test plays while the CLI runs."""
    path = os.environ.get("OFLAB_CLI")
    if not path:
        pytest.skip("OFLAB_CLI names no oflab-cli")
    return lambda *args, expect=0: started_cli(path, args, expect)


def started_cli(path, args, expect):
    process = subprocess.Popen([path, *args], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                               text=True)

    def result():
        out, err = process.communicate()
        assert process.returncode == expect, err
        if expect == 0 and "--json" in args:
            return json.loads(out)
        return subprocess.CompletedProcess(process.args, process.returncode, out, err)
    return result
