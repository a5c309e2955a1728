# SPDX-License-Identifier: BSL-1.0
"""influence2d.dask: the audit, the layer join and the precision study on a
LocalCluster (two workers of one thread, in processes and in threads) give
what the single-process calls give; bad input is refused before any task."""

import os
import subprocess
import sys

import numpy as np
import pandas as pd
import pandas.testing
import pytest
import shapely.affinity
import shapely.geometry
import shapely.wkt

import influence2d
import influence2d.dask
from conftest import star_polygon
from test_audit import POLYGONS
from test_pairs import layer_of
from test_real_layers import layer as real_layer
from test_world import steps_table

distributed = pytest.importorskip("distributed")


@pytest.fixture(scope="module", params=[True, False], ids=["processes", "threads"])
def client(request):
    """A LocalCluster of two one-thread workers (processes, then threads) and
    its client, for the whole module."""
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=request.param,
                                  dashboard_address=None) as cluster, distributed.Client(cluster) as c:
        yield c


def parcels(rng, rows, columns):
    """A grid of quadrilaterals sharing their edges and corners exactly
    (jittered dyadic corners), every one meeting its eight neighbours."""
    corner = {(i, j): (j + rng.randint(-16, 16) / 64, i + rng.randint(-16, 16) / 64)
              for i in range(rows + 1) for j in range(columns + 1)}
    return [shapely.geometry.Polygon([corner[i, j], corner[i, j + 1], corner[i + 1, j + 1], corner[i + 1, j]])
            for i in range(rows) for j in range(columns)]


def straddling(rng, count):
    """Long thin polygons across the whole layer: each crosses every
    partition's border."""
    return [shapely.geometry.box(0, y, 12, y + 0.25) if k % 2 else shapely.geometry.box(y, 0, y + 0.25, 12)
            for k, y in enumerate(rng.randint(0, 44) / 4 for _ in range(count))]


# --- audit -------------------------------------------------------------------

def audit_layer_of(rng):
    """A layer of every input form (WKT, WKB, shapely, Polygon) of the audit
    test's polygons, those a reader refuses kept as text (a finding), and
    random stars."""
    forms = [lambda t: t, lambda t: shapely.wkt.loads(t).wkb, shapely.wkt.loads, influence2d.Polygon.from_wkt]
    layer = []
    for k in range(60):
        text = POLYGONS[k % len(POLYGONS)]
        try:
            layer.append(forms[k % 4](text))
        except Exception:
            layer.append(text)
    return layer + [star_polygon(rng, rng.randint(3, 12)) for _ in range(20)]


@pytest.mark.parametrize("chunk_size", [1, 7, 1000])
def test_audit_is_the_single_process_audit(client, rng, chunk_size):
    layer = audit_layer_of(rng)
    want = influence2d.audit_layer(layer)
    got = influence2d.dask.audit(layer, client, chunk_size=chunk_size)
    pandas.testing.assert_frame_equal(got, want)
    assert len(want) > len(layer) // 2


def test_chunks_typed_apart_merge_as_the_rows_typed_at_once(rng):
    # The audit's chunks are typed each by pandas, then merged: a column of
    # numbers and None (ints in one chunk, None only or floats in another)
    # must come out as pandas types all the rows at once; bools stay bools.
    pools = [[1, 2], [None], [0.5, None], [3, None], [4]]
    columns = ["polygon", "kind", "ring", "vertex", "x", "what", "effect", "rejects"]
    for _ in range(300):
        chosen = {c: [rng.choice(pools) for _ in range(3)] for c in ("ring", "vertex", "x")}
        rows, frames = [], []
        for part in range(3):
            chunk = [dict(polygon=len(rows) + k, kind=rng.choice("ab"), what="w", effect=rng.choice("xyz"),
                          rejects=rng.choice([True, False]), **{c: rng.choice(chosen[c][part]) for c in chosen})
                     for k in range(rng.randint(1, 4))]
            rows += chunk
            frames.append(pd.DataFrame(chunk, columns=columns).astype({c: "category" for c in ("kind", "what",
                                                                                            "effect")}))
        pandas.testing.assert_frame_equal(influence2d.dask._audit_frame(frames), pd.DataFrame(rows, columns=columns))


