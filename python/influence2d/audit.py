# SPDX-License-Identifier: BSL-1.0
"""The input audit: every degeneracy of a polygon as given (repeated and
near-repeated vertices, collinear runs and spikes, edges that meet, reversed
or zero-area rings, holes outside their shell, coordinates beyond a number
type's range...), where it is and what the library does with it; found with
exact predicates, as ``influence2d audit`` finds them."""

from . import _core, _options
from .polygon import Polygon, as_polygon

__all__ = ["audit", "audit_report", "audit_layer"]


def _item(value, name):
    """What the audit reads: WKT text and WKB bytes as they are (what the
    readers refuse is a finding); a Polygon's rings as given; a shapely
    geometry's WKB."""
    if isinstance(value, (str, bytes)):
        return value
    if isinstance(value, Polygon):
        return value._p
    if getattr(value, "geom_type", None) is not None:
        if value.geom_type not in ("Polygon", "MultiPolygon"):
            raise _core.InvalidInput(f"{name}: expected a Polygon or MultiPolygon, got a {value.geom_type}")
        return value.wkb
    return as_polygon(value, name)._p


def audit_report(polygon, max_per_kind=50):
    """The audit of one polygon as a dict: ``accepted`` (whether the library
    takes it), ``rejection`` (its message when not), ``total`` findings,
    ``counts`` by kind, ``rings``, ``vertices`` and ``findings`` (as
    :func:`audit` lists them; at most ``max_per_kind`` of each kind).

    >>> r = audit_report("POLYGON ((0 0, 1 0, 1 0, 1 1, 0 0))")
    >>> r["accepted"], r["counts"]
    (True, {'repeated_vertex': 1})
    """
    return _core.audit([_item(polygon, "polygon")], "polygon", _options.integer(max_per_kind, "max_per_kind", least=0),
                       1)[0]


def audit(polygon, max_per_kind=50):
    """The findings of the audit of one polygon (WKT text, WKB bytes, a
    shapely geometry or a Polygon), one dict each: ``kind``, ``ring`` and
    ``vertex`` (input numbering; the edge for edge findings, None for ring
    findings), ``other_ring`` and ``other_vertex`` (findings between two
    places), the location ``x``, ``y``, ``what`` it is, its ``effect`` (what
    the library does with it) and whether it ``rejects`` the input.

    >>> [f["kind"] for f in audit("POLYGON ((0 0, 0 1, 1 1, 1 0, 0 0))")]
    ['reversed_orientation']
    >>> [(f["kind"], f["vertex"], f["other_vertex"]) for f in audit("POLYGON ((0 0, 2 2, 2 0, 0 2, 0 0))")]
    [('zero_area', None, None), ('self_intersection', 0, 2), ('centroid_on_edge_line', 0, None), ('centroid_on_edge_line', 2, None)]
    """
    return audit_report(polygon, max_per_kind)["findings"]


def audit_layer(polygons, max_per_kind=50, threads=0):
    """The audits of many polygons on all cores, as a pandas DataFrame of
    findings with a ``polygon`` column (its position in ``polygons``) before
    the columns of :func:`audit`.

    >>> audit_layer(["POLYGON ((0 0, 1 0, 0 1, 0 0))", "POLYGON ((0 0, 0 1, 1 0, 0 0))"])[["polygon", "kind"]]
       polygon                  kind
    0        1  reversed_orientation
    """
    import pandas as pd
    items = [_item(p, f"polygons[{k}]") for k, p in enumerate(polygons)]
    reports = _core.audit(items, "polygons", _options.integer(max_per_kind, "max_per_kind", least=0),
                          _options.integer(threads, "threads"))
    rows = [dict(polygon=k, **f) for k, r in enumerate(reports) for f in r["findings"]]
    columns = ["polygon", "kind", "ring", "vertex", "other_ring", "other_vertex", "x", "y", "what", "effect",
               "rejects"]
    return pd.DataFrame(rows, columns=columns)
