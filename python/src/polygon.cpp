// SPDX-License-Identifier: BSL-1.0
// influence2d._core.Polygon: a polygon read from WKT, WKB or coordinate
// arrays in the GeoArrow layout, with its rings as given kept for the audit.

#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <pybind11/stl.h>

#include "bindings.hpp"
#include "wkb.hpp"

namespace influence2d::python {

namespace {

py_polygon from_rings(std::vector<wkt_ring> rings, const std::string& source) {
    py_polygon p{polygon_of_rings(rings, source), std::move(rings)};
    return p;
}

py_polygon from_wkt(const std::string& text, const std::string& source) {
    return from_rings(read_wkt_rings(text, source), source);
}

py_polygon from_wkb(const py::bytes& data, const std::string& source) {
    const std::string_view view = data;
    return from_rings(wkb_reader(view.data(), view.size(), source).rings(), source);
}

/// An offsets array: 1-D, non-decreasing, within [0, limit].
std::vector<std::int64_t> offsets_of(const py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>& a,
                                     const char* name, std::int64_t limit) {
    if (a.ndim() != 1 || a.shape(0) < 2)
        throw invalid_input(std::string(name) + ": expected a 1-D array of at least 2 offsets, got shape " +
                            shape_text(a));
    std::vector<std::int64_t> o(a.data(), a.data() + a.shape(0));
    for (std::size_t k = 0; k < o.size(); ++k) {
        if (o[k] < 0 || o[k] > limit)
            throw invalid_input(std::string(name) + "[" + std::to_string(k) + "] is " + std::to_string(o[k]) +
                                ", outside [0, " + std::to_string(limit) + "]");
        if (k > 0 && o[k] < o[k - 1])
            throw invalid_input(std::string(name) + "[" + std::to_string(k) + "] is " + std::to_string(o[k]) +
                                ", less than the offset before it (" + std::to_string(o[k - 1]) + ")");
    }
    return o;
}

/// The rings of (n, 2) float64 coordinates read in place (any strides) and
/// GeoArrow offsets: ring k is coords[ring_offsets[k]:ring_offsets[k + 1]],
/// part j the rings polygon_offsets[j]:polygon_offsets[j + 1], each part's
/// first ring outer. Open rings are closed (the library takes both).
py_polygon from_coords(const py::array& coords,
                       const py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>& ring_offsets,
                       const py::object& polygon_offsets) {
    if (!coords.dtype().equal(py::dtype::of<double>()))
        throw invalid_input("coords: expected float64 coordinates, got dtype " + std::string(py::str(coords.dtype())));
    if (coords.ndim() != 2 || coords.shape(1) != 2)
        throw invalid_input("coords: expected an array of shape (n, 2), got shape " + shape_text(coords));
    const auto n = static_cast<std::int64_t>(coords.shape(0));
    const char* base = static_cast<const char*>(coords.data());
    const py::ssize_t s0 = coords.strides(0), s1 = coords.strides(1);
    const auto at = [&](std::int64_t i, int c) {
        double v;
        std::memcpy(&v, base + i * s0 + c * s1, sizeof v);
        return v;
    };
    const std::vector<std::int64_t> rings = offsets_of(ring_offsets, "ring_offsets", n);
    const auto ring_count = static_cast<std::int64_t>(rings.size() - 1);
    std::vector<std::int64_t> parts{0, ring_count};
    if (!polygon_offsets.is_none())
        parts =
            offsets_of(py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(polygon_offsets),
                       "polygon_offsets", ring_count);
    std::vector<wkt_ring> out;
    for (std::size_t j = 0; j + 1 < parts.size(); ++j) {
        for (std::int64_t r = parts[j]; r < parts[j + 1]; ++r) {
            wkt_ring ring;
            ring.role = r == parts[j] ? ring_role::outer : ring_role::hole;
            for (std::int64_t i = rings[r]; i < rings[r + 1]; ++i) {
                const point<double> q{at(i, 0), at(i, 1)};
                if (!std::isfinite(q.x) || !std::isfinite(q.y))
                    throw invalid_input("coords[" + std::to_string(i) + ", " + (std::isfinite(q.x) ? "1" : "0") +
                                        "] is " + shortest_decimal(std::isfinite(q.x) ? q.y : q.x) + " (ring " +
                                        std::to_string(out.size()) + ", vertex " + std::to_string(i - rings[r]) +
                                        "): not a finite number");
                ring.points.push_back(q);
            }
            if (ring.points.size() > 1 && ring.points.front() != ring.points.back())
                ring.points.push_back(ring.points.front());
            out.push_back(std::move(ring));
        }
    }
    if (out.empty()) throw invalid_input("coords: no ring (the offsets select none)");
    return from_rings(std::move(out), "coords");
}

py::tuple state_of(const py_polygon& p) {
    std::string roles, counts, xy;
    append_ring_bytes(p.source, roles, counts, xy);
    return py::make_tuple(py::bytes(roles), py::bytes(counts), py::bytes(xy));
}

py_polygon from_state(const py::tuple& state) {
    if (state.size() != 3) throw invalid_input("pickle: expected 3 byte strings, got " + std::to_string(state.size()));
    const std::string roles = state[0].cast<std::string>(), counts = state[1].cast<std::string>(),
                      xy = state[2].cast<std::string>();
    if (counts.size() != roles.size() * sizeof(std::uint64_t))
        throw invalid_input("pickle: " + std::to_string(roles.size()) + " rings but " + std::to_string(counts.size()) +
                            " bytes of counts");
    std::vector<wkt_ring> source(roles.size());
    std::size_t at = 0;
    for (std::size_t k = 0; k < roles.size(); ++k) {
        std::uint64_t n = 0;
        std::memcpy(&n, counts.data() + k * sizeof n, sizeof n);
        if (n > (xy.size() - at) / (2 * sizeof(double)))
            throw invalid_input("pickle: ring " + std::to_string(k) + " runs past the coordinates");
        source[k] = ring_from_bytes(roles[k], n, xy, at);
    }
    if (at != xy.size()) throw invalid_input("pickle: coordinates left over after the last ring");
    return from_rings(std::move(source), "pickle");
}

}  // namespace

void append_ring_bytes(const std::vector<wkt_ring>& rings, std::string& roles, std::string& counts, std::string& xy) {
    for (const wkt_ring& r : rings) {
        roles.push_back(r.role == ring_role::outer ? 0 : 1);
        const std::uint64_t n = r.points.size();
        counts.append(reinterpret_cast<const char*>(&n), sizeof n);
        for (const point<double>& q : r.points) {
            xy.append(reinterpret_cast<const char*>(&q.x), sizeof q.x);
            xy.append(reinterpret_cast<const char*>(&q.y), sizeof q.y);
        }
    }
}

wkt_ring ring_from_bytes(char role, std::size_t n, std::string_view xy, std::size_t& at) {
    wkt_ring r;
    r.role = role == 0 ? ring_role::outer : ring_role::hole;
    r.points.resize(n);
    for (point<double>& q : r.points) {
        std::memcpy(&q.x, xy.data() + at, sizeof q.x);
        std::memcpy(&q.y, xy.data() + at + sizeof q.x, sizeof q.y);
        at += 2 * sizeof(double);
    }
    return r;
}

void bind_polygon(py::module_& m) {
    py::class_<py_polygon>(m, "Polygon")
        .def_static("from_wkt", &from_wkt, py::arg("text"), py::arg("source") = "wkt")
        .def_static("from_wkb", &from_wkb, py::arg("data"), py::arg("source") = "wkb")
        .def_static("from_coords", &from_coords, py::arg("coords"), py::arg("ring_offsets"),
                    py::arg("polygon_offsets") = py::none())
        .def_static(
            "many_from_wkb",
            [](const py::sequence& items, const std::string& name) {
                std::vector<py_polygon> out;
                out.reserve(items.size());
                for (std::size_t k = 0; k < items.size(); ++k) {
                    const std::string source = name + "[" + std::to_string(k) + "]";
                    const py::object item = items[k];
                    if (!py::isinstance<py::bytes>(item)) throw invalid_input(source + ": expected WKB bytes");
                    out.push_back(from_wkb(item.cast<py::bytes>(), source));
                }
                return out;
            },
            py::arg("items"), py::arg("name") = "layer")
        .def("to_wkt", [](const py_polygon& p) { return to_wkt(p.shape); })
        .def_property_readonly("num_vertices", [](const py_polygon& p) { return p.shape.size(); })
        .def_property_readonly("num_rings", [](const py_polygon& p) { return p.shape.ring_count(); })
        .def_property_readonly("bounds",
                               [](const py_polygon& p) {
                                   const box& b = p.shape.bounds();
                                   return py::make_tuple(b.min_x, b.min_y, b.max_x, b.max_y);
                               })
        .def_property_readonly("area", [](const py_polygon& p) { return static_cast<double>(p.shape.area()); })
        .def(py::pickle(&state_of, &from_state));
}

}  // namespace influence2d::python
