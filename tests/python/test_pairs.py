# SPDX-License-Identifier: BSL-1.0
"""pairs: the layer join against the exact reference (every pair tested in
rational arithmetic), shapely and the influence2d tool."""

import numpy as np
import pytest
import shapely.affinity
import shapely.geometry

import influence2d
import exact_reference
from conftest import run_tool, star_polygon, tiling_layer


def layer_of(rng, count, spread=6.0):
    """Random star polygons on a dyadic grid, some touching exactly: every
    fourth one a copy of an earlier one translated to share a vertex."""
    layer = []
    for k in range(count):
        if k % 4 == 3:
            # A copy of an earlier polygon moved so that its vertex 0 lands
            # on that polygon's vertex i: they touch at least there.
            src = layer[rng.randrange(len(layer))]
            pts = list(src.exterior.coords)
            i = rng.randrange(1, len(pts) - 1)
            layer.append(shapely.affinity.translate(src, pts[i][0] - pts[0][0], pts[i][1] - pts[0][1]))
        else:
            c = (round(rng.uniform(0, spread) * 64) / 64, round(rng.uniform(0, spread) * 64) / 64)
            layer.append(star_polygon(rng, rng.randint(3, 12), radius=rng.uniform(0.3, 1.0), center=c))
    return layer


def reference_pairs(first, second=None):
    rings_a = [exact_reference.oriented(exact_reference.rings_of(g)) for g in first]
    rings_b = rings_a if second is None else [exact_reference.oriented(exact_reference.rings_of(g)) for g in second]
    out = []
    for i, ra in enumerate(rings_a):
        for j, rb in enumerate(rings_b):
            if (second is not None or j > i) and first[i].envelope.intersects(
                    (first if second is None else second)[j].envelope) and exact_reference.regions_meet(ra, rb):
                out.append((i, j))
    return out


@pytest.mark.parametrize("number_type", ["certified", "exact"])
def test_one_layer_against_the_exact_reference(rng, number_type):
    layer = layer_of(rng, 40)
    got = influence2d.pairs(layer, number_type=number_type)
    assert got.dtype == np.int64 and got.shape[1] == 2
    assert [tuple(p) for p in got.tolist()] == reference_pairs(layer)


def test_two_layers_against_the_exact_reference(rng):
    first, second = layer_of(rng, 25), layer_of(rng, 20)
    got = influence2d.pairs(first, second)
    assert [tuple(p) for p in got.tolist()] == reference_pairs(first, second)


def test_double_agrees_away_from_contact(rng):
    layer = [star_polygon(rng, 8, radius=0.5, center=(rng.uniform(0, 5), rng.uniform(0, 5))) for _ in range(40)]
    want = {(i, j) for i in range(len(layer)) for j in range(i + 1, len(layer)) if layer[i].intersects(layer[j])}
    near = {(i, j) for i in range(len(layer)) for j in range(i + 1, len(layer))
            if layer[i].distance(layer[j]) < 1e-9 and layer[i].intersection(layer[j]).area < 1e-9}
    got = {tuple(p) for p in influence2d.pairs(layer, number_type="double").tolist()}
    assert got - near == want - near


def test_within_against_shapely(rng):
    layer = [star_polygon(rng, 8, radius=0.4, center=(rng.uniform(0, 6), rng.uniform(0, 6))) for _ in range(50)]
    got = {tuple(p) for p in influence2d.pairs(layer, within=0.5).tolist()}
    for i in range(len(layer)):
        for j in range(i + 1, len(layer)):
            d = layer[i].distance(layer[j])
            if abs(d - 0.5) > 1e-9:
                assert ((i, j) in got) == (d <= 0.5)


def test_inputs_of_every_kind_give_the_same_pairs(rng):
    layer = layer_of(rng, 16)
    want = influence2d.pairs(layer).tolist()
    assert influence2d.pairs([g.wkt for g in layer]).tolist() == want
    assert influence2d.pairs([g.wkb for g in layer]).tolist() == want
    assert influence2d.pairs([influence2d.Polygon.from_shapely(g) for g in layer]).tolist() == want
    assert influence2d.pairs(layer, threads=1).tolist() == want


def test_geoseries_when_geopandas_is_there(rng):
    gpd = pytest.importorskip("geopandas")
    layer = layer_of(rng, 16)
    assert influence2d.pairs(gpd.GeoSeries(layer)).tolist() == influence2d.pairs(layer).tolist()


