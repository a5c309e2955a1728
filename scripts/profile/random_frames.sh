#!/usr/bin/env bash
# SPDX-License-Identifier: BSL-1.0
# Profiles detector<double> on the time study's random poses under callgrind:
# instructions per frame for each cell, split by the source file the
# instructions come from (inlined code counts where it is written), grouped
# into the parts of a frame. Writes the markdown table to standard output.
#   bash scripts/profile/random_frames.sh [type:static:moving ...]
# Needs valgrind and a C++17 compiler; a few minutes for the default cells.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
cells=("$@")
if [ ${#cells[@]} -eq 0 ]; then
    cells=(convex:8:8 contour:64:64 contour:1024:8 starred:256:256 hole:1024:64 irregular:1024:1024
           convex:1024:1024 contour:8:1024)
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
${CXX:-g++} -std=c++17 -O2 -g -DNDEBUG -ffp-contract=off -I"$root/include" -I"$root" \
    "$root/scripts/profile/random_frames.cpp" -o "$work/random_frames" -lgmp -lmpfr
(cd "$work" && valgrind --tool=callgrind --instr-atstart=no --callgrind-out-file=cg.%p.out \
    ./random_frames "${cells[@]}" >frames.txt 2>valgrind.txt)
echo "| cell | instructions per frame | tree traversal | every pair (small pairs) | filters | posing | containment | exact tests | libm (sincos, hypot) | the rest |"
echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
for dump in "$work"/cg.*.out.*; do
    cell=$(grep -a "^desc: Trigger" "$dump" | sed 's/.*Request: //')
    frames=$(awk -v c="$cell" '$1 == c {print $2}' "$work/frames.txt")
    callgrind_annotate --inclusive=no --threshold=100 --auto=no "$dump" 2>/dev/null |
        awk -v cell="$cell" -v frames="$frames" '
        /^ *[0-9,]+ \(/ && !/PROGRAM TOTALS/ {
            n = $1; gsub(",", "", n); where = $0
            # The source file of the instructions; for the standard
            # library'"'"'s inlined helpers, the function they were inlined into.
            file = where; sub(/^ *[0-9,]+ \([ 0-9.]+%\) +/, "", file); sub(/:.*/, "", file)
            fn = where; sub(/^[^:]*:/, "", fn)
            if (file ~ /^\/usr\/include/) file = fn
            where = file
            part = "rest"
            if (where ~ /influence\/edge_tree\.hpp|core\/box\.hpp|edge_tree::query/) part = "tree"
            else if (where ~ /::every_pair/) part = "pairs"
            else if (where ~ /predicates\/filters\.hpp/) part = "filters"
            else if (where ~ /core\/pose\.hpp|detect\/scene\.hpp/) part = "posing"
            else if (where ~ /covering\/|influence\/influence_areas\.hpp|detect\/containment\.hpp/) part = "containment"
            else if (where ~ /predicates\/(orientation|segments)\.hpp/) part = "exact"
            else if (where ~ /libm|s_sin|sincos|hypot/) part = "libm"
            sum[part] += n; total += n
        }
        END {
            printf "| %s | %.0f | %.0f | %.0f | %.0f | %.0f | %.0f | %.0f | %.0f | %.0f |\n", cell, total / frames,
                sum["tree"] / frames, sum["pairs"] / frames, sum["filters"] / frames, sum["posing"] / frames, sum["containment"] / frames,
                sum["exact"] / frames, sum["libm"] / frames, sum["rest"] / frames
        }'
done | sort
