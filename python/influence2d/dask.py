# SPDX-License-Identifier: BSL-1.0
"""The work that outgrows one machine, on Dask's distributed scheduler: the
audit of a layer in chunks, the layer join partitioned by boxes, the
precision study split by scenes, a world's steps split into runs; each on a
``distributed.Client`` (a LocalCluster, or a real cluster by its scheduler
address, ``Client("tcp://scheduler:8786")``), each with the same result as
the single-process call of the package.

The workers import ``influence2d`` themselves: it must be installed (or on
their PYTHONPATH) where they run. Polygons pickle, so the partitions are
scattered to the workers once and the tasks name them; a layer given as a
dask collection is read and packed on the workers and stays there.
"""

import pickle

import numpy as np

from . import _core, _options
from .audit import _item, audit_layer
from .pairs import pairs as _local_pairs
from .polygon import Polygon, _core_polygons, as_polygons
from .study import _frames, study_names
from .world import _frame as _world_frame
from .world import _Plan as _WorldPlan
from .world import _plan_of as _world_plan_of
from .world import _play as _world_play

__all__ = ["audit", "pairs", "study", "world_contacts"]

#: Disagreements the study keeps as examples per number type and decision
#: (or query): the command's and the package's fixed count.
STUDY_EXAMPLES_KEPT = 3

#: The audit's columns of text, a few values each.
_AUDIT_TEXTS = ("kind", "what", "effect")


# --- Checks -----------------------------------------------------------------

def _client(client):
    """The client, checked: a ``distributed.Client`` (not its address: a
    connection is the caller's to open and close)."""
    from distributed import Client
    if not isinstance(client, Client):
        raise _core.InvalidInput(f"client: expected a distributed.Client, got {type(client).__name__}")
    return client


def _sequence(values, name):
    """The items of a layer (a sequence, a pandas Series or a GeoSeries) as a
    list, positions as indices; one geometry or a string refused."""
    if isinstance(values, (str, bytes, Polygon)) or hasattr(values, "geom_type") and not hasattr(values, "to_numpy"):
        raise _core.InvalidInput(f"{name}: expected a sequence of polygons, got one {type(values).__name__}")
    if hasattr(values, "to_numpy"):  # a pandas Series or a GeoSeries: positions, not labels
        values = values.to_numpy()
    try:
        return list(values)
    except TypeError:
        raise _core.InvalidInput(f"{name}: expected a sequence of polygons, got {type(values).__name__}") from None


# --- audit ------------------------------------------------------------------

def _audit_chunk(items, start, max_per_kind, threads, columns):
    """The findings of one chunk (items as the audit reads them), each row
    with its polygon's position in the whole layer: a frame whose columns
    pandas types from the chunk's rows as the single-process audit types
    them from the layer's (numbers travel as arrays, not one object each),
    its texts as categories (each text sent once)."""
    import pandas as pd
    reports = _core.audit(items, "geoms", max_per_kind, threads)
    rows = [dict(polygon=start + k, **f) for k, r in enumerate(reports) for f in r["findings"]]
    frame = pd.DataFrame(rows, columns=columns)
    return frame.astype({c: "category" for c in _AUDIT_TEXTS})


def _audit_packed(packed, start, max_per_kind, threads, columns):
    """_audit_chunk of a chunk sent pickled whole (one bytes object: Dask
    sends a list of many items one by one, 20 times slower)."""
    return _audit_chunk(pickle.loads(packed), start, max_per_kind, threads, columns)


def _audit_partition(items, name, max_per_kind, threads, columns):
    """One partition of a dask collection audited where it was computed:
    its findings (positions within the partition) and its length."""
    items = [_item(g, f"{name}[{k}]") for k, g in enumerate(_sequence(items, name))]
    return _audit_chunk(items, 0, max_per_kind, threads, columns), len(items)


