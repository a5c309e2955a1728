# SPDX-License-Identifier: BSL-1.0
"""Polygon: reading WKT, WKB, shapely and GeoArrow coordinates, writing WKT,
shapely round trips, pickling."""

import pickle

import numpy as np
import pytest
import shapely.geometry
import shapely.wkb
import shapely.wkt

import influence2d
from influence2d import InvalidInput, Polygon

from conftest import star_polygon

SQUARE_WITH_HOLE = "POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0), (1 1, 1 3, 3 3, 3 1, 1 1))"


def test_from_wkt_counts_vertices_and_rings():
    p = Polygon.from_wkt(SQUARE_WITH_HOLE)
    assert (p.num_vertices, p.num_rings, p.bounds) == (8, 2, (0.0, 0.0, 4.0, 4.0))


def test_multipolygon():
    p = Polygon.from_wkt("MULTIPOLYGON (((0 0, 1 0, 0 1, 0 0)), ((5 5, 6 5, 6 6, 5 6, 5 5), (5.2 5.2, 5.2 5.8, 5.8 5.8, 5.8 5.2, 5.2 5.2)))")
    assert (p.num_vertices, p.num_rings) == (11, 3)


def test_to_wkt_reads_back_the_same_polygon():
    p = Polygon.from_wkt(SQUARE_WITH_HOLE)
    q = Polygon.from_wkt(p.to_wkt())
    assert q.to_wkt() == p.to_wkt()
    assert shapely.wkt.loads(p.to_wkt()).equals(shapely.wkt.loads(SQUARE_WITH_HOLE))


def test_shapely_round_trip_keeps_every_coordinate(rng):
    for _ in range(20):
        g = star_polygon(rng, rng.randint(3, 30), radius=rng.uniform(0.1, 1e6))
        g = shapely.affinity.translate(g, rng.uniform(-1e3, 1e3) / 3, rng.uniform(-1e3, 1e3) / 7)
        p = Polygon.from_shapely(g)
        back = p.to_shapely()
        assert back.equals_exact(shapely.geometry.polygon.orient(g, 1.0), 0.0)
        assert Polygon.from_wkb(g.wkb).to_wkt() == p.to_wkt()


def test_a_layer_of_shapely_geometries_reads_as_each_one_alone(rng):
    layer = [star_polygon(rng, rng.randint(3, 30), radius=rng.uniform(0.1, 1e6)) for _ in range(20)]
    layer += [shapely.wkt.loads(SQUARE_WITH_HOLE),
              shapely.wkt.loads("MULTIPOLYGON (((0 0, 1 0, 0 1, 0 0)), ((5 5, 6 5, 5 6, 5 5)))")]
    together = influence2d.as_polygons(layer)
    assert [p.to_wkt() for p in together] == [Polygon.from_shapely(g).to_wkt() for g in layer]


def test_from_wkb_both_byte_orders():
    g = shapely.wkt.loads(SQUARE_WITH_HOLE)
    little = Polygon.from_wkb(shapely.wkb.dumps(g, big_endian=False))
    big = Polygon.from_wkb(shapely.wkb.dumps(g, big_endian=True))
    srid = Polygon.from_wkb(shapely.wkb.dumps(g, srid=4326))
    assert little.to_wkt() == big.to_wkt() == srid.to_wkt()


def test_from_coords_geoarrow_layout():
    coords = np.array([[0, 0], [4, 0], [4, 4], [0, 4], [0, 0], [1, 1], [1, 3], [3, 3], [3, 1], [1, 1],
                       [10, 10], [11, 10], [10, 11], [10, 10]], dtype=np.float64)
    p = Polygon.from_coords(coords, np.array([0, 5, 10, 14], dtype=np.int32), [0, 2, 3])
    assert (p.num_vertices, p.num_rings) == (11, 3)
    assert shapely.wkt.loads(p.to_wkt()).equals(shapely.wkt.loads(
        "MULTIPOLYGON (((0 0, 4 0, 4 4, 0 4, 0 0), (1 1, 1 3, 3 3, 3 1, 1 1)), ((10 10, 11 10, 10 11, 10 10)))"))


def test_from_coords_reads_strided_arrays_in_place():
    xy = np.array([[0, 0, 9], [2, 0, 9], [2, 2, 9], [0, 2, 9]], dtype=np.float64)[:, :2]
    assert not xy.flags.c_contiguous
    assert Polygon.from_coords(xy, [0, 4]).to_wkt() == "POLYGON((0 0,2 0,2 2,0 2,0 0))"


def test_shapely_geometries_are_accepted_wherever_a_polygon_is():
    a = shapely.geometry.box(0, 0, 2, 2)
    poses = np.array([[1.0, 1.0, 0.0], [3.0, 0.0, 0.0]])
    for b in (shapely.geometry.box(0, 0, 1, 1), "POLYGON ((0 0, 1 0, 1 1, 0 1, 0 0))",
              shapely.geometry.box(0, 0, 1, 1).wkb, Polygon.from_wkt("POLYGON ((0 0, 1 0, 1 1, 0 1, 0 0))")):
        assert influence2d.intersects(a, b, poses).tolist() == [True, False]


def test_pickle_keeps_the_rings_as_given():
    p = Polygon.from_wkt("POLYGON ((0 0, 0 1, 1 1, 1 0, 0 0))")
    q = pickle.loads(pickle.dumps(p))
    assert q.to_wkt() == p.to_wkt()
    assert influence2d.audit(q) == influence2d.audit(p)


def test_pickle_of_multipolygons_with_holes_round_trips():
    p = Polygon.from_wkt("MULTIPOLYGON (((0 0, 4 0, 4 4, 0 4, 0 0), (1 1, 1 2, 2 2, 2 1, 1 1)),"
                         " ((10 10, 11 10, 10 11, 10 10)))")
    q = pickle.loads(pickle.dumps(p))
    assert q.to_wkt() == p.to_wkt()
    assert q.num_rings == 3 and q.num_vertices == p.num_vertices


@pytest.mark.parametrize("state, message", [
    ((b"\x00", b"\x05" + bytes(7), bytes(16)), "runs past the coordinates"),
    ((b"", b"", b"x"), "left over"),
    ((b"\x00",), "expected 3 byte strings"),
    ((b"\x00\x00", bytes(8), bytes(0)), "2 rings but 8 bytes of counts"),
])
def test_a_corrupt_pickle_is_refused(state, message):
    from influence2d import _core
    fresh = _core.Polygon.__new__(_core.Polygon)
    with pytest.raises(InvalidInput, match=message):
        fresh.__setstate__(state)


def test_repr_names_the_wkt():
    assert "POLYGON((0 0,1 0,0 1,0 0))" in repr(Polygon.from_wkt("POLYGON ((0 0, 1 0, 0 1, 0 0))"))


def test_direct_construction_is_refused():
    with pytest.raises(TypeError):
        Polygon("POLYGON ((0 0, 1 0, 0 1, 0 0))")
