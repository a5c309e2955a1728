# SPDX-License-Identifier: BSL-1.0
"""audit: the findings of the input audit against `influence2d audit --json`."""

import json

import shapely.geometry
import shapely.wkt

import influence2d
from conftest import run_tool

POLYGONS = [
    "POLYGON ((0 0, 1 0, 1 1, 0 1, 0 0))",
    "POLYGON ((0 0, 0 1, 1 1, 1 0, 0 0))",
    "POLYGON ((0 0, 2 2, 2 0, 0 2, 0 0))",
    "POLYGON ((0 0, 1 0, 1 0, 2 0, 2 2, 0 2, 0 0))",
    "POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0), (5 5, 6 5, 6 6, 5 6, 5 5))",
    "POLYGON ((0 0, 1 0, 0 1))",
    "POLYGON ((0 0, 1 0, 0 0))",
    "MULTIPOLYGON (((0 0, 2 0, 2 2, 0 2, 0 0)), ((2 2, 3 2, 3 3, 2 3, 2 2)))",
    "POLYGON ((0 0, 3 0, 3 3, 0 3, 0 0), (1 1, 2 1, 2 2, 1 2, 1 1), (1 1, 1.5 1, 1.5 1.5, 1 1))",
    "POLYGON ((0 0, 1e-300 0, 1e300 1, 0 1, 0 0))",
    "POLYGON ((0.1 0.1, 1.1 0.1, 0.1 1.1, 0.1 0.1))",
]


def test_findings_match_the_tool(tool, tmp_path):
    (tmp_path / "layer.wkt").write_text("\n".join(POLYGONS) + "\n")
    r = run_tool(tool, "audit", tmp_path / "layer.wkt", "--json", tmp_path / "audit.json", check=False)
    assert r.returncode in (0, 1), r.stderr
    report = json.loads((tmp_path / "audit.json").read_text())
    for k, (text, want) in enumerate(zip(POLYGONS, report["polygons"])):
        ours = influence2d.audit_report(text)
        assert ours["accepted"] == want["accepted"], k
        assert ours["total"] == want["total"], k
        assert ours["counts"] == {g["kind"]: g["count"] for g in want["findings"]}, k
        for group in want["findings"]:
            mine = [f for f in ours["findings"] if f["kind"] == group["kind"]][:len(group["first"])]
            for f, w in zip(mine, group["first"]):
                assert (f["ring"], f["vertex"], f["other_ring"], f["other_vertex"]) == (
                    w["ring"], w.get("vertex"), w.get("other_ring"), w.get("other_vertex")), k
                assert [f["x"], f["y"]] == [float(v) for v in w["at"]], k
                assert (f["what"], f["effect"]) == (w["what"], w["effect"]), k


def test_layer_audit_is_the_polygons_audits(tmp_path):
    frame = influence2d.audit_layer(POLYGONS)
    for k, text in enumerate(POLYGONS):
        assert frame[frame.polygon == k]["kind"].tolist() == [f["kind"] for f in influence2d.audit(text)]


def test_every_input_form_gives_the_same_findings():
    text = "POLYGON ((0 0, 0 1, 1 1, 1 0, 0 0))"
    g = shapely.wkt.loads(text)
    want = influence2d.audit(text)
    assert influence2d.audit(g.wkb) == want
    assert influence2d.audit(influence2d.Polygon.from_wkt(text)) == want
    # shapely keeps the ring as given: the reversed orientation is found.
    assert influence2d.audit(g) == want
    assert [f["kind"] for f in want] == ["reversed_orientation"]


def test_refused_polygons_are_findings_not_errors():
    r = influence2d.audit_report("POLYGON ((0 0, 1 0, 0 1))")
    assert not r["accepted"] and "not closed" in r["rejection"]
    assert [f["kind"] for f in r["findings"] if f["rejects"]] == ["unclosed_ring"]
