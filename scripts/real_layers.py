#!/usr/bin/python3
# SPDX-License-Identifier: BSL-1.0
"""Writes real polygon layers as WKT, one geometry per line, from the data
sets Debian ships in python3-geopandas: the 177 country borders of Natural
Earth's 1:110m map (degrees; neighbours share border vertices exactly) and
New York City's five boroughs (feet, x near 1e6; multipolygons of up to a
few hundred parts).

    /usr/bin/python3 scripts/real_layers.py DATASETS_DIR OUT_DIR

DATASETS_DIR is geopandas/datasets of that package; OUT_DIR receives
countries.wkt (name order of the data set), countries.names, boroughs.wkt and
boroughs.names. Coordinates are written with repr(): the doubles read back
are the data set's own. Rings are grouped into polygons by the shapefile
reader (pyshp: outer rings clockwise, holes counter-clockwise)."""

import io
import os
import sys
import zipfile

import shapefile  # python3-pyshp


def ring_text(ring):
    return "(" + ", ".join(f"{x!r} {y!r}" for x, y in ring) + ")"


def wkt(geo):
    if geo["type"] == "Polygon":
        return "POLYGON (" + ", ".join(ring_text(r) for r in geo["coordinates"]) + ")"
    if geo["type"] == "MultiPolygon":
        return "MULTIPOLYGON (" + ", ".join(
            "(" + ", ".join(ring_text(r) for r in poly) + ")" for poly in geo["coordinates"]) + ")"
    raise ValueError(f"not a polygon: {geo['type']}")


def write(reader, name_field, out_dir, stem):
    names = [f[0] for f in reader.fields[1:]]
    at = names.index(name_field)
    with open(os.path.join(out_dir, stem + ".wkt"), "w") as w, \
            open(os.path.join(out_dir, stem + ".names"), "w") as n:
        count = 0
        for shape_record in reader.iterShapeRecords():
            w.write(wkt(shape_record.shape.__geo_interface__) + "\n")
            n.write(str(shape_record.record[at]) + "\n")
            count += 1
    print(f"{stem}.wkt: {count} geometries")


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: real_layers.py DATASETS_DIR OUT_DIR")
    datasets, out_dir = sys.argv[1], sys.argv[2]
    os.makedirs(out_dir, exist_ok=True)
    lowres = os.path.join(datasets, "naturalearth_lowres", "naturalearth_lowres")
    write(shapefile.Reader(lowres, encoding="latin-1"), "name", out_dir, "countries")
    with zipfile.ZipFile(os.path.join(datasets, "nybb_16a.zip")) as z:
        files = {ext: io.BytesIO(z.read("nybb." + ext)) for ext in ("shp", "shx", "dbf")}
    write(shapefile.Reader(shp=files["shp"], shx=files["shx"], dbf=files["dbf"]), "BoroName", out_dir, "boroughs")


if __name__ == "__main__":
    main()
