# SPDX-License-Identifier: BSL-1.0
"""intersects, Detector, separation and first_contact against the exact
reference (exact_reference.py, rational arithmetic without the library),
shapely away from contact, and the influence2d tool of the same build."""

import functools
import math

import numpy as np
import pytest
import shapely.affinity
import shapely.geometry
import shapely.wkt

import influence2d
import exact_reference
from conftest import random_poses, star_polygon, tool_frames

EXACT_TYPES = ("certified", "exact")


def shapely_posed(b, pose):
    tx, ty, theta = pose
    return shapely.affinity.translate(shapely.affinity.rotate(b, theta, origin=(0, 0), use_radians=True), tx, ty)


def touching_poses(rng, a, b, count):
    """Translations (theta = 0, dyadic) putting a vertex of B on a vertex or
    an edge midpoint of A, then pushed by 0 or +-2^-20 along a random axis:
    exact contacts and the nearest misses and overlaps."""
    a_pts = list(a.exterior.coords)[:-1]
    b_pts = list(b.exterior.coords)[:-1]
    poses = []
    for _ in range(count):
        i = rng.randrange(len(a_pts))
        p = a_pts[i]
        if rng.random() < 0.5:
            q = a_pts[(i + 1) % len(a_pts)]
            p = ((p[0] + q[0]) / 2, (p[1] + q[1]) / 2)
        v = b_pts[rng.randrange(len(b_pts))]
        push = rng.choice([0.0, 2.0 ** -20, -(2.0 ** -20)])
        axis = rng.randrange(2)
        poses.append((p[0] - v[0] + (push if axis == 0 else 0.0), p[1] - v[1] + (push if axis == 1 else 0.0), 0.0))
    return np.array(poses, dtype=np.float64)


@pytest.mark.parametrize("number_type", EXACT_TYPES)
def test_intersects_exact_at_touching_translations(rng, number_type):
    for _ in range(8):
        a = star_polygon(rng, rng.randint(3, 16))
        b = star_polygon(rng, rng.randint(3, 16), radius=0.6)
        poses = touching_poses(rng, a, b, 40)
        got = influence2d.intersects(a, b, poses, number_type=number_type)
        want = [exact_reference.intersects(a, b, p) for p in poses]
        assert got.tolist() == want


@pytest.mark.parametrize("number_type", EXACT_TYPES)
def test_intersects_exact_at_random_turned_poses(np_rng, rng, number_type):
    a = star_polygon(rng, 12)
    b = star_polygon(rng, 9, radius=0.7)
    poses = random_poses(np_rng, 200, 2, 4)
    got = influence2d.intersects(a, b, poses, number_type=number_type)
    assert got.tolist() == [exact_reference.intersects(a, b, p) for p in poses]


def test_intersects_agrees_with_shapely_away_from_contact(np_rng, rng):
    a = star_polygon(rng, 20)
    b = star_polygon(rng, 12, radius=0.5)
    poses = random_poses(np_rng, 300, 2, 4)
    for number_type in ("double", "certified", "exact"):
        got = influence2d.intersects(a, b, poses, number_type=number_type)
        for k, p in enumerate(poses):
            posed = shapely_posed(b, p)
            if a.distance(posed) > 1e-9 or a.intersection(posed).area > 1e-9:
                assert got[k] == a.intersects(posed), (number_type, k, p)


def test_intersects_degenerate_scenes():
    ring = "POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0), (1 1, 1 3, 3 3, 3 1, 1 1))"
    small = "POLYGON ((0 0, 1 0, 1 1, 0 1, 0 0))"
    cases = [
        ((4.0, 0.0, 0.0), True),     # edge on edge
        ((4.0, 4.0, 0.0), True),     # vertex on vertex
        ((4.0, 4.5, 0.0), False),    # beside, clear
        ((1.5, 1.5, 0.0), False),    # inside the hole, not touching it
        ((1.0, 1.5, 0.0), True),     # inside the hole, touching its edge
        ((0.5, 0.0, 0.0), True),     # overlapping the outer ring
        ((2.0, 1.5, math.pi / 4), False),  # turned inside the hole
    ]
    poses = np.array([p for p, _ in cases])
    want = [w for _, w in cases]
    for number_type in ("double", "certified", "exact"):
        assert influence2d.intersects(ring, small, poses, number_type=number_type).tolist() == want
    a, b = shapely.wkt.loads(ring), shapely.wkt.loads(small)
    assert [exact_reference.intersects(a, b, p) for p in poses] == want


