# SPDX-License-Identifier: BSL-1.0
"""Pose arrays: (n, 3) float64 rows of ``tx, ty, theta`` (the tool's
convention: B turned by theta radians about its own origin, then moved by
(tx, ty)). A C-contiguous float64 array is handed to the library as it is,
never copied; a list or a single pose is made into one; an array of another
dtype or shape is refused with InvalidInput.
"""

import numpy as np

from ._core import InvalidInput

__all__ = ["as_poses"]


def as_poses(poses, name="poses"):
    """The (n, 3) float64 C-contiguous array of ``poses``: the array itself
    when it is one; a list of (tx, ty, theta) rows or one such row converted;
    any other array refused with InvalidInput naming ``name`` and the shape
    or dtype.

    >>> a = np.zeros((4, 3))
    >>> as_poses(a) is a
    True
    >>> as_poses([0.5, 0.0, 0.0]).shape
    (1, 3)
    >>> as_poses(np.zeros((4, 2)))
    Traceback (most recent call last):
    ...
    influence2d.InvalidInput: poses: expected an array of shape (n, 3) (tx, ty, theta), got shape (4, 2)
    """
    if isinstance(poses, np.ndarray):
        if poses.ndim != 2 or poses.shape[1] != 3:
            shape = ", ".join(str(s) for s in poses.shape) + ("," if poses.ndim == 1 else "")
            raise InvalidInput(f"{name}: expected an array of shape (n, 3) (tx, ty, theta), got shape ({shape})")
        if poses.dtype != np.float64:
            raise InvalidInput(f"{name}: expected dtype float64, got {poses.dtype} (poses.astype(numpy.float64))")
        if not poses.flags.c_contiguous:
            raise InvalidInput(f"{name}: expected a C-contiguous array (numpy.ascontiguousarray)")
        return poses
    try:
        a = np.array(poses, dtype=np.float64)
    except (TypeError, ValueError) as e:
        raise InvalidInput(f"{name}: not an array of numbers ({e})") from None
    if a.ndim == 1 and a.shape[0] == 3:
        a = a.reshape(1, 3)
    if a.ndim == 2 and a.shape[0] == 0:
        a = a.reshape(0, 3)
    return as_poses(a, name)
