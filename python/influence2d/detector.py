# SPDX-License-Identifier: BSL-1.0
"""A frame detector kept across calls: the frames of a trajectory, one call
or many, answered in order so that consecutive poses reuse the last frame's
candidate edges (its coherence)."""

import numpy as np

from . import _core, _options
from .polygon import as_polygon
from .poses import as_poses

__all__ = ["Detector"]


class Detector:
    """The detector of A (static) and B (moving) in ``number_type``
    ("double", the default, rounded; "certified" or "exact", exact answers).
    A frame collides when the closed regions are within ``within`` (0: they
    meet, touching counts). ``witness=True`` makes every frame gather its
    witnesses (``witness`` builds a second detector for them otherwise).

    >>> import numpy as np
    >>> d = Detector("POLYGON ((0 0, 2 0, 2 2, 0 2, 0 0))", "POLYGON ((0 0, 1 0, 1 1, 0 1, 0 0))")
    >>> d.collide(np.array([[1.5, 0.0, 0.0], [2.0, 0.0, 0.0], [2.5, 0.0, 0.0]]))
    array([ True,  True, False])
    """

    def __init__(self, a, b, number_type="double", witness=False, within=0.0):
        self._d = _core.Detector(as_polygon(a, "a")._p, as_polygon(b, "b")._p,
                                 _options.name(number_type, "number_type"), _options.flag(witness, "witness"),
                                 _options.number(within, "within"))

    def collide(self, poses):
        """Whether each pose's frame collides, answered in order (the GIL
        released): an (n,) bool array.

        >>> d = Detector("POLYGON ((0 0, 2 0, 2 2, 0 2, 0 0))", "POLYGON ((0 0, 1 0, 1 1, 0 1, 0 0))",
        ...              number_type="certified", within=0.5)
        >>> d.collide([[2.5, 0.0, 0.0], [2.6, 0.0, 0.0]])
        array([ True, False])
        """
        return self._d.collide(as_poses(poses))

    def witness(self, pose):
        """The edge pairs (static edge, moving edge) within ``within`` of
        each other at one pose (tx, ty, theta), as a sorted list; empty when
        the frame does not collide or collides by containment alone. Edges
        are numbered in input order (edge k runs from vertex k).

        >>> d = Detector("POLYGON ((0 0, 2 0, 2 2, 0 2, 0 0))", "POLYGON ((0 0, 1 0, 1 1, 0 1, 0 0))")
        >>> d.witness((2.0, 0.5, 0.0))
        [(1, 0), (1, 2), (1, 3)]
        """
        try:
            p = np.asarray(pose, dtype=np.float64)
        except (TypeError, ValueError) as e:
            raise _core.InvalidInput(f"pose: not numbers ({e})") from None
        if p.size != 3:
            raise _core.InvalidInput(f"pose: expected one pose (tx, ty, theta), got shape {p.shape}")
        p = np.ascontiguousarray(p.reshape(1, 3))
        return self._d.witness(float(p[0, 0]), float(p[0, 1]), float(p[0, 2]))[1]

    def witnesses(self, poses):
        """Each pose's frame in order, from the detector that witnesses (as
        :meth:`witness`): ``(collides, pairs)``, ``collides`` an (n,) bool
        array and ``pairs`` an (k, 3) int64 array of rows (row of the pose,
        static edge, moving edge), one per edge pair within ``within``,
        sorted by pose and then as :meth:`witness` lists them. A frame that
        collides by containment alone has no row.

        >>> d = Detector("POLYGON ((0 0, 2 0, 2 2, 0 2, 0 0))", "POLYGON ((0 0, 1 0, 1 1, 0 1, 0 0))")
        >>> collides, pairs = d.witnesses([[2.0, 0.5, 0.0], [0.5, 0.5, 0.0], [3.0, 0.0, 0.0]])
        >>> collides
        array([ True,  True, False])
        >>> pairs.tolist()
        [[0, 1, 0], [0, 1, 2], [0, 1, 3]]
        """
        return self._d.witnesses(as_poses(poses))

    @property
    def exact_frames(self):
        """Frames answered again in exact rationals so far (certified; 0 for
        the other types).

        >>> Detector("POLYGON ((0 0, 2 0, 2 2, 0 2, 0 0))", "POLYGON ((0 0, 1 0, 1 1, 0 1, 0 0))").exact_frames
        0
        """
        return self._d.exact_frames
