# SPDX-License-Identifier: BSL-1.0
"""The precision study: every decision of the method and the queries
(separation, first contact) in every number type, against the exact
reference, on generated scenes; its tables as pandas DataFrames (the
columns of ``influence2d study``'s CSV files)."""

from . import _core, _options

__all__ = ["study", "study_names"]


def study_names():
    """The names ``study`` takes: ``families``, ``default_families``,
    ``types``, ``decisions`` and ``queries``.

    >>> "certified" in study_names()["types"]
    True
    """
    return _core.study_names()


def study(families=None, types=None, decisions=None, queries=None, cases=1, frames=40, query_frames=128,
          seed=20040202):
    """Runs the precision study (the GIL released) and returns its tables as
    a dict of DataFrames: ``decisions`` (study.csv: disagreements with the
    exact answer per number type, family and decision), ``queries``
    (queries.csv), ``stability`` (stability.csv, the offset and scale
    sweeps), ``summaries`` (per type: questions, fallbacks) and ``examples``
    (disagreements kept). ``families``, ``types``, ``decisions`` default to
    the command's defaults (``study_names()``); ``queries`` to all of
    separation, first_contact, turning_rational and turning_angle_linear
    (``[]``: none). The defaults of
    ``cases`` and ``frames`` are the command's ``--quick`` run.

    >>> t = study(families=["convex"], types=["double", "certified"], decisions=["collides"], queries=[],
    ...           frames=10)
    >>> t["decisions"][["number_type", "family", "decision", "cases"]]
      number_type  family  decision  cases
    0      double  convex  collides     10
    1   certified  convex  collides     10
    >>> int(t["decisions"]["disagreements"][1])
    0
    """
    names = _core.study_names()
    r = _core.study(list(families or []), list(types or []), list(decisions or []),
                    list(names["queries"] if queries is None else queries),
                    _options.integer(cases, "cases", least=1), _options.integer(frames, "frames", least=1),
                    _options.integer(query_frames, "query_frames", least=0),
                    _options.integer(seed, "seed", least=0, most=2**64 - 1))
    return _frames(r)


#: The columns of each table, as the command's CSV files name them.
_COLUMNS = {
    "decisions": ["number_type", "family", "decision", "cases", "disagreements", "rate", "ns_per_query"],
    "queries": ["number_type", "family", "query", "questions", "differing", "meeting_differs", "features_differ",
                "values_differ", "measured", "largest_error", "median_error", "ns_per_question"],
    "stability": ["number_type", "sweep", "magnitude", "cases", "disagreements", "rate"],
    "summaries": ["number_type", "claims_exact", "has_fallback", "questions", "fallbacks", "setup_fallbacks",
                  "refused_scenes", "refused_query_scenes"],
    "examples": ["number_type", "family", "decision", "scene", "question", "got", "expected"],
}


def _frames(r):
    """The study's tables (``_core.study``'s lists of rows) as DataFrames."""
    import pandas as pd
    return {name: pd.DataFrame(r[name], columns=cols) for name, cols in _COLUMNS.items()}
