#!/usr/bin/python3
# SPDX-License-Identifier: BSL-1.0
"""The cost of the Python package, measured (a benchmark, never a test):

1. influence2d.intersects on N poses (default 1e6) against the C++ batch
   call, the tool's own timed frame loop (`influence2d collide --poses`,
   its "time per frame" line, the same detectors on the same threads): the
   Python overhead per pose.
2. Against shapely 1.8 per pose on the same posed inputs: B posed with
   shapely.affinity.affine_transform (the library's c, s, tx, ty), A
   prepared once with shapely.prepared.prep, then intersects.
3. pairs on a layer against shapely's STRtree query plus intersects on
   each candidate, per layer and per pair found.
4. A World of many drifting bodies stepped from Python (move every body,
   step) against the tool's own timed step loop on the same scene
   (`influence2d world`, its "time per step" line), and against shapely:
   every body posed with affine_transform, an STRtree of the posed bodies
   and intersects on each candidate pair, per step.

Each figure is the median of --repeats runs. Run it alone on the machine:

  PYTHONPATH=BUILD/python /usr/bin/python3 python/bench/overhead.py \
      --tool BUILD/src/influence2d [--layer LAYER.wkt]
"""

import argparse
import math
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time
import warnings

import numpy as np
import shapely
import shapely.affinity
import shapely.prepared
import shapely.strtree
import shapely.wkt

import influence2d

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def median_seconds(f, repeats):
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        f()
        times.append(time.perf_counter() - start)
    return statistics.median(times)


def poses_about(a, b, count, rng):
    """Poses of B about A: its origin uniform in A's box grown by B's reach,
    any angle (about a third of them meet for the contour families)."""
    x0, y0, x1, y1 = a.bounds
    bx0, by0, bx1, by1 = b.bounds
    reach = max(abs(bx0), abs(by0), abs(bx1), abs(by1))
    return np.column_stack([rng.uniform(x0 - reach, x1 + reach, count), rng.uniform(y0 - reach, y1 + reach, count),
                            rng.uniform(-math.pi, math.pi, count)])


def tool_seconds_per_frame(tool, a_path, b_path, poses, number_type, threads, directory, repeats):
    path = os.path.join(directory, "poses.csv")
    with open(path, "w") as f:
        f.write("tx,ty,theta\n")
        f.writelines(f"{tx!r},{ty!r},{th!r}\n" for tx, ty, th in poses.tolist())
    per_frame = []
    for _ in range(repeats):
        out = subprocess.run([tool, "collide", "--static", a_path, "--moving", b_path, "--poses", path,
                              "--number-type", number_type, "--threads", str(threads), "--out",
                              os.path.join(directory, "frames.csv")], capture_output=True, text=True, check=True)
        m = re.search(r"^time per frame:\s*([0-9.eE+-]+)\s*(ns|us|µs|ms|s)", out.stdout, re.M)
        if not m:
            raise SystemExit("no 'time per frame' line in the tool's output:\n" + out.stdout)
        scale = {"ns": 1e-9, "us": 1e-6, "µs": 1e-6, "ms": 1e-3, "s": 1.0}[m.group(2)]
        per_frame.append(float(m.group(1)) * scale)
    return statistics.median(per_frame)


def shapely_per_pose(a, b, poses, repeats):
    prepared = shapely.prepared.prep(a)
    rows = [(math.cos(t), math.sin(t), tx, ty) for tx, ty, t in poses.tolist()]

    def run():
        return [prepared.intersects(shapely.affinity.affine_transform(b, [c, -s, s, c, tx, ty]))
                for c, s, tx, ty in rows]
    return median_seconds(run, repeats) / len(rows), run()