def test_nested_and_multipolygons():
    outer = "MULTIPOLYGON (((0 0, 10 0, 10 10, 0 10, 0 0), (2 2, 2 8, 8 8, 8 2, 2 2)), ((4 4, 6 4, 6 6, 4 6, 4 4)))"
    b = "POLYGON ((0 0, 0.5 0, 0.5 0.5, 0 0.5, 0 0))"
    poses = np.array([[3.0, 3.0, 0.0], [4.5, 4.5, 0.0], [6.0, 6.0, 0.0], [6.25, 6.25, 0.0], [-1, -1, 0.0]])
    want = [False, True, True, False, False]
    for number_type in ("double", "certified", "exact"):
        assert influence2d.intersects(outer, b, poses, number_type=number_type).tolist() == want
    a, bb = shapely.wkt.loads(outer), shapely.wkt.loads(b)
    assert [exact_reference.intersects(a, bb, p) for p in poses] == want


def test_role_swap_gives_the_same_answers(rng):
    """A meets B translated by t exactly when B meets A translated by -t."""
    for _ in range(5):
        a = star_polygon(rng, 10)
        b = star_polygon(rng, 7, radius=0.5)
        poses = touching_poses(rng, a, b, 40)
        swapped = np.column_stack([-poses[:, 0], -poses[:, 1], poses[:, 2]])
        assert (influence2d.intersects(a, b, poses).tolist()
                == influence2d.intersects(b, a, swapped).tolist())


def test_threads_do_not_change_the_answers(np_rng, rng):
    a = star_polygon(rng, 30)
    b = star_polygon(rng, 30, radius=0.8)
    poses = random_poses(np_rng, 2000, 2, 4)
    one = influence2d.intersects(a, b, poses, threads=1)
    assert (influence2d.intersects(a, b, poses, threads=0) == one).all()
    assert (influence2d.intersects(a, b, poses, threads=3) == one).all()
    assert (influence2d.Detector(a, b, number_type="certified").collide(poses) == one).all()


def test_arrays_unpickled_are_taken_as_they_are(np_rng, rng):
    # An array that crossed a pickle (a Dask task's, a multiprocessing
    # worker's) holds a float64 dtype equal to numpy's but not the same
    # object; it was once refused as "expected dtype float64, got float64".
    import pickle
    a, b = star_polygon(rng, 9), star_polygon(rng, 7)
    poses = random_poses(np_rng, 50, 1.5, math.pi)
    back = pickle.loads(pickle.dumps(poses, protocol=5))
    assert (influence2d.intersects(a, b, back) == influence2d.intersects(a, b, poses)).all()
    assert (influence2d.Detector(a, b).collide(back) == influence2d.Detector(a, b).collide(poses)).all()
    coords = pickle.loads(pickle.dumps(np.array(a.exterior.coords), protocol=5))
    assert influence2d.Polygon.from_coords(coords, np.array([0, len(coords)])).num_vertices == len(coords) - 1


def test_empty_pose_array():
    out = influence2d.intersects("POLYGON ((0 0, 1 0, 0 1, 0 0))", "POLYGON ((0 0, 1 0, 0 1, 0 0))",
                                 np.zeros((0, 3)))
    assert out.shape == (0,) and out.dtype == bool


@pytest.mark.parametrize("number_type", ["double", "certified", "exact"])
def test_intersects_matches_the_tool(tool, tmp_path, rng, number_type):
    a = star_polygon(rng, 24)
    b = star_polygon(rng, 16, radius=0.7)
    poses = np.concatenate([touching_poses(rng, a, b, 100),
                            np.array([[rng.uniform(-2, 2), rng.uniform(-2, 2), rng.uniform(-3, 3)] for _ in range(100)])])
    want = [row[1] == "1" for row in tool_frames(tool, tmp_path, a, b, poses, "--number-type", number_type)]
    assert influence2d.intersects(a, b, poses, number_type=number_type).tolist() == want
    assert influence2d.Detector(a, b, number_type=number_type).collide(poses).tolist() == want