def _audit_frame(frames):
    """The chunks' findings as one frame, typed as the single-process audit
    types its columns: texts as objects; a column of numbers and None that
    chunks typed apart (int64 in one, float64 or None only in another) as
    float64, as pandas types such a column from all its values at once.
    (The audit's other columns hold one kind of value each: bools, or
    numbers in every row.)"""
    import pandas as pd
    for c in _AUDIT_TEXTS:  # (categories made one, so that pandas concatenates codes, not texts)
        union = pd.api.types.union_categoricals([f[c] for f in frames]).categories
        frames = [f.assign(**{c: f[c].cat.set_categories(union)}) for f in frames]
    for c in frames[0].columns:
        numeric = [f[c].dtype.kind in "if" for f in frames]
        if any(numeric) and not all(numeric) and all(numeric[k] or f[c].isna().all() for k, f in enumerate(frames)):
            frames = [f if numeric[k] else f.astype({c: float}) for k, f in enumerate(frames)]
    return pd.concat(frames, ignore_index=True).astype({c: object for c in _AUDIT_TEXTS})


def audit(geoms, client, chunk_size=1000, max_per_kind=50, threads=1):
    """The audit of a layer (a sequence or pandas Series of WKT text, WKB
    bytes, shapely geometries or Polygons) in chunks of ``chunk_size``, one
    task each on ``threads`` threads of a worker: the same DataFrame as
    :func:`influence2d.audit_layer`, ``polygon`` the position in ``geoms``.
    Every item is checked before any task starts. ``geoms`` may also be a
    dask collection (a ``dask.bag`` of WKT lines read from files, a
    DataFrame's column): then each of its partitions is read and audited on
    a worker (one task each, ``chunk_size`` unused), an item the audit
    cannot read is refused naming ``geoms partition p[index]``, and
    positions count through the partitions in order.

    >>> from distributed import Client, LocalCluster
    >>> import influence2d.dask
    >>> with LocalCluster(n_workers=2, threads_per_worker=1, processes=False, dashboard_address=None) as cluster, \\
    ...         Client(cluster) as client:
    ...     found = influence2d.dask.audit(["POLYGON ((0 0, 1 0, 0 1, 0 0))"] * 3 + ["POLYGON ((0 0, 0 1, 1 0, 0 0))"],
    ...                                    client, chunk_size=2)
    >>> found[["polygon", "kind"]]
       polygon                  kind
    0        3  reversed_orientation
    """
    import pandas as pd
    client = _client(client)
    chunk_size = _options.integer(chunk_size, "chunk_size", least=1)
    max_per_kind = _options.integer(max_per_kind, "max_per_kind", least=0)
    threads = _options.integer(threads, "threads", least=0)
    columns = list(audit_layer([]).columns)
    if _is_collection(geoms):
        import dask
        parts = client.gather(client.compute(
            [dask.delayed(_audit_partition)(d, f"geoms partition {i}", max_per_kind, threads, columns)
             for i, d in enumerate(geoms.to_delayed())]))
        offsets = np.cumsum([0] + [n for _, n in parts])
        found = [frame.assign(polygon=frame["polygon"] + start) for (frame, _), start in zip(parts, offsets)
                 if len(frame)]
        return _audit_frame(found) if found else pd.DataFrame([], columns=columns)
    items = [_item(g, f"geoms[{k}]") for k, g in enumerate(_sequence(geoms, "geoms"))]
    if not items:
        return pd.DataFrame([], columns=columns)
    starts = range(0, len(items), chunk_size)
    chunks = client.scatter([pickle.dumps(items[s:s + chunk_size], protocol=5) for s in starts], hash=False)
    tasks = [client.submit(_audit_packed, c, s, max_per_kind, threads, columns, pure=False)
             for c, s in zip(chunks, starts)]
    found = [frame for frame in client.gather(tasks) if len(frame)]
    if not found:
        return pd.DataFrame([], columns=columns)
    return _audit_frame(found)


# --- pairs ------------------------------------------------------------------