def test_audit_of_a_collection_read_on_the_workers(client, rng):
    import dask.bag
    layer = audit_layer_of(rng)
    texts = [g if isinstance(g, (str, bytes)) else g.to_wkt() if isinstance(g, influence2d.Polygon) else g.wkb
             for g in layer]
    want = influence2d.audit_layer(texts)
    for count in (1, 4, 9):
        pandas.testing.assert_frame_equal(influence2d.dask.audit(dask.bag.from_sequence(texts, npartitions=count),
                                                                 client), want)
    pandas.testing.assert_frame_equal(influence2d.dask.audit(column_of_wkb(POLYGONS[:0], 1), client),
                                      influence2d.audit_layer([]))
    with pytest.raises(influence2d.InvalidInput, match=r"geoms partition 1\[0\]"):
        influence2d.dask.audit(dask.bag.from_sequence(texts[:2] + [3.5], npartitions=2), client)


def test_audit_of_a_series_and_of_nothing(client):
    series = pd.Series(POLYGONS, index=[10 * k for k in range(len(POLYGONS))])
    pandas.testing.assert_frame_equal(influence2d.dask.audit(series, client, chunk_size=4),
                                      influence2d.audit_layer(POLYGONS))
    pandas.testing.assert_frame_equal(influence2d.dask.audit([], client), influence2d.audit_layer([]))
    clean = ["POLYGON ((0 0, 1 0, 0 1, 0 0))"] * 5
    pandas.testing.assert_frame_equal(influence2d.dask.audit(clean, client, chunk_size=2),
                                      influence2d.audit_layer(clean))


# --- pairs -------------------------------------------------------------------

def bag_of_wkb(layer, count):
    """The layer as a dask.bag of WKB in ``count`` partitions: read on the
    workers."""
    import dask.bag
    return dask.bag.from_sequence([g.wkb for g in layer], npartitions=count)


def column_of_wkb(layer, count):
    """The layer as a dask DataFrame's column of WKB in ``count`` partitions."""
    import dask.dataframe
    return dask.dataframe.from_pandas(pd.DataFrame({"wkb": [g.wkb for g in layer]}), npartitions=count)["wkb"]


def same_pairs(client, layer, other=None, **options):
    """influence2d.dask.pairs against influence2d.pairs on several cuts of
    the layers into partitions, the layers held by the client or given as
    dask collections partitioned otherwise; each pair found once."""
    local = {k: v for k, v in options.items() if k in ("within", "number_type")}
    want = influence2d.pairs(layer, other, **local)
    forms = [(lambda g, n: g, 1), (bag_of_wkb, 1), (bag_of_wkb, 5), (column_of_wkb, 3)]
    for partitions in (1, 3, 7, 16):
        for k in (0, 1 + partitions % 3):
            form, count = forms[k]
            first = form(layer, count)
            second = None if other is None else forms[(k + partitions) % len(forms)][0](other, count + 1)
            got = influence2d.dask.pairs(first, second, client, partitions=partitions, **options)
            assert got.dtype == np.int64 and got.shape == want.shape, (partitions, k)
            np.testing.assert_array_equal(got, want, err_msg=f"partitions={partitions}, form {k}")
    return want


@pytest.mark.parametrize("number_type", ["certified", "exact", "double"])
def test_pairs_of_a_random_layer_with_shared_borders(client, rng, number_type):
    layer = layer_of(rng, 60, spread=10.0) + parcels(rng, 6, 8)
    assert len(same_pairs(client, layer, number_type=number_type)) > 100


def test_pairs_of_polygons_straddling_the_partitions(client, rng):
    layer = parcels(rng, 8, 8)
    layer = [g for pair in zip(layer, straddling(rng, len(layer))) for g in pair]
    assert len(same_pairs(client, layer)) > 200


def test_pairs_of_two_layers(client, rng):
    first, second = layer_of(rng, 50, spread=10.0), parcels(rng, 5, 9) + straddling(rng, 6)
    same_pairs(client, first, second)
    same_pairs(client, second, first, number_type="double")