def layer_from(path, count, rng):
    if path:
        with open(path) as f:
            return [shapely.wkt.loads(line) for line in f if line.strip()]
    # Parcels: star polygons of 8 to 24 vertices on a jittered grid, most
    # touching or overlapping their neighbours.
    side = int(math.ceil(math.sqrt(count)))
    layer = []
    for k in range(count):
        cx, cy = k % side + rng.uniform(-0.2, 0.2), k // side + rng.uniform(-0.2, 0.2)
        n = int(rng.integers(8, 25))
        angles = np.sort(rng.uniform(0, 2 * math.pi, n))
        radii = rng.uniform(0.4, 0.75, n)
        layer.append(shapely.geometry.Polygon(np.column_stack([cx + radii * np.cos(angles),
                                                               cy + radii * np.sin(angles)])))
    return layer


def strtree_pairs(layer):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # shapely 1.8's notice of the STRtree of shapely 2
        tree = shapely.strtree.STRtree(layer)
    index = {id(g): k for k, g in enumerate(layer)}
    found = []
    for i, g in enumerate(layer):
        for h in tree.query(g):
            j = index[id(h)]
            if j > i and g.intersects(h):
                found.append((i, j))
    return sorted(found)


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--tool", default=os.path.join(ROOT, "build", "src", "influence2d"))
    p.add_argument("--static", default=os.path.join(ROOT, "data", "families", "contour_64.wkt"))
    p.add_argument("--moving", default=os.path.join(ROOT, "data", "families", "contour_64.wkt"))
    p.add_argument("--poses", type=int, default=1_000_000)
    p.add_argument("--shapely-poses", type=int, default=20_000)
    p.add_argument("--layer", help="WKT file, one polygon per line (default: 10,000 generated parcels)")
    p.add_argument("--layer-size", type=int, default=10_000)
    p.add_argument("--repeats", type=int, default=5)
    p.add_argument("--number-type", default="certified")
    p.add_argument("--bodies", type=int, default=2_000, help="bodies of the world (4.)")
    p.add_argument("--steps", type=int, default=40, help="steps of the world (4.; shapely runs a tenth of them)")
    p.add_argument("--parts", default="overhead,shapely,pairs,world",
                   help="which measurements, comma-separated (default: all four)")
    o = p.parse_args()
    rng = np.random.default_rng(20240601)
    threads = os.cpu_count()

    with open(o.static) as f:
        a_geom = shapely.wkt.loads(f.read())
    with open(o.moving) as f:
        b_geom = shapely.wkt.loads(f.read())
    a, b = influence2d.Polygon.from_shapely(a_geom), influence2d.Polygon.from_shapely(b_geom)
    poses = poses_about(a_geom, b_geom, o.poses, rng)
    print(f"machine: {threads} cores; shapely {shapely.__version__}; numpy {np.__version__}; "
          f"{os.path.basename(o.static)} ({a.num_vertices} vertices) and {os.path.basename(o.moving)} "
          f"({b.num_vertices}); number type {o.number_type}; medians of {o.repeats} runs")

    parts = o.parts.split(",")
    if "overhead" in parts:
        measure_overhead(o, a, b, poses, threads)
    if "shapely" in parts:
        measure_shapely(o, a, b, a_geom, b_geom, poses, threads)
    if "pairs" in parts:
        measure_pairs(o, rng, threads)
    if "world" in parts:
        measure_world(o, rng)


def measure_overhead(o, a, b, poses, threads):
    """1. Python against the C++ batch call, every core and one."""
    with tempfile.TemporaryDirectory() as d:
        for t in (0, 1):
            n = len(poses) if t == 0 else min(len(poses), 200_000)
            sub = poses[:n]
            cpp = tool_seconds_per_frame(o.tool, o.static, o.moving, sub, o.number_type, t, d, o.repeats)
            py = median_seconds(lambda: influence2d.intersects(a, b, sub, o.number_type, threads=t),
                                o.repeats) / n
            label = f"{threads} threads" if t == 0 else "1 thread"
            print(f"intersects, {n} poses, {label}: python {py * 1e9:.1f} ns/pose, C++ batch {cpp * 1e9:.1f} "
                  f"ns/pose, overhead {100 * (py / cpp - 1):+.1f}%")