def _hilbert_keys(x, y, extent, order=16):
    """The positions of points on a Hilbert curve of 2^order x 2^order cells
    over ``extent`` (min x, min y, max x, max y): near points, near keys."""
    n = 1 << order
    size_x, size_y = max(extent[2] - extent[0], 1e-300), max(extent[3] - extent[1], 1e-300)
    xi = np.clip(((x - extent[0]) / size_x * (n - 1)).astype(np.int64), 0, n - 1)
    yi = np.clip(((y - extent[1]) / size_y * (n - 1)).astype(np.int64), 0, n - 1)
    key = np.zeros(len(xi), dtype=np.int64)
    s = n >> 1
    while s > 0:
        rx, ry = (xi & s) > 0, (yi & s) > 0
        key += s * s * ((3 * rx.astype(np.int64)) ^ ry.astype(np.int64))
        flip = ~ry & rx
        xi, yi = np.where(flip, n - 1 - xi, xi), np.where(flip, n - 1 - yi, yi)
        swap = ~ry
        xi, yi = np.where(swap, yi, xi), np.where(swap, xi, yi)
        s >>= 1
    return key


def _partitions(boxes, extent, count):
    """The layer cut into at most ``count`` runs of the Hilbert order of its
    boxes' centres (as dask-geopandas' spatial shuffle): each a sorted array
    of positions and the box around its polygons' boxes."""
    keys = _hilbert_keys((boxes[:, 0] + boxes[:, 2]) / 2, (boxes[:, 1] + boxes[:, 3]) / 2, extent)
    runs = np.array_split(np.argsort(keys, kind="stable"), min(count, len(boxes)))
    out = []
    for run in runs:
        members = np.sort(run)
        b = boxes[members]
        out.append((members, (b[:, 0].min(), b[:, 1].min(), b[:, 2].max(), b[:, 3].max())))
    return out


# The room _reach adds to ``within``: 2^-40 of it and 2^-30 of the layers'
# scale (their largest coordinate, plus within). For the exact and
# certified types ``within`` alone would do: two polygons within it have
# boxes within it on each axis, so do the partitions' boxes that hold them,
# and a sum rounded to nearest cannot fall below a double that the exact
# sum reaches. The room is for double's answers, whose coordinates and
# distances round by a few units of 2^-53 of the scale, far inside 2^-30.
_WITHIN_ROOM = 2.0 ** -40
_SCALE_ROOM = 2.0 ** -30


def _reach(boxes, within):
    """How far two partitions' boxes may be apart and still hold a pair:
    ``within``, with room (_WITHIN_ROOM, _SCALE_ROOM; joining more
    partitions than needed costs time, never a different answer)."""
    scale = float(np.abs(boxes).max()) if len(boxes) else 0.0
    return within * (1 + _WITHIN_ROOM) + (scale + within) * _SCALE_ROOM


def _boxes_meet(p, q, reach):
    """Whether boxes p and q come within ``reach`` of each other (a sum
    rounded one way cannot hide a gap of exactly ``reach``); p's four
    components may be arrays (then for each box of them)."""
    return (p[2] + reach >= q[0]) & (q[2] + reach >= p[0]) & (p[3] + reach >= q[1]) & (q[3] + reach >= p[1])


def _at(found, at_a, at_b):
    """Local index pairs of two partitions at the positions of the layers."""
    return np.column_stack((at_a[found[:, 0]], at_b[found[:, 1]]))


def _layer_pairs(first, second, within, number_type, threads):
    """The (k, 2) local index pairs of two packed partitions (_core.Layer;
    ``second`` None: within ``first``); the arguments checked by the caller."""
    return _core.pairs(first, second, within, number_type, threads)[0].reshape(-1, 2).astype(np.int64, copy=False)


def _near(part, around, reach):
    """The polygons of a partition (packed polygons, positions) whose boxes
    come within ``reach`` of the box ``around`` (another partition's): only
    these can meet a polygon of that partition, so two partitions are
    joined along their common border, not whole; a task run where the
    partition is, so only the strip travels."""
    polys, at = part
    keep = np.flatnonzero(_boxes_meet(polys.bounds().T, around, reach))
    return polys.take(keep), at[keep]


