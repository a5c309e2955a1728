// SPDX-License-Identifier: BSL-1.0
// influence2d._core.pairs: the layer join (layer_pairs and
// certified_layer_pairs): the pairs of polygons of one layer, or of two,
// whose closed regions meet or come within a distance, as a (k, 2) array;
// influence2d._core.Layer: a layer's partition packed for a worker, its
// boxes, the parts of it another partition takes, partitions joined.

#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

#include "bindings.hpp"
#include "influence2d/exact/certified_world.hpp"
#include "influence2d/number/cgal.hpp"
#include "influence2d/world/layer_pairs.hpp"

namespace influence2d::python {

namespace {

/// A partition of a layer as a worker receives it: its polygons, with their
/// rings as given, pickled as four flat byte strings (each polygon's ring
/// count, each ring's role and point count, every point's x and y) instead
/// of one Python object per polygon: 100,000 polygons travel as a few
/// megabytes made and read by one loop each.
struct py_layer {
    std::vector<polygon> shapes;
    std::vector<std::vector<wkt_ring>> rings;
};

py_layer layer_from(const py::sequence& items) {
    py_layer out;
    out.shapes.reserve(items.size());
    out.rings.reserve(items.size());
    for (std::size_t k = 0; k < items.size(); ++k) {
        const py::object item = items[k];
        if (!py::isinstance<py_polygon>(item))
            throw invalid_input("Layer: item " + std::to_string(k) + " is not a Polygon");
        const py_polygon& p = item.cast<const py_polygon&>();
        out.shapes.push_back(p.shape);
        out.rings.push_back(p.source);
    }
    return out;
}

py::tuple layer_state(const py_layer& l) {
    std::string ring_counts, roles, point_counts, xy;
    for (const std::vector<wkt_ring>& rings : l.rings) {
        const std::uint64_t n = rings.size();
        ring_counts.append(reinterpret_cast<const char*>(&n), sizeof n);
        append_ring_bytes(rings, roles, point_counts, xy);
    }
    return py::make_tuple(py::bytes(ring_counts), py::bytes(roles), py::bytes(point_counts), py::bytes(xy));
}

/// The (n, 4) float64 boxes (min x, min y, max x, max y) of a layer's
/// polygons: what a spatial partitioning needs to know of them.
py::array_t<double> layer_bounds(const py_layer& l) {
    py::array_t<double> out({static_cast<py::ssize_t>(l.shapes.size()), py::ssize_t{4}});
    double* o = out.mutable_data();
    for (const polygon& p : l.shapes) {
        const box& b = p.bounds();
        *o++ = b.min_x;
        *o++ = b.min_y;
        *o++ = b.max_x;
        *o++ = b.max_y;
    }
    return out;
}

/// The polygons of `l` at `positions` (an int64 array), in that order; a
/// position out of range is refused naming it.
py_layer layer_take(const py_layer& l,
                    const py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>& positions) {
    if (positions.ndim() != 1) throw invalid_input("Layer.take: expected a one-dimensional array of positions");
    py_layer out;
    out.shapes.reserve(static_cast<std::size_t>(positions.size()));
    out.rings.reserve(static_cast<std::size_t>(positions.size()));
    const std::int64_t* at = positions.data();
    for (py::ssize_t k = 0; k < positions.size(); ++k) {
        if (at[k] < 0 || static_cast<std::uint64_t>(at[k]) >= l.shapes.size())
            throw invalid_input("Layer.take: positions[" + std::to_string(k) + "] is " + std::to_string(at[k]) +
                                ", outside a layer of " + std::to_string(l.shapes.size()) + " polygons");
        out.shapes.push_back(l.shapes[static_cast<std::size_t>(at[k])]);
        out.rings.push_back(l.rings[static_cast<std::size_t>(at[k])]);
    }
    return out;
}

/// The polygons of `layers` one after another.
py_layer layer_concat(const py::sequence& layers) {
    py_layer out;
    for (std::size_t k = 0; k < layers.size(); ++k) {
        const py::object item = layers[k];
        if (!py::isinstance<py_layer>(item))
            throw invalid_input("Layer.concat: item " + std::to_string(k) + " is not a Layer");
        const py_layer& l = item.cast<const py_layer&>();
        out.shapes.insert(out.shapes.end(), l.shapes.begin(), l.shapes.end());
        out.rings.insert(out.rings.end(), l.rings.begin(), l.rings.end());
    }
    return out;
}

/// Reads the next T of `data` at `at`, or throws naming what ran short.
template <class T>
T read_raw(const std::string_view data, std::size_t& at, const char* what) {
    T value;
    if (data.size() - at < sizeof value) throw invalid_input(std::string("Layer pickle: ") + what + " run short");
    std::memcpy(&value, data.data() + at, sizeof value);
    at += sizeof value;
    return value;
}

py_layer layer_from_state(const py::tuple& state) {
    if (state.size() != 4)
        throw invalid_input("Layer pickle: expected 4 byte strings, got " + std::to_string(state.size()));
    const std::string ring_counts = state[0].cast<std::string>(), roles = state[1].cast<std::string>(),
                      point_counts = state[2].cast<std::string>(), xy = state[3].cast<std::string>();
    py_layer out;
    std::size_t at_rings = 0, at_role = 0, at_counts = 0, at_xy = 0;
    while (at_rings < ring_counts.size()) {
        const auto n_rings = read_raw<std::uint64_t>(ring_counts, at_rings, "the ring counts");
        if (n_rings > roles.size() - at_role) throw invalid_input("Layer pickle: the ring roles run short");
        std::vector<wkt_ring> rings(n_rings);
        for (wkt_ring& r : rings) {
            const auto n = read_raw<std::uint64_t>(point_counts, at_counts, "the point counts");
            if (n > (xy.size() - at_xy) / (2 * sizeof(double)))
                throw invalid_input("Layer pickle: the coordinates run short");
            r = ring_from_bytes(roles[at_role++], n, xy, at_xy);
        }
        out.shapes.push_back(polygon_of_rings(rings, "Layer pickle"));
        out.rings.push_back(std::move(rings));
    }
    if (at_role != roles.size() || at_counts != point_counts.size() || at_xy != xy.size())
        throw invalid_input("Layer pickle: bytes left over after the last polygon");
    return out;
}

/// The polygons of a Layer (referred to) or of a sequence of Polygons
/// (copied into `copy`): layer_pairs takes a vector.
const std::vector<polygon>& layer_of(const py::object& items, const char* name, std::vector<polygon>& copy) {
    if (py::isinstance<py_layer>(items)) return items.cast<const py_layer&>().shapes;
    const py::sequence seq = items.cast<py::sequence>();
    copy.reserve(seq.size());
    for (std::size_t k = 0; k < seq.size(); ++k) {
        const py::object item = seq[k];
        if (!py::isinstance<py_polygon>(item))
            throw invalid_input(std::string(name) + "[" + std::to_string(k) + "] is not a Polygon");
        copy.push_back(item.cast<const py_polygon&>().shape);
    }
    return copy;
}

/// The pairs as a (k, 2) int64 array, with the join's layer_statistics:
/// (pairs, candidates, exact_pairs).
py::tuple pairs(const py::object& first, const py::object& second, double within, const std::string& number_type,
                long threads) {
    const number_kind kind = number_kind_of(number_type);
    const unsigned t = threads_of(threads);
    std::vector<polygon> copy_a, copy_b;
    const std::vector<polygon>& a = layer_of(first, "layer", copy_a);
    const bool two = !second.is_none();
    const std::vector<polygon>& b = two ? layer_of(second, "other", copy_b) : copy_b;
    std::vector<body_pair> found;
    layer_statistics stats;
    {
        py::gil_scoped_release release;
        switch (kind) {
        case number_kind::certified_type:
            found = two ? certified_layer_pairs(a, b, within, t, &stats) : certified_layer_pairs(a, within, t, &stats);
            break;
        case number_kind::double_type:
            found = two ? layer_pairs<double>(a, b, within, t, &stats) : layer_pairs<double>(a, within, t, &stats);
            break;
        case number_kind::exact_type:
            found = two ? layer_pairs<exact_rational>(a, b, within, t, &stats)
                        : layer_pairs<exact_rational>(a, within, t, &stats);
            break;
        }
    }
    py::array_t<std::int64_t> out({static_cast<py::ssize_t>(found.size()), py::ssize_t{2}});
    std::int64_t* o = out.mutable_data();
    for (std::size_t k = 0; k < found.size(); ++k) {
        o[2 * k] = found[k].first;
        o[2 * k + 1] = found[k].second;
    }
    return py::make_tuple(out, stats.candidates, stats.exact_pairs);
}

}  // namespace

void bind_pairs(py::module_& m) {
    py::class_<py_layer>(m, "Layer")
        .def(py::init(&layer_from), py::arg("polygons"))
        .def("__len__", [](const py_layer& l) { return l.shapes.size(); })
        .def("bounds", &layer_bounds)
        .def("take", &layer_take, py::arg("positions"))
        .def_static("concat", &layer_concat, py::arg("layers"))
        .def(py::pickle(&layer_state, &layer_from_state));
    m.def("pairs", &pairs, py::arg("layer"), py::arg("other"), py::arg("within"), py::arg("number_type"),
          py::arg("threads"));
}

}  // namespace influence2d::python
