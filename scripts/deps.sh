#!/usr/bin/env bash
# SPDX-License-Identifier: BSL-1.0
# Installs the Debian packages the build needs, only those missing.
set -euo pipefail
packages=(g++ cmake make clang clang-format libcgal-dev libgmp-dev libmpfr-dev libboost-dev catch2 libcli11-dev nlohmann-json3-dev gnuplot-nox
    libgeos-dev libbox2d-dev doxygen libtbb-dev
    pybind11-dev python3-dev python3-numpy python3-shapely python3-pandas python3-dask python3-distributed python3-pytest
    python3-geopandas)
missing=()
for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
    echo "installing: ${missing[*]}"
    sudo_cmd=()
    [ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
    "${sudo_cmd[@]}" apt-get update -qq
    DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi
