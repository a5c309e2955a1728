# SPDX-License-Identifier: BSL-1.0
"""The vectorised queries on one pair of polygons: whether B posed meets A,
their separation, the first contact of a motion. Each takes an array of
poses, releases the GIL and uses every core (``threads=0``) or the number
given; the answers do not depend on the threads.

Number types: ``"certified"`` (the default: exact answers at about double's
cost, a pose in doubt answered again in exact rationals), ``"exact"`` (CGAL's
exact rationals throughout, slower) and ``"double"`` (rounded: may differ at
near contact).
"""

import numpy as np

from . import _core, _options
from .polygon import as_polygon
from .poses import as_poses

__all__ = ["intersects", "separation", "first_contact"]

_KINDS = np.array(["vertex", "edge", "interior"])


def intersects(a, b, poses, number_type="certified", threads=0):
    """Whether A and B posed by each row of ``poses`` (tx, ty, theta) meet:
    their closed regions share a point (touching counts; B inside a hole of A
    does not meet A). Returns an (n,) bool array.

    >>> import numpy as np
    >>> a = "POLYGON ((0 0, 2 0, 2 2, 0 2, 0 0))"
    >>> b = "POLYGON ((0 0, 1 0, 1 1, 0 1, 0 0))"
    >>> intersects(a, b, np.array([[2.0, 0.0, 0.0], [2.5, 0.0, 0.0], [0.5, 0.5, 0.8]]))
    array([ True, False,  True])
    """
    return _core.intersects(as_polygon(a, "a")._p, as_polygon(b, "b")._p, as_poses(poses),
                            _options.name(number_type, "number_type"), _options.integer(threads, "threads"))


def separation(a, b, poses, number_type="certified", threads=0, features=False):
    """The distance between the closed regions of A and of B posed by each
    row of ``poses``: an (n,) float64 array, 0 where they meet (certified:
    within one unit in the last place of the exact distance).

    With ``features=True``, a dict of arrays: ``distance``; the closest
    features ``static_kind`` and ``moving_kind`` ("vertex", "edge" or
    "interior") with their input numbers ``static_index`` and
    ``moving_index`` (-1 for the interior; edge k runs from vertex k, rings
    numbered one after another); and the closest points ``static_point`` and
    ``moving_point`` ((n, 2), in A's frame).

    >>> import numpy as np
    >>> a = "POLYGON ((0 0, 2 0, 2 2, 0 2, 0 0))"
    >>> b = "POLYGON ((0 0, 1 0, 1 1, 0 1, 0 0))"
    >>> separation(a, b, np.array([[3.0, 0.0, 0.0], [1.0, 1.0, 0.0]]))
    array([1., 0.])
    >>> f = separation(a, b, np.array([[3.0, 0.5, 0.0]]), features=True)
    >>> f["static_kind"][0], int(f["static_index"][0]), f["moving_kind"][0], int(f["moving_index"][0])
    ('edge', 1, 'vertex', 0)
    """
    features = _options.flag(features, "features")
    (distance, static_kind, static_index, moving_kind, moving_index, static_point,
     moving_point) = _core.separation(as_polygon(a, "a")._p, as_polygon(b, "b")._p, as_poses(poses),
                                      _options.name(number_type, "number_type"), _options.integer(threads, "threads"))
    if not features:
        return distance
    return {
        "distance": distance,
        "static_kind": _KINDS[static_kind],
        "static_index": static_index,
        "moving_kind": _KINDS[moving_kind],
        "moving_index": moving_index,
        "static_point": static_point,
        "moving_point": moving_point,
    }


def first_contact(a, b, start_poses, end_poses, number_type="certified", threads=0, motion="angle-linear",
                  max_steps=100000, undecided=False):
    """The first contact of B moving from each start pose to its end pose
    with A: a bool array (whether they meet at some time in [0, 1]) and a
    float64 array (the earliest such time, rounded to the nearest double;
    NaN where they never meet).

    The translation is linear in time. A motion whose angles differ turns
    as ``motion`` says:

    - ``"angle-linear"``: the angle linear in time; contact reported within
      the library's tolerance of 1e-9 (never after the true first contact),
      by conservative advancement of at most ``max_steps`` steps (0: no
      limit). A motion that grazes A for long may reach the limit: it is
      then reported without contact, and with ``undecided=True`` a third
      bool array marks it (its time is then where the advancement stopped:
      no contact before it, none decided after);
    - ``"rational"``: the tangent of half the turn since the start linear in
      time, in pieces of at most a quarter turn (the README's definition);
      exact in the ``"certified"`` and ``"exact"`` types.

    >>> import numpy as np
    >>> a = "POLYGON ((0 0, 2 0, 2 2, 0 2, 0 0))"
    >>> b = "POLYGON ((0 0, 1 0, 1 1, 0 1, 0 0))"
    >>> first_contact(a, b, np.array([[4.0, 0.0, 0.0], [4.0, 5.0, 0.0]]), np.array([[0.0, 0.0, 0.0], [0.0, 5.0, 0.0]]))
    (array([ True, False]), array([0.5, nan]))
    >>> start, end = np.array([[2.5, 0.5, 0.0]]), np.array([[2.5, 0.5, np.pi]])
    >>> first_contact(a, b, start, end)  # touches after a sixth of the half turn
    (array([ True]), array([0.16666667]))
    >>> first_contact(a, b, start, end, motion="rational")  # t = tan(pi / 12) / tan(pi / 4) / 2
    (array([ True]), array([0.1339746]))
    >>> first_contact(a, b, start, end, max_steps=2, undecided=True)  # two steps do not reach it
    (array([False]), array([0.12464294]), array([ True]))
    """
    undecided = _options.flag(undecided, "undecided")
    contact, time, limited = _core.first_contact(as_polygon(a, "a")._p, as_polygon(b, "b")._p,
                                                 as_poses(start_poses, "start_poses"), as_poses(end_poses, "end_poses"),
                                                 _options.name(number_type, "number_type"),
                                                 _options.name(motion, "motion"), _options.integer(threads, "threads"),
                                                 _options.integer(max_steps, "max_steps"))
    if undecided:
        return contact, time, limited
    return contact, np.where(limited, np.nan, time)
