"""The kept frames are numpy views of the run's memory (no copy), and the maps agree with
an independent computation from the frames."""

import struct
import zlib

import numpy as np
import oflab
import pytest

from conftest import QUICK


@pytest.fixture(scope="module")
def plane_run():
    return oflab.run("rotation", "affine", keep_frames=True, **QUICK)


def test_frames_are_views_of_the_runs_memory(plane_run):
    frames = plane_run.frames
    assert frames.shape[0] == QUICK["frames"] and frames.shape[3] == 4
    assert frames.dtype == np.uint8
    # Two accesses are two arrays over the same memory, which belongs to the run object.
    assert np.shares_memory(plane_run.frames[3], plane_run.frames[3])
    assert np.shares_memory(frames, plane_run.frames)
    base = frames
    while isinstance(base, np.ndarray) and base.base is not None:
        base = base.base
    assert base is plane_run
    assert not frames.flags.writeable
    # A copy is not a view: the negative control of shares_memory.
    assert not np.shares_memory(np.array(plane_run.frames[3]), plane_run.frames[3])


def test_views_outlive_the_name_of_the_run():
    frame = oflab.run("zoom", "perspective", keep_frames=True, **QUICK).frames[5]
    again = np.array(frame)  # the run lives on as the view's base
    assert frame.sum() == again.sum() and frame.sum() > 0


def test_differences_are_the_largest_channel_difference(plane_run):
    shown = plane_run.frames.astype(np.int16)
    exact = plane_run.exact_frames.astype(np.int16)
    expected = np.abs(shown - exact).max(axis=3)
    assert np.array_equal(plane_run.differences, expected)
    assert plane_run.differences.max() > 0  # the affine view is not exact


def test_a_plane_has_no_holes(plane_run):
    assert plane_run.holes.shape == plane_run.differences.shape
    assert plane_run.holes.max() == 0


def test_depth_reprojection_holes_are_pixels_the_exact_frame_covers():
    run = oflab.run("compound", "depth-reprojection", scene="four-cubes", keep_frames=True,
                    frames=8, repeat_timing=1, warm_up=False)
    holes = run.holes.astype(bool)
    assert holes.any()
    assert not (holes & (run.exact_frames[..., 3] == 0)).any()
    assert holes.sum() == run.summary["hole_pixels"]


def test_a_run_without_kept_frames_says_how_to_keep_them():
    run = oflab.run("rotation", "affine", **QUICK)
    with pytest.raises(ValueError, match="keep_frames=True"):
        run.frames  # noqa: B018


def png_size(data):
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    length, kind = struct.unpack(">I4s", data[8:16])
    assert kind == b"IHDR"
    width, height = struct.unpack(">II", data[16:24])
    assert zlib.crc32(data[12:16 + length]) == struct.unpack(">I", data[16 + length:20 + length])[0]
    return width, height


def test_frames_and_maps_show_as_png(plane_run):
    h, w = plane_run.frames.shape[1:3]
    assert png_size(plane_run.frames[0]._repr_png_()) == (w, h)
    assert png_size(plane_run.differences[2]._repr_png_()) == (w, h)
    assert plane_run.frames._repr_png_() is None  # a stack of frames is no picture


def test_a_run_shows_as_html_with_its_level_strip(plane_run):
    html = plane_run._repr_html_()
    assert html.count("flex:1;background") == QUICK["frames"]
    assert "max_measured_error_px" in html
