# SPDX-License-Identifier: BSL-1.0
"""Bad input: every case raises InvalidInput (a ValueError) naming the value
and its index; nothing crashes."""

import math

import numpy as np
import pytest
import shapely.geometry
import shapely.wkt

import influence2d
from influence2d import InvalidInput, Polygon

A = "POLYGON ((0 0, 2 0, 2 2, 0 2, 0 0))"
B = "POLYGON ((0 0, 1 0, 1 1, 0 1, 0 0))"


def raises(match, f, *args, **kwargs):
    with pytest.raises(InvalidInput, match=match) as e:
        f(*args, **kwargs)
    assert isinstance(e.value, ValueError)
    return str(e.value)


def test_invalid_input_is_a_value_error():
    assert issubclass(InvalidInput, ValueError)


@pytest.mark.parametrize("value, name", [(math.nan, "nan"), (math.inf, "inf"), (-math.inf, "-inf")])
@pytest.mark.parametrize("column", [0, 1, 2])
def test_non_finite_poses_name_row_and_component(value, name, column):
    poses = np.zeros((5, 3))
    poses[3, column] = value
    component = ["tx", "ty", "theta"][column]
    for f in (influence2d.intersects, influence2d.separation):
        raises(rf"poses\[3, {column}\] \({component}\) is {name}", f, A, B, poses)
    raises(r"poses\[3", influence2d.Detector(A, B).collide, poses)
    raises(r"end_poses\[3", influence2d.first_contact, A, B, np.zeros((5, 3)), poses)


@pytest.mark.parametrize("poses, message", [
    (np.zeros((4, 2)), r"shape \(4, 2\)"),
    (np.zeros((2,)), r"shape \(2,\)"),
    (np.zeros((2, 3, 1)), r"shape \(2, 3, 1\)"),
    (np.zeros((4, 3), dtype=np.float32), "float32"),
    (np.zeros((4, 3), dtype=np.int64), "int64"),
    (np.zeros((3, 4))[:, :3], "C-contiguous"),
    ([[1, 2]], r"shape \(1, 2\)"),
    ("abc", "not an array of numbers"),
])
def test_wrong_pose_arrays(poses, message):
    raises(message, influence2d.intersects, A, B, poses)


def test_the_extension_refuses_what_it_would_have_to_copy():
    p = influence2d.Polygon.from_wkt(A)._p
    raises("float64", influence2d._core.intersects, p, p, np.zeros((2, 3), dtype=np.float32), "certified", 0)
    raises("C-contiguous", influence2d._core.intersects, p, p, np.asfortranarray(np.zeros((4, 3))), "certified", 0)


@pytest.mark.parametrize("wkt, message", [
    ("POLYGON ((0 0, 1 0, 0 1))", "ring 0 is not closed"),
    ("POLYGON ((0 0, 1 0, 0 0))", "ring 0: fewer than three distinct vertices"),
    ("POLYGON ((0 0, 1 0, 1 0, 0 0))", "fewer than three distinct vertices"),
    ("POLYGON EMPTY", "empty"),
    ("POLYGON ((0 0, 1 0, nan 1, 0 0))", r"ring 0, vertex 2"),
    ("POLYGON ((0 0, 1 0, 0 1, 0 0), (0.1 0.1, 0.2 0.1, 0.1 0.1))", "ring 1"),
    ("POINT (1 2)", "expected POLYGON or MULTIPOLYGON"),
    ("POLYGON ((0 0, 1 0, 0 1, 0 0)", "parse error"),
    ("POLYGON Z ((0 0 0, 1 0 0, 0 1 0, 0 0 0))", ""),
    ("", "empty input"),
])
def test_bad_wkt(wkt, message):
    raises(message, Polygon.from_wkt, wkt)
    raises(message, influence2d.intersects, wkt, B, np.zeros((1, 3)))


