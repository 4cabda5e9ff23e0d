"""Bad input raises ValueError or TypeError naming the setting and its allowed range, with
the project's own refusal (the CLI's message, its options written as settings); a long run
stops on Ctrl-C with KeyboardInterrupt."""

import _thread
import threading

import oflab
import pytest

from conftest import QUICK


@pytest.mark.parametrize("settings, error, words", [
    ({"threshold": 1e6}, ValueError, ["threshold:", "0..100"]),
    ({"thresholds": [1, 2, 3]}, ValueError, ["thresholds"]),
    ({"frames": 0}, ValueError, ["frames:"]),
    ({"quality": 1000}, ValueError, ["quality:"]),
    ({"sampling": "cubic"}, ValueError, ["sampling:", "nearest"]),
    ({"threshold": "x"}, ValueError, ["threshold:", "not a finite number"]),
    ({"threshold": True}, TypeError, ["threshold:"]),
    ({"threshold": [1.0]}, TypeError, ["threshold:"]),
    ({"warm_up": 1}, TypeError, ["warm_up:", "True or False"]),
    ({"no_such_setting": 1}, TypeError, ["no_such_setting", "accepted:", "threshold"]),
    ({"out": "/tmp/x"}, TypeError, ["out"]),
    ({"near": 0.5}, ValueError, ["near:", "scene"]),
])
def test_bad_settings_name_the_setting(settings, error, words):
    with pytest.raises(error) as caught:
        oflab.run("rotation", "affine", **{**QUICK, **settings})
    for word in words:
        assert word in str(caught.value)
    assert "--" not in str(caught.value)


def test_an_unknown_policy_names_the_policy_and_the_known_ones():
    with pytest.raises(ValueError, match="policy:.*perspective"):
        oflab.run("rotation", "fastest", **QUICK)


def test_a_policy_that_needs_a_scene_says_so():
    with pytest.raises(ValueError, match="scene"):
        oflab.run("rotation", "hierarchical-cache", **QUICK)


def test_an_unknown_source_names_the_source(tmp_path):
    with pytest.raises(ValueError, match="source"):
        oflab.run("no-such-script", "affine", **QUICK)
    broken = tmp_path / "broken.json"
    broken.write_text("{\"format\": ")
    with pytest.raises(ValueError, match="broken.json"):
        oflab.run(broken, "affine", **QUICK)
    with pytest.raises(TypeError, match="source"):
        oflab.run(42, "affine")


def test_compare_refuses_bad_policy_lists():
    with pytest.raises(ValueError, match="policies:"):
        oflab.compare("rotation", ["affine", "affine"], frames=4, repeat_timing=1)
    with pytest.raises(TypeError, match="policies"):
        oflab.compare("rotation", 3)


def test_flow_and_explain_name_their_fields():
    good = dict(focal=500, image=[640, 480], plane_point=[0, 0, 10], plane_normal=[0, 0, -1],
                velocity=[0.1, 0, 0], omega=[0, 0.1, 0])
    with pytest.raises(ValueError, match="focal:"):
        oflab.flow(**{**good, "focal": -1})
    with pytest.raises(ValueError, match="plane_normal"):
        oflab.flow(**{**good, "plane_normal": [0, 0, 0]})
    with pytest.raises(ValueError, match="plane_point:"):
        oflab.flow(**{**good, "plane_point": [0, 0]})
    with pytest.raises(ValueError, match="grid_step:"):
        oflab.flow(**good, grid_step=0)
    with pytest.raises(ValueError, match="coefficients: needs 8"):
        oflab.explain([1, 2, 3], focal=500)
    with pytest.raises(TypeError, match="focal"):
        oflab.explain([0] * 8)
    with pytest.raises(ValueError, match="name:"):
        oflab.lesson("no-such-lesson")


def test_ctrl_c_stops_a_long_run_with_keyboard_interrupt():
    """The timer's thread runs Python while the run plays (the run released the GIL) and
    interrupts the main thread, whose run sees the signal between two frames."""
    timer = threading.Timer(0.3, _thread.interrupt_main)
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            # 15 timed passes of 150 frames: far longer than the timer.
            oflab.run("rotation", "perspective", repeat_timing=15, repeat=20)
    finally:
        timer.cancel()