def _join_partitions(first, second, kind, within, number_type, threads):
    """One task: the pairs between two partitions, (packed polygons,
    positions) each, at the positions of the whole layers. ``kind``: "same"
    (one partition of one layer: i < j; ``second`` unused), "layer" (two
    partitions of one layer: each pair as (lower, higher)) or "layers" (one
    of each layer). Within one layer a pair is tested with its lower
    position first, as the single-process join tests it: a rounded type's
    answer may depend on the order, so in double each way is asked and kept
    where it is that order."""
    polys_a, at_a = first
    if kind == "same":
        return _at(_layer_pairs(polys_a, None, within, number_type, threads), at_a, at_a)
    polys_b, at_b = second
    out = _at(_layer_pairs(polys_a, polys_b, within, number_type, threads), at_a, at_b)
    if kind == "layers":
        return out
    if number_type != "double":
        return np.sort(out, axis=1)
    back = _at(_layer_pairs(polys_b, polys_a, within, number_type, threads), at_b, at_a)
    return np.concatenate((out[out[:, 0] < out[:, 1]], back[back[:, 0] < back[:, 1]]))


def _is_collection(values):
    """Whether ``values`` is a dask collection (a Bag, a DataFrame's column):
    its partitions are computed, and stay, on the workers."""
    return hasattr(values, "to_delayed") and hasattr(values, "npartitions") and hasattr(values, "dask")


def _pack(items, name):
    """One partition of a dask collection packed where it was computed: a
    _core.Layer of its polygons, each refused naming ``name[index]``."""
    return _core.Layer(_core_polygons(_sequence(items, name), name))


def _bounds_of(layer):
    """The (n, 4) boxes of a packed partition's polygons."""
    return layer.bounds()


def _taken(layer, positions):
    """The polygons of a packed partition at ``positions``."""
    return layer.take(positions)


def _joined(pieces, members):
    """A spatial partition made of its pieces (in the order of the input
    partitions), with its positions in the whole layer."""
    return _core.Layer.concat(pieces), members


def _held_here(client, polygons):
    """A layer held by the client: its boxes, and how its spatial partitions
    reach the workers (each packed from the whole and scattered once)."""
    whole = _core.Layer([p._p for p in polygons])
    return whole.bounds(), lambda parts: client.scatter([(whole.take(m), m) for m, _ in parts], hash=False)


def _held_there(client, collection, name):
    """A layer given as a dask collection: each of its partitions computed
    and packed on a worker; only the boxes come to the client. Its spatial
    partitions are gathered from the input partitions on the workers (one
    take per input partition that holds part of one, then one
    concatenation), so the polygons never pass through the client."""
    import dask
    packed = client.compute([dask.delayed(_pack)(d, f"{name} partition {i}")
                             for i, d in enumerate(collection.to_delayed())])
    boxes = client.gather([client.submit(_bounds_of, f, pure=False) for f in packed])
    offsets = np.cumsum([0] + [len(b) for b in boxes])

    def send(parts):
        out = []
        for members, _ in parts:
            cuts = np.searchsorted(members, offsets)
            pieces = [client.submit(_taken, f, members[cuts[i]:cuts[i + 1]] - offsets[i], pure=False)
                      for i, f in enumerate(packed) if cuts[i + 1] > cuts[i]]
            out.append(client.submit(_joined, pieces, members, pure=False))
        return out

    return np.concatenate([np.empty((0, 4))] + boxes), send


def _source(client, values, name):
    """A layer as the join reads it: (its boxes, how its spatial partitions
    are sent), from a dask collection or from a sequence the client holds."""
    if _is_collection(values):
        return _held_there(client, values, name)
    return _held_here(client, as_polygons(_sequence(values, name), name))


def _kind(p, q, one_layer):
    """What a task joins: one partition, two of one layer, or one of each."""
    return ("same" if p == q else "layer") if one_layer else "layers"


def _partition_pairs(parts_a, parts_b, reach):
    """The pairs of partitions (indices) whose boxes come within ``reach``:
    each unordered pair once within one layer (``parts_b`` None)."""
    if parts_b is None:
        return [(p, q) for p in range(len(parts_a)) for q in range(p, len(parts_a))
                if _boxes_meet(parts_a[p][1], parts_a[q][1], reach)]
    return [(p, q) for p in range(len(parts_a)) for q in range(len(parts_b))
            if _boxes_meet(parts_a[p][1], parts_b[q][1], reach)]


