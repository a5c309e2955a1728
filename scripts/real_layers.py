#!/usr/bin/python3
# SPDX-License-Identifier: BSL-1.0
"""Writes real polygon layers as WKT, one geometry per line, from the data
sets Debian ships in python3-geopandas, r-cran-sf and r-cran-spdata:

    countries  the 177 country borders of Natural Earth's 1:110m map (degrees;
               neighbours share border vertices exactly)
    boroughs   New York City's five boroughs (feet, x near 1e6; multipolygons
               of up to a few hundred parts)
    counties   the 100 counties of North Carolina (degrees; a tiling of the
               state, neighbours sharing their borders)
    blocks     the 470 city blocks of Olinda, Brazil (metres, UTM: x near
               3e5, y near 9e6)
    tracts     Boston's 506 census tracts (degrees)
    plots      a field of 500 wheat plots (a grid of small quadrilaterals,
               each sharing its sides with its neighbours)

    /usr/bin/python3 scripts/real_layers.py USR_DIR OUT_DIR

USR_DIR is the usr directory of the three packages extracted together;
OUT_DIR receives LAYER.wkt (in the data set's order) and LAYER.names for
each layer above. Coordinates are written with repr(): the doubles read back
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
        sys.exit("usage: real_layers.py USR_DIR OUT_DIR")
    usr, out_dir = sys.argv[1], sys.argv[2]
    datasets = os.path.join(usr, "lib", "python3", "dist-packages", "geopandas", "datasets")
    r_library = os.path.join(usr, "lib", "R", "site-library")
    os.makedirs(out_dir, exist_ok=True)
    lowres = os.path.join(datasets, "naturalearth_lowres", "naturalearth_lowres")
    write(shapefile.Reader(lowres, encoding="latin-1"), "name", out_dir, "countries")
    with zipfile.ZipFile(os.path.join(datasets, "nybb_16a.zip")) as z:
        files = {ext: io.BytesIO(z.read("nybb." + ext)) for ext in ("shp", "shx", "dbf")}
    write(shapefile.Reader(shp=files["shp"], shx=files["shx"], dbf=files["dbf"]), "BoroName", out_dir, "boroughs")
    for package, stem, name_field, layer in (("sf/shape", "nc", "NAME", "counties"),
                                             ("sf/shape", "olinda1", "CD_GEOCODI", "blocks"),
                                             ("spData/shapes", "boston_tracts", "TOWN", "tracts"),
                                             ("spData/shapes", "wheat", "SP_ID_1", "plots")):
        path = os.path.join(r_library, *package.split("/"), stem)
        write(shapefile.Reader(path, encoding="latin-1"), name_field, out_dir, layer)


if __name__ == "__main__":
    main()
