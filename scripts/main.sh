#!/usr/bin/env bash
# SPDX-License-Identifier: BSL-1.0
# The main job: installs what is missing, builds, and runs the paper's worst
# case (irregular contour polygons) on the circular and the linear trajectory,
# in double and in exact arithmetic, with the sound and the paper-literal
# detectors, and prints a summary table; then a short precision study of the
# method's decisions per number type, and a quick time study against the peers
# (the paper's trajectories, random poses near contact, one-shot queries), and
# the time study on pairs of real polygons (countries and New York City
# boroughs, downloaded from Debian's archive by scripts/real_layers.sh; skipped,
# with the reason, when that fails). Outputs go to build/main-job/.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/scripts/deps.sh"
cmake -S "$root" -B "$root/build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$root/build" -j "$(nproc)" --target influence2d_cli influence2d_bench_cli influence2d_real_bench_cli >/dev/null
# The Python package (when pybind11 and /usr/bin/python3 with numpy are there), installed.
bash "$root/scripts/install_python.sh" "$root/build" >/dev/null
tool="$root/build/src/influence2d"
bench_tool="$root/build/src/influence2d-bench"
data="$root/data/families"
out="$root/build/main-job"
rm -rf "$out"
mkdir -p "$out"

# run NAME ARGS...: one collide run; prints one table row from its summary.
# One thread, so that the time per frame is one detector's, the same for
# every run of the table.
run() {
    local name=$1
    shift
    local log="$out/$name.log"
    "$tool" collide "$@" --threads 1 --out "$out/$name.csv" >"$log"
    local frames collisions first per_frame
    frames=$(awk -F': *' '/^frames:/ {print $2}' "$log")
    collisions=$(awk -F': *' '/^collisions:/ {print $2}' "$log")
    first=$(awk -F': *' '/^first collision:/ {print $2}' "$log")
    per_frame=$(awk -F': *' '/^time per frame:/ {print $2}' "$log")
    printf '%-34s %8s %10s %-16s %s\n' "$name" "$frames" "$collisions" "${first:-none}" "$per_frame"
}

# agree A B: frames on which two runs' answers differ.
agree() {
    paste -d, "$out/$1.csv" "$out/$2.csv" | awk -F, 'NR > 1 && $2 != $4 {n++} END {print n + 0}'
}

echo "influence2d main job: contour polygons (the paper's hardest family), $(date -u +%Y-%m-%d)"
echo "machine: $(nproc) cores, $(awk '/MemTotal/ {printf "%.0f GiB", $2 / 1048576}' /proc/meminfo), $(uname -m)"
echo
printf '%-34s %8s %10s %-16s %s\n' run frames collisions "first collision" "time per frame"
for pair in "64 64" "1024 8" "8 1024" "256 256"; do
    set -- $pair
    s=$1 m=$2
    for traj in circular linear; do
        for nt in double exact; do
            run "${traj}_${s}x${m}_${nt}" --static "$data/contour_$s.wkt" --moving "$data/contour_$m.wkt" \
                --trajectory "$traj" --number-type "$nt"
        done
        run "${traj}_${s}x${m}_paper" --static "$data/contour_$s.wkt" --moving "$data/contour_$m.wkt" \
            --trajectory "$traj" --number-type double --algorithm paper
    done
done
echo
echo "disagreements with the exact answer (frames):"
for pair in "64 64" "1024 8" "8 1024" "256 256"; do
    set -- $pair
    for traj in circular linear; do
        base="${traj}_$1x$2"
        printf '  %-22s double: %s   paper-literal: %s\n' "$base" "$(agree "${base}_double" "${base}_exact")" \
            "$(agree "${base}_paper" "${base}_exact")"
    done
done
echo
echo "per-frame answers: $out/*.csv"
echo
echo "precision study (short run: every decision of the method, the separation and the first contact along translations and turns, in every number type against exact):"
"$tool" study --quick --out "$out/study" --regressions "$out/regressions" >"$out/study.log"
sed -n '/^## What this means/,/^## /p' "$out/study/study.md" | sed '$d'
grep '^`separation`\|^`first_contact`\|^`turning_' "$out/study/study.md"
echo
echo "tables and plots: $out/study/study.md, $out/study/*.svg"
echo
echo "time study (quick grid: sizes 8 and 1024, every polygon type; the two trajectories, random poses and one-shot queries; every method on the same poses):"
"$bench_tool" --quick --out "$out/bench" >"$out/bench.log"
sed -n '/^## Methods/,/^## Targets/p' "$out/bench/bench.md" | sed '$d'
sed -n '/^## Targets/,/^## Speed-up/p' "$out/bench/bench.md" | sed '$d'
echo "tables and heat maps: $out/bench/bench.md, $out/bench/heatmap_*.png (full grid: influence2d-bench)"
echo
echo "real pairs (countries and NYC boroughs, 200 poses a pair along a random walk and shuffled, then each pushed just apart, against GEOS prepared):"
if bash "$root/scripts/real_layers.sh" "$out/real_layers" >"$out/real_layers.log" 2>&1; then
    "$root/build/src/influence2d-real-bench" --layers "$out/real_layers" --poses 200 --runs 3 --out "$out/real" \
        2>/dev/null | grep -E '^\| static|\| (double|certified|GEOS prepared) \|'
    echo "table: $out/real/real.md (full run: influence2d-real-bench --layers DIR)"
else
    echo "skipped: the real layers could not be made ($out/real_layers.log)"
fi