def _join_tasks(client, first, second, within, number_type, threads, count):
    """The layers (``_source``'s) cut into partitions and sent, and one task
    per two partitions whose boxes come within ``within`` (``second`` None:
    one layer)."""
    boxes_a, send_a = first
    boxes_b = None if second is None else second[0]
    every = boxes_a if second is None else np.concatenate((boxes_a, boxes_b))
    extent = (every[:, 0].min(), every[:, 1].min(), every[:, 2].max(), every[:, 3].max())
    parts_a = _partitions(boxes_a, extent, count)
    parts_b = None if second is None else _partitions(boxes_b, extent, count)
    sent_a = send_a(parts_a)
    sent_b = sent_a if second is None else second[1](parts_b)
    reach = _reach(every, within)
    tasks = []
    for p, q in _partition_pairs(parts_a, parts_b, reach):
        kind = _kind(p, q, second is None)
        if kind == "same":
            tasks.append(client.submit(_join_partitions, sent_a[p], None, kind, within, number_type, threads,
                                       pure=False))
            continue
        strip_a = client.submit(_near, sent_a[p], (parts_b or parts_a)[q][1], reach, pure=False)
        strip_b = client.submit(_near, sent_b[q], parts_a[p][1], reach, pure=False)
        tasks.append(client.submit(_join_partitions, strip_a, strip_b, kind, within, number_type, threads,
                                   pure=False))
    return tasks


def pairs(layer, other=None, client=None, within=0.0, number_type="certified", partitions=None, threads=1):
    """The same (k, 2) int64 array as :func:`influence2d.pairs` (positions,
    sorted), found on the workers: each layer is cut into ``partitions``
    runs of the Hilbert order of its polygons' box centres (default: two per
    worker thread), each partition with the box around its polygons; every
    two partitions whose boxes come within ``within`` are joined by one task
    (``influence2d.pairs`` on ``threads`` threads). A polygon is in one
    partition only, so a pair is found by one task only, and two polygons
    that meet lie in partitions whose boxes meet: none is lost at a
    partition's border.

    ``layer`` and ``other`` are what :func:`influence2d.pairs` takes, held
    by the client (sent to the workers once, packed), or dask collections
    (a ``dask.bag`` of WKT lines read from files, a DataFrame's column of
    WKB): then each input partition is read and packed on a worker, only
    its boxes come to the client, and the spatial partitions are gathered
    from the input partitions on the workers, as a layer larger than the
    client's memory needs. Positions count through the collection's
    partitions in order.

    >>> from distributed import Client, LocalCluster
    >>> import shapely.geometry as g, influence2d.dask
    >>> layer = [g.box(i, 0, i + 1, 1) for i in range(6)]
    >>> with LocalCluster(n_workers=2, threads_per_worker=1, processes=False, dashboard_address=None) as cluster, \\
    ...         Client(cluster) as client:
    ...     one = influence2d.dask.pairs(layer, client=client, partitions=3)
    ...     two = influence2d.dask.pairs(layer, [g.box(2.5, 0.5, 3.5, 3)], client, within=0.5, partitions=3)
    ...     import dask.bag
    ...     lines = dask.bag.from_sequence([b.wkt for b in layer], npartitions=2)
    ...     three = influence2d.dask.pairs(lines, client=client, partitions=3)
    >>> one.tolist(), two.tolist()
    ([[0, 1], [1, 2], [2, 3], [3, 4], [4, 5]], [[1, 0], [2, 0], [3, 0], [4, 0]])
    >>> (three == one).all()
    True
    """
    client = _client(client)
    threads = _options.integer(threads, "threads", least=0)
    _local_pairs([], None if other is None else [], within, number_type, 1)  # within and number_type checked
    within = _options.number(within, "within")
    count = (max(1, 2 * sum(client.nthreads().values())) if partitions is None
             else _options.integer(partitions, "partitions", least=1))
    first = _source(client, layer, "layer")
    second = None if other is None else _source(client, other, "other")
    if not len(first[0]) or second is not None and not len(second[0]):
        return np.empty((0, 2), dtype=np.int64)
    tasks = _join_tasks(client, first, second, within, number_type, threads, count)
    found = np.concatenate([np.empty((0, 2), dtype=np.int64)] + client.gather(tasks)).astype(np.int64, copy=False)
    return found[np.lexsort((found[:, 1], found[:, 0]))]


