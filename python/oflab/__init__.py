"""oflab: optic flow of moving planes, image reuse policies and lessons, from Python.

The module binds oflab's own layers (core, analysis, session): run() and compare() play
a source as ``oflab-cli animate`` and ``oflab-cli compare`` do and return their JSON
summaries as dicts, with the per-frame records and, on request, the frames as numpy
arrays; flow() and explain() are ``oflab-cli flow`` and ``oflab-cli explain``;
lessons() and lesson(name).check() check the lessons' engine claims headlessly.
See manual/python.md.
"""

import numpy as _np

from ._oflab import (Comparison, Lesson, Run, _png, compare, explain, flow, lesson,
                     lessons, policies, published_experiment1, run)


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