def measure_shapely(o, a, b, a_geom, b_geom, poses, threads):
    """2. Against shapely 1.8, per pose."""
    sub = poses[:o.shapely_poses]
    shp, shp_answers = shapely_per_pose(a_geom, b_geom, sub, max(1, o.repeats // 2))
    ours1 = median_seconds(lambda: influence2d.intersects(a, b, sub, o.number_type, threads=1), o.repeats) / len(sub)
    ours = median_seconds(lambda: influence2d.intersects(a, b, sub, o.number_type, threads=0), o.repeats) / len(sub)
    agree = int((np.array(shp_answers) == influence2d.intersects(a, b, sub, o.number_type)).sum())
    print(f"intersects vs shapely (prep + affine_transform + intersects), {len(sub)} poses: shapely "
          f"{shp * 1e6:.2f} us/pose; influence2d {ours1 * 1e6:.3f} us/pose on 1 thread ({shp / ours1:.1f}x), "
          f"{ours * 1e6:.3f} us/pose on {threads} ({shp / ours:.1f}x); same answer on {agree} of {len(sub)}")


def measure_pairs(o, rng, threads):
    """3. pairs against STRtree + intersects."""
    layer = layer_from(o.layer, o.layer_size, rng)
    polys = [influence2d.Polygon.from_shapely(g) for g in layer]
    ours_pairs = influence2d.pairs(polys, number_type=o.number_type)
    tree_pairs = strtree_pairs(layer)
    t_tree = median_seconds(lambda: strtree_pairs(layer), max(1, o.repeats // 2))
    t_ours1 = median_seconds(lambda: influence2d.pairs(polys, number_type=o.number_type, threads=1), o.repeats)
    t_ours = median_seconds(lambda: influence2d.pairs(polys, number_type=o.number_type, threads=0), o.repeats)
    t_convert = median_seconds(lambda: influence2d.pairs(layer, number_type=o.number_type, threads=0), o.repeats)
    k = len(ours_pairs)
    same = sorted(map(tuple, ours_pairs.tolist())) == tree_pairs
    name = os.path.basename(o.layer) if o.layer else "generated parcels"
    print(f"pairs, {len(layer)} polygons ({name}), {k} pairs ({'same as' if same else 'differ from'} STRtree's "
          f"{len(tree_pairs)}): STRtree + intersects {t_tree * 1e3:.1f} ms ({t_tree / max(k, 1) * 1e6:.2f} us/pair); "
          f"influence2d {t_ours1 * 1e3:.1f} ms on 1 thread ({t_tree / t_ours1:.1f}x), {t_ours * 1e3:.1f} ms on "
          f"{threads} ({t_tree / t_ours:.1f}x, {t_ours / max(k, 1) * 1e6:.2f} us/pair); from shapely geometries "
          f"(WKB read included) {t_convert * 1e3:.1f} ms")


def drifting_scene(count, steps, rng):
    """Star bodies (8 to 24 vertices, 8 shapes) on a jittered grid, each
    drifting at its own small velocity and turn rate: the poses of every
    body at every step, (steps, count, 3)."""
    side = int(math.ceil(math.sqrt(count)))
    shapes = []
    for _ in range(8):
        n = int(rng.integers(8, 25))
        angles = np.sort(rng.uniform(0, 2 * math.pi, n))
        radii = rng.uniform(0.35, 0.7, n)
        shapes.append(shapely.geometry.Polygon(np.column_stack([radii * np.cos(angles), radii * np.sin(angles)])))
    kind = rng.integers(0, len(shapes), count)
    start = np.column_stack([np.arange(count) % side + rng.uniform(-0.2, 0.2, count),
                             np.arange(count) // side + rng.uniform(-0.2, 0.2, count),
                             rng.uniform(-math.pi, math.pi, count)])
    velocity = np.column_stack([rng.uniform(-0.01, 0.01, count), rng.uniform(-0.01, 0.01, count),
                                rng.uniform(-0.02, 0.02, count)])
    poses = start[None, :, :] + np.arange(steps)[:, None, None] * velocity[None, :, :]
    return shapes, kind, np.ascontiguousarray(poses)


def world_run(shapes, kind, poses, number_type):
    """The contacts of every step of a World stepped from Python."""
    w = influence2d.World(number_type)
    w.add_shapes(shapes)
    ids = w.add_bodies(kind, poses[0])
    found = [w.step()]
    for k in range(1, len(poses)):
        w.move(ids, poses[k])
        found.append(w.step())
    return found


def tool_seconds_per_step(tool, shapes, kind, poses, number_type, directory, repeats):
    with open(os.path.join(directory, "shapes.wkt"), "w") as f:
        f.writelines(g.wkt + "\n" for g in shapes)
    with open(os.path.join(directory, "steps.csv"), "w") as f:
        f.write("step,body,shape,tx,ty,theta\n")
        for k, step in enumerate(poses.tolist()):
            f.writelines(f"{k},{b},{kind[b]},{tx!r},{ty!r},{th!r}\n" for b, (tx, ty, th) in enumerate(step))
    per_step = []
    for _ in range(repeats):
        out = subprocess.run([tool, "world", "--shapes", os.path.join(directory, "shapes.wkt"), "--steps",
                              os.path.join(directory, "steps.csv"), "--number-type", number_type], capture_output=True,
                             text=True, check=True)
        m = re.search(r"^time per step:\s*([0-9.eE+-]+) us", out.stdout, re.M)
        if not m:
            raise SystemExit("no 'time per step' line in the tool's output:\n" + out.stdout)
        per_step.append(float(m.group(1)) * 1e-6)
    return statistics.median(per_step)


def shapely_step(shapes, kind, poses):
    """One step in shapely: every body posed, an STRtree of them, each
    candidate pair (i < j) tested."""
    return strtree_pairs([shapely.affinity.affine_transform(shapes[k], [math.cos(t), -math.sin(t), math.sin(t),
                                                                        math.cos(t), x, y])
                          for k, (x, y, t) in zip(kind.tolist(), poses.tolist())])


def measure_world(o, rng):
    """4. A World stepped from Python, against the tool and shapely."""
    shapes, kind, poses = drifting_scene(o.bodies, o.steps, rng)
    found = world_run(shapes, kind, poses, o.number_type)
    t_py = median_seconds(lambda: world_run(shapes, kind, poses, o.number_type), o.repeats) / len(poses)
    with tempfile.TemporaryDirectory() as d:
        t_tool = tool_seconds_per_step(o.tool, shapes, kind, poses, o.number_type, d, o.repeats)
    few = max(1, len(poses) // 10)
    t_shp = median_seconds(lambda: [shapely_step(shapes, kind, p) for p in poses[:few]], max(1, o.repeats // 2)) / few
    same = sum(shapely_step(shapes, kind, poses[k]) == sorted(map(tuple, found[k].tolist())) for k in range(few))
    contacts = sum(len(f) for f in found) / len(found)
    print(f"world, {o.bodies} bodies drifting, {len(poses)} steps, {contacts:.0f} contacts a step: python (move all, "
          f"step) {t_py * 1e6:.1f} us/step, C++ (the tool's step loop) {t_tool * 1e6:.1f} us/step, overhead "
          f"{100 * (t_py / t_tool - 1):+.1f}%; shapely (affine_transform, STRtree, intersects) {t_shp * 1e3:.2f} "
          f"ms/step ({t_shp / t_py:.1f}x); same contacts as shapely in {same} of {few} steps")


if __name__ == "__main__":
    sys.exit(main())
