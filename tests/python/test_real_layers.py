# SPDX-License-Identifier: BSL-1.0
"""intersects on real neighbours against GEOS (shapely), a reference that
shares nothing with the library, and within d against the rational distance
of exact_reference.py: North Carolina's 100 counties
(data/real/nc_counties.wkt, from r-cran-sf's nc.shp; a tiling whose shared
borders touch exactly) and four countries of Natural Earth's 1:110m map
(data/real/neighbours.wkt), every pair that touches as given, in both roles.

The poses are translations (theta = 0, so that B's posed vertices are
x + tx and y + ty, as shapely.affinity.translate makes them) kept only where
every such sum is exact in double: then GEOS sees the exactly posed polygon,
and its predicates decide exactly on doubles. A translation of about the
coordinates' unit in the last place or less, made of a coarser unit, moves
the shared border by the least amounts the data can express."""

import math
import os
from fractions import Fraction

import numpy as np
import pytest
import shapely.affinity
import shapely.wkt

import influence2d

DATA = os.path.join(os.path.dirname(__file__), "..", "..", "data", "real")


def layer(name):
    with open(os.path.join(DATA, name)) as f:
        return [line.strip() for line in f if line.strip()]


def coordinates(geometry):
    parts = geometry.geoms if geometry.geom_type == "MultiPolygon" else [geometry]
    for p in parts:
        for ring in [p.exterior, *p.interiors]:
            yield from ring.coords


def touching_pairs(geometries):
    """Every ordered pair (i, j), i != j, of geometries that touch as given."""
    n = len(geometries)
    return [(i, j) for i in range(n) for j in range(n) if i != j and geometries[i].touches(geometries[j])]


def near_pairs(geometries, gap):
    """The pairs (i, j), i < j, of geometries apart by less than gap (GEOS's
    distance), nearest first."""
    n = len(geometries)
    found = [(geometries[i].distance(geometries[j]), i, j) for i in range(n) for j in range(i + 1, n)
             if not geometries[i].intersects(geometries[j])]
    return [(i, j) for d, i, j in sorted(found) if d < gap]


def last_place_unit(points):
    """The largest unit in the last place of the points' coordinates."""
    return max(math.ulp(abs(c)) for p in points for c in p)


def turned_about(point, theta):
    """The pose that turns by theta about point (its translation in double,
    so the point lands a hair off where it stood)."""
    px, py = point
    c, s = math.cos(theta), math.sin(theta)
    return (px - (c * px - s * py), py - (s * px + c * py), theta)


def exact_translation(points, tx, ty):
    """Whether x + tx and y + ty round to nothing for every point."""
    ftx, fty = Fraction(tx), Fraction(ty)
    return all(Fraction(x + tx) == Fraction(x) + ftx and Fraction(y + ty) == Fraction(y) + fty for x, y in points)


def translations(rng, points):
    """The identity, and pushes along the axes and in random directions at
    scales from below the coordinates' unit in the last place to 1e-3,
    each a multiple of 2^-k for the scale's k; those not exact dropped."""
    unit = last_place_unit(points)
    out = [(0.0, 0.0)]
    for scale in (unit, 4 * unit, 2.0 ** -30, 1e-6, 1e-3):
        grain = 2.0 ** math.floor(math.log2(scale))
        directions = [(1, 0), (-1, 0), (0, 1), (0, -1)]
        for _ in range(3):
            a = rng.uniform(0, 2 * math.pi)
            directions.append((math.cos(a), math.sin(a)))
        for dx, dy in directions:
            out.append((round(scale * dx / grain) * grain, round(scale * dy / grain) * grain))
    return [t for t in out if exact_translation(points, *t)]