# --- world ------------------------------------------------------------------

def _world_part(polygons, plan, number_type, within, events, threads, skip_first):
    """One task: a run of consecutive steps of the table (with, when it is
    not the first, a step before it that sets every body where the earlier
    steps left it), its contacts or events."""
    return _world_play([p._p for p in polygons], plan, number_type, within, events, threads, skip_first)


def _world_parts(plan, count):
    """The table cut into at most ``count`` runs of consecutive steps of
    about equal rows, each a plan of its own: a run after the first starts
    with one step, numbered as the step before the run, that adds every
    body the earlier rows made at its last pose there (so the run's first
    contacts and events are the single run's); and whether it has that
    step."""
    steps = len(plan.starts)
    cuts = np.unique(np.searchsorted(plan.starts, np.linspace(0, len(plan.step), count + 1)[1:-1], side="left"))
    cuts = cuts[(cuts > 0) & (cuts < steps)]
    bounds = np.concatenate(([0], cuts, [steps]))
    out = []
    for i0, i1 in zip(bounds[:-1], bounds[1:]):
        begin, end = plan.starts[i0], plan.ends[i1 - 1]
        if i0 == 0:
            keep, state = np.arange(begin, end), 0
        else:
            # Each body's last row before the run, moved to the step before it.
            _, last_from_end = np.unique(plan.body[:begin][::-1], return_index=True)
            state = len(last_from_end)
            keep = np.concatenate((np.sort(begin - 1 - last_from_end), np.arange(begin, end)))
        step = plan.step[keep]
        if state:
            step[:state] = plan.step[begin - 1]
        out.append((_WorldPlan(step, plan.body[keep], plan.shape[keep], plan.poses[keep], plan.fixed[keep]), i0 > 0))
    return out


def world_contacts(shapes, steps, client, number_type="certified", within=0.0, events=False, parts=None, threads=1):
    """The same DataFrame as :func:`influence2d.world_contacts` (the
    contacts, or events, after each step of a table of steps), found on the
    workers: the table is cut into ``parts`` runs of consecutive steps
    (default: two per worker thread), one task each, on ``threads``
    threads of a worker. A run after the first starts with every body where
    the earlier steps left it (one step made of their last rows), so its
    contacts and events are those of the single run: in "certified" and
    "exact" the world's answer to a step is the exact one for its bodies'
    poses, whatever came before. The shapes are sent to the workers once.

    >>> from distributed import Client, LocalCluster
    >>> import pandas as pd, influence2d.dask
    >>> steps = pd.DataFrame({"step": [0, 0, 1, 2, 3], "body": [1, 2, 2, 2, 2], "shape": [0] * 5,
    ...                       "tx": [0.0, 3.0, 2.0, 1.0, 0.5], "ty": [0.0] * 5, "theta": [0.0] * 5})
    >>> with LocalCluster(n_workers=2, threads_per_worker=1, processes=False, dashboard_address=None) as cluster, \\
    ...         Client(cluster) as client:
    ...     found = influence2d.dask.world_contacts(["POLYGON ((0 0, 1 0, 1 1, 0 1, 0 0))"], steps, client,
    ...                                             events=True, parts=3)
    >>> found
       step  a  b  event
    0     2  1  2  begin
    """
    client = _client(client)
    threads = _options.integer(threads, "threads", least=0)
    count = max(1, 2 * sum(client.nthreads().values())) if parts is None else _options.integer(parts, "parts", least=1)
    within, events = _options.number(within, "within"), _options.flag(events, "events")
    number_type = _options.name(number_type, "number_type")
    polygons = as_polygons(shapes, "shapes")
    plan = _world_plan_of(steps, len(polygons))
    _core.World(number_type, within, False, True, threads)  # the number type and distance checked
    if not len(plan.step):
        return _world_frame(*_world_play([], plan, number_type, within, events, threads), events)
    shared = client.scatter(polygons, broadcast=True, hash=False)
    tasks = [client.submit(_world_part, shared, part, number_type, within, events, threads, skip, pure=False)
             for part, skip in _world_parts(plan, count)]
    found = client.gather(tasks)
    return _world_frame(np.concatenate([f[0] for f in found]), np.concatenate([f[1] for f in found]),
                        np.concatenate([f[2] for f in found]), events)