@pytest.mark.parametrize("within", [0.25, 1.5])
def test_pairs_within_a_distance(client, rng, within):
    layer = [star_polygon(rng, 8, radius=0.4, center=(rng.uniform(0, 12), rng.uniform(0, 12))) for _ in range(80)]
    assert len(same_pairs(client, layer, within=within)) > len(same_pairs(client, layer))
    same_pairs(client, layer, [shapely.affinity.translate(g, 0.3, 0.1) for g in layer[:30]], within=within,
               number_type="double")


def snapped(geometry, cell):
    """The geometry with every vertex rounded to a multiple of ``cell`` (a
    power of two: exact), its rings left with fewer than three distinct
    vertices dropped; None when none is left."""
    def ring(r):
        points = [(round(x / cell) * cell, round(y / cell) * cell) for x, y in r.coords]
        return points if len(set(points)) >= 3 else None
    parts = []
    for p in geometry.geoms if geometry.geom_type == "MultiPolygon" else [geometry]:
        outer = ring(p.exterior)
        if outer is not None:
            parts.append(shapely.geometry.Polygon(outer, [h for h in map(ring, p.interiors) if h is not None]))
    return None if not parts else parts[0] if len(parts) == 1 else shapely.geometry.MultiPolygon(parts)


def test_pairs_of_a_snapped_real_layer_at_a_tie(client):
    # North Carolina's counties rounded to a quarter-degree grid: repeated
    # vertices, collinear runs, and counties exactly one cell apart, on
    # partition borders wherever the cuts fall; alone and against the
    # layer moved by whole cells.
    cell = 0.25
    layer = [g for g in (snapped(shapely.wkt.loads(t), cell) for t in real_layer("nc_counties.wkt")) if g is not None]
    assert len(layer) == 99
    at_a_tie = same_pairs(client, layer, within=cell)
    assert len(at_a_tie) > len(influence2d.pairs(layer, within=np.nextafter(cell, 0))) + 5  # premise: ties
    np.testing.assert_array_equal(influence2d.pairs(layer, within=cell, number_type="exact"), at_a_tie)
    same_pairs(client, layer, [shapely.affinity.translate(g, 3 * cell, cell) for g in layer], within=cell)


def test_pairs_of_few_polygons_and_of_none(client):
    square = shapely.geometry.box(0, 0, 1, 1)
    same_pairs(client, [square])
    same_pairs(client, [square, square])
    same_pairs(client, [square], [square, square])
    assert influence2d.dask.pairs([], client=client).shape == (0, 2)
    assert influence2d.dask.pairs([square], [], client).shape == (0, 2)


def test_pairs_of_a_layer_read_from_files_on_the_workers(client, rng, tmp_path):
    import dask.bag
    layer = layer_of(rng, 60, spread=10.0) + parcels(rng, 7, 7)
    texts = [influence2d.Polygon.from_shapely(g).to_wkt() for g in layer]
    for k, cut in enumerate(np.array_split(np.arange(len(texts)), 4)):
        (tmp_path / f"part-{k}.wkt").write_text("".join(texts[i] + "\n" for i in cut))
    lines = dask.bag.read_text(str(tmp_path / "part-*.wkt")).map(str.strip)
    want = influence2d.pairs(layer)
    assert len(want) > 100
    np.testing.assert_array_equal(influence2d.dask.pairs(lines, client=client, partitions=5), want)
    np.testing.assert_array_equal(influence2d.dask.pairs(lines, lines, client, partitions=3),
                                  influence2d.pairs(layer, layer))


def test_a_bad_polygon_in_a_collection_is_named_by_its_partition(client):
    import dask.bag
    lines = dask.bag.from_sequence(["POLYGON ((0 0, 1 0, 0 1, 0 0))"] * 3 + ["POLYGON ((0 0, 1 0, 0 1))"],
                                   npartitions=2)
    with pytest.raises(influence2d.InvalidInput, match=r"layer partition 1\[1\].*not closed"):
        influence2d.dask.pairs(lines, client=client)
    empty = dask.bag.from_sequence([], npartitions=1)
    assert influence2d.dask.pairs(empty, client=client).shape == (0, 2)
    square = dask.bag.from_sequence(["POLYGON ((0 0, 1 0, 0 1, 0 0))"], npartitions=1)
    assert influence2d.dask.pairs(square, empty, client).shape == (0, 2)