@pytest.mark.parametrize("file", ["nc_counties.wkt", "neighbours.wkt"])
def test_touching_real_neighbours_against_geos(rng, file):
    lines = layer(file)
    geometries = [shapely.wkt.loads(w) for w in lines]
    pairs = touching_pairs(geometries)
    assert len(pairs) >= 4  # both roles of at least two borders
    poses_asked = met = 0
    for i, j in pairs:
        points = list(coordinates(geometries[j]))
        kept = translations(rng, points)
        assert len(kept) >= 20  # the identity and most pushes are exact
        poses = np.array([(tx, ty, 0.0) for tx, ty in kept], dtype=np.float64)
        want = [geometries[i].intersects(shapely.affinity.translate(geometries[j], tx, ty)) for tx, ty in kept]
        assert want[0]  # touching where they stand
        poses_asked += len(kept)
        met += sum(want)
        for number_type in ("certified", "exact", "double"):
            got = influence2d.intersects(lines[i], lines[j], poses, number_type=number_type)
            assert got.tolist() == want, (file, i, j, number_type)
    # Both answers came up often: the pushes cross the shared borders both ways.
    assert 0.2 * poses_asked < met < 0.95 * poses_asked


@pytest.mark.parametrize("file", ["nc_counties.wkt", "neighbours.wkt"])
def test_layer_join_of_real_neighbours_against_geos(file):
    """Every pair that meets in one layer, and between the layer and a copy
    shifted by an exact translation of a few units in the last place (some
    borders then overlap, some part), against GEOS on every pair."""
    lines = layer(file)
    geometries = [shapely.wkt.loads(w) for w in lines]
    points = [p for g in geometries for p in coordinates(g)]
    unit = last_place_unit(points)
    shift = (3 * unit, -2 * unit)
    assert exact_translation(points, *shift)
    moved = [shapely.affinity.translate(g, *shift) for g in geometries]
    n = len(geometries)
    want_one = [[i, j] for i in range(n) for j in range(i + 1, n) if geometries[i].intersects(geometries[j])]
    want_two = [[i, j] for i in range(n) for j in range(n) if geometries[i].intersects(moved[j])]
    assert want_one and want_two
    for number_type in ("certified", "exact", "double"):
        assert influence2d.pairs(lines, number_type=number_type).tolist() == want_one
        assert influence2d.pairs(lines, moved, number_type=number_type).tolist() == want_two


def test_turned_counties_against_the_exact_reference(rng):
    """Counties turned by small angles about a vertex of their shared border
    (the pose's translation in double, so the border's vertices land a hair
    off where they stood, on either side): certified and exact against the
    rational reference of exact_reference.py, which does not use the library."""
    import exact_reference

    lines = layer("nc_counties.wkt")
    geometries = [shapely.wkt.loads(w) for w in lines]
    pairs = touching_pairs(geometries)
    met = asked = 0
    for i, j in rng.sample(pairs, 10):
        shared = list(set(coordinates(geometries[i])) & set(coordinates(geometries[j])))
        assert shared  # the tiling's borders share their vertices
        poses = []
        for theta in (1e-9, -1e-9, 1e-6, -1e-6, 1e-3, -1e-3):
            poses.append(turned_about(rng.choice(shared), theta))
        poses = np.array(poses, dtype=np.float64)
        want = [exact_reference.intersects(geometries[i], geometries[j], p) for p in poses]
        asked += len(want)
        met += sum(want)
        for number_type in ("certified", "exact"):
            got = influence2d.intersects(lines[i], lines[j], poses, number_type=number_type)
            assert got.tolist() == want, (i, j, number_type)
    assert 0 < met < asked  # 53 of 60 meet with the seed of conftest.py


