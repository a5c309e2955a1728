// SPDX-License-Identifier: BSL-1.0
// influence2d._core.pairs: the layer join (layer_pairs and
// certified_layer_pairs): the pairs of polygons of one layer, or of two,
// whose closed regions meet or come within a distance, as a (k, 2) array.

#include <cstdint>
#include <vector>

#include "bindings.hpp"
#include "influence2d/exact/certified_world.hpp"
#include "influence2d/number/cgal.hpp"
#include "influence2d/world/layer_pairs.hpp"

namespace influence2d::python {

namespace {

/// The polygons of a sequence of Polygons, copied (layer_pairs takes a vector).
std::vector<polygon> layer_of(const py::sequence& items, const char* name) {
    std::vector<polygon> layer;
    layer.reserve(items.size());
    for (std::size_t k = 0; k < items.size(); ++k) {
        const py::object item = items[k];
        if (!py::isinstance<py_polygon>(item))
            throw invalid_input(std::string(name) + "[" + std::to_string(k) + "] is not a Polygon");
        layer.push_back(item.cast<const py_polygon&>().shape);
    }
    return layer;
}

py::array_t<std::int64_t> pairs(const py::sequence& first, const py::object& second, double within,
                                const std::string& number_type, long threads) {
    const number_kind kind = number_kind_of(number_type);
    const unsigned t = threads_of(threads);
    const std::vector<polygon> a = layer_of(first, "layer");
    const bool two = !second.is_none();
    const std::vector<polygon> b = two ? layer_of(second.cast<py::sequence>(), "other") : std::vector<polygon>{};
    std::vector<body_pair> found;
    {
        py::gil_scoped_release release;
        switch (kind) {
        case number_kind::certified_type:
            found = two ? certified_layer_pairs(a, b, within, t) : certified_layer_pairs(a, within, t);
            break;
        case number_kind::double_type:
            found = two ? layer_pairs<double>(a, b, within, t) : layer_pairs<double>(a, within, t);
            break;
        case number_kind::exact_type:
            found = two ? layer_pairs<exact_rational>(a, b, within, t) : layer_pairs<exact_rational>(a, within, t);
            break;
        }
    }
    py::array_t<std::int64_t> out({static_cast<py::ssize_t>(found.size()), py::ssize_t{2}});
    std::int64_t* o = out.mutable_data();
    for (std::size_t k = 0; k < found.size(); ++k) {
        o[2 * k] = found[k].first;
        o[2 * k + 1] = found[k].second;
    }
    return out;
}

}  // namespace

void bind_pairs(py::module_& m) {
    m.def("pairs", &pairs, py::arg("layer"), py::arg("other"), py::arg("within"), py::arg("number_type"),
          py::arg("threads"));
}

}  // namespace influence2d::python
