# SPDX-License-Identifier: BSL-1.0
"""Many bodies moved step by step (the library's world): each body a polygon
at its own pose, and after each step every pair of bodies in contact. Ids
and poses go in as numpy arrays, pairs come out as (k, 2) arrays."""

import numpy as np

from . import _core, _options
from ._core import InvalidInput
from .polygon import _core_polygons, as_polygon
from .poses import as_poses

__all__ = ["World", "world_contacts"]

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
        self._w = _core.World(_options.name(number_type, "number_type"), _options.number(within, "within"),
                              _options.flag(witness, "witness"), _options.flag(coherence, "coherence"),
                              _options.integer(threads, "threads"))
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
        polygons = _core_polygons(shapes, "shapes")
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
        if np.ndim(fixed) == 0:
            flags = np.full(shapes.shape[0], _options.flag(fixed, "fixed"))
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
        pairs answered by edges next to the last step's (nearby_edges),
        pairs answered again in exact rationals because double could not
        settle a sign (exact_pairs; "certified" only), and contacts
        reported."""
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


# --- A scene from a table of steps --------------------------------------------

#: The columns of a table of steps (the tool's STEPS.csv), ``fixed`` optional.
STEP_COLUMNS = ("step", "body", "shape", "tx", "ty", "theta")


class _Plan:
    """A table of steps: its columns as arrays, each body's internal id (in
    order of first appearance), the row where each row's body first
    appears, whether each row adds its body, and where each step's rows
    begin."""

    def __init__(self, step, body, shape, poses, fixed):
        self.step, self.body, self.shape, self.poses, self.fixed = step, body, shape, poses, fixed
        users, first, inverse = np.unique(body, return_index=True, return_inverse=True)
        order = np.argsort(first, kind="stable")
        rank = np.empty(len(users), dtype=np.int64)
        rank[order] = np.arange(len(users))
        self.internal = rank[inverse]
        self.user_of = users[order]
        self.first_row = first[inverse]
        self.adds = self.first_row == np.arange(len(body))
        self.starts = np.concatenate(([0], np.flatnonzero(np.diff(step)) + 1)).astype(np.int64)[:len(step)]
        self.ends = np.concatenate((self.starts[1:], [len(step)])).astype(np.int64)[:len(self.starts)]


def _integers(frame, column, least=0):
    """The table's column as int64, refused unless of an integer dtype with
    every value from ``least`` to 2^63 - 1."""
    values = frame[column].to_numpy()
    if values.dtype.kind not in "iu":
        raise InvalidInput(f"steps, column {column}: expected integers, got dtype {values.dtype}")
    bad = np.flatnonzero(values < least) if values.dtype.kind == "i" else np.flatnonzero(values > np.iinfo(np.int64).max)
    if len(bad):
        raise InvalidInput(f"steps, row {bad[0]}, column {column}: {values[bad[0]]} is not an integer from {least} "
                           "to 2^63 - 1")
    return values.astype(np.int64)


def _plan_of(steps, shape_count):
    """The table ``steps`` (a pandas DataFrame, or anything pandas makes one
    of, with the columns of STEP_COLUMNS and optionally ``fixed``) checked
    as the tool checks STEPS.csv: integer steps, bodies and shape ids, a
    shape id below ``shape_count``, finite poses, steps never going back
    (the rows of a step consecutive), a body listed once per step and
    keeping its shape and fixedness; each refusal names the row (its
    position) and column."""
    import pandas as pd
    if not isinstance(steps, pd.DataFrame):
        try:
            steps = pd.DataFrame(steps)
        except (TypeError, ValueError) as e:
            raise InvalidInput(f"steps: not a table ({e})") from None
    missing = [c for c in STEP_COLUMNS if c not in steps.columns]
    if missing:
        raise InvalidInput(f"steps: no column {missing[0]!r} (expected the columns "
                           f"{', '.join(STEP_COLUMNS)} and optionally fixed)")
    step, body, shape = (_integers(steps, c) for c in ("step", "body", "shape"))
    poses = np.empty((len(steps), 3))
    for c, name in enumerate(("tx", "ty", "theta")):
        values = steps[name].to_numpy()
        if values.dtype.kind not in "iuf":
            raise InvalidInput(f"steps, column {name}: expected numbers, got dtype {values.dtype}")
        poses[:, c] = values
        bad = np.flatnonzero(~np.isfinite(poses[:, c]))
        if len(bad):
            raise InvalidInput(f"steps, row {bad[0]}, column {name}: {poses[bad[0], c]} is not a finite number")
    if "fixed" in steps.columns:
        fixed = steps["fixed"].to_numpy()
        if fixed.dtype.kind in "iu":
            bad = np.flatnonzero((fixed != 0) & (fixed != 1))
            if len(bad):
                raise InvalidInput(f"steps, row {bad[0]}, column fixed: {fixed[bad[0]]} is not 0 or 1")
        elif fixed.dtype.kind != "b":
            raise InvalidInput(f"steps, column fixed: expected bools or 0 and 1, got dtype {fixed.dtype}")
        fixed = fixed.astype(bool)
    else:
        fixed = np.zeros(len(steps), dtype=bool)
    bad = np.flatnonzero(shape >= shape_count)
    if len(bad):
        raise InvalidInput(f"steps, row {bad[0]}, column shape: no shape {shape[bad[0]]} (there are {shape_count})")
    bad = np.flatnonzero(np.diff(step) < 0)
    if len(bad):
        k = bad[0] + 1
        raise InvalidInput(f"steps, row {k}: step {step[k]} after step {step[k - 1]}: steps must not go back (the "
                           "rows of a step are consecutive)")
    order = np.lexsort((np.arange(len(step)), body, step))
    twice = np.flatnonzero((np.diff(step[order]) == 0) & (np.diff(body[order]) == 0))
    if len(twice):
        k, was = order[twice[0] + 1], order[twice[0]]
        raise InvalidInput(f"steps, row {k}: body {body[k]} is listed twice in step {step[k]} (also row {was})")
    plan = _Plan(step, body, shape, np.ascontiguousarray(poses), fixed)
    for name, values, what in (("shape", shape, "keeps its shape"), ("fixed", fixed, "stays fixed or free")):
        bad = np.flatnonzero(values != values[plan.first_row])
        if len(bad):
            k, was = bad[0], plan.first_row[bad[0]]
            raise InvalidInput(f"steps, row {k}, column {name}: body {body[k]} has {name} {values[was]} since row "
                               f"{was}, not {values[k]}: a body {what}")
    return plan


def _play(polygons, plan, number_type, within, events, threads, skip_first=False):
    """The contacts (or events) after each step of ``plan``, in a world of
    ``polygons`` (the _core objects): arrays step, a, b (the bodies' ids
    in the table, a < b) and, for events, begins; sorted by step, a, b. The
    first step's rows are left out with ``skip_first`` (it only sets the
    bodies where an earlier part of the table left them)."""
    w = _core.World(number_type, within, False, True, threads)
    w.add_shapes(polygons)
    out_step, out_pairs, out_begins = [], [], []
    for k, (s, e) in enumerate(zip(plan.starts, plan.ends)):
        adds = plan.adds[s:e]
        if adds.any():
            rows = np.arange(s, e)[adds]
            w.add_bodies(plan.shape[rows], plan.poses[rows], plan.fixed[rows])
        if not adds.all():
            rows = np.arange(s, e)[~adds]
            w.move(plan.internal[rows], plan.poses[rows])
        contacts = w.step()
        if skip_first and k == 0:
            continue
        if events:
            pairs, begins = w.events()
        else:
            pairs, begins = contacts, np.ones(len(contacts), dtype=bool)
        users = plan.user_of[pairs].reshape(-1, 2)
        a, b = users.min(axis=1), users.max(axis=1)
        order = np.lexsort((b, a))
        out_step.append(np.full(len(order), plan.step[s], dtype=np.int64))
        out_pairs.append(np.column_stack((a[order], b[order])))
        out_begins.append(begins[order])
    if not out_step:
        return np.zeros(0, np.int64), np.zeros((0, 2), np.int64), np.zeros(0, bool)
    return np.concatenate(out_step), np.concatenate(out_pairs), np.concatenate(out_begins)


def _frame(step, pairs, begins, events):
    """The contacts (or events) as the tool's CONTACTS.csv: a DataFrame of
    step, a, b (and event, "begin" or "end")."""
    import pandas as pd
    frame = pd.DataFrame({"step": step, "a": pairs[:, 0], "b": pairs[:, 1]})
    if events:
        frame["event"] = np.where(begins, "begin", "end")
    return frame


def world_contacts(shapes, steps, number_type="certified", within=0.0, events=False, threads=1):
    """The ``influence2d world`` command on a table: bodies of ``shapes`` (a
    sequence of polygons; shape k the k-th) placed and moved as ``steps``
    says (a pandas DataFrame, or a dict of columns, with the columns
    ``step, body, shape, tx, ty, theta`` and optionally ``fixed``: a body
    appears at its first row and keeps its last pose until a later row
    moves it; steps never go back). Returns a DataFrame ``step, a, b``: one
    row per pair of bodies a < b (the table's ids) in contact after each
    step, sorted by step, a, b; with ``events=True`` the contacts that began
    or ended, with a column ``event`` ("begin" or "end"). Bad input raises
    InvalidInput naming the row and column.

    >>> import pandas as pd
    >>> steps = pd.DataFrame({"step": [0, 0, 0, 1], "body": [10, 20, 30, 30], "shape": [0, 0, 0, 0],
    ...                       "tx": [0.0, 1.0, 3.0, 2.0], "ty": [0.0] * 4, "theta": [0.0] * 4})
    >>> world_contacts(["POLYGON ((0 0, 1 0, 1 1, 0 1, 0 0))"], steps)
       step   a   b
    0     0  10  20
    1     1  10  20
    2     1  20  30
    >>> world_contacts(["POLYGON ((0 0, 1 0, 1 1, 0 1, 0 0))"], steps, events=True)
       step   a   b  event
    0     0  10  20  begin
    1     1  20  30  begin
    """
    number_type, within = _options.name(number_type, "number_type"), _options.number(within, "within")
    events, threads = _options.flag(events, "events"), _options.integer(threads, "threads")
    polygons = _core_polygons(shapes, "shapes")
    plan = _plan_of(steps, len(polygons))
    return _frame(*_play(polygons, plan, number_type, within, events, threads), events)

