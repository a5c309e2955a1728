# SPDX-License-Identifier: BSL-1.0
"""Many bodies moved step by step (the library's world): each body a polygon
at its own pose, and after each step every pair of bodies in contact. Ids
and poses go in as numpy arrays, pairs come out as (k, 2) arrays."""

import numpy as np

from . import _core
from ._core import InvalidInput
from .polygon import as_polygon, as_polygons
from .poses import as_poses

__all__ = ["World"]

_KINDS = np.array(["vertex", "edge", "interior"])


def _ids(values, name):
    """``values`` (an id or a sequence of ids) as a 1-D int64 C-contiguous
    array; refused with InvalidInput unless every value is an integer."""
    try:
        a = np.asarray(values)
    except (TypeError, ValueError) as e:
        raise InvalidInput(f"{name}: not an array of ids ({e})") from None
    if a.ndim == 0:
        a = a.reshape(1)
    if a.ndim != 1:
        raise InvalidInput(f"{name}: expected a 1-D array of ids, got shape {a.shape}")
    if a.size == 0:
        return np.zeros(0, dtype=np.int64)
    if a.dtype.kind not in "iu":
        raise InvalidInput(f"{name}: expected integer ids, got dtype {a.dtype}")
    if a.dtype.kind == "u" and a.max() > np.iinfo(np.int64).max:
        raise InvalidInput(f"{name}: id {a.max()} is beyond int64")
    return np.ascontiguousarray(a, dtype=np.int64)


class World:
    """Bodies in the plane, each a polygon (non-convex, holes, several parts)
    at its own pose (tx, ty, theta: turned by theta about its own origin,
    then moved by (tx, ty)); after each :meth:`step`, every pair of bodies
    whose closed regions meet (touching counts), or with ``within`` > 0 that
    come within that distance. Bodies of one shape share its preparation;
    ``fixed`` bodies are never tested against each other. Between steps a
    pair in contact keeps what showed it (coherence: ``coherence=False``
    tests every pair with a moved body afresh, with the same answers).

    ``number_type``: "certified" (the default: the exact answers at about
    double's cost), "exact" (CGAL's rationals) or "double" (rounded).
    ``threads`` shares each step's pair tests among threads (0: every core;
    the answers are the serial run's). ``witness=True`` keeps the features
    that show each contact (:meth:`witnesses`).

    Every call that adds, moves or removes bodies checks its whole input
    first: a refused call (InvalidInput) leaves the world as it was.

    >>> import numpy as np
    >>> w = World()
    >>> square = w.add_shape("POLYGON ((0 0, 1 0, 1 1, 0 1, 0 0))")
    >>> w.add_bodies([square] * 3, [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [3.0, 0.0, 0.0]])
    array([0, 1, 2])
    >>> w.step()  # bodies 0 and 1 touch along an edge
    array([[0, 1]])
    >>> w.move([2], [[1.5, 0.5, 0.0]])
    >>> w.step()
    array([[0, 1],
           [1, 2]])
    >>> w.events()  # what began (True) or ended at the last step
    (array([[1, 2]]), array([ True]))
    """

    def __init__(self, number_type="certified", within=0.0, witness=False, coherence=True, threads=1):
        try:
            within = float(within)
        except (TypeError, ValueError):
            raise InvalidInput(f"within: expected a number, got {within!r}") from None
        if not isinstance(threads, (int, np.integer)) or isinstance(threads, bool):
            raise InvalidInput(f"threads: expected an integer, got {threads!r}")
        self._w = _core.World(number_type, within, bool(witness), bool(coherence), int(threads))
        self._number_type = number_type

    @property
    def number_type(self):
        """The number type the world answers in."""
        return self._number_type

    def add_shape(self, shape):
        """Adds a shape (a Polygon, shapely geometry, WKT or WKB) that bodies
        may take; returns its id (0, 1, ... in order)."""
        return int(self._w.add_shapes([as_polygon(shape, "shape")._p]))

    def add_shapes(self, shapes):
        """Adds the shapes of a sequence (or GeoSeries) in order; returns
        their ids as an int64 array.

        >>> World().add_shapes(["POLYGON ((0 0, 1 0, 0 1, 0 0))", "POLYGON ((0 0, 2 0, 0 2, 0 0))"])
        array([0, 1])
        """
        polygons = [p._p for p in as_polygons(shapes, "shapes")]
        first = self._w.add_shapes(polygons)
        return np.arange(first, first + len(polygons), dtype=np.int64)

    def add_bodies(self, shapes, poses, fixed=False):
        """Adds a body for each shape id of ``shapes`` at the pose of the same
        row of ``poses`` ((n, 3): tx, ty, theta), fixed where ``fixed`` (one
        flag for all, or an (n,) bool array); returns their ids as an int64
        array (0, 1, ... in order of addition, never reused). The bodies take
        part from the next step."""
        shapes = _ids(shapes, "shapes")
        poses = as_poses(poses)
        if isinstance(fixed, (bool, np.bool_)):
            flags = np.full(shapes.shape[0], bool(fixed))
        else:
            flags = np.asarray(fixed)
            if flags.dtype != np.bool_:
                raise InvalidInput(f"fixed: expected a bool or an array of bools, got dtype {flags.dtype}")
            flags = np.ascontiguousarray(flags)
        first = self._w.add_bodies(shapes, poses, flags)
        return np.arange(first, first + shapes.shape[0], dtype=np.int64)

    def add_body(self, shape, pose, fixed=False):
        """Adds one body of shape id ``shape`` at ``pose`` (tx, ty, theta);
        returns its id."""
        return int(self.add_bodies([shape], as_poses(pose, "pose"), fixed)[0])

    def move(self, bodies, poses):
        """Moves each body of ``bodies`` (ids, each listed once) to the pose
        of the same row of ``poses``; bodies not listed stay where they are.
        The world answers for the new poses at the next step."""
        self._w.move(_ids(bodies, "bodies"), as_poses(poses))

    def remove(self, bodies):
        """Removes the bodies listed (ids, each listed once): their contacts
        end at the next step; their ids are not reused."""
        self._w.remove(_ids(bodies, "bodies"))

    def step(self):
        """Brings the world to its bodies' present poses (the GIL released);
        returns the pairs in contact, an (k, 2) int64 array of ids, each row
        i < j, rows sorted."""
        return self._w.step()

    @property
    def contacts(self):
        """The pairs in contact after the last step (as :meth:`step` returned)."""
        return self._w.contacts()

    def events(self):
        """The contacts that began or ended at the last step: their pairs, an
        (e, 2) int64 array sorted, and an (e,) bool array, True where the
        contact began."""
        return self._w.events()

    def witnesses(self):
        """What shows each contact of the last step (a world made with
        ``witness=True``), one row per row of :attr:`contacts`: a dict of
        ``first_kind`` and ``second_kind`` ("vertex", "edge" or "interior",
        of the bodies of the smaller and the larger id) and ``first_index``
        and ``second_index`` (input numbering: edge k runs from vertex k of
        its ring order, as in :meth:`Detector.witness`; -1 for the
        interior). Two edges that meet; or a vertex of one body in the
        other's region (the other's kind "interior").

        >>> w = World(witness=True)
        >>> s = w.add_shape("POLYGON ((0 0, 1 0, 1 1, 0 1, 0 0))")
        >>> w.add_bodies([s, s], [[0.0, 0.0, 0.0], [1.0, 0.5, 0.0]])
        array([0, 1])
        >>> w.step()
        array([[0, 1]])
        >>> wit = w.witnesses()
        >>> str(wit["first_kind"][0]), str(wit["second_kind"][0])
        ('edge', 'edge')
        """
        first_kind, first_index, second_kind, second_index = self._w.witnesses()
        return {"first_kind": _KINDS[first_kind], "first_index": first_index,
                "second_kind": _KINDS[second_kind], "second_index": second_index}

    @property
    def statistics(self):
        """The world's work so far, a dict of counters: steps, bodies moved,
        boxes escaped, tree rebuilds, candidate pairs, pairs carried
        untested, witness hits, pairs kept apart by their separating edge
        (separated) or by one sought before the pair test (found_apart),
        pairs answered by edges next to the last step's (nearby_edges), and
        contacts reported."""
        return self._w.statistics()

    @property
    def alive(self):
        """Whether each body id is alive (not removed), an (n,) bool array."""
        return self._w.alive()

    @property
    def shape_count(self):
        """The number of shapes added."""
        return self._w.shape_count

    def __len__(self):
        """The number of bodies added (removed ones included)."""
        return self._w.body_count

    def __repr__(self):
        return (f"World(number_type={self._number_type!r}, bodies={len(self)}, shapes={self.shape_count}, "
                f"contacts={len(self.contacts)})")