# --- study ------------------------------------------------------------------

def _check_names(given, known, name):
    """The names, checked against ``known``: a list (None: empty)."""
    given = [] if given is None else list(given)
    for k, n in enumerate(given):
        if n not in known:
            raise _core.InvalidInput(f"{name}[{k}] is {n!r}: expected one of {', '.join(known)}")
    return given


def _study_families(families):
    """The families a split study runs, one task each (None: the command's
    defaults); a family named twice is refused (it would count twice)."""
    names = study_names()
    families = _check_names(families, names["families"], "families") or names["default_families"]
    for k, f in enumerate(families):
        if f in families[:k]:
            raise _core.InvalidInput(f"families[{k}] is {f!r}, named twice: each family is run once")
    return families


def _study_part(family, first, end, args):
    """One task: the study of ``family``'s scenes [first, end), its tables
    as rows (the queries' rows with their measured errors)."""
    return _core.study([family], args["types"], args["decisions"], args["queries"], args["cases"], args["frames"],
                       args["query_frames"], args["seed"], first, end)


def _summed(parts, table, key, counts, order, time=None):
    """One table's rows of the parts, the rows of the same ``key`` merged
    (``counts`` summed, measured errors joined, and with ``time`` = (a time
    per unit, the count of units) the time summed as nanoseconds in
    ``_ns``), in the single run's order (``order`` of a row)."""
    merged = {}
    for part in parts:
        for row in part[table]:
            k = tuple(row[c] for c in key)
            if k not in merged:
                merged[k] = dict(row, errors=list(row.get("errors", [])), _ns=0.0)
            else:
                for c in counts:
                    merged[k][c] += row[c]
                merged[k]["errors"] += row.get("errors", [])
            if time:
                merged[k]["_ns"] += row[time[0]] * row[time[1]]
    return sorted(merged.values(), key=order)


def _rate(row):
    """The row's disagreements per case, as the study computes it."""
    row["rate"] = row["disagreements"] / row["cases"] if row["cases"] else 0.0
    return row


