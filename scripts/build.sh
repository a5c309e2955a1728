#!/usr/bin/env bash
# SPDX-License-Identifier: BSL-1.0
# Configures and builds one build tree: scripts/build.sh DIR [extra cmake args].
set -euo pipefail
dir=$1
shift
root=$(cd "$(dirname "$0")/.." && pwd)
cmake -S "$root" -B "$dir" -DCMAKE_BUILD_TYPE=Release "$@" >/dev/null
cmake --build "$dir" -j "$(nproc)"
# The Python package, when this build has it: installed for /usr/bin/python3.
bash "$root/scripts/install_python.sh" "$dir"
