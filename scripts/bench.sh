#!/usr/bin/env bash
# SPDX-License-Identifier: BSL-1.0
# Benchmarks: installs Google Benchmark if missing, builds the benchmarks in
# build-bench (Release, -DINFLUENCE2D_BUILD_BENCHMARKS=ON), runs them with 3
# repetitions into build-bench/bench.json, and prints per scene the detector's
# time per frame in double, certified and exact, and the ratios to double,
# and the time of each compile-time feature build (medians of the
# repetitions, CPU time).
#
#   bash scripts/bench.sh [extra benchmark arguments, e.g. --benchmark_filter=detector]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/scripts/deps.sh"
if ! dpkg-query -W -f='${Status}' libbenchmark-dev 2>/dev/null | grep -q "install ok installed"; then
    echo "installing: libbenchmark-dev"
    sudo_cmd=()
    [ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
    "${sudo_cmd[@]}" apt-get update -qq
    DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends libbenchmark-dev >/dev/null
fi
build="$root/build-bench"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DINFLUENCE2D_BUILD_BENCHMARKS=ON >/dev/null
cmake --build "$build" -j "$(nproc)" --target influence2d_bench >/dev/null
out="$build/bench.json"
"$build/verification/bench/influence2d_bench" --benchmark_out="$out" --benchmark_out_format=json \
    --benchmark_repetitions=3 --benchmark_min_time=0.5 --benchmark_report_aggregates_only=true "$@" >&2

/usr/bin/python3 - "$out" <<'EOF'
import json
import sys

with open(sys.argv[1]) as f:
    data = json.load(f)

# Median of the repetitions; per frame = CPU time of one pass / frames per pass.
per_frame = {}   # (scene, type) -> ns per frame
per_call = {}    # (predicate, type) -> ns per call
fallbacks = {}   # (scene, type) -> exact frames per pass
per_feature = {} # (scene, type, build) -> (ns per frame, state bytes)
per_query = {}   # (query, cell, method) -> (ns per query, max relative difference, contacts)
scale = {"ns": 1.0, "us": 1e3, "ms": 1e6, "s": 1e9}
for b in data["benchmarks"]:
    if b.get("run_type") == "aggregate" and b.get("aggregate_name") != "median":
        continue
    kind, what, nt, *build = b.get("run_name", b["name"]).split("/")
    ns = b["cpu_time"] * scale[b.get("time_unit", "ns")]
    if kind in ("separation", "first_contact", "first_contact_turning"):
        # kind/method/cell: one query per iteration
        per_query[(kind, nt, what)] = (ns, b.get("max_relative_difference"), b.get("contacts"))
    elif kind == "detector":
        per_frame[(what, nt)] = ns / b["frames"]
        fallbacks[(what, nt)] = b.get("exact_frames", 0)
    elif kind == "features":
        per_feature[(what, nt, build[0])] = (ns / b["frames"], b.get("state_bytes", 0))
    else:
        per_call[(what, nt)] = ns / 4096

def fmt(x):
    return "-" if x is None else (f"{x:.1f}" if x < 1e4 else f"{x:.0f}")

def ratio(a, b):
    return "-" if a is None or b is None else f"{a / b:.2f}"

if per_frame:
    scenes = sorted({s for s, _ in per_frame}, key=lambda s: (s.split("_")[1], s.split("_")[0]))
    print(f"{'scene':<20} {'double ns/frame':>16} {'certified ns/frame':>19} {'exact ns/frame':>15} "
          f"{'certified/double':>17} {'exact/double':>13} {'fallbacks/pass':>15}")
    for s in scenes:
        d, c, e = (per_frame.get((s, t)) for t in ("double", "certified", "exact"))
        print(f"{s:<20} {fmt(d):>16} {fmt(c):>19} {fmt(e):>15} {ratio(c, d):>17} {ratio(e, d):>13} "
              f"{fallbacks.get((s, 'certified'), 0):>15.0f}")
    types = sorted({t for _, t in per_frame}, key=lambda t: per_frame.get((scenes[0], t), 0))
    print()
    print("ns per frame, every number type:")
    print(f"{'scene':<20} " + " ".join(f"{t:>11}" for t in types))
    for s in scenes:
        print(f"{s:<20} " + " ".join(f"{fmt(per_frame.get((s, t))):>11}" for t in types))
if per_feature:
    builds = ["minimal", "coherence", "all_unused", "all_witness"]
    print()
    print("compile-time features, ns per frame (state bytes); all_unused/coherence = the cost of unused features:")
    print(f"{'scene':<20} {'type':<7} " + " ".join(f"{c:>18}" for c in builds) + f" {'all_unused/coherence':>21}")
    for (s, t) in sorted({(s, t) for s, t, _ in per_feature}):
        cells = [per_feature.get((s, t, c)) for c in builds]
        row = " ".join(f"{'-' if v is None else fmt(v[0]) + ' (' + str(int(v[1])) + ')':>18}" for v in cells)
        r = ratio(cells[2][0], cells[1][0]) if cells[1] and cells[2] else "-"
        print(f"{s:<20} {t:<7} {row} {r:>21}")
if per_query:
    print()
    print("queries, ns per query (separation: GEOS's largest relative difference from ours in brackets;")
    print("first contact: the share of motions with contact in brackets):")
    for q in ("separation", "first_contact", "first_contact_turning"):
        methods = sorted({m for k, _, m in per_query if k == q}, key=lambda m: (m not in ("double", "certified"), m))
        if not methods:
            continue
        print(f"{q:<22} " + " ".join(f"{m:>24}" for m in methods))
        for c in sorted({c for k, c, _ in per_query if k == q}):
            row = []
            for m in methods:
                v = per_query.get((q, c, m))
                if v is None:
                    row.append(f"{'-':>24}")
                    continue
                extra = v[1] if q == "separation" else v[2]
                row.append(f"{fmt(v[0]) + ('' if extra is None else f' ({extra:.2g})'):>24}")
            print(f"{c:<22} " + " ".join(row))
if per_call:
    preds = sorted({p for p, _ in per_call})
    types = sorted({t for _, t in per_call}, key=lambda t: per_call.get(("orientation", t), 0))
    print()
    print("predicates, ns per call:")
    print(f"{'predicate':<20} " + " ".join(f"{t:>11}" for t in types))
    for p in preds:
        print(f"{p:<20} " + " ".join(f"{fmt(per_call.get((p, t))):>11}" for t in types))
EOF