def test_detector_witness_matches_the_tool(tool, tmp_path, rng):
    a = star_polygon(rng, 12)
    b = star_polygon(rng, 8, radius=0.7)
    poses = touching_poses(rng, a, b, 30)
    rows = tool_frames(tool, tmp_path, a, b, poses, "--number-type", "certified", "--witness", "--distance", "0.01")
    d = influence2d.Detector(a, b, number_type="certified", within=0.01)
    dw = influence2d.Detector(a, b, number_type="certified", within=0.01, witness=True)
    for (_, collides, edges), pose in zip(rows, poses):
        want = [tuple(map(int, e.split(":"))) for e in edges.split(";")] if edges else []
        assert d.witness(pose) == want
        assert dw.witness(pose) == want


@pytest.mark.parametrize("number_type", ["double", "certified", "exact"])
def test_detector_witnesses_in_a_batch_match_the_tool(tool, tmp_path, rng, number_type):
    a = star_polygon(rng, 12)
    b = star_polygon(rng, 8, radius=0.7)
    # Poses that touch, overlap deeply (B inside A: containment alone) and
    # lie apart, mixed.
    poses = np.concatenate([touching_poses(rng, a, b, 40), np.array([[0.0, 0.0, 0.3], [5.0, 5.0, 0.0]]),
                            np.array([[rng.uniform(-2, 2), rng.uniform(-2, 2), rng.uniform(-3, 3)] for _ in range(40)])])
    rng.shuffle(poses)
    rows = tool_frames(tool, tmp_path, a, b, poses, "--number-type", number_type, "--witness", "--distance", "0.01")
    want_collides = [cols[1] == "1" for cols in rows]
    want_pairs = [[k, *map(int, e.split(":"))]
                  for k, cols in enumerate(rows) if cols[2] for e in cols[2].split(";")]
    assert 0 < len(want_pairs) and any(c and not cols[2] for c, cols in zip(want_collides, rows))
    for witness in (False, True):
        d = influence2d.Detector(a, b, number_type=number_type, within=0.01, witness=witness)
        collides, pairs = d.witnesses(poses)
        assert collides.dtype == bool and pairs.dtype == np.int64 and pairs.shape == (len(want_pairs), 3)
        assert collides.tolist() == want_collides
        assert pairs.tolist() == want_pairs
        # Split in two calls, in order: the same rows, numbered per call.
        first, second = d.witnesses(poses[:30]), d.witnesses(poses[30:])
        assert first[0].tolist() + second[0].tolist() == want_collides
        assert first[1].tolist() + [[k + 30, s, m] for k, s, m in second[1].tolist()] == want_pairs
        assert d.collide(poses).tolist() == want_collides
    empty = influence2d.Detector(a, b).witnesses(np.zeros((0, 3)))
    assert empty[0].shape == (0,) and empty[1].shape == (0, 3)


@pytest.mark.parametrize("number_type", EXACT_TYPES)
def test_detector_witnesses_are_the_exactly_meeting_edges(rng, number_type):
    # The exact reference: every edge pair of A and posed B that shares a
    # point, in rationals (edge k of the input ring order from vertex k).
    a = star_polygon(rng, 10)
    b = star_polygon(rng, 7, radius=0.6)
    poses = np.concatenate([touching_poses(rng, a, b, 40),
                            np.array([[rng.uniform(-1.5, 1.5), rng.uniform(-1.5, 1.5), rng.uniform(-3, 3)]
                                      for _ in range(40)])])
    a_ring = exact_reference.rings_of(a)[0][0]
    b_ring = exact_reference.rings_of(b)[0][0]
    collides, pairs = influence2d.Detector(a, b, number_type=number_type).witnesses(poses)
    for k, pose in enumerate(poses):
        posed = exact_reference.posed([b_ring], pose)[0]
        want = [[k, i, j] for i in range(len(a_ring)) for j in range(len(posed))
                if exact_reference.segments_meet(a_ring[i], a_ring[(i + 1) % len(a_ring)], posed[j],
                                                 posed[(j + 1) % len(posed)])]
        assert pairs[pairs[:, 0] == k].tolist() == want, f"pose {k}: {pose.tolist()}"
        assert collides[k] == exact_reference.intersects(a, b, pose)


