# SPDX-License-Identifier: BSL-1.0
"""The layer join: which polygons of a layer meet each other, or which of one
layer meet which of another, all at their own coordinates (the library's
layer_pairs: a box tree, then each candidate pair tested exactly)."""

import numpy as np

from . import _core, _options
from .polygon import _core_polygons

__all__ = ["pairs"]


def pairs(layer, other=None, within=0.0, number_type="certified", threads=0, return_statistics=False):
    """The index pairs (i, j) whose closed regions meet (or come within
    ``within``; touching counts) as a (k, 2) int64 array, sorted: i < j in
    one layer, or i of ``layer`` and j of ``other``. ``layer`` and ``other``
    are sequences of Polygons, shapely geometries, WKT or WKB, or GeoPandas
    GeoSeries (index pairs are positions, not the series' labels).

    With ``return_statistics``, the pair ``(pairs, statistics)``: a dict of
    ``candidates`` (the pairs whose boxes, grown by ``within``, meet: each
    one tested) and ``exact_pairs`` (those of them answered again in exact
    rationals because the number type could not settle a sign; always 0 for
    "double" and "exact").

    >>> import shapely.geometry as g
    >>> layer = [g.box(0, 0, 1, 1), g.box(1, 0, 2, 1), g.box(3, 0, 4, 1)]
    >>> pairs(layer)
    array([[0, 1]])
    >>> pairs(layer, within=1.0)
    array([[0, 1],
           [1, 2]])
    >>> pairs(layer, [g.box(0.5, 0.5, 3.5, 0.6)])
    array([[0, 0],
           [1, 0],
           [2, 0]])
    >>> pairs(layer, within=1.0, return_statistics=True)[1]
    {'candidates': 2, 'exact_pairs': 1}
    """
    within, number_type = _options.number(within, "within"), _options.name(number_type, "number_type")
    threads, return_statistics = _options.integer(threads, "threads"), _options.flag(return_statistics,
                                                                                     "return_statistics")
    first = _core_polygons(layer, "layer")
    second = None if other is None else _core_polygons(other, "other")
    out, candidates, exact_pairs = _core.pairs(first, second, within, number_type, threads)
    out = out.reshape(-1, 2).astype(np.int64, copy=False)
    if not return_statistics:
        return out
    return out, {"candidates": candidates, "exact_pairs": exact_pairs}