def test_statistics_count_the_candidates_and_the_pairs_answered_again(rng):
    # A row of unit squares exactly 0.5 apart: each neighbour is within 0.5
    # only at the distance itself, a sign certified leaves to rationals.
    row = [shapely.geometry.box(1.5 * k, 0, 1.5 * k + 1, 1) for k in range(5)]
    for number_type, again in [("certified", 4), ("double", 0), ("exact", 0)]:
        got, stats = influence2d.pairs(row, within=0.5, number_type=number_type, return_statistics=True)
        assert got.tolist() == [[0, 1], [1, 2], [2, 3], [3, 4]]
        assert stats == {"candidates": 4, "exact_pairs": again}
    assert influence2d.pairs(row, return_statistics=True)[1] == {"candidates": 0, "exact_pairs": 0}
    # Random stars: the candidates are the pairs whose boxes, each grown by
    # half the distance, meet: apart by at most the distance along x and
    # along y (shapely's bounds; no tie this close); the pairs among them.
    layer = [star_polygon(rng, 7, radius=0.4, center=(rng.uniform(0, 6), rng.uniform(0, 6))) for _ in range(50)]
    bounds = [g.bounds for g in layer]
    gaps = [max(p[0] - q[2], q[0] - p[2], p[1] - q[3], q[1] - p[3])
            for i, p in enumerate(bounds) for q in bounds[i + 1:]]
    assert all(abs(gap - 0.3) > 1e-9 for gap in gaps)
    got, stats = influence2d.pairs(layer, other=None, within=0.3, return_statistics=True)
    assert stats["candidates"] == sum(gap <= 0.3 for gap in gaps) >= len(got)
    assert got.tolist() == influence2d.pairs(layer, within=0.3).tolist()


def test_no_pair_and_empty_layers():
    assert influence2d.pairs([]).shape == (0, 2)
    assert influence2d.pairs(["POLYGON ((0 0, 1 0, 0 1, 0 0))"], []).shape == (0, 2)


@pytest.mark.parametrize("two", [False, True])
def test_matches_the_tool(tool, tmp_path, rng, two):
    first, second = layer_of(rng, 60), layer_of(rng, 30)
    (tmp_path / "a.wkt").write_text("\n".join(g.wkt for g in first) + "\n")
    (tmp_path / "b.wkt").write_text("\n".join(g.wkt for g in second) + "\n")
    args = ["pairs", "--layer", tmp_path / "a.wkt", "--number-type", "certified", "--out", tmp_path / "pairs.csv"]
    if two:
        args += ["--other", tmp_path / "b.wkt"]
    run_tool(tool, *args)
    want = np.loadtxt(tmp_path / "pairs.csv", delimiter=",", skiprows=1, dtype=np.int64, ndmin=2).tolist()
    got = influence2d.pairs(first, second if two else None).tolist()
    assert got == want


def reference_within(first, second, within):
    """The pairs (i, j) (i < j in one layer) whose exact squared distance is
    at most within**2, both layers at their own coordinates."""
    one = second is None
    second = first if one else second
    out = []
    for i, a in enumerate(first):
        for j, b in enumerate(second):
            if one and j <= i:
                continue
            if exact_reference.squared_distance(a, b, (0.0, 0.0, 0.0), within) is not None:
                out.append((i, j))
    return out


@pytest.mark.parametrize("number_type", ["certified", "exact"])
def test_tilings_with_shared_borders_holes_and_islands_against_the_exact_reference(rng, number_type):
    # Neighbours that share their borders to the bit, islands that fill a
    # hole exactly or touch it at a corner, and islands exactly 1/64 (the
    # grid's step) inside a hole: the certified and exact joins are the
    # exact answer at every tie, within 0 and 1/64, one layer and two (each
    # role).
    for _ in range(3):
        layer = tiling_layer(rng, rng.randint(3, 5), rng.randint(3, 5))
        for within in [0.0, 1 / 64]:
            want = reference_within(layer, None, within)
            got = influence2d.pairs(layer, within=within, number_type=number_type)
            assert [tuple(p) for p in got.tolist()] == want
        first, second = layer[0::2], layer[1::2]
        want = reference_within(first, second, 1 / 64)
        assert [tuple(p) for p in influence2d.pairs(first, second, within=1 / 64,
                                                    number_type=number_type).tolist()] == want
        swapped = influence2d.pairs(second, first, within=1 / 64, number_type=number_type).tolist()
        assert sorted((j, i) for i, j in swapped) == want
