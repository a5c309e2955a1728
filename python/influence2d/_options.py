# SPDX-License-Identifier: BSL-1.0
"""What a call's options must be: a number, an integer, a name, a flag. Each
check raises InvalidInput naming the option and the value it was given,
before the extension is called (whose own conversion would raise a
TypeError listing its signatures, or turn a string into a number)."""

import numpy as np

from ._core import InvalidInput

#: The largest integer the extension takes for a count (a C++ long).
LONG_MAX = 2**63 - 1


def number(value, option):
    """``value`` as a float: a real number (an int, a float, a numpy scalar);
    a string, a bool or anything float() does not take is refused. The
    extension checks its range (a distance finite and >= 0)."""
    if isinstance(value, (str, bytes, bool, np.bool_)):
        raise InvalidInput(f"{option}: expected a number, got {value!r}")
    try:
        return float(value)
    except (TypeError, ValueError, OverflowError):
        raise InvalidInput(f"{option}: expected a number, got {value!r}") from None


def integer(value, option, least=None, most=LONG_MAX):
    """``value`` as an int: an integer (a Python or numpy integer; a bool or
    a float refused) at most ``most`` and, when given, at least ``least``
    (the extension checks the ranges it names itself, such as threads')."""
    if isinstance(value, (bool, np.bool_)) or not isinstance(value, (int, np.integer)):
        raise InvalidInput(f"{option} is {value!r}: expected an integer" +
                           ("" if least is None else f" >= {least}"))
    v = int(value)
    if least is not None and v < least:
        raise InvalidInput(f"{option} is {v}: expected an integer >= {least}")
    lowest = -LONG_MAX - 1 if least is None else least
    if not lowest <= v <= most:
        raise InvalidInput(f"{option} is {v}: expected an integer from {lowest} to {most}")
    return v


def name(value, option):
    """``value`` as it is: a str (which names the extension checks)."""
    if not isinstance(value, str):
        raise InvalidInput(f"{option} is {value!r}: expected a name (a str)")
    return value


def flag(value, option):
    """``value`` as a bool: True or False (a numpy bool, or the integers 0
    and 1, taken as them); anything else refused, rather than read by its
    truth (``witness="no"`` would be True)."""
    if isinstance(value, (bool, np.bool_)):
        return bool(value)
    if isinstance(value, (int, np.integer)) and value in (0, 1):
        return bool(value)
    raise InvalidInput(f"{option} is {value!r}: expected True or False")