def test_a_packed_partition_takes_and_joins_its_polygons(rng):
    layer = influence2d._core.Layer([influence2d.Polygon.from_shapely(g)._p for g in layer_of(rng, 30)])
    boxes = layer.bounds()
    assert boxes.shape == (30, 4) and (boxes[:, :2] <= boxes[:, 2:]).all()
    picked = layer.take(np.array([4, 0, 4, 29]))
    assert len(picked) == 4 and np.array_equal(picked.bounds(), boxes[[4, 0, 4, 29]])
    whole = influence2d._core.Layer.concat([layer.take(np.arange(0, 12)), layer.take(np.arange(12, 30))])
    assert np.array_equal(influence2d._core.pairs(whole, None, 0.0, "certified", 1)[0],
                          influence2d._core.pairs(layer, None, 0.0, "certified", 1)[0])
    for bad, message in [(np.array([30]), r"positions\[0\] is 30, outside a layer of 30"),
                         (np.array([0, -1]), r"positions\[1\] is -1"), (np.zeros((2, 2)), "one-dimensional")]:
        with pytest.raises(influence2d.InvalidInput, match=message):
            layer.take(bad)
    with pytest.raises(influence2d.InvalidInput, match="item 1 is not a Layer"):
        influence2d._core.Layer.concat([layer, "layer"])


def test_pairs_of_a_series_use_positions(client):
    layer = pd.Series([shapely.geometry.box(k, 0, k + 1, 1) for k in range(5)], index=list("abcde"))
    assert influence2d.dask.pairs(layer, client=client, partitions=2).tolist() == [[0, 1], [1, 2], [2, 3], [3, 4]]


