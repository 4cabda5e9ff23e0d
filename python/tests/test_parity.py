"""Parity: oflab.run(...).summary and oflab.compare(...).summary equal oflab-cli animate
--json and compare --json, times left out (they differ from run to run), for the Experiment
1 scripts and the compound script under every policy of the registry.

Every source under every policy goes through compare (one CLI process per source, each
policy played as animate plays it); animate's own summary is compared under every policy
for a plane (rotation) and the scene (compound), and under perspective for every script:
each CLI process costs a third of a second of start-up, which 90 of them would spend."""

import oflab
import pytest

from conftest import COMPOUND, EXPERIMENT1_SCRIPTS, QUICK, cli_options, without_times

POLICIES = [p["name"] for p in oflab.policies()]
SOURCES = [{"source": s} for s in EXPERIMENT1_SCRIPTS] + [COMPOUND]


def source_options(source):
    args = ["--script", source["source"]]
    if "scene" in source:
        args += ["--scene", source["scene"]]
    return args


def source_call(source):
    settings = dict(QUICK)
    if "scene" in source:
        settings["scene"] = source["scene"]
    return source["source"], settings


def playable(source):
    """The policies the source's kind can play: a single plane has no BSP tree to group,
    so the node-image policy (hierarchical-cache) needs a scene, and so does frame
    generation along motion vectors (their refusal is tested in test_refusals.py)."""
    if "scene" in source:
        return POLICIES
    return [p["name"] for p in oflab.policies() if not p["scenes_only"]]


def check_animate_parity(cli_started, source, policies):
    name, settings = source_call(source)
    for policy in policies:
        expected = cli_started("animate", *source_options(source), "--mode", policy, "--json",
                               "--quiet", *cli_options(QUICK))
        summary = oflab.run(name, policy, **settings).summary
        assert without_times(summary) == without_times(expected()), policy
        assert summary["mode"] == policy


@pytest.mark.parametrize("source", [SOURCES[5], SOURCES[-1]], ids=lambda s: s["source"])
def test_run_summary_equals_animate_json_under_every_policy(cli_started, source):
    policies = playable(source)
    assert len(policies) >= 10
    check_animate_parity(cli_started, source, policies)


def test_run_summary_equals_animate_json_for_every_script(cli_started):
    for source in SOURCES:
        check_animate_parity(cli_started, source, ["perspective"])


@pytest.mark.parametrize("source", SOURCES, ids=lambda s: s["source"])
def test_compare_summary_equals_compare_json(cli_started, source):
    name, settings = source_call(source)
    del settings["warm_up"]  # compare always warms up
    timing = {"frames": QUICK["frames"], "repeat_timing": QUICK["repeat_timing"]}
    policies = playable(source)
    expected = cli_started("compare", *source_options(source), "--policies", ",".join(policies),
                           "--json", "--quiet", *cli_options(timing))
    comparison = oflab.compare(name, policies, **settings)
    assert without_times(comparison.summary) == without_times(expected())
    assert comparison.policies == policies


def test_records_are_the_cli_csv_columns(cli, tmp_path):
    out = tmp_path / "run"
    cli("animate", "--script", "rotation", "--mode", "affine", "--out", str(out), "--quiet",
        *cli_options(QUICK))
    lines = (out / "frames.csv").read_text().splitlines()
    header = lines[0].split(",")
    records = oflab.run("rotation", "affine", **QUICK).records
    assert list(records) == header
    rows = [line.split(",") for line in lines[1:]]
    for k, name in enumerate(header):
        if "time" in name or "_ms" in name or name == "note":
            continue
        for row, value in zip(rows, records[name]):
            if name == "level":
                assert row[k] == value
            else:
                # the CLI prints six significant digits, the records keep every digit
                assert float(row[k]) == pytest.approx(float(value), rel=1e-5, abs=1e-9), name
