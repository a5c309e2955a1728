# SPDX-License-Identifier: BSL-1.0
"""Polygons: read from WKT, WKB, shapely geometries or GeoArrow coordinate
arrays; and the conversion of whatever the package's functions take in
place of a Polygon (a shapely Polygon or MultiPolygon, WKT text, WKB bytes).
"""

import numpy as np

from . import _core
from ._core import InvalidInput

__all__ = ["Polygon", "as_polygon", "as_polygons"]


class Polygon:
    """A polygon of the library: any number of closed rings (outer rings and
    holes) of double coordinates, as POLYGON or MULTIPOLYGON geometries hold
    them. Build one with ``from_wkt``, ``from_wkb``, ``from_shapely`` or
    ``from_coords``; every function of the package also takes shapely
    geometries, WKT text and WKB bytes where it takes a Polygon.

    >>> p = Polygon.from_wkt("POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0), (1 1, 1 2, 2 2, 2 1, 1 1))")
    >>> p.num_vertices, p.num_rings
    (8, 2)
    """

    __slots__ = ("_p",)

    def __init__(self, core):
        if not isinstance(core, _core.Polygon):
            raise TypeError("build a Polygon with Polygon.from_wkt, from_wkb, from_shapely or from_coords")
        self._p = core

    @classmethod
    def from_wkt(cls, text):
        """The polygon of WKT text: POLYGON (first ring outer, the others
        holes) or MULTIPOLYGON. Rings must be closed; unclosed rings,
        non-finite coordinates, rings with fewer than three distinct vertices
        and empty geometries raise InvalidInput naming the ring and vertex.

        >>> Polygon.from_wkt("POLYGON ((0 0, 1 0, 0 1, 0 0))").num_vertices
        3
        >>> Polygon.from_wkt("POLYGON ((0 0, 1 0, 0 1))")
        Traceback (most recent call last):
        ...
        influence2d.InvalidInput: wkt: ring 0 is not closed: first point (0 0) differs from last point (0 1)
        """
        if not isinstance(text, str):
            raise InvalidInput(f"wkt: expected a str, got {type(text).__name__}")
        return cls(_core.Polygon.from_wkt(text))

    @classmethod
    def from_wkb(cls, data):
        """The polygon of WKB bytes (ISO or extended, either byte order):
        POLYGON or MULTIPOLYGON, x and y only.

        >>> import shapely.geometry
        >>> Polygon.from_wkb(shapely.geometry.box(0, 0, 2, 1).wkb).to_wkt()
        'POLYGON((2 0,2 1,0 1,0 0,2 0))'
        """
        if isinstance(data, (bytearray, memoryview)):
            data = bytes(data)
        if not isinstance(data, bytes):
            raise InvalidInput(f"wkb: expected bytes, got {type(data).__name__}")
        return cls(_core.Polygon.from_wkb(data))

    @classmethod
    def from_shapely(cls, geom):
        """The polygon of a shapely Polygon or MultiPolygon (read through its
        WKB, so coordinates are kept exactly).

        >>> import shapely.geometry
        >>> Polygon.from_shapely(shapely.geometry.box(0, 0, 1, 1)).num_vertices
        4
        """
        if getattr(geom, "geom_type", None) is None:
            raise InvalidInput(f"shapely: expected a Polygon or MultiPolygon, got {type(geom).__name__}")
        return cls(_shapely_polygon(geom, "shapely"))

    @classmethod
    def from_coords(cls, coords, ring_offsets, polygon_offsets=None):
        """The polygon of coordinates in the GeoArrow layout: ``coords`` an
        (n, 2) float64 array (read in place, whatever its strides), ring k
        the rows ``ring_offsets[k]:ring_offsets[k + 1]``; with
        ``polygon_offsets``, part j (a polygon of a MultiPolygon) the rings
        ``polygon_offsets[j]:polygon_offsets[j + 1]``, each part's first ring
        outer and the others holes (without: one part). Rings may be closed
        or open.

        >>> import numpy as np
        >>> xy = np.array([[0, 0], [2, 0], [2, 2], [0, 2], [0, 0]], dtype=np.float64)
        >>> Polygon.from_coords(xy, [0, 5]).to_wkt()
        'POLYGON((0 0,2 0,2 2,0 2,0 0))'
        """
        if not isinstance(coords, np.ndarray):
            try:
                coords = np.asarray(coords, dtype=np.float64)
            except (TypeError, ValueError) as e:
                raise InvalidInput(f"coords: not an array of numbers ({e})") from None
        return cls(_core.Polygon.from_coords(coords, _offsets(ring_offsets, "ring_offsets"),
                                             None if polygon_offsets is None
                                             else _offsets(polygon_offsets, "polygon_offsets")))

    def to_wkt(self):
        """The polygon as WKT: each coordinate in the fewest digits that read
        back to it, rings closed and stored counter-clockwise (outer) or
        clockwise (holes).

        >>> Polygon.from_wkt("POLYGON ((0 0, 0 1, 1 0, 0 0))").to_wkt()
        'POLYGON((1 0,0 1,0 0,1 0))'
        """
        return self._p.to_wkt()

    def to_shapely(self):
        """The polygon as a shapely geometry (through its WKT, exact).

        >>> Polygon.from_wkt("POLYGON ((0 0, 1 0, 0 1, 0 0))").to_shapely().area
        0.5
        """
        import shapely.wkt
        return shapely.wkt.loads(self.to_wkt())

    @property
    def num_vertices(self):
        """The number of vertices of all rings (closing points not counted).

        >>> Polygon.from_wkt("MULTIPOLYGON (((0 0, 1 0, 0 1, 0 0)), ((5 5, 6 5, 6 6, 5 6, 5 5)))").num_vertices
        7
        """
        return self._p.num_vertices

    @property
    def num_rings(self):
        """The number of rings.

        >>> Polygon.from_wkt("POLYGON ((0 0, 1 0, 0 1, 0 0))").num_rings
        1
        """
        return self._p.num_rings

    @property
    def bounds(self):
        """(min_x, min_y, max_x, max_y) of the vertices.

        >>> Polygon.from_wkt("POLYGON ((0 0, 3 0, 0 1, 0 0))").bounds
        (0.0, 0.0, 3.0, 1.0)
        """
        return self._p.bounds

    def __getstate__(self):
        return self._p

    def __setstate__(self, state):
        self._p = state

    def __repr__(self):
        wkt = self.to_wkt()
        return f"<influence2d.Polygon {wkt if len(wkt) <= 60 else wkt[:57] + '...'}>"


