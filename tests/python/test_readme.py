# SPDX-License-Identifier: BSL-1.0
"""The README's Python example runs, and the README shows it as it is."""

import os
import runpy

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))


def test_readme_example_runs(capsys):
    runpy.run_path(os.path.join(HERE, "readme_example.py"), run_name="__main__")
    out = capsys.readouterr().out
    assert out.strip() == ("[ True False  True] [0.  0.5 0. ] [ True False] [ 0. nan] [[0, 1], [1, 2], [2, 3]] "
                           "['reversed_orientation'] [[0, 1], [1, 2]]")


def test_readme_shows_the_example():
    with open(os.path.join(HERE, "readme_example.py")) as f:
        code = "".join(line for line in f if not line.startswith("#"))
    with open(os.path.join(ROOT, "README.md")) as f:
        readme = f.read()
    assert code.strip() in readme
