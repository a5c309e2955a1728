#!/usr/bin/env bash
# SPDX-License-Identifier: BSL-1.0
# Profiles detector<double> on the real layers' time study under callgrind
# (scripts/profile/real_frames.cpp): instructions per frame of each pair of
# real polygons in each order of its poses, split by the part of the frame
# they come from (inlined code counts where it is written, the standard
# library's helpers in the function they were inlined into), with the
# detector's counters. Writes the markdown table to standard output.
#   bash scripts/profile/real_frames.sh LAYERS_DIR [POSES]
# LAYERS_DIR from scripts/real_layers.sh. Needs valgrind and a C++17
# compiler; about six minutes at the default 600 poses.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
if [ $# -lt 1 ]; then
    echo "usage: bash scripts/profile/real_frames.sh LAYERS_DIR [POSES]" >&2
    exit 2
fi
layers=$(cd "$1" && pwd)
poses=${2:-600}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
${CXX:-g++} -std=c++17 -O2 -g -DNDEBUG -ffp-contract=off -I"$root/include" -I"$root" \
    "$root/scripts/profile/real_frames.cpp" -o "$work/real_frames" -lgmp -lmpfr
(cd "$work" && valgrind --tool=callgrind --instr-atstart=no --callgrind-out-file=cg.%p.out \
    ./real_frames "$layers" "$poses" >frames.txt 2>valgrind.txt)
echo "| pair / order | instructions per frame | tree traversal | candidates | pair tests | filters | posing | containment | libm | the rest | frames through the trees | candidate edges per frame | segment tests per frame |"
echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
for dump in $(ls -v "$work"/cg.*.out.*); do
    name=$(grep -a "^desc: Trigger" "$dump" | sed 's/.*Request: //')
    counters=$(awk -F'\t' -v n="$name" '$1 == n {print $2, $3, $4, $5, $6}' "$work/frames.txt")
    callgrind_annotate --inclusive=no --threshold=100 --auto=no "$dump" 2>/dev/null |
        awk -v name="$name" -v counters="$counters" '
        BEGIN { split(counters, c, " "); frames = c[1] }
        /^ *[0-9,]+ \(/ && !/PROGRAM TOTALS/ {
            n = $1; gsub(",", "", n)
            line = $0; sub(/^ *[0-9,]+ \([ 0-9.]+%\) +/, "", line)
            file = line; sub(/:.*/, "", file)
            fn = line; sub(/^[^:]*:/, "", fn)
            # By the file the instructions are written in; for the detector
            # and the standard library, by the function they run in.
            if (file ~ /libm|s_sin|sincos|hypot/) part = "libm"
            else if (file ~ /predicates\/filters\.hpp/) part = "filters"
            else if (file ~ /predicates\/(orientation|segments)\.hpp/) part = "pairs"
            else if (file ~ /extended_area|edge_grid/) part = "candidates"
            else if (file ~ /covering\/|influence_areas|detect\/containment\.hpp/) part = "containment"
            else if (file ~ /core\/pose\.hpp|scene\/posed_polygon\.hpp/) part = "posing"
            else if (file ~ /influence\/edge_tree\.hpp|core\/box\.hpp/) part = "tree"
            else if (fn ~ /::test_pair/) part = "pairs"
            else if (fn ~ /::test_edge|pairs_through_candidates|gather/) part = "candidates"
            else if (fn ~ /::contains/) part = "containment"
            else if (fn ~ /edge_tree::query_(pairs|below)/) part = "tree"
            else part = "rest"
            sum[part] += n; total += n
        }
        END {
            printf "| %s | %.0f | %.0f | %.0f | %.0f | %.0f | %.0f | %.0f | %.0f | %.0f | %d | %.1f | %.1f |\n", name,
                total / frames, sum["tree"] / frames, sum["candidates"] / frames, sum["pairs"] / frames,
                sum["filters"] / frames, sum["posing"] / frames, sum["containment"] / frames, sum["libm"] / frames,
                sum["rest"] / frames, c[2], c[4] / frames, c[5] / frames
        }'
done
