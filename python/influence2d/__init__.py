# SPDX-License-Identifier: BSL-1.0
"""influence2d: exact collision detection between 2D polygons, vectorised
over numpy arrays of poses (tx, ty, theta), with shapely geometries, WKT and
WKB accepted wherever a Polygon is.

>>> import numpy as np, influence2d
>>> a = influence2d.Polygon.from_wkt("POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0))")
>>> influence2d.intersects(a, "POLYGON ((0 0, 1 0, 0 1, 0 0))", np.array([[4.0, 0.0, 0.0], [4.5, 0.0, 0.0]]))
array([ True, False])

``influence2d.dask`` runs the audit of a layer, the layer join, the precision
study and a world's steps on Dask's distributed scheduler; it is imported on first use
(``import influence2d.dask``, or the attribute), not with the package.

Errors in the input (non-finite values, empty or malformed polygons, arrays
of the wrong shape or dtype) raise :class:`InvalidInput`, a ValueError naming
the value and its index.
"""

from . import _core
from ._core import InvalidInput
from .audit import audit, audit_layer, audit_report
from .detector import Detector
from .pairs import pairs
from .polygon import Polygon, as_polygon, as_polygons
from .poses import as_poses
from .queries import first_contact, intersects, separation
from .study import study, study_names
from .world import World, world_contacts

InvalidInput.__module__ = "influence2d"

__version__ = _core.__version__

#: The number types the queries take.
NUMBER_TYPES = ("certified", "exact", "double")



def __getattr__(name):
    """``influence2d.dask`` on first use: the package does not import
    distributed until it is asked for."""
    if name == "dask":
        import importlib
        return importlib.import_module(".dask", __name__)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


__all__ = [
    "InvalidInput", "Polygon", "Detector", "World", "world_contacts", "intersects", "separation", "first_contact",
    "pairs", "audit", "audit_report", "audit_layer", "study", "study_names", "as_polygon", "as_polygons", "as_poses",
    "NUMBER_TYPES",
]
