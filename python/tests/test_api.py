"""flow, explain, policies and lessons against independent computations and the CLI."""

import json
import os
import re

import numpy as np
import oflab
import pytest

# A tilted plane ten units ahead, moving and turning (centred pixels, Y down, Z forward).
SCENE = dict(focal=500.0, image=[640, 480], plane_point=[0.5, -0.2, 10.0],
             plane_normal=[0.2, 0.1, -1.0], velocity=[0.3, -0.1, 0.5], omega=[0.02, -0.03, 0.05])


def exact_flow(x, y):
    """The image velocity at centred pixel (x, y), from the 3D velocity V + Omega x R of the
    plane point R seen there (an independent computation of the planar flow)."""
    f = SCENE["focal"]
    p0, n = np.array(SCENE["plane_point"]), np.array(SCENE["plane_normal"])
    ray = np.array([x / f, y / f, 1.0])
    r = ray * (n @ p0) / (n @ ray)
    dr = np.array(SCENE["velocity"]) + np.cross(SCENE["omega"], r)
    return f * (dr[0] * r[2] - r[0] * dr[2]) / r[2] ** 2, f * (dr[1] * r[2] - r[1] * dr[2]) / r[2] ** 2


def test_flow_field_is_the_exact_flow_on_the_grid():
    result = oflab.flow(**SCENE, grid_step=40)
    field, xs, ys = result["field"], result["grid_x"], result["grid_y"]
    assert field.shape == (len(ys), len(xs), 2)
    assert xs[0] >= -320 and xs[-1] <= 320 and 0.0 in xs
    for j in range(0, len(ys), 3):
        for i in range(0, len(xs), 4):
            u, v = exact_flow(xs[i], ys[j])
            assert field[j, i] == pytest.approx([u, v], rel=1e-9, abs=1e-9)


def test_coefficients_are_named_in_every_basis():
    result = oflab.flow(**SCENE)
    c = result["coefficients"]
    assert list(c) == ["j11", "j12", "j21", "j22", "px", "py", "tx", "ty"] or set(c) == {
        "tx", "ty", "j11", "j12", "j21", "j22", "px", "py"}
    u, v = exact_flow(0.0, 0.0)
    assert (c["tx"], c["ty"]) == pytest.approx((u, v))
    assert set(result["bases"]) == {"taylor", "waxman-ullman", "planar"}
    assert all(len(terms) == 12 for terms in result["bases"].values())
    assert result["bases"]["planar"]["scale"] == pytest.approx(result["basis"]["scale"])
    # The planar basis' rotation is the curl's half: (dv/dx - du/dy) / 2.
    assert result["basis"]["rotation"] == pytest.approx((c["j21"] - c["j12"]) / 2)


def test_exact_homography_moves_points_by_the_flow_over_a_short_step():
    dt = 1e-4
    result = oflab.flow(**SCENE, dt=dt)
    for key in ("homography_taylor", "homography_exact"):
        assert result[key].shape == (3, 3)
    for x, y in [(0.0, 0.0), (100.0, -50.0), (-200.0, 120.0)]:
        q = result["homography_exact"] @ [x, y, 1.0]
        moved = (q[:2] / q[2] - [x, y]) / dt
        assert moved == pytest.approx(exact_flow(x, y), rel=1e-3, abs=1e-3)


def test_flow_equals_oflab_cli_flow(cli):
    args = ["flow", "--json", "--dt", "0.5", "--explain"]
    for name, value in SCENE.items():
        args += ["--" + name.replace("_", "-")] + [str(v) for v in np.atleast_1d(value)]
    expected = cli(*args)
    result = oflab.flow(**SCENE, dt=0.5, explain=True)
    for key in ("coefficients", "basis", "explain", "units", "motion", "dt"):
        assert result[key] == expected[key]
    assert result["homography_exact"].tolist() == expected["homography_exact"]


def test_explain_finds_the_given_plane_among_its_two_solutions():
    result = oflab.flow(**SCENE)
    solutions = oflab.explain(result)["solutions"]
    assert len(solutions) == 2
    n = np.array(SCENE["plane_normal"]) / np.linalg.norm(SCENE["plane_normal"])
    n = n if n @ SCENE["plane_point"] > 0 else -n
    assert any(np.allclose(s["normal"], n, atol=1e-6) for s in solutions)
    again = oflab.explain([result["coefficients"][k] for k in
                           ("tx", "ty", "j11", "j12", "j21", "j22", "px", "py")], focal=500.0)
    assert again == oflab.explain(result)


def test_policies_are_the_registry_of_oflab_cli_policies(cli):
    assert oflab.policies() == cli("policies", "--json")["policies"]


def test_lessons_are_the_shipped_files():
    here = os.path.dirname(os.path.abspath(__file__))
    folder = os.path.join(here, "..", "..", "datasets", "lessons")
    names = sorted(f[:-5] for f in os.listdir(folder) if f.endswith(".json"))
    assert sorted(lesson["name"] for lesson in oflab.lessons()) == names
    with open(os.path.join(folder, "flow-of-a-plane.json"), encoding="utf-8") as f:
        data = json.load(f)
    lesson = oflab.lesson("flow-of-a-plane")
    assert lesson.title == data["title"] and len(lesson.info()["steps"]) == len(data["steps"])


def test_a_lesson_check_equals_oflab_cli_lesson_check(cli):
    checks = oflab.lesson("flow-of-a-plane").check()
    printed = cli("lesson", "check", "flow-of-a-plane").stdout.splitlines()
    assert [c["text"] for c in checks] == printed[:-1]
    assert checks and all(c["holds"] for c in checks)
    assert re.search(r"%d engine claims" % len(checks), printed[-1])


def test_a_script_given_as_a_dict_plays_as_its_file(tmp_path):
    here = os.path.dirname(os.path.abspath(__file__))
    with open(os.path.join(here, "..", "..", "datasets", "scripts", "zoom.json"),
              encoding="utf-8") as f:
        script = json.load(f)
    script["name"] = "my-zoom"
    from_dict = oflab.run(script, "affine", frames=10, repeat_timing=1, warm_up=False).summary
    from_name = oflab.run("zoom", "affine", frames=10, repeat_timing=1, warm_up=False).summary
    assert from_dict["script"] == "my-zoom"
    assert from_dict["levels"] == from_name["levels"]
    assert from_dict["max_measured_error_px"] == from_name["max_measured_error_px"]
    script["camera"]["focal_px"] = -5
    with pytest.raises(ValueError, match="focal"):
        oflab.run(script, "affine", frames=2)
