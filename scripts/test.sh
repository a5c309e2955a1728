#!/usr/bin/env bash
# SPDX-License-Identifier: BSL-1.0
# Installs what is missing, builds, and runs the test suite twice: an optimised
# build, then an AddressSanitizer + UBSan build; then a short fuzz run.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
# Each phase's wall time, on stderr, for a run that nears its time limit.
phase_start=$SECONDS
phase() {
    echo "test.sh: $1 took $((SECONDS - phase_start)) s" >&2
    phase_start=$SECONDS
}
bash "$root/scripts/deps.sh"
phase "installing what is missing"
bash "$root/scripts/build.sh" "$root/build"
phase "the optimised build"
(cd "$root/build" && ctest --output-on-failure --no-tests=error -j "$(nproc)")
phase "the optimised tests"
# Built at -O1 with line tables only (-g1): the reports still name file and
# line, and the build takes about 2.5x less time than -O2 -g. Without oneTBB,
# so that the parallel calls' std::thread path is tested too.
bash "$root/scripts/build.sh" "$root/build-sanitize" -DINFLUENCE2D_SANITIZE=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo \
    "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g1 -DNDEBUG" -DINFLUENCE2D_WITH_TBB=OFF
phase "the sanitizer build"
# Instrumented code runs several times slower: the heavy tests draw fewer random frames.
(cd "$root/build-sanitize" && INFLUENCE2D_TEST_EFFORT=0.25 ctest --output-on-failure --no-tests=error -j "$(nproc)")
phase "the sanitizer tests"
# A short fuzz run (clang, libFuzzer, ASan + UBSan): each target for
# INFLUENCE2D_FUZZ_SECONDS (default 30) on the corpus in data/fuzz/.
bash "$root/scripts/fuzz.sh" "${INFLUENCE2D_FUZZ_SECONDS:-30}"
phase "the fuzz run"