def test_bad_wkb():
    good = shapely.geometry.box(0, 0, 1, 1).wkb
    raises("announced", Polygon.from_wkb, good[:-3])
    raises("truncated", Polygon.from_wkb, good[:7])
    raises("bytes after", Polygon.from_wkb, good + b"\0")
    raises("geometry type 1", Polygon.from_wkb, shapely.geometry.Point(1, 2).wkb)
    raises("Z or M", Polygon.from_wkb, shapely.geometry.Polygon([(0, 0, 1), (1, 0, 1), (0, 1, 1)]).wkb)
    raises("byte order", Polygon.from_wkb, b"\x07" + good[1:])
    raises("announced", Polygon.from_wkb, good[:5] + b"\xff\xff\xff\x7f" + good[9:])
    raises("expected bytes", Polygon.from_wkb, "not bytes")


def test_bad_shapely_geometries():
    raises("LineString", Polygon.from_shapely, shapely.geometry.LineString([(0, 0), (1, 1)]))
    raises("empty", Polygon.from_shapely, shapely.wkt.loads("POLYGON EMPTY"))
    raises(r"b: expected a Polygon or MultiPolygon, got a Point", influence2d.intersects, A,
           shapely.geometry.Point(0, 0), np.zeros((1, 3)))
    raises("z coordinates", Polygon.from_shapely, shapely.geometry.Polygon([(0, 0, 1), (1, 0, 1), (0, 1, 1)]))


def test_bad_coords():
    xy = np.array([[0, 0], [1, 0], [0, 1], [0, 0]], dtype=np.float64)
    raises(r"shape \(n, 2\), got shape \(4, 3\)$", Polygon.from_coords, np.zeros((4, 3)), [0, 4])
    raises(r"got shape \(8,\)$", Polygon.from_coords, np.zeros(8), [0, 4])
    raises(r"ring_offsets: expected a 1-D array of at least 2 offsets, got shape \(1,\)$", Polygon.from_coords,
           xy, [0])
    raises(r"ring_offsets: .* got shape \(2, 2\)$", Polygon.from_coords, xy, [[0, 4], [0, 4]])
    raises("float64", Polygon.from_coords, xy.astype(np.float32), [0, 4])
    raises(r"ring_offsets\[1\] is 9", Polygon.from_coords, xy, [0, 9])
    raises(r"ring_offsets\[2\] is 1, less than", Polygon.from_coords, xy, [0, 2, 1])
    raises("integer offsets", Polygon.from_coords, xy, [0.0, 4.0])
    raises(r"ring_offsets\[1\] is 18446744073709551615: more than", Polygon.from_coords, xy,
           np.array([0, 2**64 - 1], dtype=np.uint64))
    raises(r"polygon_offsets\[1\] is 9223372036854775808: more than", Polygon.from_coords, xy, [0, 4],
           np.array([0, 2**63], dtype=np.uint64))
    bad = xy.copy()
    bad[2, 1] = np.nan
    raises(r"coords\[2, 1\] is nan \(ring 0, vertex 2\)", Polygon.from_coords, bad, [0, 4])
    raises("fewer than three distinct", Polygon.from_coords, xy, [0, 2])
    raises(r"polygon_offsets\[1\] is 3", Polygon.from_coords, xy, [0, 4], [0, 3])


def test_bad_options():
    raises("number_type 'float'", influence2d.intersects, A, B, np.zeros((1, 3)), number_type="float")
    raises("number_type 'quad'", influence2d.Detector, A, B, number_type="quad")
    raises("threads is -1", influence2d.intersects, A, B, np.zeros((1, 3)), threads=-1)
    raises("within is -1", influence2d.Detector, A, B, within=-1.0)
    raises("within is nan", influence2d.Detector, A, B, within=math.nan)
    raises("distance", influence2d.pairs, [A, B], within=-1.0)
    raises("one end pose per start pose", influence2d.first_contact, A, B, np.zeros((2, 3)), np.zeros((3, 3)))
    raises("motion 'linear' is not a turning model", influence2d.first_contact, A, B, np.zeros((1, 3)),
           np.zeros((1, 3)), motion="linear")
    raises("max_steps is -1", influence2d.first_contact, A, B, np.zeros((1, 3)), np.zeros((1, 3)), max_steps=-1)
    raises(r"pose: expected one pose", influence2d.Detector(A, B).witness, np.zeros((2, 3)))
    raises(r"poses: expected an array of shape \(n, 3\).*got shape \(2, 2\)", influence2d.Detector(A, B).witnesses,
           np.zeros((2, 2)))
    raises(r"poses\[1", influence2d.Detector(A, B).witnesses, np.array([[0.0, 0.0, 0.0], [math.inf, 0.0, 0.0]]))


