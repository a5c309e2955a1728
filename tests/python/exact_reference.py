# SPDX-License-Identifier: BSL-1.0
"""An exact reference that does not use the library: whether two closed
polygonal regions meet, and how far apart they are, in rational arithmetic
(fractions.Fraction) on the posed coordinates.

Posing follows the library's definition (core/pose.hpp): B's vertex q goes
to (c qx - s qy + tx, s qx + c qy + ty) with the doubles c = cos(theta) and
s = sin(theta), evaluated exactly here. A region is closed: a point is in it
when it lies on an edge or when the winding number of its rings (outer rings
counter-clockwise, holes clockwise) around it is not zero. Two regions meet
when an edge of one meets an edge of the other, or a vertex of one lies in
the other (a bounded intersection without boundary crossings has a boundary
point of one inside the other).
"""

import math
from fractions import Fraction


def rings_of(geom):
    """The rings of a shapely Polygon or MultiPolygon as lists of (x, y)
    Fractions without the closing point, each with its role ("outer" or
    "hole")."""
    polys = list(geom.geoms) if geom.geom_type == "MultiPolygon" else [geom]
    rings = []
    for p in polys:
        for k, ring in enumerate([p.exterior] + list(p.interiors)):
            pts = [(Fraction(x), Fraction(y)) for x, y in ring.coords]
            if pts and pts[0] == pts[-1]:
                pts.pop()
            rings.append((pts, "outer" if k == 0 else "hole"))
    return rings


def _area2(pts):
    return sum(pts[i][0] * pts[(i + 1) % len(pts)][1] - pts[(i + 1) % len(pts)][0] * pts[i][1]
               for i in range(len(pts)))


def oriented(rings):
    """The rings with outer rings counter-clockwise and holes clockwise (a
    ring of zero area as given)."""
    out = []
    for pts, role in rings:
        a = _area2(pts)
        if (a < 0 and role == "outer") or (a > 0 and role == "hole"):
            pts = pts[::-1]
        out.append(pts)
    return out


def posed(rings, pose):
    """The rings of B posed exactly by (tx, ty, theta)."""
    tx, ty, theta = pose
    c, s = Fraction(math.cos(theta)), Fraction(math.sin(theta))
    tx, ty = Fraction(tx), Fraction(ty)
    return [[(c * x - s * y + tx, s * x + c * y + ty) for x, y in ring] for ring in rings]


def _orient(a, b, c):
    d = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
    return (d > 0) - (d < 0)


def _on_segment(a, b, p):
    return (_orient(a, b, p) == 0 and min(a[0], b[0]) <= p[0] <= max(a[0], b[0])
            and min(a[1], b[1]) <= p[1] <= max(a[1], b[1]))


def segments_meet(a, b, c, d):
    """Whether the closed segments ab and cd share a point."""
    o1, o2, o3, o4 = _orient(a, b, c), _orient(a, b, d), _orient(c, d, a), _orient(c, d, b)
    if o1 * o2 < 0 and o3 * o4 < 0:
        return True
    return (_on_segment(a, b, c) or _on_segment(a, b, d) or _on_segment(c, d, a) or _on_segment(c, d, b))


def _edges(rings):
    for ring in rings:
        for i in range(len(ring)):
            yield ring[i], ring[(i + 1) % len(ring)]


def contains(rings, p):
    """Whether p lies in the closed region of the oriented rings."""
    winding = 0
    for a, b in _edges(rings):
        if _on_segment(a, b, p):
            return True
        if a[1] <= p[1]:
            if b[1] > p[1] and _orient(a, b, p) > 0:
                winding += 1
        elif b[1] <= p[1] and _orient(a, b, p) < 0:
            winding -= 1
    return winding != 0


def regions_meet(a_rings, b_rings):
    """Whether the closed regions of two lists of oriented rings meet."""
    for a0, a1 in _edges(a_rings):
        for b0, b1 in _edges(b_rings):
            if segments_meet(a0, a1, b0, b1):
                return True
    return (any(contains(a_rings, p) for ring in b_rings for p in ring)
            or any(contains(b_rings, p) for ring in a_rings for p in ring))


