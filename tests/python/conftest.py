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
