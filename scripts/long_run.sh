#!/usr/bin/env bash
# SPDX-License-Identifier: BSL-1.0
# The long verification run: the final answer (collides) of the certified and
# the exact modes against the exact reference (CGAL's exact kernel) on at least
# a million frames of every case family, the stiff and extreme ones included.
# About an hour on one core. Outputs go to build/long-run/ (one study folder
# per part); a disagreement is written to build/long-run/regressions/.
#   scripts/long_run.sh [FRAMES_PER_FAMILY]   (default 1000000)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
per_family=${1:-1000000}
bash "$root/scripts/deps.sh"
cmake -S "$root" -B "$root/build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$root/build" -j "$(nproc)" --target influence2d_cli >/dev/null
tool="$root/build/src/influence2d"
out="$root/build/long-run"
rm -rf "$out"
mkdir -p "$out"
common=(--types certified,exact --decisions collides --regressions "$out/regressions" --progress)

# Every family but the sweeps and `large`: 4 scenes each.
families=$("$tool" study --help | sed -n 's/.*--families.*\[default: \([^;]*\);.*/\1/p' | tr ',' '\n' |
    grep -v -e '^offset_sweep$' -e '^scale_sweep$' | paste -sd, -)
"$tool" study "${common[@]}" --families "$families" --cases 4 --frames $(((per_family + 3) / 4)) --out "$out/families"
# large: its two scenes (a ring of over 100,000 vertices).
"$tool" study "${common[@]}" --families large --cases 2 --frames $(((per_family + 1) / 2)) --out "$out/large"
# The sweeps: one scene per magnitude (13 offsets, 11 scales).
"$tool" study "${common[@]}" --families offset_sweep --cases 1 --frames $(((per_family + 12) / 13)) --out "$out/offset_sweep"
"$tool" study "${common[@]}" --families scale_sweep --cases 1 --frames $(((per_family + 10) / 11)) --out "$out/scale_sweep"

echo
echo "long run: frames and disagreements per family and number type"
for part in families large offset_sweep scale_sweep; do
    tail -n +2 "$out/$part/study.csv"
done | awk -F, '{printf "%-12s %-24s %10d frames %6d disagreements %10.0f ns per frame\n", $1, $2, $4, $5, $7}'
if [ -d "$out/regressions" ]; then
    echo "DISAGREEMENTS written to $out/regressions" >&2
    exit 1
fi