def intersects(a_geom, b_geom, pose):
    """The exact answer of influence2d.intersects for one pose."""
    return regions_meet(oriented(rings_of(a_geom)), posed(oriented(rings_of(b_geom)), pose))



def _point_segment_squared(a, b, p):
    """The squared distance from p to the closed segment ab."""
    dx, dy = b[0] - a[0], b[1] - a[1]
    length2 = dx * dx + dy * dy
    t = Fraction(0) if length2 == 0 else min(max(((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / length2, 0), 1)
    ex, ey = p[0] - (a[0] + t * dx), p[1] - (a[1] + t * dy)
    return ex * ex + ey * ey


def segments_squared_distance(a, b, c, d):
    """The squared distance between the closed segments ab and cd: 0 when
    they meet, else that of the nearest end to the other segment."""
    if segments_meet(a, b, c, d):
        return Fraction(0)
    return min(_point_segment_squared(a, b, c), _point_segment_squared(a, b, d), _point_segment_squared(c, d, a),
               _point_segment_squared(c, d, b))


def squared_distance(a_geom, b_geom, pose, reach, a_pose=(0.0, 0.0, 0.0)):
    """The exact squared distance between A posed by a_pose and B posed by
    pose (0 when the closed regions meet), or None when it exceeds reach**2:
    apart, the nearest points lie on the boundaries, and edge pairs whose
    boxes are farther than reach apart on either axis are not asked."""
    a_rings = posed(oriented(rings_of(a_geom)), a_pose)
    b_rings = posed(oriented(rings_of(b_geom)), pose)
    if regions_meet(a_rings, b_rings):
        return Fraction(0)
    reach = Fraction(reach)
    best = None
    for a0, a1 in _edges(a_rings):
        low_x, high_x = min(a0[0], a1[0]) - reach, max(a0[0], a1[0]) + reach
        low_y, high_y = min(a0[1], a1[1]) - reach, max(a0[1], a1[1]) + reach
        for b0, b1 in _edges(b_rings):
            if (max(b0[0], b1[0]) < low_x or min(b0[0], b1[0]) > high_x or max(b0[1], b1[1]) < low_y
                    or min(b0[1], b1[1]) > high_y):
                continue
            d2 = segments_squared_distance(a0, a1, b0, b1)
            if best is None or d2 < best:
                best = d2
    return best if best is not None and best <= reach * reach else None

def rational_turn_transform(start, end, t):
    """B's rotation (c, s) and translation (tx, ty) at time t of the motion
    from `start` to `end` in the rational turning model, as Fractions: the
    turn cut into k pieces, k the least power of two with |turn| / k at most
    pi / 2 rounded; piece j starts at the double angle start.theta + j * step
    (piece 0 at start.theta) and turns by 2 atan(u), u = w tau, w =
    tan(step / 2) in double, tau = (t - j / k) k; the translation is
    start + t (end - start). The piece of t is the one with j / k <= t <
    (j + 1) / k (the last piece includes t = 1)."""
    turn = end[2] - start[2]
    k = 1
    while abs(turn) / k > 1.5707963267948966:
        k *= 2
    step = turn / k
    w = Fraction(math.tan(step / 2))
    t = Fraction(t)
    j = min(int(t * k), k - 1)
    angle = start[2] if j == 0 else start[2] + j * step
    c0, s0 = Fraction(math.cos(angle)), Fraction(math.sin(angle))
    u = w * (t - Fraction(j, k)) * k
    h = 1 + u * u
    mc, ms = (1 - u * u) / h, 2 * u / h
    c, s = c0 * mc - s0 * ms, s0 * mc + c0 * ms
    tx = Fraction(start[0]) + t * (Fraction(end[0]) - Fraction(start[0]))
    ty = Fraction(start[1]) + t * (Fraction(end[1]) - Fraction(start[1]))
    return c, s, tx, ty


def meet_in_rational_turn(a_geom, b_geom, start, end, t):
    """Whether A and B meet at time t of B's rational turning motion."""
    c, s, tx, ty = rational_turn_transform(start, end, t)
    b_rings = [[(c * x - s * y + tx, s * x + c * y + ty) for x, y in ring] for ring in oriented(rings_of(b_geom))]
    return regions_meet(oriented(rings_of(a_geom)), b_rings)