def test_detector_within_is_a_distance():
    d = influence2d.Detector("POLYGON ((0 0, 1 0, 1 1, 0 1, 0 0))", "POLYGON ((0 0, 1 0, 1 1, 0 1, 0 0))",
                             within=0.25, number_type="exact")
    assert d.collide([[1.25, 0, 0], [1.2500001, 0, 0]]).tolist() == [True, False]


def test_separation_against_shapely_and_the_tool(tool, tmp_path, rng, np_rng):
    a = star_polygon(rng, 16)
    b = star_polygon(rng, 10, radius=0.5)
    poses = random_poses(np_rng, 100, 3, 3)
    for number_type in ("double", "certified", "exact"):
        d = influence2d.separation(a, b, poses, number_type=number_type)
        for k, p in enumerate(poses):
            assert d[k] == pytest.approx(a.distance(shapely_posed(b, p)), rel=1e-9, abs=1e-12)
    rows = tool_frames(tool, tmp_path, a, b, poses, "--number-type", "certified", "--separation", "--witness")
    f = influence2d.separation(a, b, poses, features=True)
    names = {"vertex": "v", "edge": "e"}
    for k, cols in enumerate(rows):
        assert float(cols[3]) == f["distance"][k]
        ours = [names.get(f["static_kind"][k], "interior") + (str(f["static_index"][k]) if f["static_index"][k] >= 0 else ""),
                names.get(f["moving_kind"][k], "interior") + (str(f["moving_index"][k]) if f["moving_index"][k] >= 0 else "")]
        assert cols[4] == ":".join(ours)


def test_separation_features_exact_case():
    f = influence2d.separation("POLYGON ((0 0, 2 0, 2 2, 0 2, 0 0))", "POLYGON ((0 0, 1 0, 1 1, 0 1, 0 0))",
                               [[3.0, 3.0, 0.0]], features=True)
    assert math.isclose(f["distance"][0], math.sqrt(2), rel_tol=1e-15)
    assert (f["static_kind"][0], f["static_index"][0]) == ("vertex", 2)
    assert (f["moving_kind"][0], f["moving_index"][0]) == ("vertex", 0)
    assert f["static_point"][0].tolist() == [2.0, 2.0]
    assert f["moving_point"][0].tolist() == [3.0, 3.0]


def test_first_contact_translations_exact():
    a = "POLYGON ((0 0, 2 0, 2 2, 0 2, 0 0))"
    b = "POLYGON ((0 0, 1 0, 1 1, 0 1, 0 0))"
    start = np.array([[5.0, 0.0, 0.0], [5.0, 3.0, 0.0], [1.0, 1.0, 0.0], [-3.0, 2.0, 0.0]])
    end = np.array([[0.0, 0.0, 0.0], [0.0, 3.0, 0.0], [9.0, 9.0, 0.0], [3.0, 2.0, 0.0]])
    for number_type in ("double", "certified", "exact"):
        contact, t = influence2d.first_contact(a, b, start, end, number_type=number_type)
        assert contact.tolist() == [True, False, True, True]
        assert t[0] == 3 / 5 and math.isnan(t[1]) and t[2] == 0.0 and t[3] == 1 / 3


def test_first_contact_matches_the_tool(tool, tmp_path, rng):
    a = star_polygon(rng, 12)
    b = star_polygon(rng, 8, radius=0.5)
    poses = np.array([[rng.uniform(-3, 3), rng.uniform(-3, 3), 0.0] for _ in range(41)])
    rows = tool_frames(tool, tmp_path, a, b, poses, "--number-type", "certified", "--continuous")
    contact, t = influence2d.first_contact(a, b, poses[:-1], poses[1:])
    for k, cols in enumerate(rows[1:]):
        assert (cols[2] != "") == contact[k]
        if contact[k]:
            assert float(cols[2]) == t[k]


