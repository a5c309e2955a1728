# SPDX-License-Identifier: BSL-1.0
"""What the tests share: the influence2d tool of the same build tree (its
answers are the reference the package must match), random polygons, and the
exact reference (exact_reference.py) on the path."""

import math
import os
import random
import shutil
import subprocess
import sys

import numpy as np
import pytest
import shapely.geometry

sys.path.insert(0, os.path.dirname(__file__))


@pytest.fixture(scope="session")
def tool():
    """The influence2d tool: $INFLUENCE2D_TOOL (ctest sets it), else one on PATH."""
    path = os.environ.get("INFLUENCE2D_TOOL") or shutil.which("influence2d")
    if not path or not os.path.exists(path):
        pytest.skip("the influence2d tool is not built (set INFLUENCE2D_TOOL)")
    return path


def run_tool(tool, *args, check=True):
    """Runs the tool; returns the completed process."""
    r = subprocess.run([tool, *map(str, args)], capture_output=True, text=True)
    if check and r.returncode != 0:
        raise AssertionError(f"influence2d {' '.join(map(str, args))} failed ({r.returncode}): {r.stderr}")
    return r


def write_poses(path, poses):
    """A poses CSV the tool reads (repr: the shortest text of each double)."""
    with open(path, "w") as f:
        f.write("tx,ty,theta\n")
        for tx, ty, theta in poses:
            f.write(f"{float(tx)!r},{float(ty)!r},{float(theta)!r}\n")


def dyadic(x, bits=10):
    """x rounded to a multiple of 2^-bits."""
    return round(x * (1 << bits)) / (1 << bits)


def star_polygon(rng, n, radius=1.0, center=(0.0, 0.0)):
    """A random star-shaped simple polygon of n vertices on a dyadic grid."""
    angles = sorted(rng.uniform(0, 2 * math.pi) for _ in range(n))
    pts = []
    for a in angles:
        r = radius * rng.uniform(0.4, 1.0)
        p = (dyadic(center[0] + r * math.cos(a)), dyadic(center[1] + r * math.sin(a)))
        if not pts or p != pts[-1]:
            pts.append(p)
    if len(set(pts)) < 3:
        return star_polygon(rng, n, radius, center)
    poly = shapely.geometry.Polygon(pts)
    if not poly.is_valid:
        return star_polygon(rng, n, radius, center)
    return poly


@pytest.fixture
def rng():
    return random.Random(20240601)


@pytest.fixture
def np_rng():
    return np.random.default_rng(20240601)


def random_poses(np_rng, n, reach, turn):
    """n poses (tx, ty, theta): tx and ty uniform in [-reach, reach], theta
    in [-turn, turn], drawn column by column."""
    return np.column_stack([np_rng.uniform(-reach, reach, n), np_rng.uniform(-reach, reach, n),
                            np_rng.uniform(-turn, turn, n)])


def tool_frames(tool, directory, a, b, poses, *options):
    """`influence2d collide` on shapely polygons A and B at the poses, with
    the options given: its FRAMES.csv rows, each a list of its columns."""
    (directory / "a.wkt").write_text(a.wkt)
    (directory / "b.wkt").write_text(b.wkt)
    write_poses(directory / "poses.csv", poses)
    run_tool(tool, "collide", "--static", directory / "a.wkt", "--moving", directory / "b.wkt", "--poses",
             directory / "poses.csv", *options, "--out", directory / "frames.csv")
    return [line.split(",") for line in (directory / "frames.csv").read_text().splitlines()[1:]]


def tiling_layer(rng, nx, ny, q=64):
    """A layer cut from a jittered grid of nx x ny cells whose neighbours
    share their borders to the bit (corners on multiples of 1/q, up to two
    points between corners, shared by both cells); some cells have a
    square hole, left empty, filled exactly by an island, or holding an
    island that touches it at a corner, lies inside it, or lies 1/64 or
    1/32 inside its sides (the grid's step: exact distances); some are
    joined with a cell far away into a multipolygon; some get a sliver
    touching them at a corner."""
    corner = {}
    for i in range(nx + 1):
        for j in range(ny + 1):
            jx = 0 if i in (0, nx) else rng.randint(-q // 4, q // 4) / q
            jy = 0 if j in (0, ny) else rng.randint(-q // 4, q // 4) / q
            corner[(i, j)] = (i + jx, j + jy)
    between = {}

    def inner_points(a, b):
        key = (min(a, b), max(a, b))
        if key not in between:
            (x0, y0), (x1, y1) = corner[key[0]], corner[key[1]]
            k = rng.choice([0, 0, 1, 2])
            between[key] = [(x0 + (x1 - x0) * t / (k + 1) + rng.randint(-q // 8, q // 8) / q,
                             y0 + (y1 - y0) * t / (k + 1) + rng.randint(-q // 8, q // 8) / q) for t in range(1, k + 1)]
        pts = between[key]
        return pts if key[0] == a else pts[::-1]

    cells = {}
    for i in range(nx):
        for j in range(ny):
            c = [(i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1)]
            cells[(i, j)] = [p for k in range(4) for p in [corner[c[k]]] + inner_points(c[k], c[(k + 1) % 4])]
    layer, used = [], set()
    for key in sorted(cells, key=lambda _: rng.random()):
        if key in used:
            continue
        used.add(key)
        shell, r = cells[key], rng.random()
        far = [k for k in cells if k not in used and abs(k[0] - key[0]) + abs(k[1] - key[1]) > 2]
        if r < 0.15 and far:
            other = rng.choice(far)
            used.add(other)
            layer.append(shapely.geometry.MultiPolygon([shapely.geometry.Polygon(shell),
                                                       shapely.geometry.Polygon(cells[other])]))
        elif r < 0.4:
            cx, cy, h = key[0] + 0.5, key[1] + 0.5, rng.choice([0.125, 0.25])
            hole = [(cx - h, cy - h), (cx + h, cy - h), (cx + h, cy + h), (cx - h, cy + h)]
            layer.append(shapely.geometry.Polygon(shell, [hole]))
            s = rng.random()
            if s < 0.2:
                layer.append(shapely.geometry.Polygon([(cx - h, cy - h), (cx, cy - h / 2), (cx - h / 2, cy)]))
            elif s < 0.4:
                layer.append(shapely.geometry.Polygon(hole))
            elif s < 0.5:
                layer.append(shapely.geometry.Polygon([(cx - h / 2, cy - h / 2), (cx + h / 2, cy - h / 2), (cx, cy)]))
            else:
                # An island one or two grid steps inside the hole's sides.
                g = rng.choice([1, 2]) / q
                layer.append(shapely.geometry.box(cx - h + g, cy - h + g, cx + h - g, cy + h - g))
        else:
            layer.append(shapely.geometry.Polygon(shell))
            if r < 0.5:
                x, y = shell[0]
                layer.append(shapely.geometry.Polygon([(x, y), (x - 0.1, y - 0.3), (x - 0.3, y - 0.1)]))
    return layer

