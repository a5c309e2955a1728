#!/usr/bin/env bash
# SPDX-License-Identifier: BSL-1.0
# Real polygon layers as WKT (one geometry per line) in OUT_DIR: the 177
# country borders of Natural Earth's 1:110m map and New York City's five
# boroughs, from the data sets of Debian's python3-geopandas package; the 100
# counties of North Carolina and the 470 city blocks of Olinda (Brazil), from
# r-cran-sf; Boston's 506 census tracts and a grid of 500 wheat plots, from
# r-cran-spdata. The packages are downloaded, not installed, and their
# shapefiles converted by scripts/real_layers.py with python3-pyshp (installed
# if missing). Nothing is done when every file is there already.
#
#   bash scripts/real_layers.sh [OUT_DIR]     (default: build/real_layers)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=${1:-$root/build/real_layers}
made=1
for layer in countries boroughs counties blocks tracts plots; do [ -s "$out/$layer.wkt" ] || made=0; done
[ "$made" = 1 ] && exit 0
sudo_cmd=()
[ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
if ! dpkg-query -W -f='${Status}' python3-pyshp 2>/dev/null | grep -q "install ok installed"; then
    echo "installing: python3-pyshp"
    "${sudo_cmd[@]}" apt-get update -qq
    DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends python3-pyshp >/dev/null
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
packages=(python3-geopandas r-cran-sf r-cran-spdata)
if ! (cd "$work" && apt-get download -qq "${packages[@]}" >/dev/null 2>&1); then
    "${sudo_cmd[@]}" apt-get update -qq
    (cd "$work" && apt-get download -qq "${packages[@]}" >/dev/null)
fi
for package in "${packages[@]}"; do dpkg -x "$work/${package}"_*.deb "$work/extracted"; done
/usr/bin/python3 "$root/scripts/real_layers.py" "$work/extracted/usr" "$out"