def turning_motions(np_rng, count):
    """Motions that start 1.7 to 2.6 from A's origin, move toward it by up to
    1.2 and turn by up to 1.5 turns (pieces of a quarter turn and more): most
    meet A on the way, few at the start."""
    r, phi = np_rng.uniform(1.7, 2.6, count), np_rng.uniform(0, 2 * np.pi, count)
    theta = np_rng.uniform(-3, 3, count)
    start = np.column_stack([r * np.cos(phi), r * np.sin(phi), theta])
    closer = 1 - np_rng.uniform(0, 1.2, count) / r
    end = np.column_stack([start[:, 0] * closer, start[:, 1] * closer, theta + np_rng.uniform(-9.5, 9.5, count)])
    return start, end


def test_first_contact_rational_model_against_exact_reference(np_rng, rng):
    """The rational model's contact, checked without the library
    (exact_reference.meet_in_rational_turn): apart at the double before the
    reported time and at 12 times sampled before it, meeting at the double
    after it; a motion reported free is apart at 25 sampled times. The
    certified and exact types give the same answers; double the same yes/no
    here; angle-linear gives other times."""
    a = star_polygon(rng, 12)
    b = star_polygon(rng, 8, radius=0.6)
    start, end = turning_motions(np_rng, 40)
    contact, t = influence2d.first_contact(a, b, start, end, motion="rational")
    contact_x, t_x = influence2d.first_contact(a, b, start, end, number_type="exact", motion="rational")
    assert (contact == contact_x).all() and np.array_equal(t, t_x, equal_nan=True)
    meet = functools.partial(exact_reference.meet_in_rational_turn, a, b)
    later = 0
    for k in range(len(start)):
        s, e = start[k], end[k]
        if not contact[k]:
            assert not any(meet(s, e, x) for x in np.linspace(0, 1, 25))
            continue
        if t[k] == 0:
            assert meet(s, e, 0.0)
            continue
        later += 1
        assert meet(s, e, np.nextafter(t[k], 2.0))
        assert not meet(s, e, np.nextafter(t[k], -1.0))
        assert not any(meet(s, e, x) for x in np.linspace(0, t[k], 12, endpoint=False))
    assert later >= 8 and (~contact).sum() >= 2
    contact_d, _ = influence2d.first_contact(a, b, start, end, number_type="double", motion="rational")
    assert (contact_d == contact).all()
    _, t_linear = influence2d.first_contact(a, b, start, end)
    assert (t_linear[contact & (t > 0)] != t[contact & (t > 0)]).any()


def test_first_contact_rational_matches_the_tool(tool, tmp_path, rng):
    a = star_polygon(rng, 12)
    b = star_polygon(rng, 8, radius=0.5)
    poses = np.array([[rng.uniform(-3, 3), rng.uniform(-3, 3), rng.uniform(-6, 6)] for _ in range(31)])
    rows = tool_frames(tool, tmp_path, a, b, poses, "--number-type", "certified", "--continuous", "--motion",
                       "rational")
    contact, t = influence2d.first_contact(a, b, poses[:-1], poses[1:], motion="rational")
    assert contact.sum() >= 3
    for k, cols in enumerate(rows[1:]):
        assert (cols[2] != "") == contact[k]
        if contact[k]:
            assert float(cols[2]) == t[k]


def test_first_contact_step_limit_leaves_a_grazing_motion_undecided():
    """A unit square slides 1.04e-9 above a 4 x 4 square (notched below, so
    not convex) while turning by 1e-12: just beyond where the probes stop
    (the tolerance, 1e-9, and double's error bound), within max_steps the
    advancement cannot decide (no contact before the time it reached); the
    rational model answers no contact. 3e-9 above, the swept boxes decide
    it without a step, apart. Without the notch the two convex polygons
    step by their vertices' own approach and decide it, apart."""
    a = "POLYGON ((0 0, 1.5 0, 1.5 1, 2.5 1, 2.5 0, 4 0, 4 4, 0 4, 0 0))"
    b = "POLYGON ((-0.5 -0.5, 0.5 -0.5, 0.5 0.5, -0.5 0.5, -0.5 -0.5))"
    far_start = np.array([[-2.0, 4.5 + 3e-9, 0.0]])
    far_end = np.array([[6.0, 4.5 + 3e-9, 1e-12]])
    for number_type in ("double", "certified", "exact"):
        contact, t, undecided = influence2d.first_contact(a, b, far_start, far_end, number_type=number_type,
                                                          max_steps=1000, undecided=True)
        assert contact.tolist() == [False] and undecided.tolist() == [False]
    start = np.array([[-2.0, 4.5 + 1.04e-9, 0.0], [-2.0, 2.0, 0.0]])
    end = np.array([[6.0, 4.5 + 1.04e-9, 1e-12], [6.0, 2.0, 1.0]])
    for number_type in ("double", "certified", "exact"):
        contact, t, undecided = influence2d.first_contact(a, b, start, end, number_type=number_type, max_steps=1000,
                                                          undecided=True)
        assert contact.tolist() == [False, True] and undecided.tolist() == [True, False]
        assert 0.1875 < t[0] < 0.19  # B's right side passes over A's corner at 0.1875
        contact, t = influence2d.first_contact(a, b, start, end, number_type=number_type, max_steps=1000)
        assert math.isnan(t[0]) and not contact[0]
    contact, t = influence2d.first_contact(a, b, start, end, motion="rational")
    assert contact.tolist() == [False, True]
    square = "POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0))"
    for number_type in ("double", "certified", "exact"):
        contact, t, undecided = influence2d.first_contact(square, b, start, end, number_type=number_type,
                                                          max_steps=20, undecided=True)
        assert contact.tolist() == [False, True] and undecided.tolist() == [False, False]


def test_detector_keeps_its_state_across_calls(np_rng, rng):
    """Frames split over many calls answer as one call (and as intersects)."""
    a = star_polygon(rng, 40)
    b = star_polygon(rng, 20, radius=0.6)
    steps = np.linspace(0, 1, 600)
    poses = np.column_stack([2.5 * np.cos(6 * steps), 2.5 * np.sin(4 * steps), 3 * steps])
    for number_type in ("double", "certified"):
        d = influence2d.Detector(a, b, number_type=number_type)
        split = np.concatenate([d.collide(poses[k:k + 37]) for k in range(0, len(poses), 37)])
        assert (split == influence2d.Detector(a, b, number_type=number_type).collide(poses)).all()
    assert (split == influence2d.intersects(a, b, poses)).all()


@pytest.mark.parametrize("e", [-600, -300, 300, 600])
def test_double_far_from_one_in_scale(rng, np_rng, e):
    """Every coordinate times 2^e: double answers as at scale 1 (its query
    scaled into its range first), its distances times 2^e exactly."""
    a = star_polygon(rng, 16)
    b = star_polygon(rng, 10, radius=0.5)
    poses = random_poses(np_rng, 100, 3, 3)
    s = 2.0 ** e
    a_s = shapely.affinity.scale(a, s, s, origin=(0, 0))
    b_s = shapely.affinity.scale(b, s, s, origin=(0, 0))
    poses_s = poses.copy()
    poses_s[:, :2] *= s
    meet = influence2d.intersects(a, b, poses, number_type="double")
    assert 0 < meet.sum() < len(poses)
    assert influence2d.intersects(a_s, b_s, poses_s, number_type="double").tolist() == meet.tolist()
    d = influence2d.separation(a, b, poses, number_type="double")
    assert influence2d.separation(a_s, b_s, poses_s, number_type="double").tolist() == (d * s).tolist()
    ends = np.roll(poses, 1, axis=0)
    ends[:, 2] = poses[:, 2]
    ends_s = ends.copy()
    ends_s[:, :2] *= s
    contact, t = influence2d.first_contact(a, b, poses, ends, number_type="double")
    contact_s, t_s = influence2d.first_contact(a_s, b_s, poses_s, ends_s, number_type="double")
    assert contact_s.tolist() == contact.tolist()
    assert np.array_equal(t_s, t, equal_nan=True)
