#!/usr/bin/env bash
# SPDX-License-Identifier: BSL-1.0
# Real polygon layers as WKT (one geometry per line) in OUT_DIR: the 177
# country borders of Natural Earth's 1:110m map and New York City's five
# boroughs, taken from the data sets of Debian's python3-geopandas package
# (downloaded, not installed) and converted by scripts/real_layers.py with
# python3-pyshp (installed if missing). Nothing is done when both files are
# there already.
#
#   bash scripts/real_layers.sh [OUT_DIR]     (default: build/real_layers)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=${1:-$root/build/real_layers}
if [ -s "$out/countries.wkt" ] && [ -s "$out/boroughs.wkt" ]; then exit 0; fi
sudo_cmd=()
[ "$(id -u)" -eq 0 ] || sudo_cmd=(sudo)
if ! dpkg-query -W -f='${Status}' python3-pyshp 2>/dev/null | grep -q "install ok installed"; then
    echo "installing: python3-pyshp"
    "${sudo_cmd[@]}" apt-get update -qq
    DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends python3-pyshp >/dev/null
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
if ! (cd "$work" && apt-get download -qq python3-geopandas >/dev/null 2>&1); then
    "${sudo_cmd[@]}" apt-get update -qq
    (cd "$work" && apt-get download -qq python3-geopandas >/dev/null)
fi
dpkg -x "$work"/python3-geopandas_*.deb "$work/extracted"
/usr/bin/python3 "$root/scripts/real_layers.py" "$work/extracted/usr/lib/python3/dist-packages/geopandas/datasets" "$out"
