#!/usr/bin/env bash
# SPDX-License-Identifier: BSL-1.0
# Regenerates the README's pictures, docs/pictures/*.svg, with `influence2d render`
# from the polygon families of data/families/.
#
#   bash scripts/pictures.sh [BUILD_DIR]     (default build-dev; the tool must be built there)
#
# The moving polygons are family polygons scaled down by a power of two (so the
# scaled coordinates are exact); the scaled files and the pose lists are
# written to a temporary directory, in which the tool runs, so that the
# pictures' titles name data/families/... and scaled/... whatever the checkout.
set -euo pipefail

repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=${1:-build-dev}
case $build in
    /*) ;;
    *) build=$repo/$build ;;
esac
tool=$build/src/influence2d
if [[ ! -x $tool ]]; then
    echo "pictures.sh: $tool not found: build it first (cmake --build $build --target influence2d_cli)" >&2
    exit 2
fi
out=$repo/docs/pictures
mkdir -p "$out"

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
ln -s "$repo/data" data
mkdir scaled poses

# scaled FAMILY FACTOR: data/families/FAMILY.wkt with every coordinate times
# FACTOR, written to scaled/FAMILY_xFACTOR.wkt.
scaled() {
    awk -v f="$2" '{
        out = ""; s = $0
        while (match(s, /-?[0-9]+(\.[0-9]+)?([eE][-+]?[0-9]+)?/)) {
            out = out substr(s, 1, RSTART - 1) sprintf("%.17g", substr(s, RSTART, RLENGTH) * f)
            s = substr(s, RSTART + RLENGTH)
        }
        print out s
    }' "data/families/$1.wkt" > "scaled/$1_x$2.wkt"
}

# first_collision ARGS...: the first colliding frame that `collide` reports (exact answers).
first_collision() {
    "$tool" collide "$@" --number-type certified | sed -n 's/^first collision: *frame //p'
}

render() {
    local name=$1
    shift
    "$tool" render "$@" --out "$out/$name.svg"
    echo "pictures.sh: wrote docs/pictures/$name.svg"
}

scaled irregular_8 0.25
scaled convex_8 0.125
scaled convex_8 0.5
scaled convex_8 0.0625

# 1. A starred A, a small B on the circular trajectory passing close to a tip;
# with d = 0.75 the pose nearest the tip is within d: its pairs are drawn.
render starred --static data/families/starred_16.wkt --moving scaled/irregular_8_x0.25.wkt \
    --trajectory circular --trajectory-frames 720 --gap 0.5 --distance 0.75 --frames 8,100,250,480

# 2. An A with a hole: B inside the hole (apart), inside the ring (collides by
# containment), across the hole's boundary and across the outer boundary.
printf 'tx,ty,theta\n0,0,0\n-31,6,0.4\n15,-1,0.2\n47,12,0.8\n' > poses/hole_16.csv
render hole --static data/families/hole_16.wkt --moving scaled/convex_8_x0.125.wkt --poses poses/hole_16.csv

# 3. The linear trajectory: two frames on the way and the first colliding
# frame with its witness pairs; the paper's band as the extended area.
linear=(--static data/families/irregular_32.wkt --moving scaled/convex_8_x0.5.wkt --trajectory linear)
first=$(first_collision "${linear[@]}")
render linear "${linear[@]}" --extended-area band --frames "$((first - 1600)),$((first - 800)),$first"

# 4. A large A (256 edges) and a small B: at the first colliding frame only the
# few edges near B's centroid are candidates.
large=(--static data/families/irregular_256.wkt --moving scaled/convex_8_x0.0625.wkt --trajectory linear)
first=$(first_collision "${large[@]}")
render large "${large[@]}" --frames "$((first - 1200)),$((first - 600)),$first"
