#!/usr/bin/env bash
# SPDX-License-Identifier: BSL-1.0
# Builds the libFuzzer targets (clang, ASan + UBSan) in build-fuzz and runs
# each for SECONDS (default 60) on a copy of its corpus from data/fuzz/; new
# inputs that widen coverage go to build-fuzz/corpus/, crashes to
# build-fuzz/crashes/ (and the run fails). libFuzzer also writes there a
# unit slower than 10 s (slow-unit-*): each is run again alone, and fails
# the run only if it is slow again; otherwise it is moved to
# build-fuzz/slow/ and named (a stall of the machine, not of the input).
#   bash scripts/fuzz.sh [SECONDS]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
seconds=${1:-60}
bash "$root/scripts/deps.sh"
for p in clang libclang-rt-14-dev; do
    if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
        sudo_cmd=()
        [ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
        "${sudo_cmd[@]}" apt-get update -qq
        DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "$p" >/dev/null
    fi
done
build="$root/build-fuzz"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
    -DINFLUENCE2D_BUILD_FUZZERS=ON -DINFLUENCE2D_BUILD_TESTS=OFF -DINFLUENCE2D_BUILD_CLI=OFF >/dev/null
cmake --build "$build" -j "$(nproc)" --target wkt_fuzz csv_fuzz detector_fuzz world_fuzz queries_fuzz >/dev/null
mkdir -p "$build/crashes"
for target in wkt csv detector world queries; do
    corpus="$build/corpus/$target"
    mkdir -p "$corpus"
    cp -n "$root/data/fuzz/$target/"* "$corpus/" 2>/dev/null || true
    echo "fuzz: $target for $seconds s"
    "$build/fuzz/${target}_fuzz" "$corpus" -max_total_time="$seconds" -max_len=4096 -timeout=20 \
        -artifact_prefix="$build/crashes/${target}-" -print_final_stats=1 2>&1 | grep -E "^(stat::number_of_executed_units|stat::new_units_added|==[0-9]+==ERROR|SUMMARY)" || true
done
mkdir -p "$build/slow"
for unit in "$build"/crashes/*-slow-unit-*; do
    [ -e "$unit" ] || continue
    target=$(basename "$unit")
    target=${target%%-slow-unit-*}
    start=$(date +%s)
    if "$build/fuzz/${target}_fuzz" -timeout=10 "$unit" >/dev/null 2>&1; then
        echo "fuzz: $(basename "$unit") took $(($(date +%s) - start)) s when run again alone: moved to $build/slow" >&2
        mv "$unit" "$build/slow/"
    else
        echo "fuzz: $(basename "$unit") is slow (or fails) again alone" >&2
    fi
done
if [ -n "$(ls -A "$build/crashes")" ]; then
    echo "fuzz: crashes in $build/crashes" >&2
    exit 1
fi