P1 = np.zeros((1, 3))


@pytest.mark.parametrize("call, message", [
    # numbers: a string is not read as one, nor is a bool
    (lambda: influence2d.Detector(A, B, within="0.5"), "within: expected a number, got '0.5'"),
    (lambda: influence2d.Detector(A, B, within=None), "within: expected a number, got None"),
    (lambda: influence2d.Detector(A, B, within=True), "within: expected a number, got True"),
    (lambda: influence2d.pairs([A, B], within=[1.0, 2.0]), "within: expected a number, got [1.0, 2.0]"),
    (lambda: influence2d.pairs([A, B], within=10**400), "within: expected a number, got 1000"),
    # integers: no float, bool or string, nor one beyond a C++ long
    (lambda: influence2d.intersects(A, B, P1, threads=1.5), "threads is 1.5: expected an integer"),
    (lambda: influence2d.intersects(A, B, P1, threads="2"), "threads is '2': expected an integer"),
    (lambda: influence2d.separation(A, B, P1, threads=None), "threads is None: expected an integer"),
    (lambda: influence2d.pairs([A, B], threads=True), "threads is True: expected an integer"),
    (lambda: influence2d.intersects(A, B, P1, threads=2**70), f"threads is {2**70}: expected an integer from"),
    (lambda: influence2d.first_contact(A, B, P1, P1, max_steps=2.0), "max_steps is 2.0: expected an integer"),
    (lambda: influence2d.first_contact(A, B, P1, P1, max_steps=2**63), f"max_steps is {2**63}"),
    (lambda: influence2d.first_contact(A, B, P1, P1, threads="all"), "threads is 'all'"),
    (lambda: influence2d.audit_layer([A], threads=0.5), "threads is 0.5"),
    (lambda: influence2d.audit_layer([A], max_per_kind=-1), "max_per_kind is -1: expected an integer >= 0"),
    (lambda: influence2d.audit_report(A, max_per_kind="all"), "max_per_kind is 'all'"),
    (lambda: influence2d.study(frames=2.5), "frames is 2.5"),
    (lambda: influence2d.study(cases=0), "cases is 0: expected an integer >= 1"),
    (lambda: influence2d.study(seed=-1), "seed is -1: expected an integer >= 0"),
    (lambda: influence2d.study(seed=2**64), f"seed is {2**64}: expected an integer from 0 to {2**64 - 1}"),
    # names
    (lambda: influence2d.intersects(A, B, P1, number_type=None), "number_type is None: expected a name"),
    (lambda: influence2d.Detector(A, B, number_type=1), "number_type is 1: expected a name"),
    (lambda: influence2d.pairs([A, B], number_type=b"double"), "number_type is b'double': expected a name"),
    (lambda: influence2d.first_contact(A, B, P1, P1, motion=0), "motion is 0: expected a name"),
    # flags: "no" is not read as True
    (lambda: influence2d.Detector(A, B, witness="no"), "witness is 'no': expected True or False"),
    (lambda: influence2d.separation(A, B, P1, features=np.array([True, False])), "features is array"),
    (lambda: influence2d.first_contact(A, B, P1, P1, undecided=2), "undecided is 2: expected True or False"),
    (lambda: influence2d.pairs([A, B], return_statistics="yes"), "return_statistics is 'yes'"),
])
def test_bad_options_of_the_wrong_kind_are_named(call, message):
    # (Each refused before the extension's own conversion, which would raise
    # a TypeError listing its signatures, or read a string as a number.)
    assert message in raises("", call)


