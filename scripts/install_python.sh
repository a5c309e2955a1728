#!/usr/bin/env bash
# SPDX-License-Identifier: BSL-1.0
# Builds and installs the Python package of a build tree, when it has one
# (INFLUENCE2D_BUILD_PYTHON, on by default: not in the sanitizer build), into
# the directory of /usr/bin/python3 (the component influence2d_python of
# cmake --install), then checks that /usr/bin/python3 imports it:
#   scripts/install_python.sh DIR
set -euo pipefail
dir=$1
if ! grep -q '^INFLUENCE2D_BUILD_PYTHON:BOOL=ON$' "$dir/CMakeCache.txt" 2>/dev/null ||
    [ ! -f "$dir/python/influence2d/__init__.py" ]; then
    exit 0
fi
cmake --build "$dir" -j "$(nproc)" --target influence2d_python
sudo_cmd=()
[ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
"${sudo_cmd[@]}" cmake --install "$dir" --component influence2d_python >/dev/null
python=$(sed -n 's/^Python_EXECUTABLE:FILEPATH=//p' "$dir/CMakeCache.txt")
(cd / && "${python:-/usr/bin/python3}" -c "import influence2d")