def test_within_a_hair_of_the_exact_distance(rng):
    """Counties that do not touch but come near, asked whether they lie
    within d of each other for d a few units in the last place either side
    of their exact distance (the hardest d there is), posed as given, turned
    about a vertex and moved, in the layer join, the detector and the world
    (both bodies posed); certified and exact against the rational distance
    of exact_reference.py, and separation within a unit in the last place
    of it."""
    import exact_reference

    lines = layer("nc_counties.wkt")
    geometries = [shapely.wkt.loads(w) for w in lines]
    near = near_pairs(geometries, 0.03)
    assert len(near) >= 6
    reach = 0.06
    asked = within = 0
    steps_in_contact = [0, 0]
    for i, j in near[:6]:
        points = list(coordinates(geometries[j]))
        poses = [(0.0, 0.0, 0.0), (0.003, -0.002, 0.0)]
        for theta in (1e-7, -1e-5, 3e-4):
            poses.append(turned_about(rng.choice(points), theta))
        for pose in poses:
            d2 = exact_reference.squared_distance(geometries[i], geometries[j], pose, reach)
            assert d2, (i, j, pose)  # apart, and within reach
            for number_type in ("certified", "exact"):
                got = influence2d.separation(lines[i], lines[j], np.array([pose]), number_type=number_type)[0]
                ulp = Fraction(math.ulp(got))
                assert (Fraction(got) - ulp) ** 2 <= d2 <= (Fraction(got) + ulp) ** 2, (i, j, pose, number_type)
            nearest = math.sqrt(float(d2))
            for k in range(-3, 4):
                d = nearest
                for _ in range(abs(k)):
                    d = math.nextafter(d, math.copysign(math.inf, k))
                want = Fraction(d) ** 2 >= d2
                asked += 1
                within += want
                for number_type in ("certified", "exact"):
                    detector = influence2d.Detector(lines[i], lines[j], number_type=number_type, within=d)
                    assert bool(detector.collide(np.array([pose]))[0]) == want, (i, j, pose, d, number_type)
                    if pose == poses[0]:
                        got = influence2d.pairs([lines[i], lines[j]], within=d, number_type=number_type)
                        assert got.tolist() == ([[0, 1]] if want else []), (i, j, d, number_type)
        # The world poses both bodies, A turned about one of its vertices: a
        # world for each pose at that pose's own distance, and one at the
        # first pose's with B moved along the poses step after step, there
        # and back (each step's contact kept or dropped against the new pose).
        a_pose = turned_about(rng.choice(list(coordinates(geometries[i]))), 2e-6)
        distances = [exact_reference.squared_distance(geometries[i], geometries[j], p, reach, a_pose) for p in poses]
        assert all(distances)
        for number_type in ("certified", "exact"):
            for pose, d2 in zip(poses, distances):
                d = math.sqrt(float(d2))
                world = influence2d.World(number_type=number_type, within=d)
                world.add_bodies(world.add_shapes([lines[i], lines[j]]), [a_pose, pose])
                assert world.step().tolist() == ([[0, 1]] if Fraction(d) ** 2 >= d2 else []), (i, j, pose)
            d = math.sqrt(float(distances[0]))
            world = influence2d.World(number_type=number_type, within=d)
            world.add_bodies(world.add_shapes([lines[i], lines[j]]), [a_pose, poses[0]])
            for k in [*range(len(poses)), *reversed(range(len(poses) - 1))]:
                world.move([1], [poses[k]])
                want = [[0, 1]] if Fraction(d) ** 2 >= distances[k] else []
                assert world.step().tolist() == want, (i, j, poses[k], number_type)
                steps_in_contact[bool(want)] += 1
    # d fell on both sides of the distance, and the moving world's contacts
    # came and went.
    assert 0.3 * asked < within < 0.7 * asked
    assert min(steps_in_contact) > 0, steps_in_contact


def test_first_contact_of_real_neighbours_against_the_exact_reference():
    """Counties that come near, the second moved 0.1 degrees towards the
    first's centroid while turning by 0, 1e-4 or -2e-3 rad (the rational
    model: exact in certified and exact): the time of first contact is the
    double nearest the exact one, so the exact reference finds them apart
    one double before it and meeting one after (moving on into A)."""
    import exact_reference

    lines = layer("nc_counties.wkt")
    geometries = [shapely.wkt.loads(w) for w in lines]
    for i, j in near_pairs(geometries, 0.03)[:4]:
        a, b = geometries[i].centroid, geometries[j].centroid
        length = math.hypot(a.x - b.x, a.y - b.y)
        start = (0.0, 0.0, 0.0)
        for theta in (0.0, 1e-4, -2e-3):
            end = ((a.x - b.x) / length * 0.1, (a.y - b.y) / length * 0.1, theta)
            for number_type in ("certified", "exact"):
                contact, t = influence2d.first_contact(lines[i], lines[j], np.array([start]), np.array([end]),
                                                       number_type=number_type, motion="rational")
                assert contact[0], (i, j, theta, number_type)
                assert 0 < t[0] < 1
                before, after = math.nextafter(t[0], 0), math.nextafter(t[0], 1)
                assert not exact_reference.meet_in_rational_turn(geometries[i], geometries[j], start, end, before)
                assert exact_reference.meet_in_rational_turn(geometries[i], geometries[j], start, end, after)
