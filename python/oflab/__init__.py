"""oflab: optic flow of moving planes, image reuse policies and lessons, from Python.

The module binds oflab's own layers (core, analysis, session): run() and compare() play
a source as ``oflab-cli animate`` and ``oflab-cli compare`` do and return their JSON
summaries as dicts, with the per-frame records and, on request, the frames as numpy
arrays; flow() and explain() are ``oflab-cli flow`` and ``oflab-cli explain``;
lessons() and lesson(name).check() check the lessons' engine claims headlessly.
See manual/python.md.
"""

import contextlib as _contextlib
import json as _json
import os as _os
import tempfile as _tempfile

import numpy as _np

from . import _oflab
from ._oflab import (Comparison, Lesson, Run, _png, explain, flow, lesson, lessons, policies,
                     published_experiment1)


@_contextlib.contextmanager
def _source_file(source, kind):
    """A motion or viewer script given as a dict (a script file's JSON object), written to a
    temporary file named after its "name" for the project's reader; any other source as is."""
    if not isinstance(source, dict):
        yield source
        return
    with _tempfile.TemporaryDirectory(prefix="oflab-") as folder:
        path = _os.path.join(folder, str(source.get("name", kind)) + ".json")
        with open(path, "w", encoding="utf-8") as f:
            _json.dump(source, f)
        yield path


def run(source, policy="perspective", **settings):
    """Plays a source under a reuse policy as ``oflab-cli animate`` does; see _oflab.run.

    source: a shipped script's name, a file path or a script's JSON object (a dict);
    with scene=NAME|FILE a viewer script played through a scene."""
    with _source_file(source, "script") as path:
        return _oflab.run(path, policy, **settings)


def compare(source, policies, **settings):  # pylint: disable=redefined-outer-name
    """Plays a source under several policies as ``oflab-cli compare`` does; see _oflab.compare."""
    with _source_file(source, "script") as path:
        return _oflab.compare(path, policies, **settings)


run.__doc__ += "\n\n" + _oflab.run.__doc__
compare.__doc__ += "\n\n" + _oflab.compare.__doc__


class Picture(_np.ndarray):
    """A frame (H x W x 4, premultiplied RGBA, uint8) or a map (H x W, uint8) of a run.

    A read-only view of the run's memory (no copy): it stays valid while any view of it
    lives. In a notebook a single frame or map shows itself as a PNG (``_repr_png_``).
    """

    def _repr_png_(self):
        if self.ndim == 2 or (self.ndim == 3 and self.shape[2] == 4):
            return _png(_np.asarray(self))
        return None


__all__ = ["Comparison", "Lesson", "Picture", "Run", "compare", "explain", "flow",
           "lesson", "lessons", "policies", "published_experiment1", "run"]