def _measured(row):
    """A query row's error figures from its joined errors, as the study
    computes them (the largest, the lower median)."""
    errors = sorted(row["errors"])
    row["measured"] = len(errors)
    row["largest_error"] = errors[-1] if errors else None
    row["median_error"] = errors[(len(errors) - 1) // 2] if errors else None
    return row


def _merged_summaries(parts):
    """The per-type summaries: the counts summed over the parts (integer
    sums, in the single run's order of types)."""
    first = [dict(row) for row in parts[0]["summaries"]]
    for part in parts[1:]:
        for row, more in zip(first, part["summaries"]):
            for column, value in more.items():
                if column not in ("number_type", "claims_exact", "has_fallback"):
                    row[column] += value
    return first


def _merged_examples(parts):
    """The examples in the single run's order (family by family, scene by
    scene), at most STUDY_EXAMPLES_KEPT per number type and decision or
    query, as the single run keeps them."""
    kept, rows = {}, []
    for part in parts:
        for row in part["examples"]:
            key = (row["number_type"], row["decision"])
            kept[key] = kept.get(key, 0) + 1
            if kept[key] <= STUDY_EXAMPLES_KEPT:
                rows.append(row)
    return rows


def _merged_study(parts, families):
    """The tables of one study from its parts (in the order of the families
    and their scenes): counts summed, error figures from the joined
    errors, rows in the single run's order; only the times (summed as
    nanoseconds) are the workers' own."""
    names = study_names()
    rank = {t: k for k, t in enumerate(names["types"])}
    family = {f: k for k, f in enumerate(families)}
    decision = {d: k for k, d in enumerate(names["decisions"])}
    query = {q: k for k, q in enumerate(names["queries"])}
    decisions = _summed(parts, "decisions", ("number_type", "family", "decision"), ("cases", "disagreements"),
                        lambda r: (rank[r["number_type"]], family[r["family"]], decision[r["decision"]]),
                        time=("ns_per_query", "cases"))
    queries = _summed(parts, "queries", ("number_type", "family", "query"),
                      ("questions", "differing", "meeting_differs", "features_differ", "values_differ"),
                      lambda r: (rank[r["number_type"]], family[r["family"]], query[r["query"]]),
                      time=("ns_per_question", "questions"))
    stability = _summed(parts, "stability", ("number_type", "sweep", "magnitude"), ("cases", "disagreements"),
                        lambda r: (rank[r["number_type"]], r["sweep"], r["magnitude"]))
    for row in decisions:
        _rate(row)["ns_per_query"] = row["_ns"] / row["cases"] if row["cases"] else 0.0
    for row in queries:
        _measured(row)["ns_per_question"] = row["_ns"] / row["questions"] if row["questions"] else 0.0
    return _frames({"decisions": decisions, "queries": queries, "stability": [_rate(r) for r in stability],
                    "summaries": _merged_summaries(parts), "examples": _merged_examples(parts)})


def study(families=None, types=None, decisions=None, queries=None, cases=1, frames=40, query_frames=128,
          seed=20040202, client=None, scenes_per_task=1):
    """The precision study of :func:`influence2d.study` (the same arguments)
    on the workers: each family's scenes (``cases`` per family, per
    magnitude for a sweep) cut into runs of ``scenes_per_task``, one task
    each, the tables merged: every count the same as the single run's
    (integer sums; the largest and median errors from the joined errors),
    every table in its order; only the measured times (``ns_per_query``,
    ``ns_per_question``) are the workers' own. A family's scenes are drawn
    from the seed and the family alone, and each starts with fresh
    evaluators, which is what lets them run apart. A scene's frames are not
    split among tasks: a rounded type's answer to a frame may depend on the
    frames its evaluator answered before (the coherence of its detector,
    parts built on first use), so a task that started at a later frame
    could count other disagreements (float's masks on ``scale_sweep`` did:
    68 against 66). Split a long study into many scenes (``cases``), not
    into long scenes. The tasks with the most vertices start first (the
    longest last would leave one worker alone at the end).

    >>> from distributed import Client, LocalCluster
    >>> import influence2d.dask
    >>> with LocalCluster(n_workers=2, threads_per_worker=1, processes=False, dashboard_address=None) as cluster, \\
    ...         Client(cluster) as client:
    ...     t = influence2d.dask.study(families=["convex", "starred"], types=["double", "certified"],
    ...                                decisions=["collides"], queries=[], cases=3, frames=10, client=client)
    >>> t["decisions"][["number_type", "family", "cases", "disagreements"]]
      number_type   family  cases  disagreements
    0      double   convex     30              3
    1      double  starred     30              0
    2   certified   convex     30              0
    3   certified  starred     30              0
    >>> t["summaries"][["number_type", "questions"]]
      number_type  questions
    0      double         60
    1   certified         60
    """
    client = _client(client)
    names = study_names()
    families = _study_families(families)
    scenes_per_task = _options.integer(scenes_per_task, "scenes_per_task", least=1)
    args = dict(types=_check_names(types, names["types"], "types"),
                decisions=_check_names(decisions, names["decisions"], "decisions"),
                queries=list(names["queries"]) if queries is None else _check_names(queries, names["queries"],
                                                                                    "queries"),
                cases=_options.integer(cases, "cases", least=1), frames=_options.integer(frames, "frames", least=1),
                query_frames=_options.integer(query_frames, "query_frames", least=0),
                seed=_options.integer(seed, "seed", least=0, most=2**64 - 1))
    tasks = []
    for f in families:
        sizes = _core.study_scene_sizes(f, args["cases"], args["frames"], args["seed"])
        tasks += [client.submit(_study_part, f, first, first + scenes_per_task, args, pure=False,
                                priority=sum(sizes[first:first + scenes_per_task]))
                  for first in range(0, len(sizes), scenes_per_task)]
    return _merged_study(client.gather(tasks), families)
