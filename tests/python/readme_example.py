# SPDX-License-Identifier: BSL-1.0
# The README's Python example, run by tests/python/test_readme.py.
import numpy as np
import shapely.geometry
import influence2d

a = influence2d.Polygon.from_wkt("POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0), (1 1, 1 3, 3 3, 3 1, 1 1))")
b = shapely.geometry.box(0, 0, 0.5, 0.5)           # shapely geometries are taken wherever a Polygon is
poses = np.array([[4.0, 0.0, 0.0],                 # (tx, ty, theta) rows, float64, read in place
                  [1.5, 1.5, 0.0],                 # inside the hole: no contact
                  [1.0, 1.5, 0.3]])
hits = influence2d.intersects(a, b, poses)          # certified: exact, all cores, the GIL released
dist = influence2d.separation(a, b, poses)          # 0 where they meet
contact, t = influence2d.first_contact(a, b, poses[:2], poses[:2] + [0.5, 0.0, 0.0])
layer = [shapely.geometry.box(i, 0, i + 1, 1) for i in range(4)]
join = influence2d.pairs(layer)                     # (k, 2) int64: [[0, 1], [1, 2], [2, 3]]
findings = influence2d.audit("POLYGON ((0 0, 0 1, 1 1, 1 0, 0 0))")   # [{'kind': 'reversed_orientation', ...}]
world = influence2d.World()                         # many bodies stepped, certified
square = world.add_shape(b)
world.add_bodies([square] * 3, [[0.0, 0.0, 0.0], [0.5, 0.0, 0.0], [2.0, 0.0, 0.0]])
world.move([2], [[0.75, 0.25, 0.5]])                # ids and poses as arrays
touching = world.step()                             # (k, 2) int64: [[0, 1], [1, 2]]
print(hits, dist, contact, t, join.tolist(), [f["kind"] for f in findings], touching.tolist())