def _offsets(offsets, name):
    a = np.asarray(offsets)
    if a.dtype.kind not in "iu":
        raise InvalidInput(f"{name}: expected integer offsets, got dtype {a.dtype}")
    largest = np.uint64(np.iinfo(np.int64).max)  # (compared as uint64: as floats 2^63 and 2^63 - 1 are one)
    if a.dtype.kind == "u" and a.size and a.max() > largest:  # (as int64 it would turn negative)
        k = int(np.argmax(a > largest)) if a.ndim == 1 else None
        at = f"[{k}]" if k is not None else ""
        raise InvalidInput(f"{name}{at} is {a.max() if k is None else a[k]}: more than any offset can be")
    return a.astype(np.int64, copy=False)


def _shapely_polygon(geom, name):
    """The extension's polygon of a shapely geometry, read from its WKB."""
    kind = geom.geom_type
    if kind not in ("Polygon", "MultiPolygon"):
        raise InvalidInput(f"{name}: expected a Polygon or MultiPolygon, got a {kind}")
    if geom.is_empty:
        raise InvalidInput(f"{name}: the {kind} is empty")
    if geom.has_z:
        raise InvalidInput(f"{name}: the {kind} has z coordinates: x and y only")
    return _core.Polygon.from_wkb(geom.wkb, name)


def as_polygon(value, name="polygon"):
    """The Polygon of ``value``: a Polygon as it is; a shapely Polygon or
    MultiPolygon, WKT text or WKB bytes read; anything else refused with
    InvalidInput naming ``name``.

    >>> as_polygon("POLYGON ((0 0, 1 0, 0 1, 0 0))").num_vertices
    3
    """
    if isinstance(value, Polygon):
        return value
    if isinstance(value, str):
        return Polygon(_core.Polygon.from_wkt(value, name))
    if isinstance(value, (bytes, bytearray, memoryview)):
        return Polygon(_core.Polygon.from_wkb(bytes(value), name))
    if getattr(value, "geom_type", None) is not None:
        return Polygon(_shapely_polygon(value, name))
    raise InvalidInput(f"{name}: expected a Polygon, a shapely geometry, WKT text or WKB bytes, "
                       f"got {type(value).__name__}")


def as_polygons(values, name="layer"):
    """The Polygons of a sequence (Polygons, shapely geometries, WKT, WKB) or
    of a GeoPandas GeoSeries, each refused with InvalidInput naming
    ``name[index]``.

    >>> import shapely.geometry
    >>> [p.num_vertices for p in as_polygons([shapely.geometry.box(0, 0, 1, 1), "POLYGON ((0 0, 1 0, 0 1, 0 0))"])]
    [4, 3]
    """
    return [Polygon(p) for p in _core_polygons(values, name)]


def _core_polygons(values, name="layer"):
    """as_polygons, the extension's polygons without their Polygon wrappers
    (what the package's functions hand to the extension)."""
    if hasattr(values, "geom_type") and hasattr(values, "to_wkb"):  # a GeoSeries
        values = list(values.values)
    elif isinstance(values, (str, bytes, Polygon)) or hasattr(values, "geom_type"):
        raise InvalidInput(f"{name}: expected a sequence of polygons, got one {type(values).__name__}")
    try:
        values = list(values)
    except TypeError:
        raise InvalidInput(f"{name}: expected a sequence of polygons, got {type(values).__name__}") from None
    if values and all(_is_shapely(v) for v in values):
        # Shapely geometries, all read in one call from their WKB (one WKB
        # writer for them all); a geometry refused is named below, one by one.
        try:
            return _core.Polygon.many_from_wkb(_wkb_of(values), name)
        except InvalidInput:
            pass
    return [as_polygon(v, f"{name}[{k}]")._p for k, v in enumerate(values)]


def _is_shapely(value):
    """Whether value is a shapely geometry (by its class where shapely is
    there: its geom_type asks GEOS)."""
    try:
        from shapely.geometry.base import BaseGeometry
    except ImportError:
        return getattr(value, "geom_type", None) is not None
    return isinstance(value, BaseGeometry)


def _wkb_of(geoms):
    """The WKB of each shapely geometry, as its ``wkb`` gives it, written by
    one shapely WKBWriter where shapely has them (``wkb`` makes one for
    every geometry, half the time of the conversion of a layer)."""
    try:
        from shapely.geos import WKBWriter, lgeos
    except ImportError:
        return [g.wkb for g in geoms]
    writer = WKBWriter(lgeos)
    return [writer.write(g) for g in geoms]