def test_a_packed_partition_pickles_whole_and_joins_as_its_polygons(rng):
    import pickle
    layer = [influence2d.Polygon.from_shapely(star_polygon(rng, 3 + k % 9, 1.0, ((k % 4) * 0.7, (k // 4) * 0.7)))
             for k in range(24)]
    layer += [influence2d.Polygon.from_wkt("MULTIPOLYGON (((0 0, 4 0, 4 4, 0 4, 0 0), (1 1, 1 3, 3 3, 3 1, 1 1)), "
                                           "((5 5, 6 5, 6 6, 5 5)))")]
    core = [p._p for p in layer]
    packed = pickle.loads(pickle.dumps(influence2d._core.Layer(core)))
    assert len(packed) == len(layer)
    for number_type in ("double", "certified"):
        want = influence2d._core.pairs(core, None, 0.0, number_type, 1)[0]
        assert np.array_equal(influence2d._core.pairs(packed, None, 0.0, number_type, 1)[0], want)
        assert np.array_equal(influence2d._core.pairs(packed, packed, 0.25, number_type, 1)[0],
                              influence2d._core.pairs(core, core, 0.25, number_type, 1)[0])
    state = influence2d._core.Layer(core).__getstate__()
    for bad, message in [(state[:3], "expected 4 byte strings"), ((state[0], state[1], state[2], state[3][:-8]),
                         "coordinates run short"), ((state[0] + b"\0" * 7, *state[1:]), "ring counts run short"),
                         ((state[0], state[1] + b"\0", state[2], state[3]), "left over")]:
        with pytest.raises(influence2d.InvalidInput, match=message):
            influence2d._core.Layer.__new__(influence2d._core.Layer).__setstate__(bad)


# --- study -------------------------------------------------------------------

STUDY = dict(families=["convex", "sliver", "offset_sweep", "scale_sweep", "subnormal"],
             types=["float", "double", "certified"], frames=12, query_frames=6, cases=2)
TIMES = ("ns_per_query", "ns_per_question")


def assert_same_study(got, want):
    """Every table the same, but for the measured times."""
    assert got.keys() == want.keys()
    for name in want:
        pandas.testing.assert_frame_equal(got[name].drop(columns=list(TIMES), errors="ignore"),
                                          want[name].drop(columns=list(TIMES), errors="ignore"), obj=name)


@pytest.mark.parametrize("scenes_per_task", [1, 3, 1000])
def test_study_is_the_single_process_study(client, scenes_per_task):
    want = influence2d.study(**STUDY)
    got = influence2d.dask.study(**STUDY, client=client, scenes_per_task=scenes_per_task)
    assert_same_study(got, want)
    # What the comparison covers: sweeps, refused scenes, examples cut at the kept count, errors
    # measured in several scenes of one family (their median is not a sum).
    assert len(want["stability"]) > 0 and want["summaries"]["refused_scenes"].sum() > 0
    assert want["examples"].groupby(["number_type", "decision"]).size().max() == influence2d.dask.STUDY_EXAMPLES_KEPT
    assert (want["queries"]["measured"] > STUDY["query_frames"]).any()


def test_study_with_families_in_another_order_and_no_queries(client):
    args = dict(STUDY, families=["scale_sweep", "convex", "offset_sweep"], queries=[], decisions=["collides", "mask"],
                seed=7)
    assert_same_study(influence2d.dask.study(**args, client=client), influence2d.study(**args))


# --- bad input ---------------------------------------------------------------

SQUARE = shapely.geometry.box(0, 0, 1, 1)
STEPS = pd.DataFrame({"step": [0, 1], "body": [0, 0], "shape": [0, 0], "tx": [0.0, 1.0], "ty": [0.0, 0.0],
                      "theta": [0.0, 0.0]})


# --- world ------------------------------------------------------------------

@pytest.mark.parametrize("number_type", ["certified", "exact", "double"])
@pytest.mark.parametrize("parts", [1, 3, 7, 1000])
def test_world_contacts_is_the_single_process_run(client, rng, number_type, parts):
    shapes, table = steps_table(rng, bodies=14, steps=20)
    for events in (False, True):
        want = influence2d.world_contacts(shapes, table, number_type=number_type, events=events)
        got = influence2d.dask.world_contacts(shapes, table, client, number_type=number_type, events=events,
                                              parts=parts)
        pandas.testing.assert_frame_equal(got, want)
        assert len(want) > table["step"].nunique()


def test_world_contacts_of_one_step_and_of_none(client):
    square = "POLYGON ((0 0, 1 0, 1 1, 0 1, 0 0))"
    table = pd.DataFrame({"step": [4, 4], "body": [0, 1], "shape": [0, 0], "tx": [0.0, 1.0], "ty": [0.0, 0.0],
                          "theta": [0.0, 0.0]})
    pandas.testing.assert_frame_equal(influence2d.dask.world_contacts([square], table, client, parts=5),
                                      influence2d.world_contacts([square], table))
    pandas.testing.assert_frame_equal(influence2d.dask.world_contacts([square], table.iloc[:0], client),
                                      influence2d.world_contacts([square], table.iloc[:0]))


@pytest.mark.parametrize("call, message", [
    (lambda c: influence2d.dask.audit(POLYGONS, "tcp://scheduler:8786"), "client: expected a distributed.Client"),
    (lambda c: influence2d.dask.audit(POLYGONS, c, chunk_size=0), "chunk_size is 0"),
    (lambda c: influence2d.dask.audit(POLYGONS, c, chunk_size=2.5), "chunk_size is 2.5"),
    (lambda c: influence2d.dask.audit(POLYGONS[0], c), "geoms: expected a sequence of polygons, got one str"),
    (lambda c: influence2d.dask.audit(POLYGONS + [shapely.geometry.Point(0, 0)], c), f"geoms[{len(POLYGONS)}]"),
    (lambda c: influence2d.dask.audit(POLYGONS + [3], c), f"geoms[{len(POLYGONS)}]"),
    (lambda c: influence2d.dask.pairs([SQUARE]), "client: expected a distributed.Client, got NoneType"),
    (lambda c: influence2d.dask.pairs([SQUARE], client=c, within=-1.0), "distance"),
    (lambda c: influence2d.dask.pairs([SQUARE], client=c, within="far"), "within: expected a number"),
    (lambda c: influence2d.dask.pairs([SQUARE], client=c, number_type="float"), "number_type 'float'"),
    (lambda c: influence2d.dask.pairs([SQUARE], client=c, partitions=0), "partitions is 0"),
    (lambda c: influence2d.dask.pairs([SQUARE], client=c, threads=1.5), "threads is 1.5: expected an integer >= 0"),
    (lambda c: influence2d.dask.pairs([SQUARE], client=c, number_type=None), "number_type is None: expected a name"),
    (lambda c: influence2d.dask.pairs([SQUARE, "POLYGON ((0 0, 1 0))"], client=c), "layer[1]"),
    (lambda c: influence2d.dask.pairs([SQUARE], [SQUARE, None], c), "other[1]"),
    (lambda c: influence2d.dask.pairs(SQUARE, client=c), "layer: expected a sequence of polygons"),
    (lambda c: influence2d.dask.study(families=["convex", "cubic"], client=c), "families[1] is 'cubic'"),
    (lambda c: influence2d.dask.study(families=["convex", "convex"], client=c), "families[1] is 'convex', named twice"),
    (lambda c: influence2d.dask.study(types=["double", "decimal"], client=c), "types[1] is 'decimal'"),
    (lambda c: influence2d.dask.study(queries=["volume"], client=c), "queries[0] is 'volume'"),
    (lambda c: influence2d.dask.study(frames=0, client=c), "frames is 0"),
    (lambda c: influence2d.dask.study(cases=-1, client=c), "cases is -1"),
    (lambda c: influence2d.dask.study(scenes_per_task=0, client=c), "scenes_per_task is 0"),
    (lambda c: influence2d.dask.study(), "client: expected a distributed.Client, got NoneType"),
    (lambda c: influence2d.dask.world_contacts([SQUARE], STEPS, None), "client: expected a distributed.Client"),
    (lambda c: influence2d.dask.world_contacts([SQUARE], STEPS, c, parts=0), "parts is 0"),
    (lambda c: influence2d.dask.world_contacts([SQUARE], STEPS, c, within=-1.0), "distance"),
    (lambda c: influence2d.dask.world_contacts([SQUARE], STEPS, c, number_type="float"), "number_type 'float'"),
    (lambda c: influence2d.dask.world_contacts([SQUARE], STEPS, c, number_type=2), "number_type is 2: expected a name"),
    (lambda c: influence2d.dask.world_contacts([SQUARE], STEPS, c, events="no"), "events is 'no': expected True"),
    (lambda c: influence2d.dask.world_contacts([SQUARE], STEPS, c, within="1"), "within: expected a number, got '1'"),
    (lambda c: influence2d.dask.study(seed=2**64, client=c), f"seed is {2**64}: expected an integer from 0 to"),
    (lambda c: influence2d.dask.world_contacts([SQUARE], STEPS.assign(shape=[0, 1]), c), "row 1, column shape"),
    (lambda c: influence2d.dask.world_contacts([SQUARE, None], STEPS, c), "shapes[1]"),
])
def test_bad_input_is_refused_naming_the_value(client, call, message):
    with pytest.raises(influence2d.InvalidInput) as e:
        call(client)
    assert message in str(e.value)


def test_the_package_does_not_import_distributed():
    code = "import sys, influence2d; assert 'distributed' not in sys.modules; influence2d.dask.pairs"
    subprocess.run([sys.executable, "-c", code], check=True, env=dict(os.environ))


# --- the README --------------------------------------------------------------

def readme_dask_example():
    """The README's Python block that uses influence2d.dask."""
    root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    with open(os.path.join(root, "README.md")) as f:
        blocks = f.read().split("```python\n")[1:]
    found = [b.split("```")[0] for b in blocks if "influence2d.dask" in b]
    assert len(found) == 1, "the README shows one Dask example"
    return found[0]


def test_the_readme_dask_example_runs(tmp_path):
    """As a script of its own (its workers are processes that import it)."""
    (tmp_path / "example.py").write_text(readme_dask_example())
    r = subprocess.run([sys.executable, str(tmp_path / "example.py")], capture_output=True, text=True,
                       cwd=tmp_path, timeout=120)
    assert r.returncode == 0, r.stderr
    assert r.stdout.strip() == "39402 [[10000, 'reversed_orientation']] [720, 720]"
