// SPDX-License-Identifier: BSL-1.0
#pragma once
// What the files of the extension influence2d._core share: the Polygon it
// hands to Python, the number types it runs in, pose arrays read in place,
// and the function each file registers its part of the module with.

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include "influence2d/core/polygon.hpp"
#include "influence2d/core/pose.hpp"
#include "influence2d/io/wkt.hpp"

namespace influence2d::python {

namespace py = pybind11;

/// A polygon as Python holds it: the library's polygon and its rings as
/// given (closing points included), which the audit reads.
struct py_polygon {
    polygon shape;
    std::vector<wkt_ring> source;
};

/// Rings as given, in flat byte strings for pickling (a Polygon's and a
/// Layer's): each ring's role (1 byte: 0 outer, 1 hole) appended to
/// `roles`, its point count (uint64) to `counts`, every point's x and y
/// (float64) to `xy`, in the machine's byte order; no Python float made.
void append_ring_bytes(const std::vector<wkt_ring>& rings, std::string& roles, std::string& counts, std::string& xy);

/// The ring of role byte `role` and `n` points read from `xy` at `at`
/// (advanced past them), as append_ring_bytes wrote it; the caller has
/// checked that the n points lie within xy.
wkt_ring ring_from_bytes(char role, std::size_t n, std::string_view xy, std::size_t& at);

/// The number types a query runs in.
enum class number_kind { double_type, certified_type, exact_type };

/// The type named `name` ("double", "certified", "exact"); throws
/// invalid_input naming it otherwise.
number_kind number_kind_of(const std::string& name);

/// An array's shape as numpy writes it: (4, 2), (4,).
std::string shape_text(const py::array& a);

/// An (n, 3) float64 C-contiguous array of poses (tx, ty, theta) read in
/// place, checked: shape, dtype, layout, every component finite. Throws
/// invalid_input naming `what` and the first bad row and component.
struct pose_rows {
    const pose* rows = nullptr;
    std::size_t count = 0;
};
pose_rows pose_rows_of(const py::array& poses, const char* what);

/// The threads of a batch: 0 for every core, else the number given.
unsigned threads_of(long threads);

/// The module's parts, one file each.
void bind_errors(py::module_& m);
void bind_polygon(py::module_& m);
void bind_queries(py::module_& m);
void bind_detector(py::module_& m);
void bind_pairs(py::module_& m);
void bind_audit(py::module_& m);
void bind_study(py::module_& m);
void bind_world(py::module_& m);

}  // namespace influence2d::python