def test_options_are_checked_before_the_layers_are_read():
    # (A bad option is named even beside a bad polygon: nothing is read first.)
    raises("threads is 1.5", influence2d.pairs, ["POLYGON ((0 0, 1 0))"], threads=1.5)
    raises("return_statistics is 'no'", influence2d.pairs, ["POLYGON ((0 0, 1 0))"], return_statistics="no")
    raises("events is 'no'", influence2d.world_contacts, ["POLYGON ((0 0, 1 0))"], {}, events="no")
    raises("features is 'no'", influence2d.separation, "POLYGON ((0 0, 1 0))", B, P1, features="no")


def test_options_of_numpy_kinds_are_taken():
    expected = influence2d.intersects(A, B, np.array([[1.5, 0.0, 0.0], [3.0, 0.0, 0.0]]))
    assert influence2d.intersects(A, B, np.array([[1.5, 0.0, 0.0], [3.0, 0.0, 0.0]]), threads=np.int64(1),
                                  number_type=np.str_("certified")).tolist() == expected.tolist() == [True, False]
    assert influence2d.Detector(A, B, within=np.float32(0.5), witness=np.bool_(True)).collide(
        np.array([[2.25, 0.0, 0.0]])).tolist() == [True]
    assert influence2d.pairs([A, "POLYGON ((3 0, 4 0, 4 1, 3 1, 3 0))"], within=np.int32(1),
                             threads=np.uint8(1)).tolist() == [[0, 1]]
    _, time = influence2d.first_contact(A, B, np.array([[4.0, 0.0, 0.0]]), P1, max_steps=np.int16(10), undecided=0)
    assert time.tolist() == [0.5]


def test_bad_layers_name_the_index():
    raises(r"layer\[2\]: ring 0 is not closed", influence2d.pairs, [A, B, "POLYGON ((0 0, 1 0, 0 1))"])
    raises(r"other\[1\]: expected a Polygon", influence2d.pairs, [A], [B, 42])
    raises(r"layer\[0\]: the Polygon is empty", influence2d.pairs, [shapely.wkt.loads("POLYGON EMPTY")])
    # A layer of shapely geometries is read in one call: the one refused is
    # still named, with what is wrong with it.
    boxes = [shapely.geometry.box(k, 0, k + 1, 1) for k in range(3)]
    raises(r"layer\[2\]: expected a Polygon or MultiPolygon, got a LineString", influence2d.pairs,
           boxes[:2] + [shapely.geometry.LineString([(0, 0), (1, 1)])] + boxes[2:])
    raises(r"layer\[1\]: the Polygon has z coordinates", influence2d.pairs,
           [boxes[0], shapely.geometry.Polygon([(0, 0, 1), (1, 0, 1), (0, 1, 1)]), boxes[1]])
    raises(r"layer\[3\]: the Polygon is empty", influence2d.pairs, boxes + [shapely.wkt.loads("POLYGON EMPTY")])
    raises(r"other\[1\]: ring 0: fewer than three distinct vertices", influence2d.pairs, boxes,
           [boxes[0], shapely.geometry.Polygon([(0, 0), (1, 0), (0, 0)])])
    raises("sequence of polygons", influence2d.pairs, A)


def test_audit_refuses_only_what_is_not_a_polygon_at_all():
    raises("expected POLYGON or MULTIPOLYGON", influence2d.audit, "LINESTRING (0 0, 1 1)")
    assert not influence2d.audit_report("POLYGON ((0 0, 1 0, 0 1))")["accepted"]


def test_bad_study_names():
    raises(r"types\[0\] is 'float16'", influence2d.study, types=["float16"])
    raises(r"families\[0\] is 'nope'", influence2d.study, families=["nope"])
    raises(r"queries\[0\] is 'area'", influence2d.study, queries=["area"])
